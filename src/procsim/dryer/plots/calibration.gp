# Calibrate-then-predict, one panel per quantity: the measured value, the
# central fit and the band of the profile fits as an interval.  Variable: csv
# (calibration.csv: per quantity five columns from 4 on, measured, central,
# band min, band max, measured in band).
set multiplot layout 2,2 title 'fitted on the old-dryer batches, predicted with the modified venting: measured, central fit, band of fits within the scatter'
set key outside bottom center horizontal
set grid
set offsets 0.5, 0.5, 0, 0
set xlabel 'batch'
array ylabels[4] = ['drying time [h]', 'electricity [kWh]', 'E [kJ/kg water]', 'eta [%]']
do for [k = 1:4] {
    c = 4 + 5 * (k - 1)
    set ylabel ylabels[k]
    plot csv skip 1 u 0:(column(c + 1)):(column(c + 2)):(column(c + 3)):xtic(1) w yerrorbars pt 4 ps 1.5 lw 2 lc rgb '#1f77b4' t 'central, band', \
         '' skip 1 u 0:(column(c)) w p pt 7 ps 1.5 lc rgb 'black' t 'measured'
}
unset multiplot
