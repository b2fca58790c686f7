# Concentrations of a run over time.  Variables: csv (timeseries.csv),
# title_text, names (the species, one word each), columns (their columns).
set key outside right
set grid
set xlabel 'time (h)'
set ylabel 'concentration (mg/L)'
set title title_text.': species'
plot for [k = 1:words(names)] csv skip 1 using 1:(column(int(word(columns, k)))) with lines lw 2 title word(names, k)
