# A quantity at a report time against the last swept key; with two swept
# keys one curve per value of the first.  Variables: csv (sweep_summary.csv),
# xcol (the last swept key's column), col (the quantity's), xlabel_text,
# ylabel_text, title_text, key0 (the first key, two keys only), values0
# (its values, one word each; empty with one key).
set grid
set key outside right
set xlabel xlabel_text
set ylabel ylabel_text
set title title_text
if (words(values0) == 0) {
    plot csv using xcol:col with linespoints lw 2 pt 7 notitle
} else {
    plot for [k = 1:words(values0)] csv skip 1 using ($1 == word(values0, k) + 0 ? column(xcol) : 1/0):(column(col)) \
         with linespoints lw 2 pt 7 title key0.'='.word(values0, k)
}
