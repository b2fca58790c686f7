# Predicted against measured 24-h averages at one receptor (the Eulerian
# study's Fig 2).  Variables: csv (day, measured, predicted), title_text,
# standard (ug/m3).
set key top left
set xlabel 'day'
set ylabel '24-h average PM10 [ug/m3]'
set grid
set yrange [0:*]
set title title_text
plot csv using 1:3 with linespoints lw 2 pt 7 title 'predicted', \
     '' using 1:2 with points pt 5 ps 1.3 title 'measured', \
     standard with lines lc rgb 'red' title 'standard'
