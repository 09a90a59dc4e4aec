# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: every superstable window of t2 at one q/a, proved (thm2_windows), against a/b.
# (a) The orbit diagram of bifurcation_diagram (phases after its transient, its b/a sweep at its q/a,
#     which must be thm2_windows's) with a vertical line at each certified window: the windows are
#     far narrower than a line, so the line marks where each one is, not its width.
# (b) The width of each certified window in a/b (its inner interval), with the fit w0 + w1 (b/a) of
#     data/thm2_windows-law.tsv (fitted on b/a <= its macro WinFitMaxRatio, drawn over the whole axis).
# (c) The distance in a/b between consecutive windows, with 2 pi / |cos t2| (the growth of the flight
#     time from t2, cos t2 = -sqrt(1 - (2b/a)^2)) and 2 pi.
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,9cm
set output "fig_thm2_windows.tex"
win = data."/thm2_windows.tsv"
law = data."/thm2_windows-law.tsv"
orb = data."/bifurcation_diagram-orbits.tsv"
eval tex_macro("q_win", "thm2_windows", "WinQ")
eval tex_macro("q_bif", "bifurcation_diagram", "BifQ")
if (real(q_win) != real(q_bif)) { print "fig_thm2_windows: q/a of thm2_windows (".q_win.") is not bifurcation_diagram's (".q_bif.")"; exit status 1 }
# ranges and the fits (stats obeys ranges: read before any is set)
stats win using (column("proved") == 1 ? column("centre_a_over_b") : NaN) name "C" nooutput
stats law using (strcol("quantity") eq "width_a_over_b" ? column("c0") : NaN) name "W0" nooutput
stats law using (strcol("quantity") eq "width_a_over_b" ? column("c1") : NaN) name "W1" nooutput
w0 = W0_min; w1 = W1_min
eval tex_macro("fit_max", "thm2_windows", "WinFitMaxRatio")
xfit = 1/real(fit_max)
set multiplot
set grid noxtics noytics

# ---- (a) the orbit diagram against a/b, a line at each certified window
set lmargin at screen 0.09; set rmargin at screen 0.97
set bmargin at screen 0.6; set tmargin at screen 0.86
set logscale x
set xrange [C_min/1.15:C_max*1.15]
set format x '$%g$'
set xlabel '$a/b$' offset 0,0.5
set ytics ('$\pi$' pi, '$\frac{3\pi}{2}$' 1.5*pi, '$2\pi$' 2*pi)
set yrange [pi:2*pi]
set ylabel '$\theta_n$' offset 1.5,0
set label 1 '(a)' at graph 0.01, graph 1.04 left front
set key at screen 0.97, screen 0.975 horizontal right samplen 1.5
plot win using (column("proved") == 1 ? column("centre_a_over_b") : NaN):(pi):(0):(pi) w vectors nohead lw 0.6 lc rgb c_stop \
       title sprintf('certified window ($T(t_2)=t_2$), %d', C_records), \
     orb using (strcol("sweep") eq "b" ? 1/column("b_over_a") : NaN):"theta" w dots lc rgb c_free title 'orbit after the transient (floating)'
unset label 1; unset key

# ---- (b) widths in a/b
set bmargin at screen 0.1; set tmargin at screen 0.41
set lmargin at screen 0.1; set rmargin at screen 0.47
set xtics auto
set ytics auto
set format y '$%.2f$'
set yrange [*:*]
set ylabel 'width in $a/b$' offset 0.5,0
set label 1 '(b)' at graph 0.03, graph 0.92 left front
set key default; set key inside right center samplen 1.5
set samples 400
plot (w0 + w1/x) w l lw 1.5 dt 2 lc rgb c_prog title sprintf('fit on $a/b\ge%g$', xfit), \
     win using (column("proved") == 1 ? column("centre_a_over_b") : NaN):"width_a_over_b" w p pt 7 ps 0.3 lc rgb c_stop title 'certified windows' 
unset label 1

# ---- (c) spacing in a/b of consecutive windows (rows are in increasing b/a: decreasing a/b)
set lmargin at screen 0.6; set rmargin at screen 0.97
set ylabel 'spacing in $a/b$' offset 0.5,0
set format y '$%.2f$'
set label 1 '(c)' at graph 0.03, graph 0.92 left front
prev = NaN
gap(x) = (g = prev - x, prev = x, g)
set key default; set key inside top right samplen 1.5
plot win using (column("proved") == 1 ? column("centre_a_over_b") : NaN):(gap(column("centre_a_over_b"))) w p pt 7 ps 0.3 lc rgb c_stop \
       title 'to the next window', \
     (x > 2 ? 2*pi/sqrt(1 - 4/x**2) : NaN) w l lw 1.5 lc rgb c_prog title '$2\pi/|\cos t_2|$', \
     2*pi w l dt 2 lw 1 lc rgb c_grey title '$2\pi$'
unset multiplot
