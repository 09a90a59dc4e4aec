# Figure: the Remark of Section 9 by the full simulator (sec9_regimes): one time history per case,
# position of the mass x (coloured by regime: blue free, red progression, green stop) and of the
# delimiter y (dashed).
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,12cm
set output "fig_sec9_regimes.tex"
set multiplot layout 3,2 margins 0.08,0.98,0.06,0.99 spacing 0.08,0.07
set format x "$%g$"; set format y "$%g$"
set xlabel '$t$' offset 0,0.6
rgb(r) = (r == 0 ? 0x1f77b4 : (r == 1 ? 0xd62728 : 0x2ca02c))
do for [c in "stop progression between-high between-low b-large-q-small reference"] {
  f = data."/sec9_regimes-history-".c.".tsv"
  set label 1 "\\small ".c at graph 0.03,0.9 left front
  # the permanently stopped case is a constant: give it a range of its own
  if (c eq "stop") { set yrange [-0.5:0.5] } else { set autoscale y }
  plot f using "t":"y" with lines lw 1 dt 2 lc rgb "black", \
       f using "t":"x":(rgb(column("regime"))) with lines lw 2 lc rgb variable
}
unset multiplot
