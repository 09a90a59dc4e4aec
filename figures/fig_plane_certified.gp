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
#   certified_step       the step where the proof stopped (0 proved; 1 admissibility, 2 fewer than two
#                        candidate segments: no proof attempted; 3..6 a step of a proof attempt)
# Classes (Okabe-Ito colours of style.gp, differing in lightness too, and markers on the rare ones
# so that single cells stay visible, in greyscale as well): proved; found by the floating-point
# search but not proved (circle); a proof attempted and a step not proved, not found either
# (cross); not reached by a proof (no two candidate segments); failed or inadmissible.
# Axes: the convention of the plane figures (plane_axes, style.gp).
load figdir."/style.gp"
set terminal cairolatex pdf input size 14cm,8cm
set output "fig_plane_certified.tex"
f = data."/plane_certified.tsv"
s0 = sin_vartheta0   # Eq. (1), from eq1_vartheta0 (style.gp)
ok(x) = (strcol("status") eq "ok")
c_proved = oi_blue; c_sampled = oi_orange; c_tried = oi_verm; c_neither = "#d4d4d4"
stats f using "q_over_a" name "QQ" nooutput
stats f using (log10(column("b_over_a"))) name "BB" nooutput
stats f using (ok(0) && column("certified") == 1 ? 1 : 0) name "NP" nooutput
stats f using (ok(0) && column("certified") != 1 && column("covering") == 1 ? 1 : 0) name "NS" nooutput
tried(x) = (column("certified_step") >= 3)
stats f using (ok(0) && column("certified") != 1 && column("covering") != 1 && tried(0) ? 1 : 0) name "NT" nooutput
stats f using (ok(0) && column("certified") != 1 && column("covering") != 1 && !tried(0) ? 1 : 0) name "NN" nooutput
stats f using (ok(0) ? 0 : 1) name "NF" nooutput
stats f using (abs(column("q_over_a") - QQ_min) <= 1e-12*abs(QQ_min) ? 1 : 0) name "NBQ" nooutput
nb = int(NBQ_sum); nq = int(QQ_records / nb + 0.5)
dq = (QQ_max - QQ_min) / (nq > 1 ? nq - 1 : 1); db = (BB_max - BB_min) / (nb > 1 ? nb - 1 : 1)

set multiplot
set lmargin at screen 0.1; set rmargin at screen 0.97; set bmargin at screen 0.36; set tmargin at screen 0.97
set xrange [QQ_min - dq/2 : QQ_max + dq/2]; set yrange [BB_min - db/2 : BB_max + db/2]
eval plane_axes
set xlabel offset 0,0.5   # clear of the key below
cell(cond) = (cond ? log10(column("b_over_a")) : NaN)
plot f using "q_over_a":(cell(ok(0) && column("certified") == 1)):(0.52*dq):(0.56*db) w boxxyerror fs solid 1.0 noborder fc rgb c_proved notitle, \
     f using "q_over_a":(cell(ok(0) && column("certified") != 1 && column("covering") == 1)):(0.52*dq):(0.56*db) w boxxyerror fs solid 1.0 noborder fc rgb c_sampled notitle, \
     f using "q_over_a":(cell(ok(0) && column("certified") != 1 && column("covering") != 1 && tried(0))):(0.52*dq):(0.56*db) w boxxyerror fs solid 1.0 noborder fc rgb c_tried notitle, \
     f using "q_over_a":(cell(ok(0) && column("certified") != 1 && column("covering") != 1 && !tried(0))):(0.52*dq):(0.56*db) w boxxyerror fs solid 1.0 noborder fc rgb c_neither notitle, \
     f using "q_over_a":(cell(!ok(0))):(0.52*dq):(0.56*db) w boxxyerror fs solid 1.0 noborder fc rgb "black" notitle, \
     f using "q_over_a":(cell(ok(0) && column("certified") != 1 && column("covering") == 1)) w p pt 6 ps 1.1 lw 1.5 lc rgb "black" notitle, \
     f using "q_over_a":(cell(ok(0) && column("certified") != 1 && column("covering") != 1 && tried(0))) w p pt 2 ps 1.1 lw 1.5 lc rgb "black" notitle

# ---- the key, drawn by hand under the plot
unset border; unset tics; unset xlabel; unset ylabel
set lmargin at screen 0; set rmargin at screen 1; set bmargin at screen 0; set tmargin at screen 1
set xrange [0:1]; set yrange [0:1]
ky = 0.16; ky2 = 0.1; ky3 = 0.04
set object 11 rect center screen 0.06, screen ky size screen 0.018, screen 0.03 fc rgb c_proved fs solid noborder front
set label 11 sprintf('\small proved at the cell''s point: %d', int(NP_sum)) at screen 0.075, screen ky left front
set object 12 rect center screen 0.55, screen ky size screen 0.018, screen 0.03 fc rgb c_sampled fs solid noborder front
set label 22 '' at screen 0.55, screen ky front point pt 6 ps 1.1 lw 1.5 lc rgb "black"
set label 12 sprintf('\small floating search only, not proved: %d', int(NS_sum)) at screen 0.565, screen ky left front
set object 13 rect center screen 0.06, screen ky2 size screen 0.018, screen 0.03 fc rgb c_tried fs solid noborder front
set label 23 '' at screen 0.06, screen ky2 front point pt 2 ps 1.1 lw 1.5 lc rgb "black"
set label 13 sprintf('\small a proof tried, a step not proved: %d', int(NT_sum)) at screen 0.075, screen ky2 left front
set object 14 rect center screen 0.55, screen ky2 size screen 0.018, screen 0.03 fc rgb c_neither fs solid noborder front
set label 14 sprintf('\small no proof tried (no two candidates): %d', int(NN_sum)) at screen 0.565, screen ky2 left front
set object 15 rect center screen 0.06, screen ky3 size screen 0.018, screen 0.03 fc rgb "black" fs solid noborder front
set label 15 sprintf('\small failed or inadmissible: %d', int(NF_sum)) at screen 0.075, screen ky3 left front
plot NaN notitle
unset multiplot
