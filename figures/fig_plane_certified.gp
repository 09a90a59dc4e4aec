# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: a certified chaos map. Over the (q/a, b/a) plane, per cell, whether the covering of
# Lemma 4 (Theorem 1) is proved in ball arithmetic at the cell's parameters, only found by the
# floating-point search, or neither; from the experiment plane_certified (the cells of
# `dfchaos sweep --observables covering,certified`)  ->  build/data/plane_certified.tsv
# Columns used (by name; others are ignored):
#   q_over_a, b_over_a   the cell (a product grid: linear in q/a, log-spaced in b/a)
#   status               "ok" for a computed cell; anything else is drawn black (failed or inadmissible)
#   covering             1 where the floating-point search finds the covering, else 0
#   certified            1 where it is proved, else 0
# Colours differ in lightness too, so that the three kinds stay apart in greyscale.
load figdir."/style.gp"
set terminal cairolatex pdf input size 14cm,8.2cm
set output "fig_plane_certified.tex"
f = data."/plane_certified.tsv"
s0 = sin_vartheta0   # Eq. (1), from eq1_vartheta0 (style.gp)
ok(x) = (strcol("status") eq "ok")
c_proved = "#1b7837"; c_sampled = "#f1a340"; c_neither = "#e0e0e0"
stats f using "q_over_a" name "QQ" nooutput
stats f using (log10(column("b_over_a"))) name "BB" nooutput
stats f using (ok(0) && column("certified") == 1 ? 1 : 0) name "NP" nooutput
stats f using (ok(0) && column("certified") != 1 && column("covering") == 1 ? 1 : 0) name "NS" nooutput
stats f using (ok(0) && column("certified") != 1 && column("covering") != 1 ? 1 : 0) name "NN" nooutput
stats f using (ok(0) ? 0 : 1) name "NF" nooutput
stats f using (abs(column("q_over_a") - QQ_min) <= 1e-12*abs(QQ_min) ? 1 : 0) name "NBQ" nooutput
nb = int(NBQ_sum); nq = int(QQ_records / nb + 0.5)
dq = (QQ_max - QQ_min) / (nq > 1 ? nq - 1 : 1); db = (BB_max - BB_min) / (nb > 1 ? nb - 1 : 1)

set multiplot
set lmargin at screen 0.1; set rmargin at screen 0.97; set bmargin at screen 0.27; set tmargin at screen 0.96
set xlabel '$q/a$'
set ylabel '$b/a$' offset 0.5,0
set xrange [QQ_min - dq/2 : QQ_max + dq/2]; set yrange [BB_min - db/2 : BB_max + db/2]
set xtics 0.1 format '$%.1f$'
set mxtics 2
set ytics ('$10^{-4}$' -4, '$10^{-3}$' -3, '$10^{-2}$' -2, '$10^{-1}$' -1)
set mytics 10
cell(cond) = (cond ? log10(column("b_over_a")) : NaN)
plot f using "q_over_a":(cell(ok(0) && column("certified") == 1)):(0.52*dq):(0.56*db) w boxxyerror fs solid 1.0 noborder fc rgb c_proved notitle, \
     f using "q_over_a":(cell(ok(0) && column("certified") != 1 && column("covering") == 1)):(0.52*dq):(0.56*db) w boxxyerror fs solid 1.0 noborder fc rgb c_sampled notitle, \
     f using "q_over_a":(cell(ok(0) && column("certified") != 1 && column("covering") != 1)):(0.52*dq):(0.56*db) w boxxyerror fs solid 1.0 noborder fc rgb c_neither notitle, \
     f using "q_over_a":(cell(!ok(0))):(0.52*dq):(0.56*db) w boxxyerror fs solid 1.0 noborder fc rgb "black" notitle

# ---- the key, drawn by hand under the plot
unset border; unset tics; unset xlabel; unset ylabel
set lmargin at screen 0; set rmargin at screen 1; set bmargin at screen 0; set tmargin at screen 1
set xrange [0:1]; set yrange [0:1]
ky = 0.1; ky2 = 0.035
set object 11 rect center screen 0.06, screen ky size screen 0.018, screen 0.03 fc rgb c_proved fs solid noborder front
set label 11 sprintf('\small proved at the cell''s point: %d', int(NP_sum)) at screen 0.075, screen ky left front
set object 12 rect center screen 0.56, screen ky size screen 0.018, screen 0.03 fc rgb c_sampled fs solid noborder front
set label 12 sprintf('\small floating search only: %d', int(NS_sum)) at screen 0.575, screen ky left front
set object 13 rect center screen 0.06, screen ky2 size screen 0.018, screen 0.03 fc rgb c_neither fs solid border lc rgb "#808080" front
set label 13 sprintf('\small neither proved nor found: %d', int(NN_sum)) at screen 0.075, screen ky2 left front
set object 14 rect center screen 0.56, screen ky2 size screen 0.018, screen 0.03 fc rgb "black" fs solid noborder front
set label 14 sprintf('\small failed or inadmissible: %d', int(NF_sum)) at screen 0.575, screen ky2 left front
plot NaN notitle
unset multiplot
