# A spouted-bed batch over time: moisture with the kernels' 5-95 % band,
# kernel and outlet-air temperatures, outlet RH.  Variables: csv (the
# spouted_series.csv), limit (kernel-temperature limit, degC), target (% w.b.).
set key outside right
set grid
set multiplot layout 3,1 title 'spouted-bed batch'
set ylabel 'moisture [% w.b.]'
plot csv u 1:4:5 w filledcurves fs transparent solid 0.3 t '5-95 %', \
     '' u 1:3 w l lw 2 t 'bed mean', target w l dt 2 t 'target'
set ylabel 'temperature [degC]'
plot csv u 1:6 w l lw 2 t 'kernel mean', '' u 1:7 w l t 'kernel max', \
     '' u 1:8 w l lw 2 t 'outlet air', limit w l dt 2 t 'limit'
set ylabel 'outlet RH [%]'
set xlabel 'time [h]'
plot csv u 1:9 w l lw 2 t 'outlet RH'
unset multiplot
