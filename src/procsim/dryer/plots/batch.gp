# One batch over time: air temperatures, return-air humidity and heater
# power, moisture.  Variables: csv (the <id>_series.csv), name (the batch).
set key autotitle columnhead outside right
set grid
set multiplot layout 3,1 title 'batch '.name
set ylabel 'temperature [degC]'
plot csv u 1:2 w l lw 2, '' u 1:3 w l lw 2, '' u 1:10 w l, '' u 1:11 w l
set ylabel 'return air RH [%]'
set y2label 'heater [kW]'
set y2tics
plot csv u 1:6 w l lw 2, '' u 1:12 axes x1y2 w l
unset y2label
unset y2tics
set ylabel 'moisture [% dry basis]'
set xlabel 'time [h]'
plot csv u 1:7 w l lw 2, '' u 1:8 w l, '' u 1:9 w l
unset multiplot
