# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: the impact map along an orbit of T (dynamics_gallery): for every step, the phase at which
# the mass hits the delimiter (T1 mod 2pi, Eq. 11) and its velocity then (dG1/dt at T1, positive:
# a progression follows), coloured by the duration of the flight before it. The switching phases
# t0..t3 (closed form) are marked on the phase axis; on (t0, t1) F > q and the progression that the
# impact starts cannot stop before t1.
load figdir."/style.gp"
set terminal cairolatex pdf input size 13cm,7.2cm
set output "fig_impact_map.tex"
f = data."/dynamics_gallery-impacts.tsv"
# the parameters of the gallery (its summary table)
stats data."/dynamics_gallery.tsv" using "b_over_a" name "B" nooutput
stats data."/dynamics_gallery.tsv" using "q_over_a" name "Q" nooutput
b = B_mean; q = Q_mean
t0 = asin(q - 2*b); t1 = pi - t0; t2 = pi + asin(2*b); t3 = 2*pi - asin(2*b)
stats f using "impact_velocity" name "V" nooutput
stats f using (log10(column("flight"))) name "FL" nooutput
set lmargin at screen 0.1; set rmargin at screen 0.84; set bmargin at screen 0.15; set tmargin at screen 0.9
set title sprintf('$b/a=%g$, $q/a=%g$: %d impacts', b, q, V_records) offset 0,-0.4
set xlabel 'impact phase $T_1(\theta)\bmod 2\pi$'
set ylabel 'impact velocity $\partial_t G_1$' offset 1,0
stats f using "impact_phase" name "P" nooutput
set xrange [(P_min < t0 ? P_min : t0) - 0.25:t3 + 0.05]; set yrange [0:V_max*1.05]
set xtics ('$t_0$' t0, '$t_1$' t1, '$t_2$' t2, '$\frac{3\pi}{2}$' 1.5*pi, '$t_3$' t3)
set format y '$%.1f$'
set grid noxtics noytics
set object 1 rect from t0, graph 0 to t1, graph 1 fc rgb c_prog fs transparent solid 0.08 noborder back
set label 1 '\footnotesize $F>q$' at (t0 + t1)/2, graph 0.95 center front
set object 2 rect from t2, graph 0 to t3, graph 1 fc rgb c_free fs transparent solid 0.08 noborder back
set label 2 '\footnotesize $F<0$' at (t2 + t3)/2, graph 0.95 center front
set colorbox user origin screen 0.86, screen 0.15 size screen 0.02, screen 0.75
set cblabel 'flight time $T_1(\theta)-\theta$' offset 0.5,0
set cbrange [FL_min:FL_max]
set cbtics ('$1$' 0, '$3$' log10(3), '$10$' 1, '$30$' log10(30), '$100$' 2, '$300$' log10(300), '$1000$' 3)
plot f using "impact_phase":"impact_velocity":(log10(column("flight"))) w p pt 7 ps 0.15 lc palette notitle
