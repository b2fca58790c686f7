# Residuals against time.  Variable: csv (fit_residuals.csv).
set grid
set xlabel 'time (h)'
set ylabel 'measured - predicted (mg/L)'
set title 'residuals'
plot csv using 2:6 with points pt 7 title 'residual', 0 with lines dt 2 notitle
