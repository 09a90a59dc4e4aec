# Figure: the lap-count estimate of topological entropy (sec7_symbolic): ln(laps of T^n)/n on a
# grid, against n, beside the lower bound ln 2 from the symbolic dynamics of Section 7.
load figdir."/style.gp"
set terminal cairolatex pdf input size 10cm,6cm
set output "fig_laps.tex"
set xlabel '$n$'; set ylabel '$\frac{1}{n}\ln(\mathrm{laps\ of\ }T^n)$'
set format x '$%g$'; set format y '$%.1f$'
set yrange [0:*]
set key bottom right box opaque
f = data."/sec7_symbolic-laps.tsv"
plot f using "n":"log_laps_over_n" w lp pt 7 ps 0.7 lc rgb c_free title 'lap count', log(2) w l dt 2 lc rgb c_prog title '$\ln 2$'
