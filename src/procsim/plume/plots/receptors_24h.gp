# 24-h averages at every receptor, one line each, and the 24-h standard.
# Variables: csv (day, then one column per receptor), nreceptors,
# title_text, standard (ug/m3).
set key outside right
set xlabel 'day'
set ylabel '24-h average PM10 [ug/m3]'
set title title_text
set grid
plot for [c = 2:nreceptors + 1] csv using 1:c with linespoints title columnheader(c), \
     standard with lines lw 2 lc rgb 'red' title 'standard'
