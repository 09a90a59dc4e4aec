# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: the entropy bracket at one parameter point (sec7_symbolic, certified_claims): ln(laps of
# T^n)/n counted on a grid, against n (sampled upper estimates: laps narrower than the grid step
# are missed), beside the certified lower bound of the covering graph at the same point (the
# report's macro \dfcCertEntropyC, point C of certified_claims) and the lower bound ln 2 of the two
# symbols of Section 7. The parameters are read from the data and written above the plot; the
# certified bound is drawn only if point C is the point of the lap counts.
load figdir."/style.gp"
set terminal cairolatex pdf input size 10cm,6.4cm
set output "fig_laps.tex"
f = data."/sec7_symbolic-laps.tsv"
hdr(key) = real(system("sed -n 's/^# ".key." = //p' '".f."'"))
b = hdr("b_over_a"); q = hdr("q_over_a")
cov = data."/certified_claims-coverings.tsv"
stats cov using (strcol("point") eq "C" ? column("q_over_a") : NaN) name "CQ" nooutput
stats cov using (strcol("point") eq "C" ? column("b_over_a") : NaN) name "CB" nooutput
hcert = real(system("sed -n 's/^\\\\newcommand{\\\\dfcCertEntropyC}{\\(.*\\)}$/\\1/p' '".data."/../tables/certified_claims-macros.tex'"))
same = (abs(CQ_mean - q) < 1e-12 && abs(CB_mean - b) < 1e-12 && hcert > 0)
set title sprintf('\small $b/a=%g$, $q/a=%g$', b, q) offset 0,-0.4
set xlabel '$n$'; set ylabel '$\frac{1}{n}\ln(\mathrm{laps\ of\ }T^n)$'
set format x '$%g$'; set format y '$%.1f$'
set yrange [0:*]
# n is an integer: one tic per n; the key sits in the empty band below the lap counts
set xtics 1
set key at graph 0.97, graph 0.42 right center box opaque samplen 2
stats f using "n" name "N" nooutput
set xrange [N_min - 0.2:N_max + 0.2]
plot f using "n":"log_laps_over_n" w lp pt 7 ps 0.7 lc rgb c_free title 'lap count (sampled, upper)', \
     (same ? hcert : NaN) w l lw 2 lc rgb oi_black title 'certified lower bound', \
     log(2) w l dt 2 lc rgb c_prog title '$\ln 2$ (two symbols)'
