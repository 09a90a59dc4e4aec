# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: the topological entropy of T bounded from both sides (certified/laps.hpp).
# (a) Along q/a fixed (sec7_entropy_law, line "b"), against ln(a/b): the certified lower and upper
#     bounds, ln(a/(2 pi b)) (about the number of laps), the fitted law ln(a/b) - c
#     (data/sec7_entropy_law-fit.tsv) and ln 2; the points A, B, D of certified_claims when they lie
#     on the line (same q/a).
# (b) Along b/a fixed (line "q"), against q/a: the two bounds.
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,5.2cm
set output "fig_entropy_law.tex"
f = data."/sec7_entropy_law.tsv"
fit = data."/sec7_entropy_law-fit.tsv"
pts = data."/certified_claims-entropy.tsv"
eval tex_macro("q_law", "sec7_entropy_law", "LawQ")
stats fit using "c" name "C" nooutput
stats f using (strcol("line") eq "b" && column("proved") == 1 ? column("log_a_over_b") : NaN) name "X" nooutput
set multiplot
set grid noxtics noytics

# ---- (a) along b/a
set lmargin at screen 0.08; set rmargin at screen 0.53
set bmargin at screen 0.16; set tmargin at screen 0.95
set xlabel '$\ln(a/b)$' offset 0,0.4
set ylabel '$h_{\mathrm{top}}(T)$' offset 1,0
set format x '$%g$'; set format y '$%g$'
set xrange [X_min - 0.2:X_max + 0.2]
set yrange [0:*]
set label 1 sprintf('(a) $q/a=%s$', q_law) at graph 0.03, graph 0.93 left front
set key at graph 0.97, graph 0.04 right bottom samplen 1.5 spacing 1.2
plot x - log(2 * pi) w l dt 2 lc rgb c_grey title '$\ln\frac{a}{2\pi b}$', \
     x - C_min w l lw 1 lc rgb c_alt title sprintf('$\ln\frac{a}{b}-%.3f$ (fit)', C_min), \
     log(2) w l dt 3 lc rgb c_prog title '$\ln 2$', \
     f using (strcol("line") eq "b" ? column("log_a_over_b") : NaN):"h_lower" w lp pt 7 ps 0.3 lc rgb c_free title 'certified lower, upper', \
     f using (strcol("line") eq "b" ? column("log_a_over_b") : NaN):"h_upper" w lp pt 7 ps 0.3 lc rgb c_free notitle, \
     pts using (abs(column("q_over_a") - real(q_law)) < 1e-12 && column("proved") == 1 ? log(1 / column("b_over_a")) : NaN):"h_upper":(strcol("point")) \
       w labels offset 0,0.7 font ',8' notitle
unset label 1

# ---- (b) along q/a
set lmargin at screen 0.62; set rmargin at screen 0.98
set xlabel '$q/a$'
set ylabel ''
set format x '$%.2f$'
set xrange [*:*]
set yrange [*:*]
eval tex_macro("b_law", "sec7_entropy_law", "LawB")
set label 1 sprintf('(b) $b/a=%s$', b_law) at graph 0.03, graph 0.93 left front
set key at graph 0.97, graph 0.05 right bottom samplen 1.5 spacing 1.2
plot f using (strcol("line") eq "q" ? column("q_over_a") : NaN):"h_upper" w lp pt 7 ps 0.3 lc rgb c_free title 'certified upper', \
     f using (strcol("line") eq "q" ? column("q_over_a") : NaN):"h_lower" w lp pt 6 ps 0.3 lc rgb c_stop title 'certified lower'
unset multiplot
