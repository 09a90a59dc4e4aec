# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: the covering of Lemma 4 and a periodic orbit of Section 6, from sec6_periodic_points.
# (a) T on [t2, t3) with J0, J1 (bands on the theta axis) and the target [t2, 3pi/2] they cover
#     (band on the T axis).
# (b) T over J0 and J1 only, on the whole target: each branch runs from t2 up past 3pi/2 (the
#     covering, Eq. 18); the period-3 orbit of itinerary 001 marked on the graph, with its cobweb.
# (c) The same orbit as a sequence theta_n: two of its points lie 0.006 apart in J0, too close for
#     a cobweb at any scale that also shows the branches, but distinct here.
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,6.6cm
set output "fig_cobweb.tex"
seg = data."/sec6_periodic_points-segments.tsv"
stats seg using (strcol("name") eq "J0" ? column("lo") : NaN) name "J0L" nooutput
stats seg using (strcol("name") eq "J0" ? column("hi") : NaN) name "J0H" nooutput
stats seg using (strcol("name") eq "J1" ? column("lo") : NaN) name "J1L" nooutput
stats seg using (strcol("name") eq "J1" ? column("hi") : NaN) name "J1H" nooutput
stats seg using (strcol("name") eq "target" ? column("lo") : NaN) name "TL" nooutput
stats seg using (strcol("name") eq "target" ? column("hi") : NaN) name "TH" nooutput
stats seg using (strcol("name") eq "domain" ? column("hi") : NaN) name "DH" nooutput
t2 = TL_mean; t3 = DH_mean
graph = data."/sec6_periodic_points-graph.tsv"
web = data."/sec6_periodic_points-cobweb.tsv"
orb = data."/sec6_periodic_points-orbits.tsv"
# the period-3 orbit p0, p1, p2 and its letters (read before any range is set: stats obeys ranges)
do for [j=0:2] {
  stats orb using (column("m") == 3 && column("j") == j ? column("x_j") : NaN) name "P".j nooutput
  stats orb using (column("m") == 3 && column("j") == j ? column("letter") : NaN) name "L".j nooutput
}
set multiplot
set bmargin at screen 0.2; set tmargin at screen 0.89
set grid noxtics noytics
piticks = "set ytics ('$t_2$' t2, '$\\frac{5\\pi}{4}$' 1.25*pi, '$\\frac{3\\pi}{2}$' 1.5*pi, '$\\frac{7\\pi}{4}$' 1.75*pi, '$t_3$' t3)"

# ---- (a) the whole map
set lmargin at screen 0.075; set rmargin at screen 0.345
set title '(a) $T$ on $[t_2,t_3)$'
set xlabel '$\theta$' offset 0,-0.1; set ylabel '$T(\theta)$' offset 1.5,0
set xtics ('$t_2$' t2, '$\frac{3\pi}{2}$' 1.5*pi, '$t_3$' t3)
@piticks
set xrange [t2:t3]; set yrange [t2-0.05:t3]
set object 1 rect from J0L_mean, graph 0 to J0H_mean, graph 1 fc rgb c_prog fs transparent solid 0.2 noborder back
set object 2 rect from J1L_mean, graph 0 to J1H_mean, graph 1 fc rgb c_alt fs transparent solid 0.25 noborder back
set object 3 rect from graph 0, first TL_mean to graph 1, first TH_mean fc rgb c_stop fs transparent solid 0.1 noborder back
plot graph using "theta":"T" w p pt 7 ps 0.06 lc rgb c_free, x w l dt 2 lc rgb c_grey

# ---- (b) the two branches on J0 and J1
set lmargin at screen 0.435; set rmargin at screen 0.69
set title '(b) $T$ on $J_0\cup J_1$'
unset ylabel
lo = J0L_mean - 0.08*(J1H_mean - J0L_mean); hi = J1H_mean + 0.08*(J1H_mean - J0L_mean)
set xrange [lo:hi]; set yrange [t2-0.05:TH_mean+0.25]
set xtics 0.1 format '$%.1f$'
set mxtics 2
set ytics ('$t_2$' t2, '$\frac{5\pi}{4}$' 1.25*pi, '$\frac{3\pi}{2}$' 1.5*pi)
set arrow 1 from graph 0, first TH_mean to graph 1, first TH_mean nohead dt 3 lc rgb c_grey
set arrow 2 from graph 0, first TL_mean to graph 1, first TL_mean nohead dt 3 lc rgb c_grey
set label 1 '$J_0$' at (J0L_mean+J0H_mean)/2, graph 0.93 center front
set label 2 '$J_1$' at (J1L_mean+J1H_mean)/2, graph 0.93 center front
# the orbit points on the graph: (p_j, p_{j+1})
plot graph using "theta":(column("theta") >= lo && column("theta") <= hi ? column("T") : NaN) w p pt 7 ps 0.1 lc rgb c_free, \
     x w l dt 2 lc rgb c_grey, \
     web using "x":"y" w l lw 0.8 lc rgb "black", \
     web using (int(column(0)) % 2 == 1 ? column("x") : NaN):"y" w p pt 7 ps 0.45 lc rgb "black"
unset arrow 1; unset arrow 2; unset label 1; unset label 2

# ---- (c) the orbit as a sequence
set lmargin at screen 0.795; set rmargin at screen 0.985
set title '(c) period 3, itinerary $001$'
set xlabel '$n$' offset 0,0.2; set ylabel '$\theta_n$' offset 0.3,0
unset object 1; unset object 2; unset object 3
set object 1 rect from graph 0, first J0L_mean to graph 1, first J0H_mean fc rgb c_prog fs transparent solid 0.2 noborder back
set object 2 rect from graph 0, first J1L_mean to graph 1, first J1H_mean fc rgb c_alt fs transparent solid 0.25 noborder back
set label 1 '$J_0$' at graph 0.98, first (J0L_mean+J0H_mean)/2 right front
set label 2 '$J_1$' at graph 0.98, first (J1L_mean+J1H_mean)/2 right front
# room on the right, beyond n = 6, for the labels J0, J1 (clear of the points' itinerary letters)
set xrange [-0.5:7.6]; set xtics 0, 1, 6 format '$%g$'; set mxtics 1
set yrange [J0L_mean-0.02:J1H_mean+0.04]
set ytics 0.1 format '$%.1f$'
# two periods: n = 0..6, theta_{n} = p_{n mod 3}
set print $O
do for [n=0:6] { print sprintf("%d\t%.17g\t%d", n, value("P".(n%3)."_mean"), int(value("L".(n%3)."_mean"))) }
unset print
set datafile nocolumnheaders
plot $O using 1:2 w lp pt 7 ps 0.55 lw 0.8 lc rgb "black", \
     $O using 1:2:(sprintf("%d", $3)) w labels offset 0,0.75 tc rgb "black"
unset multiplot
