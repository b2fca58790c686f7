# Monte Carlo annual trend of one receptor (the study's Figs 2-3): the band
# of 5th-95th percentiles over the synthetic years for each day, mean and
# median, and a line per exceedance threshold.  Variables: csv (the
# daily_<receptor>.csv), title_text, thresholds (their values, one word
# each), nthresholds.
set key top right
set xlabel 'day of the year'
set ylabel '24-h average PM10 [ug/m3]'
set xrange [1:365]
set grid
set title title_text
plot csv using 1:3:5 with filledcurves lc rgb '#cfe2ff' title '5th-95th percentile', \
     '' using 1:3 with lines lc rgb '#6fa8dc' notitle, \
     '' using 1:5 with lines lc rgb '#6fa8dc' notitle, \
     '' using 1:2 with lines lw 2 lc rgb '#1c4587' title 'mean', \
     '' using 1:4 with lines lw 1 dt 2 lc rgb 'black' title 'median', \
     for [q = 1:nthresholds] word(thresholds, q) + 0 with lines lw 2 \
         lc rgb (q == 1 ? '#e69138' : '#cc0000') title word(thresholds, q).' ug/m3'
