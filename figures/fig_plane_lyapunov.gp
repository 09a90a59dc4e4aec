# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: the Lyapunov exponent of T over the (q/a, b/a) plane, from the parameter sweep
#   experiment plane_lyapunov (the cells of `dfchaos sweep --observables lyapunov`)
#   ->   build/data/plane_lyapunov.tsv
# Columns used (by name; others are ignored):
#   q_over_a   q/a of the cell
#   b_over_a   b/a of the cell (the grid is a product grid, log-spaced in b/a, linear in q/a)
#   lyapunov   the mean of ln|T'| along the orbit; -inf when a step has T' = 0 (a stop: the orbit
#              meets a stop arc, superstable); nan (or anything) where the cell failed
#   status     "ok" for a computed cell; any other value is a failed cell
# Finite lambda: viridis without its darkest part (from #3b528b), so that lightness grows with
# lambda and no finite value is near black; lambda = 0 marked on the colour bar.
# lambda = -inf: black, outside the scale, with its own key entry. Failed cells: white, crossed in
# vermilion, counted in the key. Where q/a < sin(vartheta0), assumption (2) fails: hatched.
# Axes: the convention of the plane figures (plane_axes, style.gp).
load figdir."/style.gp"
set terminal cairolatex pdf input size 14cm,8.6cm
set output "fig_plane_lyapunov.tex"
f = data."/plane_lyapunov.tsv"
s0 = sin_vartheta0   # Eq. (1), from eq1_vartheta0 (style.gp)
ok(x) = (strcol("status") eq "ok")
isinf(x) = (x < -1e300)
# the grid and the counts of each kind of cell (stats obeys ranges: before any is set)
stats f using "q_over_a" name "QQ" nooutput
stats f using (log10(column("b_over_a"))) name "BB" nooutput
stats f using (ok(0) && !isinf(column("lyapunov")) ? column("lyapunov") : NaN) name "LL" nooutput
stats f using (ok(0) && isinf(column("lyapunov")) ? 1 : 0) name "NINF" nooutput
stats f using (ok(0) ? 0 : 1) name "NFAIL" nooutput
# cell sizes: a product grid, so the cells at the smallest q/a count the b/a values
stats f using (abs(column("q_over_a") - QQ_min) <= 1e-12*abs(QQ_min) ? 1 : 0) name "NBQ" nooutput
nb = int(NBQ_sum); nq = int(QQ_records / nb + 0.5)
dq = (QQ_max - QQ_min) / (nq > 1 ? nq - 1 : 1); db = (BB_max - BB_min) / (nb > 1 ? nb - 1 : 1)
lmin = (LL_min < -0.5 ? LL_min : -0.5); lmax = (LL_max > 0.5 ? LL_max : 0.5)

set multiplot
set lmargin at screen 0.1; set rmargin at screen 0.74; set bmargin at screen 0.25; set tmargin at screen 0.96
set xrange [QQ_min - dq/2 : QQ_max + dq/2]; set yrange [BB_min - db/2 : BB_max + db/2]
eval plane_axes
set grid noxtics noytics
set colorbox user origin screen 0.77, screen 0.25 size screen 0.02, screen 0.71
# the colour bar's label placed by hand, clear of its tick labels (gnuplot misjudges the width of TeX text)
set label 95 'finite $\lambda=\langle\ln|T''|\rangle$' at screen 0.855, screen 0.605 rotate center
set cbrange [lmin:lmax]
set format cb '$%g$'
set palette defined (0 '#3b528b', 1 '#2c728e', 2 '#21918c', 3 '#28ae80', 4 '#5ec962', 5 '#addc30', 6 '#fde725')
set cbtics add ('$0$' 0)
# q/a < sin(vartheta0): hatched, over the cells
set object 1 rect from graph 0, graph 0 to first s0, graph 1 fc rgb "#707070" fs transparent pattern 5 border lc rgb "#707070" front
if (QQ_min - dq/2 >= s0 - 1e-9) { unset object 1 }
plot f using "q_over_a":(log10(column("b_over_a"))):(ok(0) && !isinf(column("lyapunov")) ? column("lyapunov") : NaN) w image pixels notitle, \
     f using "q_over_a":(ok(0) && isinf(column("lyapunov")) ? log10(column("b_over_a")) : NaN):(dq/2):(db/2) \
       w boxxyerror fs solid 1.0 noborder fc rgb "black" notitle, \
     f using "q_over_a":(ok(0) ? NaN : log10(column("b_over_a"))):(dq/2):(db/2) \
       w boxxyerror fs solid 1.0 border lc rgb c_prog fc rgb "white" notitle, \
     f using "q_over_a":(ok(0) ? NaN : log10(column("b_over_a"))) w p pt 2 ps 0.6 lc rgb c_prog notitle

# ---- the key of the categories, drawn by hand under the plot
unset border; unset tics; unset xlabel; unset ylabel; unset colorbox; unset object 1; unset label 95
set lmargin at screen 0; set rmargin at screen 1; set bmargin at screen 0; set tmargin at screen 1
set xrange [0:1]; set yrange [0:1]
ky = 0.05
set object 11 rect center screen 0.06, screen ky size screen 0.018, screen 0.03 fc rgb "black" fs solid noborder front
set label 11 sprintf('\small $\lambda=-\infty$: a step with $T''=0$ (%d cells)', int(NINF_sum)) at screen 0.075, screen ky left front
set object 12 rect center screen 0.56, screen ky size screen 0.018, screen 0.03 fc rgb "white" fs solid border lc rgb c_prog front
set label 12 sprintf('\small failed (%d)', int(NFAIL_sum)) at screen 0.575, screen ky left front
set label 14 '' at screen 0.56, screen ky front point pt 2 ps 0.6 lc rgb c_prog
# the hatched entry only when the grid reaches below sin(vartheta0)
if (QQ_min - dq/2 < s0 - 1e-9) {
  set object 13 rect center screen 0.71, screen ky size screen 0.03, screen 0.03 fc rgb "#707070" fs transparent pattern 5 border lc rgb "#707070" front
  set label 13 '\small $q/a<\sin\vartheta_0$: (2) fails' at screen 0.735, screen ky left front
}
plot NaN notitle
unset multiplot
