# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: the lap-count estimate of topological entropy (sec7_symbolic): ln(laps of T^n)/n on a
# grid, against n, beside the lower bound ln 2 from the symbolic dynamics of Section 7.
load figdir."/style.gp"
set terminal cairolatex pdf input size 10cm,6cm
set output "fig_laps.tex"
set xlabel '$n$'; set ylabel '$\frac{1}{n}\ln(\mathrm{laps\ of\ }T^n)$'
set format x '$%g$'; set format y '$%.1f$'
set yrange [0:*]
# n is an integer: one tic per n; the key sits in the empty band between ln 2 and the lap counts
set xtics 1
set key at graph 0.97, graph 0.5 right center box opaque
f = data."/sec7_symbolic-laps.tsv"
stats f using "n" name "N" nooutput
set xrange [N_min - 0.2:N_max + 0.2]
plot f using "n":"log_laps_over_n" w lp pt 7 ps 0.7 lc rgb c_free title 'lap count', log(2) w l dt 2 lc rgb c_prog title '$\ln 2$'
