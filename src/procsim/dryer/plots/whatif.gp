# A what-if quantity over the hot-air temperature, one line per vented
# fraction (one CSV data block each), scorched settings filled red.
# Variables: csv (whatif.csv), ycol (the column drawn), ylabel_text,
# title_text, nblocks (vented fractions), fractions (their labels, one word each).
set key outside right title 'vented fraction'
set xlabel 'hot-air temperature [degC]'
set grid
set title title_text
set ylabel ylabel_text
plot for [i = 0:nblocks - 1] csv index i u 1:(column(ycol)) w lp pt 6 lw 2 lc i + 1 t word(fractions, i + 1), \
     for [i = 0:nblocks - 1] csv index i u 1:($9 > 0.5 ? column(ycol) : 1/0) w p pt 7 ps 2 lc rgb 'red' notitle
