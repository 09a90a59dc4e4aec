# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: a long time history of the full system on the chaotic attractor (dynamics_gallery), from
# rest at the delimiter at a phase reached after the transient of T.
# (a) x(t) drawn by regime (style.gp: colour, width, dots) and y(t) dashed, over several steps of T; impacts (fp) marked by
#     triangles at the exact instants of the simulator's event log; the box is the window of (b).
# (b) one contact magnified (sampled finely): every regime change marked and named (fp, is).
# (c) the phase portrait: velocity of the mass against its distance to the delimiter, x - y <= 0;
#     a progression runs along x - y = 0.
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,9.5cm
set output "fig_history.tex"
h = data."/dynamics_gallery-history.tsv"
z = data."/dynamics_gallery-history-zoom.tsv"
ev = data."/dynamics_gallery-history-events.tsv"
# ranges of the data (stats obeys ranges: before any is set)
stats h using "t" name "HT" nooutput
stats h using (column("regime") == 2 ? 1 : 0) name "STOPS" nooutput   # the key lists stop only if the history has one
stats h using "x" name "HX" nooutput
stats h using "y" name "HY" nooutput
stats z using "t" name "ZT" nooutput
stats z using "x" name "ZX" nooutput
stats z using "y" name "ZY" nooutput
lo = (HX_min < HY_min ? HX_min : HY_min); hi = (HX_max > HY_max ? HX_max : HY_max)
zlo = (ZX_min < ZY_min ? ZX_min : ZY_min); zhi = (ZX_max > ZY_max ? ZX_max : ZY_max)
set multiplot
set grid noxtics noytics

# ---- (a) the history
set lmargin at screen 0.085; set rmargin at screen 0.985; set bmargin at screen 0.6; set tmargin at screen 0.925
unset title
set label 1 '(a)' at graph 0.01, graph 0.9 left front
set xlabel '$t-\theta_0$' offset 0,0.5
set ylabel '$x$, $y$' offset 1,0
set xrange [0:HT_max]; set yrange [lo - 0.08*(hi - lo):hi + 0.12*(hi - lo)]
set object 1 rect from ZT_min, zlo - 0.2 to ZT_max, zhi + 0.2 fs empty border lc rgb "black" lw 0.8 front
plot h using "t":"y" w l lw 1 dt 2 lc rgb "black" notitle, \
     for [r=0:2] h using "t":(reg(r, column("x"))) w l lt 11+r notitle, \
     ev using (strcol("kind") eq "fp" ? column("t") : NaN):(column("x") + 0.06*(hi - lo)) w p pt 11 ps 0.5 lc rgb "black" notitle
unset object 1; unset label 1

# ---- (b) one contact
set lmargin at screen 0.085; set rmargin at screen 0.47; set bmargin at screen 0.09; set tmargin at screen 0.44
set title '(b) one contact, magnified' offset 0,-0.5
set xrange [ZT_min:ZT_max]; set yrange [zlo - 0.1*(zhi - zlo):zhi + 0.15*(zhi - zlo)]
zstep = (ZT_max - ZT_min > 2.5 ? 1 : (ZT_max - ZT_min > 1 ? 0.5 : 0.2))
set xtics zstep format '$%.1f$'
plot z using "t":"y" w l lw 1 dt 2 lc rgb "black" notitle, \
     for [r=0:2] z using "t":(reg(r, column("x"))) w l lt 11+r notitle, \
     ev using (column("t") >= ZT_min && column("t") <= ZT_max ? column("t") : NaN):"x" w p pt 6 ps 0.8 lw 1.2 lc rgb "black" notitle, \
     ev using (column("t") >= ZT_min && column("t") <= ZT_max ? column("t") : NaN):"x":(strcol("kind")) w labels offset 0,0.9 notitle

# ---- (c) the phase portrait
set lmargin at screen 0.6; set rmargin at screen 0.985
set title '(c) phase portrait' offset 0,-0.5
set xtics auto format '$%g$'
set xlabel '$x-y$'; set ylabel '$\dot x$' offset 1,0
set autoscale xy
set xrange [*:0.4]
set arrow 1 from 0, graph 0 to 0, graph 1 nohead dt 3 lc rgb c_grey
plot for [r=0:2] h using "gap":(reg(r, column("v"))) w l lt 11+r lw (r == 0 ? 0.8 : 3) notitle
unset arrow 1

# ---- one key for the figure, drawn by hand at the top
unset border; unset tics; unset xlabel; unset ylabel; unset title
set lmargin at screen 0; set rmargin at screen 1; set bmargin at screen 0; set tmargin at screen 1
set xrange [0:1]; set yrange [0:1]
ky = 0.975
do for [r=0:(STOPS_sum > 0 ? 2 : 1)] {
  kx = (r == 0 ? 0.06 : (r == 1 ? 0.27 : 0.47))
  set arrow 10+r from screen kx, screen ky to screen kx + 0.035, screen ky nohead lt 11+r
  set label (10+r) (r == 0 ? '\small $x$: free flight' : (r == 1 ? '\small progression' : '\small stop')) at screen kx + 0.045, screen ky left front
}
set arrow 20 from screen 0.66, screen ky to screen 0.695, screen ky nohead dt 2 lc rgb "black"
set label 20 '\small delimiter $y$' at screen 0.705, screen ky left front
set label 21 '\small $\blacktriangledown$ impact (fp)' at screen 0.84, screen ky left front
plot NaN notitle
unset multiplot
