# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: Section 10 (sec10_robustness): the perturbed return map T_eps near J0 and J1 for several
# eps, computed by integrating the perturbed equations of motion. The covering asks each branch to
# run from the perturbed stop release t2^eps (dashed, one per eps, from sec10_robustness.tsv) up
# past 3 pi/2 (dotted). The t2^eps differ by less than 0.01: the inset of each panel magnifies the
# end of the branches, where each lands on its own t2^eps; its tick labels clear of the t2 lines.
# Each eps has its Okabe-Ito colour and its marker. One key for the figure, above the panels.
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,7.2cm
set output "fig_robustness.tex"
f = data."/sec10_robustness-graph.tsv"
tab = data."/sec10_robustness.tsv"
eps_list = "0 0.001 0.01"
ecol(k) = (k == 1 ? oi_black : (k == 2 ? oi_orange : oi_blue))
# and a marker per eps (circle, square, triangle), so that the curves and the key read in greyscale
ept(k) = (k == 1 ? 7 : (k == 2 ? 5 : 9))
sel(s, e) = (column("segment") == s && abs(column("eps") - real(e)) < 1e-15)
# t2^eps per eps, and the theta range of each segment (stats obeys ranges: before any is set)
do for [k=1:3] {
  e = word(eps_list, k)
  stats tab using (abs(column("eps") - real(e)) < 1e-15 ? column("t2_eps") : NaN) name "S".k nooutput
}
do for [s=0:1] {
  stats f using (column("segment") == s ? column("theta") : NaN) name "X".s nooutput
}
set multiplot
set grid noxtics noytics
set format x '$%.2f$'; set format y '$%.1f$'
do for [s=0:1] {
  set lmargin at screen (s == 0 ? 0.08 : 0.575); set rmargin at screen (s == 0 ? 0.48 : 0.975)
  set bmargin at screen 0.14; set tmargin at screen 0.83
  set title sprintf('near $J_%d$', s) offset 0,-0.3
  set xlabel '$\theta$' offset 0,0.3
  set ylabel (s == 0 ? '$T_\varepsilon(\theta)$' : '') offset 1.5,0
  set xrange [value("X".s."_min") - 0.004 : value("X".s."_max") + 0.004]
  set xtics 0.04
  set yrange [3.05:4.95]
  set ytics ('$t_2$' pi + asin(0.02), '$3.5$' 3.5, '$4.0$' 4.0, '$4.5$' 4.5, '$\frac{3\pi}{2}$' 1.5*pi)
  set arrow 1 from graph 0, first 1.5*pi to graph 1, first 1.5*pi nohead dt 3 lw 1.2 lc rgb c_grey
  do for [k=1:3] { set arrow 1+k from graph 0, first value("S".k."_mean") to graph 1, first value("S".k."_mean") nohead dt 2 lw 0.8 lc rgb ecol(k) }
  # the box that the inset magnifies
  ilo = (s == 0 ? 3.578 : 3.699); ihi = (s == 0 ? 3.602 : 3.734)
  set object 1 rect from ilo, 3.156 to ihi, 3.172 fs empty border lc rgb "black" lw 0.6 front
  plot for [k=1:3] f using (sel(s, word(eps_list, k)) ? column("theta") : NaN):"T_eps" w p pt ept(k) ps 0.12 lc rgb ecol(k) notitle
  unset object 1
  # inset: the landing of each branch on its t2^eps
  set lmargin at screen (s == 0 ? 0.15 : 0.645); set rmargin at screen (s == 0 ? 0.295 : 0.79)
  set bmargin at screen 0.29; set tmargin at screen 0.5
  unset title; unset xlabel; unset ylabel
  set xrange [ilo:ihi]; set yrange [3.156:3.172]
  set xtics 0.02 format '\scriptsize $%.2f$' scale 0.4
  set ytics 0.005 format '\scriptsize $%.3f$' scale 0.4
  set mxtics 2
  set object 2 rect from graph 0, graph 0 to graph 1, graph 1 fc rgb "white" fs solid 1.0 noborder behind
  unset arrow 1
  plot for [k=1:3] f using (sel(s, word(eps_list, k)) ? column("theta") : NaN):"T_eps" w lp pt ept(k) ps 0.45 lw 0.6 lc rgb ecol(k) notitle
  unset object 2
  set format x '$%.2f$'; set format y '$%.1f$'; set tics scale 0.6
  do for [k=1:3] { unset arrow 1+k }
}
# one key for the figure, drawn by hand in a strip above the panels (a gnuplot key is laid out
# inside one panel's width)
unset border; unset tics; unset xlabel; unset ylabel; unset title
set lmargin at screen 0; set rmargin at screen 1; set bmargin at screen 0; set tmargin at screen 1
set xrange [0:1]; set yrange [0:1]
ky = 0.955
do for [k=1:3] {
  kx = 0.06 + (k-1)*0.14
  set label 10+k sprintf('$\varepsilon=%s$', word(eps_list, k)) at screen kx, screen ky left front point pt ept(k) ps 0.8 lc rgb ecol(k) offset 0.8,0
}
set arrow 20 from screen 0.47, screen ky to screen 0.51, screen ky nohead dt 2 lc rgb "black"
set label 20 '$t_2^\varepsilon$ (in the colour of its $\varepsilon$)' at screen 0.52, screen ky left front
set arrow 21 from screen 0.82, screen ky to screen 0.86, screen ky nohead dt 3 lw 1.2 lc rgb c_grey
set label 21 '$3\pi/2$' at screen 0.87, screen ky left front
plot NaN notitle
unset multiplot
