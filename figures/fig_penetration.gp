# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: the drilling rate (penetration_rate): mean advance of the delimiter per unit time.
# (a) the rate against b/a on the line q/a of the experiment (its macro) (mean over initial phases, bars from min to max);
# (b) the rate divided by b/a on the same line: the rate is nearly proportional to b, and this
#     shows how it is not, and where it depends on the initial phase (open circles: relative spread
#     above the tolerance of rate.independent_of_start, read from the experiment's macros);
# (c) the rate divided by b/a over the (q/a, b/a) plane, with a labelled colour bar; crosses mark
#     cells whose rate depends on the initial phase (spread above that tolerance).
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,6.6cm
set output "fig_penetration.tex"
f = data."/penetration_rate-line.tsv"
g = data."/penetration_rate-plane.tsv"
eval tex_macro("q_line", "penetration_rate", "RateQ")
eval tex_macro("tol", "penetration_rate", "RateSpreadTol")
spread_tol = real(tol)
stats f using "b_over_a" name "L" nooutput
stats g using "q_over_a" name "Q" nooutput
stats g using (log10(column("b_over_a"))) name "B" nooutput
stats g using (column("rate_mean")/column("b_over_a")) name "R" nooutput
nq = int(sqrt(Q_records) + 0.5)
dq = (Q_max - Q_min) / (nq - 1); db = (B_max - B_min) / (nq - 1)
# The bars are drawn without points and the points on top: gnuplot's cairolatex terminal blanks a
# disc around a point of an error-bar plot, and with points this close that disc covers half of the
# neighbouring point.
set multiplot
set bmargin at screen 0.16; set tmargin at screen 0.91
set logscale x
set format x '$10^{%T}$'
set xlabel '$b/a$' offset 0,0.3
set xrange [L_min/1.5:L_max*1.5]
set xtics 100
set mxtics 10

# ---- (a)
set lmargin at screen 0.115; set rmargin at screen 0.315
set title '(a) $q/a='.q_line.'$'
# y labels placed by hand: gnuplot overestimates the width of TeX tick labels such as $10^{-4}$
unset ylabel
set label 90 'rate' at screen 0.025, graph 0.5 rotate center
set logscale y
set format y '$10^{%T}$'
plot f using "b_over_a":"rate_mean":"rate_min":"rate_max" w yerrorbars pt -1 lw 0.8 lc rgb c_free notitle, \
     f using "b_over_a":"rate_mean" w p pt 7 ps 0.35 lc rgb c_free notitle

# ---- (b)
set lmargin at screen 0.41; set rmargin at screen 0.615
set title '(b) $q/a='.q_line.'$'
set label 90 'rate$/(b/a)$' at screen 0.343, graph 0.5 rotate center
unset logscale y
set format y '$%.1f$'
set yrange [0:*]
plot f using "b_over_a":(column("rate_mean")/column("b_over_a")):(column("rate_min")/column("b_over_a")):(column("rate_max")/column("b_over_a")) \
       w yerrorbars pt -1 lw 0.8 lc rgb c_free notitle, \
     f using "b_over_a":(column("rate_mean")/column("b_over_a")) w p pt 7 ps 0.35 lc rgb c_free notitle, \
     f using "b_over_a":((column("rate_max") - column("rate_min"))/column("rate_mean") > spread_tol ? column("rate_mean")/column("b_over_a") : NaN) \
       w p pt 6 ps 1.0 lw 1.2 lc rgb c_prog notitle

# ---- (c)
unset logscale x
set lmargin at screen 0.735; set rmargin at screen 0.88
set title '(c) the plane'
set xlabel '$q/a$'; unset ylabel; unset label 90
set label 91 '$b/a$' at screen 0.65, graph 0.5 rotate center
set xrange [Q_min - dq/2 : Q_max + dq/2]; set yrange [B_min - db/2 : B_max + db/2]
set xtics 0.1 format '$%.1f$'
set mxtics 2
set ytics ('$10^{-4}$' -4, '$10^{-3}$' -3, '$10^{-2}$' -2, '$10^{-1}$' -1)
set mytics 10
set grid noxtics noytics
set colorbox user origin screen 0.89, screen 0.16 size screen 0.014, screen 0.75
set cblabel 'rate$/(b/a)$' offset 0.6,0
set format cb '$%.1f$'
set cbtics 0.4
set cbrange [R_min:R_max]
plot g using "q_over_a":(log10(column("b_over_a"))):(column("failed") == 0 ? column("rate_mean")/column("b_over_a") : NaN) w image pixels notitle, \
     g using "q_over_a":(column("relative_spread") > spread_tol ? log10(column("b_over_a")) : NaN) w p pt 7 ps 0.9 lc rgb "white" notitle, \
     g using "q_over_a":(column("relative_spread") > spread_tol ? log10(column("b_over_a")) : NaN) w p pt 6 ps 0.9 lw 1.5 lc rgb c_prog notitle
unset multiplot
