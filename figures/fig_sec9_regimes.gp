# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: the Remark of Section 9 by the full simulator (sec9_regimes): one time history per case,
# position of the mass x (coloured by regime: blue free, red progression, green stop) and of the
# delimiter y (dashed black). Each panel names its case and its parameters (read from the table
# sec9_regimes.tsv); one key for the whole figure, above the panels.
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,13cm
set output "fig_sec9_regimes.tex"
tab = data."/sec9_regimes.tsv"
rgb(r) = (r == 0 ? 0x1f77b4 : (r == 1 ? 0xd62728 : 0x2ca02c))
cases = "stop progression between-high between-low b-large-q-small reference"
# the parameters of each case (stats obeys ranges: read them before any range is set)
do for [k=1:words(cases)] {
  c = word(cases, k)
  stats tab using (strcol("case") eq c ? column("b_over_a") : NaN) name "B".k nooutput
  stats tab using (strcol("case") eq c ? column("q_over_a") : NaN) name "Q".k nooutput
  stats data."/sec9_regimes-history-".c.".tsv" using "t" name "T".k nooutput
}
set multiplot
set format x "$%g$"; set format y "$%g$"
set grid xtics ytics
# panel k: column (k-1)%2, row (k-1)/2; plot areas leave room for tick labels and axis labels
px0(k) = ((k-1)%2 == 0 ? 0.095 : 0.605); ph = 0.2
py0(k) = 0.68 - ((k-1)/2)*0.3
do for [k=1:words(cases)] {
  c = word(cases, k)
  f = data."/sec9_regimes-history-".c.".tsv"
  set lmargin at screen px0(k); set rmargin at screen px0(k) + 0.385
  set bmargin at screen py0(k); set tmargin at screen py0(k) + ph
  set title sprintf('\small %s: $b/a=%g$, $q/a=%g$', c, value("B".k."_mean"), value("Q".k."_mean")) offset 0,-0.5
  set xrange [0:value("T".k."_max")]
  # the time axis is labelled on the bottom row only
  if (k > 4) { set xlabel '$t$' offset 0,0.6 } else { unset xlabel }
  set ylabel '$x$, $y$' offset 0,0
  # the permanently stopped case is a constant: give it a range of its own
  if (c eq "stop") { set yrange [-0.5:0.5] } else { set autoscale y }
  plot f using "t":"y" with lines lw 1 dt 2 lc rgb "black" notitle, \
       f using "t":"x":(rgb(column("regime"))) with lines lw 2 lc rgb variable notitle
}
# one key for the whole figure, in a strip of its own above the panels
set lmargin at screen 0.05; set rmargin at screen 0.95; set bmargin at screen 0.955; set tmargin at screen 0.995
unset border; unset tics; unset xlabel; unset ylabel; unset title; unset grid
set xrange [0:1]; set yrange [0:1]
set key at screen 0.5, screen 0.975 center center horizontal samplen 2 spacing 1 width -2 maxrows 1 nobox
plot NaN w l lw 2 lc rgb c_free title 'mass $x$: free flight', NaN w l lw 2 lc rgb c_prog title 'progression', \
     NaN w l lw 2 lc rgb c_stop title 'stop', NaN w l lw 1 dt 2 lc rgb "black" title 'delimiter $y$'
unset multiplot
