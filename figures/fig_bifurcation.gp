# Figure: orbit diagrams of T with the Lyapunov exponent (bifurcation_diagram). Top: phases after
# the transient against b/a (q/a = 0.85) and against q/a (b/a = 0.01). Bottom: the Lyapunov
# exponent (mean of ln|T'|) where finite; grey ticks at the bottom mark parameter values whose
# orbit meets a stop arc (T' = 0: the orbit of t2, superstable when periodic).
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,11cm
set output "fig_bifurcation.tex"
set multiplot layout 2,2 margins 0.09,0.98,0.07,0.96 spacing 0.09,0.12
orb = data."/bifurcation_diagram-orbits.tsv"
lya = data."/bifurcation_diagram-lyapunov.tsv"
set ytics ("$\\pi$" pi, "$\\frac{5\\pi}{4}$" 1.25*pi, "$\\frac{3\\pi}{2}$" 1.5*pi, "$\\frac{7\\pi}{4}$" 1.75*pi, "$2\\pi$" 2*pi)
set yrange [pi:2*pi]
set logscale x
set format x '$10^{%T}$'
set xlabel '$b/a$'; set ylabel '$\theta_n$'
unset title
plot orb using (strcol("sweep") eq "b" ? column("b_over_a") : NaN):"theta" w dots lc rgb c_free
unset logscale x
set format x '$%.1f$'
set xtics 0.1
set xlabel '$q/a$'; unset ylabel
unset title
plot orb using (strcol("sweep") eq "q" ? column("q_over_a") : NaN):"theta" w dots lc rgb c_free
set ytics auto; set yrange [*:*]
set format y '$%g$'
set logscale x
set xtics auto
set format x '$10^{%T}$'
set xlabel '$b/a$'; set ylabel '$\lambda$'
unset title
set key bottom left box opaque samplen 1
plot lya using (strcol("sweep") eq "b" ? column("b_over_a") : NaN):"lyapunov" w p pt 7 ps 0.35 lc rgb c_prog title 'finite $\lambda$', \
     lya using (strcol("sweep") eq "b" && column("flat_steps") > 0 ? column("b_over_a") : NaN):(0) w p pt 2 ps 0.3 lc rgb c_grey title 'orbit of $t_2$ ($\lambda=-\infty$)'
unset logscale x
set format x '$%.1f$'
set xtics 0.1
set key bottom right
set xlabel '$q/a$'; unset ylabel
plot lya using (strcol("sweep") eq "q" ? column("q_over_a") : NaN):"lyapunov" w p pt 7 ps 0.35 lc rgb c_prog title 'finite $\lambda$', \
     lya using (strcol("sweep") eq "q" && column("flat_steps") > 0 ? column("q_over_a") : NaN):(0) w p pt 2 ps 0.3 lc rgb c_grey title 'orbit of $t_2$ ($\lambda=-\infty$)'
unset multiplot
