# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: four views beyond the paper (beyond_views), 2 x 2 panels.
#  (a) stroboscopic section of the full system: x - y against the velocity at t = 2 pi k, with the
#      a priori bound x - y >= -(2a + a^2/(4b)) of the claim dashed;
#  (b) lap-count estimate (1/n) ln laps(T^n) against b/a at q/a fixed; filled circles where Lemma 4's
#      covering is found, open squares where it is not; ln 2 dashed;
#  (c) basin map over (theta0, b/a) across one superstable interval of b/a (categories, Okabe-Ito,
#      chosen to differ in lightness); the rows where Theorem 2's conditions (21) or (22) hold with
#      T(t2) = t2 are between the dashed lines;
#  (d) the fibre map: the delimiter's advance during one step of T against theta, by scenario.
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,8.4cm
set output "fig_beyond_views.tex"
sec = data."/beyond_views-section.tsv"
lap = data."/beyond_views-laps.tsv"
bas = data."/beyond_views-basins.tsv"
fib = data."/beyond_views-fibre.tsv"
# ranges of the data, read before any range is set (stats obeys them)
stats bas using "b_over_a" name "BB" nooutput
stats bas using (column("theorem2") == 1 ? column("b_over_a") : NaN) name "W" nooutput
stats fib using "penetration" name "FP" nooutput
stats sec using "x_minus_y" name "SX" nooutput
stats lap using "b_over_a" name "LB" nooutput
# b/a and q/a of the section and the fibre map, from the headers of their files
b_sec = real(system("sed -n 's/^# b_over_a = //p' '".sec."' | head -1"))
q_all = real(system("sed -n 's/^# q_over_a = //p' '".sec."' | head -1"))
# the grid of the basin map (rows of b/a, start phases per row), from the header of its file
nrows = int(system("sed -n 's/^# rows = //p' '".bas."' | head -1"))
nphases = int(system("sed -n 's/^# phases = //p' '".bas."' | head -1"))
if (nrows < 2 || nphases < 2) { print "fig_beyond_views: no rows or phases in the header of ".bas; exit status 1 }
db = (BB_max - BB_min) / (nrows - 1)
set multiplot
set grid noxtics noytics
col_l = 0.115; col_r = 0.6; pw = 0.37
row_t = 0.62; row_b = 0.13; ph = 0.29

# ---- (a) stroboscopic section
set lmargin at screen col_l; set rmargin at screen col_l + pw
set bmargin at screen row_t; set tmargin at screen row_t + ph
set title '\small (a) stroboscopic section, $t=2\pi k$' offset 0,-0.6
set xlabel '$x-y$' offset 0,0.4
set ylabel '$\dot x$' offset 0.3,0
bound = -(2 + 1/(4*b_sec))
set xrange [bound*1.08:0.5]
set autoscale y
set format x '$%g$'; set format y '$%.1f$'
set xtics autofreq; set ytics 0.5
set arrow 1 from bound, graph 0 to bound, graph 1 nohead dt (4,3) lw 1.5 lc rgb oi_black front
set label 1 '\footnotesize bound' at bound, graph 0.9 offset 0.4,0 left front
plot sec using "x_minus_y":"v" w p pt 7 ps 0.12 lc rgb c_free notitle
unset arrow 1; unset label 1

# ---- (b) lap estimate against b/a
set lmargin at screen col_r; set rmargin at screen col_r + pw
set title '\small (b) lap estimate of $h_{\mathrm{top}}(T)$' offset 0,-0.6
set logscale x
set xrange [LB_min/1.2:LB_max*1.2]
set yrange [0:*]
set xlabel '$b/a$' offset 0,0.8
set ylabel '$h_n$' offset 0.3,0
set xtics ('$10^{-3}$' 1e-3, '$10^{-2}$' 1e-2, '$10^{-1}$' 1e-1)
set format y '$%.0f$'
set ytics 1
set arrow 2 from graph 0, first log(2) to graph 1, first log(2) nohead dt (4,3) lw 1.5 lc rgb oi_black back
set label 2 '\footnotesize $\ln 2$' at graph 0.03, first log(2) offset 0,0.45 left front
set key at graph 0.98, graph 0.98 right top samplen 1 spacing 0.9 font ",8" opaque
plot lap using (column("failed") == 0 && column("covering") == 1 ? column("b_over_a") : NaN):"entropy_estimate" \
       w p pt 7 ps 0.55 lc rgb c_free title '\footnotesize covering found', \
     lap using (column("failed") == 0 && column("covering") == 0 ? column("b_over_a") : NaN):"entropy_estimate" \
       w p pt 4 ps 0.55 lw 1.5 lc rgb c_prog title '\footnotesize not found'
unset arrow 2; unset label 2; unset logscale x; unset key

# ---- (c) basin map over (theta0, b/a)
set lmargin at screen col_l; set rmargin at screen col_l + pw
set bmargin at screen row_b; set tmargin at screen row_b + ph
set title '\small (c) where the orbit of $T$ from $\theta_0$ settles' offset 0,-0.6
t2m = pi + asin(2*BB_min); t3m = 2*pi - asin(2*BB_min)
set xrange [t2m:t3m]
unset xlabel
set xtics ('$t_2$' t2m, '$\frac{5\pi}{4}$' 1.25*pi, '$\frac{3\pi}{2}$' 1.5*pi, '$\frac{7\pi}{4}$' 1.75*pi, '$t_3$' t3m)
ysc = 1e4
set yrange [(BB_min - db/2)*ysc:(BB_max + db/2)*ysc]
unset ylabel
set label 7 '$10^4\,b/a$' at screen 0.016, screen row_b + ph/2 center rotate by 90 front
set format y '$%.1f$'
set ytics 0.1
# class -> colour, apart in lightness under luminance and under the mean of R, G, B (a yellow
# unresolved cycle was as light as the sky blue by the mean): sky 0.62/0.65, blue 0.34/0.38,
# unresolved very light grey 0.91, black 0
clsrgb(c) = (c == 0 ? 0x56B4E9 : (c == 1 ? 0x0072B2 : (c == 2 ? 0xE8E8E8 : (c == 3 ? 0x000000 : 0x7f7f7f))))
dth = (t3m - t2m) / nphases
wl = (W_min - db/2)*ysc; wh = (W_max + db/2)*ysc
set arrow 3 from graph 0, first wl to graph 1, first wl nohead lw 3.5 lc rgb "#ffffff" front
set arrow 4 from graph 0, first wh to graph 1, first wh nohead lw 3.5 lc rgb "#ffffff" front
set arrow 5 from graph 0, first wl to graph 1, first wl nohead dt (3,2) lw 1.5 lc rgb oi_verm front
set arrow 6 from graph 0, first wh to graph 1, first wh nohead dt (3,2) lw 1.5 lc rgb oi_verm front
plot bas using "theta0":(column("b_over_a")*ysc):(0.51*dth):(0.51*db*ysc):(clsrgb(column("class"))) \
       w boxxyerror fs solid 1.0 noborder lc rgb variable notitle
unset label 7
unset arrow 3; unset arrow 4; unset arrow 5; unset arrow 6

# ---- (d) fibre map
set lmargin at screen col_r; set rmargin at screen col_r + pw
set title '\small (d) fibre map: advance of $y$ in one step from $\theta$' offset 0,-0.6
t2f = pi + asin(2*b_sec); t3f = 2*pi - asin(2*b_sec)
set xrange [t2f:t3f]
set xtics ('$t_2$' t2f, '$\frac{5\pi}{4}$' 1.25*pi, '$\frac{3\pi}{2}$' 1.5*pi, '$\frac{7\pi}{4}$' 1.75*pi, '$t_3$' t3f)
set yrange [0:FP_max*1.25]
set ylabel 'advance' offset 1.2,0
unset xlabel
set format y '$%.1f$'
set ytics autofreq
set key at graph 0.98, graph 0.98 right top horizontal samplen 0.5 spacing 0.9 width -1 opaque
sc(s) = (strcol("scenario") eq s && column("failed") == 0)
plot fib using (sc("A") ? column("theta") : NaN):"penetration" w p pt 7 ps 0.18 lc rgb c_free title '\footnotesize A', \
     fib using (sc("B") ? column("theta") : NaN):"penetration" w p pt 5 ps 0.4 lc rgb c_stop title '\footnotesize B', \
     fib using (sc("C") ? column("theta") : NaN):"penetration" w p pt 9 ps 0.4 lc rgb c_alt title '\footnotesize C', \
     fib using (!sc("A") && !sc("B") && !sc("C") ? column("theta") : NaN):"penetration" w p pt 1 ps 0.4 lc rgb c_grey title '\footnotesize other'
unset key

# ---- key of (c), drawn by hand under the bottom row
unset border; unset tics; unset xlabel; unset ylabel; unset title; unset grid
set lmargin at screen 0; set rmargin at screen 1; set bmargin at screen 0; set tmargin at screen 1
set xrange [0:1]; set yrange [0:1]
kx = 0.12; ky = 0.035
set label 39 '\scriptsize (c):' at screen kx - 0.015, screen ky right front
set object 40 rect center screen kx, screen ky size screen 0.012, screen 0.022 fc rgb 0x56B4E9 fs solid noborder front
set label 40 '\scriptsize no stop' at screen kx + 0.012, screen ky left front
set object 41 rect center screen kx + 0.13, screen ky size screen 0.012, screen 0.022 fc rgb 0x0072B2 fs solid noborder front
set label 41 '\scriptsize stops, goes on' at screen kx + 0.142, screen ky left front
set object 42 rect center screen kx + 0.30, screen ky size screen 0.012, screen 0.022 fc rgb 0xE8E8E8 fs solid border lc rgb "#7f7f7f" front
set label 42 '\scriptsize unresolved cycle' at screen kx + 0.312, screen ky left front
set object 43 rect center screen kx + 0.48, screen ky size screen 0.012, screen 0.022 fc rgb 0x000000 fs solid noborder front
set label 43 '\scriptsize superstable cycle' at screen kx + 0.492, screen ky left front
set arrow 44 from screen kx + 0.665, screen ky to screen kx + 0.705, screen ky nohead lw 3.5 lc rgb "#ffffff" front
set arrow 45 from screen kx + 0.665, screen ky to screen kx + 0.705, screen ky nohead dt (3,2) lw 1.5 lc rgb oi_verm front
set label 44 '\scriptsize (21) or (22) with $T(t_2)=t_2$' at screen kx + 0.715, screen ky left front
plot NaN notitle
unset multiplot
