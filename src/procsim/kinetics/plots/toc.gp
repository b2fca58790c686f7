# TOC of a run and what it would be without discharge.  Variables: csv
# (timeseries.csv), title_text, toc (the TOC column; the next one is TOC
# without discharge).
set grid
set xlabel 'time (h)'
set ylabel 'TOC (mg C/L)'
set title title_text.': TOC'
plot csv using 1:toc with lines lw 2 title 'TOC', '' using 1:toc + 1 with lines dt 2 title 'TOC without discharge'
