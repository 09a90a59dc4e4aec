# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: the phase circle with t0 < t1 (zeros of F - q) and t2 < t3 (zeros of F), and what each
# regime may do on each arc (our version of the paper's Fig. 2). Phases from sec3_scenarios
# (table sec3_scenarios-phases.tsv, the row of the set that sec3_scenarios names in its macros).
load figdir."/style.gp"
set terminal cairolatex pdf input size 11cm,7.5cm dashlength 2.5
set output "fig_phase_circle.tex"
file = data."/sec3_scenarios-phases.tsv"
# pick the row of the set chosen by the experiment
eval tex_macro("cb", "sec3_scenarios", "SecThreeCircleB")
eval tex_macro("cq", "sec3_scenarios", "SecThreeCircleQ")
B0 = real(cb); Q0 = real(cq)
stats file using (abs(column("b_over_a")-B0)<1e-12 && abs(column("q_over_a")-Q0)<1e-12 ? column("t0") : NaN) name "T0" nooutput
stats file using (abs(column("b_over_a")-B0)<1e-12 && abs(column("q_over_a")-Q0)<1e-12 ? column("t1") : NaN) name "T1" nooutput
stats file using (abs(column("b_over_a")-B0)<1e-12 && abs(column("q_over_a")-Q0)<1e-12 ? column("t2") : NaN) name "T2" nooutput
stats file using (abs(column("b_over_a")-B0)<1e-12 && abs(column("q_over_a")-Q0)<1e-12 ? column("t3") : NaN) name "T3" nooutput
if (T0_records != 1) { print "fig_phase_circle: no single row b/a = ".cb.", q/a = ".cq; exit status 1 }
t0 = T0_mean; t1 = T1_mean; t2 = T2_mean; t3 = T3_mean
unset border; unset tics; unset grid
set size ratio -1
set xrange [-2.6:2.6]; set yrange [-1.45:1.45]
set parametric
set trange [0:1]
# arcs: phase phi drawn counter-clockwise from the positive x axis
arc(u, lo, hi) = lo + (hi - lo) * u
# mark a phase on the circle
do for [k=1:4] {
  ph = (k==1 ? t0 : (k==2 ? t1 : (k==3 ? t2 : t3)))
  nm = (k==1 ? '$t_0$' : (k==2 ? '$t_1$' : (k==3 ? '$t_2$' : '$t_3$')))
  set arrow from 0.9*cos(ph),0.9*sin(ph) to 1.1*cos(ph),1.1*sin(ph) nohead lw 2
  set label nm at 0.75*cos(ph),0.75*sin(ph) center
}
# arc descriptions, placed outside the middle of each arc
mid01 = (t0+t1)/2; mid12 = (t1+t2)/2; mid23 = (t2+t3)/2; mid30 = (t3+2*pi+t0)/2
set label '$(t_0,t_1)$: $F>q$, progression accelerates, cannot stop' at 1.3*cos(mid01),1.22*sin(mid01) center
set label '$[t_1,t_2)$: a stop lasts until $t_2$' at 1.2*cos(mid12),1.2*sin(mid12) right
set label '$[t_2,t_3)$: $F<0$, free flight starts' at 1.3*cos(mid23),1.25*sin(mid23) center
set label '$[t_3,t_0)$: a stop lasts until $t_0$' at 1.2*cos(mid30),1.2*sin(mid30) left
# arcs told apart by colour and by dash (style.gp's regimes: progression solid, stops dotted or
# dash-dotted, free flight dashed), labels in black
plot cos(arc(t,t0,t1)),sin(arc(t,t0,t1)) w l lw 5 lc rgb c_prog, \
     cos(arc(t,t1,t2)),sin(arc(t,t1,t2)) w l lw 5 dt (1, 1) lc rgb c_stop, \
     cos(arc(t,t2,t3)),sin(arc(t,t2,t3)) w l lw 5 dt (5, 2) lc rgb c_free, \
     cos(arc(t,t3,2*pi+t0)),sin(arc(t,t3,2*pi+t0)) w l lw 5 dt (5, 2, 1, 2) lc rgb c_alt
