# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: superstable windows of Theorem 2 on the line q/a that thm2_superstable shows (its macro): each piece of b/a
# where (21) or (22) holds. The pieces are far narrower than a marker on a b/a axis, so instead of
# bars their width is drawn as a quantity: (a) epsilon at the piece's middle (the width of
# [t2, t2 + epsilon) sent to t2); (b) the piece's relative width (b_hi - b_lo)/b_mid, same b/a axis.
# Conditions told apart by colour and marker (filled circle: (21); open square: (22)).
load figdir."/style.gp"
set terminal cairolatex pdf input size 14cm,8cm
set output "fig_windows.tex"
f = data."/thm2_superstable-windows.tsv"
eval tex_macro("q_shown", "thm2_superstable", "ThmTwoShownQ")
qs = real(q_shown)
sel(c) = (abs(column("q_over_a") - qs) < 1e-12 && column("condition") == c)
set multiplot
set logscale xy
set format x '$10^{%T}$'; set format y '$10^{%T}$'
set lmargin at screen 0.12; set rmargin at screen 0.97
# ---- (a) epsilon
set bmargin at screen 0.61; set tmargin at screen 0.97
set format x ''; unset xlabel
set ylabel '$\varepsilon$ at the middle'
set label 1 '(a)' at graph 0.03, graph 0.9 left front
set key bottom right box opaque
plot f using (sel(21) ? column("b_mid") : NaN):"epsilon_mid" w p pt 7 ps 0.4 lc rgb c_stop title 'condition (21)', \
     f using (sel(22) ? column("b_mid") : NaN):"epsilon_mid" w p pt 4 ps 0.45 lw 1.5 lc rgb c_alt title 'condition (22)'
# ---- (b) relative width
set bmargin at screen 0.17; set tmargin at screen 0.53
set format x '$10^{%T}$'; set xlabel '$b/a$' offset 0,0.4
set ylabel 'relative width $\frac{b_{\mathrm{hi}}-b_{\mathrm{lo}}}{b_{\mathrm{mid}}}$'
set label 1 '(b)' at graph 0.97, graph 0.1 right front
unset key
plot f using (sel(21) ? column("b_mid") : NaN):((column("b_hi") - column("b_lo"))/column("b_mid")) w p pt 7 ps 0.4 lc rgb c_stop, \
     f using (sel(22) ? column("b_mid") : NaN):((column("b_hi") - column("b_lo"))/column("b_mid")) w p pt 4 ps 0.45 lw 1.5 lc rgb c_alt
unset multiplot
