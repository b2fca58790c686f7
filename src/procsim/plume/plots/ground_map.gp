# Map of the run-mean ground-level concentration over the domain, with
# dashed terrain contours, the sources as boxes and the receptors labelled.
# The inputs are whitespace-separated gnuplot grids (a blank line after each
# row of cells).  Variables: ground (x y terrain PM10), contours (written
# here from the terrain), sources (x y half-width half-depth name),
# receptors (x y name), title_text, x0, x1, y0, y1 (the domain [m]).
set datafile separator whitespace
set size ratio -1
set xlabel 'x (east) [m]'
set ylabel 'y (north) [m]'
set title title_text
set xrange [x0:x1]
set yrange [y0:y1]
set palette defined (0 'white', 1 '#ffe680', 2 '#ff8c1a', 3 '#cc0000', 4 '#4d0000')
set cbrange [0:*]
# the terrain contours, traced once into a table (its comment names the
# curve by the data file and columns it came from)
set contour base
set cntrparam levels 10
unset surface
set view map
set table contours
splot ground using 1:2:3 with lines title "'".ground."' using 1:2:3"
unset table
unset contour
set key outside bottom horizontal
plot ground using 1:2:4 with image notitle, \
     contours using 1:2 with lines lc rgb '#555555' dt 2 notitle, \
     sources using 1:2:3:4 with boxxyerror lc rgb 'black' lw 2 title 'sources', \
     receptors using 1:2 with points pt 7 ps 1.2 lc rgb 'blue' title 'receptors', \
     receptors using 1:2:3 with labels offset 1.5,0.8 textcolor rgb 'blue' notitle
