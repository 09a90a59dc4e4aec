# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: how Theorem 2 works (thm2_superstable). The first progression after the flight from t2
# ends at theta2(t2) (Eqs. 11, 17); against b/a, its phase (points) crosses the target arcs of
# condition (21), (t1, t2) (green band), and of condition (22), (t3, 2pi) u [0, t0) (orange bands);
# the arcs move with b/a (t0..t3 in closed form, per sample). Wherever a point lies in a band, a
# whole neighbourhood [t2, t2 + eps) is sent to t2: a superstable window (Fig. of the windows).
# Filled points: the hypotheses of Theorem 2 hold there; open: the condition holds but not the
# hypotheses ((22) needs (2)). Short ticks inside the bands: every window found by the continuation
# (thm2_superstable-windows.tsv), most of them narrower than the spacing of the samples.
# Left: the line q/a inside (2) that the report shows; right: the line below sin(vartheta0), where (2) fails, so only
# (21) with (23) would count (the Remark of Section 8), and no (21) window exists on this range.
# Both values of q/a are chosen by thm2_superstable and read from its macros.
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,7.2cm
set output "fig_theta2_arcs.tex"
f = data."/thm2_superstable-theta2.tsv"
w = data."/thm2_superstable-windows.tsv"
sel(q) = (abs(column("q_over_a") - q) < 1e-12)
eval tex_macro("q_shown", "thm2_superstable", "ThmTwoShownQ")
eval tex_macro("q_outside", "thm2_superstable", "ThmTwoOutsideQ")
stats f using "b_over_a" name "B" nooutput
set multiplot
set grid noxtics noytics
set bmargin at screen 0.15; set tmargin at screen 0.86
set logscale x
set format x '$10^{%T}$'
set xrange [B_min:B_max]
set xlabel '$b/a$' offset 0,0.3
set yrange [0:2*pi]
set ytics ('$0$' 0, '$\frac{\pi}{2}$' pi/2, '$\pi$' pi, '$\frac{3\pi}{2}$' 1.5*pi, '$2\pi$' 2*pi)
do for [k=1:2] {
  q = real(k == 1 ? q_shown : q_outside)
  set lmargin at screen (k == 1 ? 0.085 : 0.585); set rmargin at screen (k == 1 ? 0.475 : 0.975)
  set title '$q/a='.(k == 1 ? q_shown : q_outside).'$'.(k == 1 ? '' : ' $<\sin\vartheta_0$: (2) fails') offset 0,-0.4
  if (k == 1) { set ylabel '$\theta_2(t_2)\bmod 2\pi$' offset 1,0 } else { unset ylabel }
  set label 1 '\footnotesize (21): $(t_1,t_2)$' at graph 0.97, first 2.68 right front
  set label 2 '\footnotesize (22): $[0,t_0)$' at graph 0.03, first 1.2 left front
  plot f using (sel(q) ? column("b_over_a") : NaN):"t1":"t2" w filledcurves fc rgb c_stop fs transparent solid 0.25 noborder notitle, \
       f using (sel(q) ? column("b_over_a") : NaN):"t3":(2*pi) w filledcurves fc rgb c_alt fs transparent solid 0.25 noborder notitle, \
       f using (sel(q) ? column("b_over_a") : NaN):(0):"t0" w filledcurves fc rgb c_alt fs transparent solid 0.25 noborder notitle, \
       f using (sel(q) && column("condition") == 0 ? column("b_over_a") : NaN):"theta2_phase" w p pt 7 ps 0.12 lc rgb c_free notitle, \
       w using (sel(q) && column("condition") == 21 ? column("b_mid") : NaN):(2.22):(0):(0.2) w vectors nohead lw 0.6 lc rgb c_stop notitle, \
       w using (sel(q) && column("condition") == 22 ? column("b_mid") : NaN):(0.05):(0):(0.25) w vectors nohead lw 0.6 lc rgb c_alt notitle, \
       f using (sel(q) && column("condition") == 21 && column("theorem2_hypotheses") == 1 ? column("b_over_a") : NaN):"theta2_phase" w p pt 7 ps 0.35 lc rgb c_stop notitle, \
       f using (sel(q) && column("condition") == 22 && column("theorem2_hypotheses") == 1 ? column("b_over_a") : NaN):"theta2_phase" w p pt 7 ps 0.35 lc rgb c_alt notitle, \
       f using (sel(q) && column("condition") != 0 && column("theorem2_hypotheses") == 0 ? column("b_over_a") : NaN):"theta2_phase" w p pt 6 ps 0.45 lc rgb c_alt notitle
}
unset multiplot
