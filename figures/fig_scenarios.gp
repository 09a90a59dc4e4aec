# Figure: time histories x(t) (mass) and y(t) (delimiter) of one simulated motion per scenario
# of Section 3, from rest at the delimiter at the phase theta; from sec3_scenarios (full
# event-driven simulator). Colour of x: regime (blue free, red progression, green stop).
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,15cm
set output "fig_scenarios.tex"
set multiplot layout 3,2 margins 0.08,0.98,0.05,0.99 spacing 0.08,0.07
set format y "$%g$"
set format x "$%g$"
set ytics 
set xlabel '$t-\theta$' offset 0,0.6
rgb(r) = (r == 0 ? 0x1f77b4 : (r == 1 ? 0xd62728 : 0x2ca02c))
do for [s in "A B C D Cprime Dprime"] {
  f = data."/sec3_scenarios-example-".s.".tsv"
  nm = (s eq "Cprime" ? "C$'$" : (s eq "Dprime" ? "D$'$" : s))
  set label 1 "\\small scenario ".nm at graph 0.97,0.92 right front
  plot f using "t_minus_start":"y" with lines lw 1 dt 2 lc rgb "black", \
       f using "t_minus_start":"x":(rgb(column("regime"))) with lines lw 2 lc rgb variable
}
unset multiplot
