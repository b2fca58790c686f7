# The fitted model over the data of one dataset.  Variables: curve (the
# model on a fine time grid), data (the measurements), names (the
# quantities, one word each, columns 2, 3, ... of both files), title_text.
set grid
set key outside right
set xlabel 'time (h)'
set ylabel 'mg/L (TOC: mg C/L)'
set title 'fit: '.title_text
plot for [q = 1:words(names)] curve skip 1 using 1:(column(q + 1)) with lines lw 2 lc q title word(names, q).' model', \
     for [q = 1:words(names)] data skip 1 using 1:(column(q + 1)) with points pt 7 lc q title word(names, q).' data'
