# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: the next-hit map T1 modulo 2pi (Eq. 11) with the arcs of Lemma 2 and of the proof of
# Lemma 4 (dynamics_gallery). L0 = [101pi/100, 3pi/2] (Lemma 2: T1 decreasing, finitely many jumps),
# L2 = [101pi/100, 51pi/50] (the proof looks there for three discontinuities z_i),
# L1 = [197pi/100, t3] (flights that end there stop before t0: T = t2).
# (a) the whole arc at the gallery's b/a: L0, L2 on the theta axis, L1 on both axes.
# (b) around L2 at a b/a small enough for the proof: the discontinuities z_i (dotted) and the hit
#     phases T1(z_i) (circles), which land in L1 as the proof needs (cos T1(z) = -cos z, Eq. 16).
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,7cm
set output "fig_T1_arcs.tex"
f = data."/dynamics_gallery-T1.tsv"
g = data."/dynamics_gallery-grazing.tsv"
stats data."/dynamics_gallery.tsv" using "b_over_a" name "B" nooutput
stats g using "b_over_a" name "BP" nooutput
stats g using "z" name "Z" nooutput
b1 = B_mean; b2 = BP_mean
L0lo = 101*pi/100; L0hi = 1.5*pi; L2lo = 101*pi/100; L2hi = 51*pi/50; L1lo = 197*pi/100
t2a = pi + asin(2*b1); t3a = 2*pi - asin(2*b1); t3b = 2*pi - asin(2*b2)
stats f using (abs(column("b_over_a") - b2) < 1e-15*b2 ? column("theta") : NaN) name "X2" nooutput
set multiplot
set grid noxtics noytics
set bmargin at screen 0.17; set tmargin at screen 0.86
set ylabel '$T_1(\theta)\bmod 2\pi$' offset 1,0
set yrange [0:2*pi]
set ytics ('$0$' 0, '$\frac{\pi}{2}$' pi/2, '$\pi$' pi, '$\frac{3\pi}{2}$' 1.5*pi, '$2\pi$' 2*pi)

# ---- (a) the whole arc
set lmargin at screen 0.085; set rmargin at screen 0.48
set title sprintf('(a) $b/a=%g$', b1) offset 0,-0.4
set xlabel '$\theta$' offset 0,-0.2
set xrange [t2a:t3a]
set xtics ('$t_2$' t2a, '$\frac{5\pi}{4}$' 1.25*pi, '$\frac{3\pi}{2}$' 1.5*pi, '$\frac{7\pi}{4}$' 1.75*pi, '$t_3$' t3a)
set object 1 rect from L0lo, graph 0 to L0hi, graph 0.06 fc rgb c_free fs solid 0.5 noborder front
set label 1 '\footnotesize $L_0$' at (L0lo + L0hi)/2, graph 0.1 center front
set object 2 rect from L2lo, graph 0 to L2hi, graph 1 fc rgb c_alt fs transparent solid 0.35 noborder back
set label 2 '\footnotesize $L_2$' at L2hi, graph 0.96 left offset 0.2,0 front
set object 3 rect from L1lo, graph 0 to t3a, graph 1 fc rgb c_stop fs transparent solid 0.3 noborder back
set object 4 rect from graph 0, first L1lo to graph 1, first t3a fc rgb c_stop fs transparent solid 0.3 noborder back
set label 3 '\footnotesize $L_1$' at graph 0.5, first (L1lo + t3a)/2 center front
set label 4 '\footnotesize $L_1$' at L1lo, graph 0.5 right offset -0.2,0 front
plot f using (abs(column("b_over_a") - b1) < 1e-15*b1 ? column("theta") : NaN):"T1_phase" w p pt 7 ps 0.08 lc rgb c_free notitle
unset object 1; unset object 2; unset object 3; unset object 4; unset label 1; unset label 2; unset label 3; unset label 4

# ---- (b) around L2 at the proof's b/a
set lmargin at screen 0.585; set rmargin at screen 0.98
set title '(b) around $L_2$, $b/a='.gprintf('%.0t', b2).'\cdot 10^{'.gprintf('%T', b2).'}$' offset 0,-0.4
unset ylabel
set xrange [X2_min:X2_max]
set xtics ('$\frac{101\pi}{100}$' L2lo, '$\frac{51\pi}{50}$' L2hi)
set object 2 rect from L2lo, graph 0 to L2hi, graph 1 fc rgb c_alt fs transparent solid 0.2 noborder back
set object 4 rect from graph 0, first L1lo to graph 1, first t3b fc rgb c_stop fs transparent solid 0.5 noborder back
# (the circles T1(z_i) in L1 are named in the caption: a label here would sit on a branch)
unset label 3
# below the axis, between the tick labels of its ends: inside the panel it would sit on a branch
set label 2 '\footnotesize $L_2$' at (L2lo + L2hi)/2, graph -0.07 center front
plot f using (abs(column("b_over_a") - b2) < 1e-15*b2 ? column("theta") : NaN):"T1_phase" w p pt 7 ps 0.08 lc rgb c_free notitle, \
     g using "z":(0):(0):(2*pi) w vectors nohead dt 3 lw 1 lc rgb "black" notitle, \
     g using "z":"T1_phase" w p pt 6 ps 0.8 lw 1.5 lc rgb "black" notitle
unset multiplot
