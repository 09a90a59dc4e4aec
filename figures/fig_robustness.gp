# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: Section 10 (sec10_robustness): the perturbed return map T_eps near J0 and J1 for several
# eps, computed by integrating the perturbed equations of motion. The covering asks each branch to
# run from the perturbed stop release t2^eps (dashed, one per eps, from sec10_robustness.tsv) up
# past 3 pi/2 (dotted). The t2^eps lie close together: the inset of each panel magnifies the end of
# the branches, where each lands on its own t2^eps (its box: the t2^eps widened by their spread on
# each side, and the phases whose T_eps fall in it). The eps drawn are those sec10_robustness names
# in its macros; t2 is that of its b/a.
# Each eps has its Okabe-Ito colour and its marker. One key for the figure, above the panels.
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,7.2cm
set output "fig_robustness.tex"
f = data."/sec10_robustness-graph.tsv"
tab = data."/sec10_robustness.tsv"
eval tex_macro("drawn", "sec10_robustness", "SecTenDrawnEps")
eval tex_macro("b10", "sec10_robustness", "SecTenB")
eps_list = system("echo '".drawn."' | tr -d ,")
neps = words(eps_list)
if (neps < 1 || neps > 3) { print "fig_robustness: one to three values of eps to draw, not ".drawn; exit status 1 }
t2 = pi + asin(2*real(b10))
ecol(k) = (k == 1 ? oi_black : (k == 2 ? oi_orange : oi_blue))
# and a marker per eps (circle, square, triangle), so that the curves and the key read in greyscale
ept(k) = (k == 1 ? 7 : (k == 2 ? 5 : 9))
sel(s, e) = (column("segment") == s && abs(column("eps") - real(e)) < 1e-15)
# t2^eps per eps, and the theta range of each segment (stats obeys ranges: before any is set)
do for [k=1:neps] {
  e = word(eps_list, k)
  stats tab using (abs(column("eps") - real(e)) < 1e-15 ? column("t2_eps") : NaN) name "S".k nooutput
  if (value("S".k."_records") != 1) { print "fig_robustness: no single t2_eps at eps = ".e; exit status 1 }
  stats f using (abs(column("eps") - real(e)) < 1e-15 ? column("theta") : NaN) name "G" nooutput
  if (G_records < 1) { print "fig_robustness: no graph of T_eps at eps = ".e; exit status 1 }
}
# the inset's box in T: the t2^eps widened by their spread on each side
ylo = S1_mean; yhi = S1_mean
do for [k=1:neps] { ylo = (value("S".k."_mean") < ylo ? value("S".k."_mean") : ylo); yhi = (value("S".k."_mean") > yhi ? value("S".k."_mean") : yhi) }
span = yhi - ylo; ylo = ylo - span; yhi = yhi + span
seleps(e) = (abs(column("eps") - real(e)) < 1e-15)
drawn_eps(dummy) = (neps >= 1 && seleps(word(eps_list, 1))) || (neps >= 2 && seleps(word(eps_list, 2))) || (neps >= 3 && seleps(word(eps_list, 3)))
# and in theta, per segment: the phases of the drawn eps whose T_eps falls in it, widened by a fifth
do for [s=0:1] {
  stats f using (column("segment") == s && drawn_eps(0) && column("T_eps") >= ylo && column("T_eps") <= yhi ? column("theta") : NaN) name "I".s nooutput
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
  set ytics ('$t_2$' t2, '$3.5$' 3.5, '$4.0$' 4.0, '$4.5$' 4.5, '$\frac{3\pi}{2}$' 1.5*pi)
  set arrow 1 from graph 0, first 1.5*pi to graph 1, first 1.5*pi nohead dt 3 lw 1.2 lc rgb c_grey
  do for [k=1:neps] { set arrow 1+k from graph 0, first value("S".k."_mean") to graph 1, first value("S".k."_mean") nohead dt 2 lw 0.8 lc rgb ecol(k) }
  # the box that the inset magnifies
  iw = value("I".s."_max") - value("I".s."_min"); ilo = value("I".s."_min") - 0.2*iw; ihi = value("I".s."_max") + 0.2*iw
  set object 1 rect from ilo, ylo to ihi, yhi fs empty border lc rgb "black" lw 0.6 front
  plot for [k=1:neps] f using (sel(s, word(eps_list, k)) ? column("theta") : NaN):"T_eps" w p pt ept(k) ps 0.12 lc rgb ecol(k) notitle
  unset object 1
  # inset: the landing of each branch on its t2^eps
  set lmargin at screen (s == 0 ? 0.15 : 0.645); set rmargin at screen (s == 0 ? 0.295 : 0.79)
  set bmargin at screen 0.29; set tmargin at screen 0.5
  unset title; unset xlabel; unset ylabel
  set xrange [ilo:ihi]; set yrange [ylo:yhi]
  set xtics 0.02 format '\scriptsize $%.2f$' scale 0.4
  set ytics 0.005 format '\scriptsize $%.3f$' scale 0.4
  set mxtics 2
  set object 2 rect from graph 0, graph 0 to graph 1, graph 1 fc rgb "white" fs solid 1.0 noborder behind
  unset arrow 1
  plot for [k=1:neps] f using (sel(s, word(eps_list, k)) ? column("theta") : NaN):"T_eps" w lp pt ept(k) ps 0.45 lw 0.6 lc rgb ecol(k) notitle
  unset object 2
  set format x '$%.2f$'; set format y '$%.1f$'; set tics scale 0.6
  do for [k=1:neps] { unset arrow 1+k }
}
# one key for the figure, drawn by hand in a strip above the panels (a gnuplot key is laid out
# inside one panel's width)
unset border; unset tics; unset xlabel; unset ylabel; unset title
set lmargin at screen 0; set rmargin at screen 1; set bmargin at screen 0; set tmargin at screen 1
set xrange [0:1]; set yrange [0:1]
ky = 0.955
do for [k=1:neps] {
  kx = 0.06 + (k-1)*0.14
  set label 10+k sprintf('$\varepsilon=%s$', word(eps_list, k)) at screen kx, screen ky left front point pt ept(k) ps 0.8 lc rgb ecol(k) offset 0.8,0
}
set arrow 20 from screen 0.47, screen ky to screen 0.51, screen ky nohead dt 2 lc rgb "black"
set label 20 '$t_2^\varepsilon$ (in the colour of its $\varepsilon$)' at screen 0.52, screen ky left front
set arrow 21 from screen 0.82, screen ky to screen 0.86, screen ky nohead dt 3 lw 1.2 lc rgb c_grey
set label 21 '$3\pi/2$' at screen 0.87, screen ky left front
plot NaN notitle
unset multiplot
