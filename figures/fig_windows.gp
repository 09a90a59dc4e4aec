# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: superstable windows of Theorem 2 at q/a = 0.85 (thm2_superstable): each window of b/a
# where (21) or (22) holds, drawn at its epsilon (the width of [t2, t2 + epsilon) sent to t2).
load figdir."/style.gp"
set terminal cairolatex pdf input size 14cm,6.5cm
set output "fig_windows.tex"
set logscale xy
set format x '$10^{%T}$'; set format y '$10^{%T}$'
set xlabel '$b/a$'; set ylabel '$\varepsilon$ at the window middle'
set key top left box opaque
f = data."/thm2_superstable-windows.tsv"
sel(c) = (abs(column("q_over_a") - 0.85) < 1e-12 && column("condition") == c)
plot f using (sel(21) ? column("b_mid") : NaN):"epsilon_mid":"b_lo":"b_hi" w xerrorbars pt 7 ps 0.35 lc rgb c_stop title 'condition (21)', \
     f using (sel(22) ? column("b_mid") : NaN):"epsilon_mid":"b_lo":"b_hi" w xerrorbars pt 5 ps 0.35 lc rgb c_alt title 'condition (22)'
