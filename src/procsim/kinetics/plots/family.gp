# One quantity of every sweep member over time, one curve each.  Variables:
# dir (the sweep directory), labels (the members, one word each), col (the
# quantity's column of timeseries.csv), ylabel_text, title_text.
set grid
set key outside right
set xlabel 'time (h)'
set ylabel ylabel_text
set title title_text
plot for [k = 1:words(labels)] dir.'/'.word(labels, k).'/timeseries.csv' using 1:col with lines lw 2 title word(labels, k)
