# Figure: the drilling rate (penetration_rate): mean advance of the delimiter per unit time. Left:
# against b/a at q/a = 0.85 (mean over initial phases, bars from min to max). Right: over the
# (q/a, b/a) plane.
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,6.8cm
set output "fig_penetration.tex"
set multiplot layout 1,2 margins 0.09,0.9,0.16,0.9 spacing 0.12
set logscale xy
set format x '$10^{%T}$'; set format y '$10^{%T}$'
set xlabel '$b/a$'; set ylabel 'rate $\langle\Delta y\rangle/\langle\Delta t\rangle$ (units of $a$)'
set title '$q/a=0.85$'
f = data."/penetration_rate-line.tsv"
plot f using "b_over_a":"rate_mean":"rate_min":"rate_max" w yerrorbars pt 7 ps 0.4 lc rgb c_free
unset logscale
set title 'over the plane'
set xlabel '$q/a$'; set ylabel '$\log_{10}(b/a)$'
set format x '$%.2f$'; set format y '$%g$'
set cblabel '$\log_{10}$ rate' offset 1,0
set format cb '$%g$'
set palette rgbformulae 30,31,32
g = data."/penetration_rate-plane.tsv"
plot g using "q_over_a":(log10(column("b_over_a"))):(column("rate_mean") > 0 ? log10(column("rate_mean")) : NaN) w image
unset multiplot
