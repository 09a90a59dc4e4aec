# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: orbit diagrams of T with the Lyapunov exponent (bifurcation_diagram). Top: phases after
# the transient against b/a (at the q/a of the experiment's option --q) and against q/a (at its --b);
# both values read from the experiment's macros. Bottom: the Lyapunov
# exponent lambda (mean of ln|T'|) where it is finite; parameter values whose orbit meets a stop
# arc (a step with T' = 0, so lambda = -inf) are drawn in a band of their own below the axis
# break, marked -inf, and those whose orbit then returns to t2 on a cycle that double precision
# resolves (a superstable cycle through t2: column t2_cycle_resolved) with a second marker; a
# computed return that it does not resolve (a cycle of the rounding) keeps the first marker. Where q/a < sin(vartheta0) assumption (2) fails: shaded.
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,10cm
set output "fig_bifurcation.tex"
orb = data."/bifurcation_diagram-orbits.tsv"
lya = data."/bifurcation_diagram-lyapunov.tsv"
s0 = sin_vartheta0   # Eq. (1), from eq1_vartheta0 (style.gp)
eval tex_macro("q_fixed", "bifurcation_diagram", "BifQ")
eval tex_macro("b_fixed", "bifurcation_diagram", "BifB")
# ranges of the data (stats obeys ranges: read before any is set)
stats lya using (strcol("sweep") eq "b" ? column("b_over_a") : NaN) name "BX" nooutput
stats lya using (strcol("sweep") eq "q" ? column("q_over_a") : NaN) name "QX" nooutput
stats lya using (strcol("sweep") eq "b" && column("flat_steps") == 0 ? column("lyapunov") : NaN) name "BL" nooutput
stats lya using (strcol("sweep") eq "q" && column("flat_steps") == 0 ? column("lyapunov") : NaN) name "QL" nooutput
set multiplot
set grid noxtics noytics
col_l = 0.085; col_r = 0.585; pw = 0.4
row_t = 0.6; row_b = 0.085; ph = 0.325

# ---- top: orbit diagrams
set bmargin at screen row_t; set tmargin at screen row_t + ph
set ytics ('$\pi$' pi, '$\frac{5\pi}{4}$' 1.25*pi, '$\frac{3\pi}{2}$' 1.5*pi, '$\frac{7\pi}{4}$' 1.75*pi, '$2\pi$' 2*pi)
set yrange [pi:2*pi]
set ylabel '$\theta_n$' offset 1.5,0
set lmargin at screen col_l; set rmargin at screen col_l + pw
set logscale x
set format x '$10^{%T}$'
set xrange [BX_min/1.15:BX_max*1.15]
set xlabel '$b/a$' offset 0,0.4
set title '$q/a='.q_fixed.'$' offset 0,-0.4
plot orb using (strcol("sweep") eq "b" ? column("b_over_a") : NaN):"theta" w dots lc rgb c_free notitle
unset logscale x
set lmargin at screen col_r; set rmargin at screen col_r + pw
set format x '$%.1f$'
set xrange [QX_min - 0.01:QX_max + 0.01]
set xtics 0.1
set xlabel '$q/a$'
set title '$b/a='.b_fixed.'$'
set object 1 rect from graph 0, graph 0 to first s0, graph 1 fc rgb "#d9d9d9" fs solid 0.5 noborder back
set label 1 '\footnotesize (2) fails' at first (QX_min + s0)/2, graph 0.94 center front
plot orb using (strcol("sweep") eq "q" ? column("q_over_a") : NaN):"theta" w dots lc rgb c_free notitle
unset object 1; unset label 1

# ---- bottom: Lyapunov exponents, with a band for lambda = -inf under an axis break
set bmargin at screen row_b; set tmargin at screen row_b + ph
set ylabel '$\lambda$' offset 1.0,0
set format y '$%g$'
unset title
do for [k=1:2] {
  sw = (k == 1 ? "b" : "q")
  lo = (k == 1 ? BL_min : QL_min); hi = (k == 1 ? BL_max : QL_max)
  span = hi - lo; band_hi = lo - 0.12*span; band_lo = band_hi - 0.14*span; ninf = (band_lo + band_hi)/2
  set yrange [band_lo:hi + 0.06*span]
  step = (span > 3 ? 1 : 0.5)
  set ytics ('$-\infty$' ninf)
  set for [j=ceil(lo/step):floor((hi+0.06*span)/step)] ytics add (sprintf('$%g$', j*step) j*step)
  set object 2 rect from graph 0, first band_lo to graph 1, first band_hi fc rgb "#eeeeee" fs solid 1 noborder back
  # the axis break: a white gap across the left border between the band and the finite values
  set object 3 rect from graph -0.02, first band_hi to graph 0.02, first band_hi + 0.04*span fc rgb "white" fs solid 1 noborder front
  set arrow 1 from graph 0, first 0 to graph 1, first 0 nohead dt 2 lw 0.8 lc rgb c_grey
  if (k == 1) {
    set lmargin at screen col_l; set rmargin at screen col_l + pw
    set logscale x; set format x '$10^{%T}$'; set xrange [BX_min/1.15:BX_max*1.15]; set xtics auto
    set xlabel '$b/a$'
    xcol = "b_over_a"
  } else {
    set lmargin at screen col_r; set rmargin at screen col_r + pw
    unset logscale x; set format x '$%.1f$'; set xrange [QX_min - 0.01:QX_max + 0.01]; set xtics 0.1
    set xlabel '$q/a$'
    unset ylabel
    set object 1 rect from graph 0, graph 0 to first s0, graph 1 fc rgb "#d9d9d9" fs solid 0.5 noborder back
    set label 1 '\footnotesize (2) fails' at first (QX_min + s0)/2, graph 0.94 center front
    xcol = "q_over_a"
  }
  plot lya using (strcol("sweep") eq sw && column("flat_steps") == 0 ? column(xcol) : NaN):"lyapunov" w p pt 7 ps 0.3 lc rgb c_prog notitle, \
       lya using (strcol("sweep") eq sw && column("flat_steps") > 0 && column("t2_cycle_resolved") == 0 ? column(xcol) : NaN):(ninf) \
         w p pt 2 ps 0.7 lw 1.5 lc rgb "black" notitle, \
       lya using (strcol("sweep") eq sw && column("t2_cycle_resolved") == 1 ? column(xcol) : NaN):(ninf) \
         w p pt 4 ps 0.9 lw 1.5 lc rgb c_stop notitle
  unset object 1; unset object 2; unset object 3; unset label 1; unset arrow 1
}

# ---- one key for the figure, drawn by hand above the bottom row
unset border; unset tics; unset xlabel; unset ylabel; unset title; unset logscale x
set lmargin at screen 0; set rmargin at screen 1; set bmargin at screen 0; set tmargin at screen 1
set xrange [0:1]; set yrange [0:1]
ky = 0.47
set object 11 circle at screen 0.03, screen ky size screen 0.004 fc rgb c_prog fs solid noborder front
set label 11 '\small finite $\lambda$' at screen 0.045, screen ky left front
set label 12 '$\times$' at screen 0.165, screen ky center front
set label 13 '\small $\lambda=-\infty$: a step with $T''=0$ (stop)' at screen 0.18, screen ky left front
set label 14 sprintf('{\color[HTML]{%s}$\square$}', c_stop[2:7]) at screen 0.56, screen ky center front
set label 15 '\small $\lambda=-\infty$, superstable cycle through $t_2$ (resolved)' at screen 0.575, screen ky left front
plot NaN notitle
unset multiplot
