# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: the topological entropy of T bounded from both sides at the parameter points A-D of
# certified_claims (data/certified_claims-entropy.tsv, certified/laps.hpp), against ln(a/(2 pi b)):
# each point a certified interval [lower, upper] (drawn as a bar; at this scale most bars are no
# taller than the marker), the line h = ln(a/(2 pi b)) and the bound ln 2 of the two symbols of
# Section 7.
load figdir."/style.gp"
set terminal cairolatex pdf input size 10cm,6.4cm
set output "fig_entropy.tex"
f = data."/certified_claims-entropy.tsv"
stats f using (column("proved") == 1 ? column("log_a_over_2pi_b") : NaN) name "X" nooutput
set xlabel '$\ln\frac{a}{2\pi b}$'
set ylabel '$h_{\mathrm{top}}(T)$'
set format x '$%g$'; set format y '$%g$'
set xrange [0:X_max + 0.5]
set yrange [0:X_max + 0.5]
set key top left box opaque samplen 2
set offsets 0, 0, 0, 0
plot x w l dt 2 lc rgb c_grey title '$\ln\frac{a}{2\pi b}$', \
     log(2) w l dt 3 lc rgb c_prog title '$\ln 2$ (Section 7)', \
     f using (column("proved") == 1 ? column("log_a_over_2pi_b") : NaN):(0.5 * (column("h_lower") + column("h_upper"))):"h_lower":"h_upper" \
       w yerrorbars pt 7 ps 0.5 lw 1.5 lc rgb c_free title 'certified bounds', \
     f using (column("proved") == 1 ? column("log_a_over_2pi_b") : NaN):"h_lower":(sprintf('%s', strcol("point"))) \
       w labels offset 0.8,-0.8 notitle
