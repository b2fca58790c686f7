# Predicted against measured, every data point.  Variables: csv
# (fit_residuals.csv), r2_text.
set grid
set xlabel 'measured (mg/L)'
set ylabel 'predicted (mg/L)'
set title 'goodness of fit: R^2 = '.r2_text
set size square
plot csv using 4:5 with points pt 7 title 'data', x with lines dt 2 title 'y = x'
