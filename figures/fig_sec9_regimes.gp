# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: the Remark of Section 9 by the full simulator (sec9_regimes): one time history per case,
# position of the mass x (drawn by regime, style.gp: free thin, progression thick, stop dotted) and of the
# delimiter y (dashed black). Each panel names its case in words and its parameters (read from the
# table sec9_regimes.tsv, columns case, label, b_over_a, q_over_a); one key for the whole figure, above the panels.
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,11cm
set output "fig_sec9_regimes.tex"
tab = data."/sec9_regimes.tsv"
cases = "stop progression between-high between-low b-large-q-small reference"
# the case's label, from the first row of the table with its identifier
label(c) = system("awk -F'\t' '$1 == \"".c."\" { print $2; exit }' '".tab."'")
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
px0(k) = ((k-1)%2 == 0 ? 0.095 : 0.605); ph = 0.18
py0(k) = 0.68 - ((k-1)/2)*0.3
do for [k=1:words(cases)] {
  c = word(cases, k)
  if (strlen(label(c)) == 0) { print "fig_sec9_regimes: no label of case ".c." in ".tab; exit status 1 }
  f = data."/sec9_regimes-history-".c.".tsv"
  set lmargin at screen px0(k); set rmargin at screen px0(k) + 0.385
  set bmargin at screen py0(k); set tmargin at screen py0(k) + ph
  set title sprintf('\small %s: $b/a=%g$, $q/a=%g$', label(c), value("B".k."_mean"), value("Q".k."_mean")) offset 0,-0.5
  set xrange [0:value("T".k."_max")]
  # the time axis is labelled on the bottom row only
  if (k > 4) { set xlabel '$t$' offset 0,0.6 } else { unset xlabel }
  set ylabel '$x$, $y$' offset 0,0
  # the permanently stopped case is a constant: give it a range of its own
  if (c eq "stop") { set yrange [-0.5:0.5] } else { set autoscale y }
  plot f using "t":"y" with lines lw 1 dt 2 lc rgb "black" notitle, \
       for [r=0:2] f using "t":(reg(r, column("x"))) with lines lt 11+r notitle
}
# one key for the whole figure, drawn by hand in one row above the panels
set lmargin at screen 0; set rmargin at screen 1; set bmargin at screen 0; set tmargin at screen 1
unset border; unset tics; unset xlabel; unset ylabel; unset title; unset grid
set xrange [0:1]; set yrange [0:1]
ky = 0.975
do for [r=0:2] {
  kx = (r == 0 ? 0.06 : (r == 1 ? 0.34 : 0.54))
  set arrow 10+r from screen kx, screen ky to screen kx + 0.035, screen ky nohead lt 11+r
  set label (10+r) (r == 0 ? '\small mass $x$: free flight' : (r == 1 ? '\small progression' : '\small stop')) at screen kx + 0.045, screen ky left front
}
set arrow 20 from screen 0.7, screen ky to screen 0.735, screen ky nohead dt 2 lc rgb "black"
set label 20 '\small delimiter $y$' at screen 0.745, screen ky left front
plot NaN notitle
unset multiplot
