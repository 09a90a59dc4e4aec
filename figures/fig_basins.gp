# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: where the drilling rate depends on the start (penetration_rate, output basins): at the
# three values of b/a on the line q/a of the experiment with the largest spread over initial phases, the rate
# of the orbit from each of 200 initial phases theta0 in [t2, t3) (transient discarded, the same
# number of steps averaged as in the rate experiment). Blue: the orbit stays on the chaotic set over
# the whole run (finite Lyapunov exponent); green: it falls onto the superstable cycle through t2
# (a step with a stop, lambda = -inf) within the run, which lowers the mean advance.
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,6.4cm
set output "fig_basins.tex"
f = data."/penetration_rate-basins.tsv"
# the b/a values present, in increasing order (up to three)
stats f using "b_over_a" name "B" nooutput
bvals = ""
bprev = 0
do for [k=1:3] {
  stats f using (column("b_over_a") > bprev*(1 + 1e-12) ? column("b_over_a") : NaN) name "N" nooutput
  if (N_records > 0) { bvals = bvals.sprintf(" %.17g", N_min); bprev = N_min }
}
nb = words(bvals)
sel(b) = (abs(column("b_over_a") - b) <= 1e-12*b && column("failed") == 0)
set multiplot
set grid noxtics noytics
set bmargin at screen 0.16; set tmargin at screen 0.8
do for [k=1:nb] {
  b = real(word(bvals, k))
  set autoscale xy   # stats obeys the ranges of the previous panel
  stats f using (sel(b) ? column("rate")/column("b_over_a") : NaN) name "R" nooutput
  stats f using (sel(b) ? column("theta0") : NaN) name "X" nooutput
  stats f using (sel(b) ? (column("flat_steps") > 0 ? 1 : 0) : NaN) name "C" nooutput
  stats f using (sel(b) && column("period_of_t2") > 0 ? column("period_of_t2") : NaN) name "P" nooutput
  set lmargin at screen 0.085 + (k-1)*0.33; set rmargin at screen 0.085 + (k-1)*0.33 + 0.235
  set title sprintf('$b/a=%s$', gprintf('%.2t\cdot10^{%T}', b)) offset 0,-0.4
  set label 1 sprintf('\footnotesize %d of %d captured,', int(C_sum), int(C_records)) at graph 0.5, graph 0.15 center front
  set label 2 sprintf('\footnotesize cycle of period %d', int(P_max)) at graph 0.5, graph 0.06 center front
  set xlabel '$\theta_0$' offset 0,0.3
  if (k == 1) { set ylabel 'rate$/(b/a)$' offset 1,0 } else { unset ylabel }
  t2 = pi + asin(2*b); t3 = 2*pi - asin(2*b)
  set xrange [t2:t3]
  set xtics ('$t_2$' t2, '$\frac{3\pi}{2}$' 1.5*pi, '$t_3$' t3)
  set yrange [0:R_max*1.15]
  set format y '$%.1f$'
  plot f using (sel(b) && column("flat_steps") == 0 ? column("theta0") : NaN):(column("rate")/column("b_over_a")) w p pt 7 ps 0.3 lc rgb c_free notitle, \
       f using (sel(b) && column("flat_steps") > 0 ? column("theta0") : NaN):(column("rate")/column("b_over_a")) w p pt 5 ps 0.45 lc rgb c_stop notitle
}
# one key for the figure, drawn by hand at the top
unset label 1; unset label 2
unset border; unset tics; unset xlabel; unset ylabel; unset title
set lmargin at screen 0; set rmargin at screen 1; set bmargin at screen 0; set tmargin at screen 1
set xrange [0:1]; set yrange [0:1]
set object 30 circle at screen 0.12, screen 0.96 size screen 0.005 fc rgb c_free fs solid noborder front
set label 30 '\small stays chaotic (finite $\lambda$)' at screen 0.135, screen 0.96 left front
set object 31 rect center screen 0.43, screen 0.96 size screen 0.01, screen 0.022 fc rgb c_stop fs solid noborder front
set label 31 '\small falls onto the superstable cycle through $t_2$ ($\lambda=-\infty$)' at screen 0.445, screen 0.96 left front
plot NaN notitle
unset multiplot
