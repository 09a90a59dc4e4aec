# Figure: the covering of Lemma 4 and a periodic orbit of Section 6, from sec6_periodic_points.
# Left: T on [t2, t3) with J0, J1 (bars on the theta axis) and the target [t2, 3pi/2] they cover
# (bar on the T axis). Right: zoom on J0, J1 with the cobweb of the period-3 orbit (itinerary 001).
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,7cm
set output "fig_cobweb.tex"
seg = data."/sec6_periodic_points-segments.tsv"
stats seg using (strcol("name") eq "J0" ? column("lo") : NaN) name "J0L" nooutput
stats seg using (strcol("name") eq "J0" ? column("hi") : NaN) name "J0H" nooutput
stats seg using (strcol("name") eq "J1" ? column("lo") : NaN) name "J1L" nooutput
stats seg using (strcol("name") eq "J1" ? column("hi") : NaN) name "J1H" nooutput
stats seg using (strcol("name") eq "target" ? column("lo") : NaN) name "TL" nooutput
stats seg using (strcol("name") eq "target" ? column("hi") : NaN) name "TH" nooutput
graph = data."/sec6_periodic_points-graph.tsv"
set multiplot layout 1,2 margins 0.08,0.98,0.15,0.9 spacing 0.09
set xlabel '$\theta$'; set ylabel '$T(\theta)$'
set xtics ("$\\pi$" pi, "$\\frac{5\\pi}{4}$" 1.25*pi, "$\\frac{3\\pi}{2}$" 1.5*pi, "$\\frac{7\\pi}{4}$" 1.75*pi, "$2\\pi$" 2*pi)
set ytics ("$\\pi$" pi, "$\\frac{5\\pi}{4}$" 1.25*pi, "$\\frac{3\\pi}{2}$" 1.5*pi, "$\\frac{7\\pi}{4}$" 1.75*pi, "$2\\pi$" 2*pi)
set xrange [TL_mean:2*pi]; set yrange [TL_mean-0.05:2*pi]
set object 1 rect from J0L_mean,graph 0 to J0H_mean,graph 1 fc rgb c_prog fs transparent solid 0.15 noborder
set object 2 rect from J1L_mean,graph 0 to J1H_mean,graph 1 fc rgb c_alt fs transparent solid 0.15 noborder
set object 3 rect from graph 0,first TL_mean to graph 1,first TH_mean fc rgb c_stop fs transparent solid 0.08 noborder
set title 'covering: $T(J_i)\supset[t_2,3\pi/2]$'
plot graph using "theta":"T" w p pt 7 ps 0.08 lc rgb c_free, x w l dt 2 lc rgb c_grey
# zoom
lo = J0L_mean - 0.3*(J1H_mean - J0L_mean); hi = J1H_mean + 0.3*(J1H_mean - J0L_mean)
set xrange [lo:hi]; set yrange [lo:hi]
set xtics auto; set ytics auto
set format x "$%.2f$"; set format y "$%.2f$"
set label 1 '$J_0$' at (J0L_mean+J0H_mean)/2, graph 0.06 center
set label 2 '$J_1$' at (J1L_mean+J1H_mean)/2, graph 0.06 center
set title 'period-3 orbit, itinerary $001$'
web = data."/sec6_periodic_points-cobweb.tsv"
plot graph using "theta":"T" w p pt 7 ps 0.12 lc rgb c_free, x w l dt 2 lc rgb c_grey, \
     web using "x":"y" w l lw 1.5 lc rgb "black", web using "x":"y" w p pt 7 ps 0.4 lc rgb "black"
unset multiplot
