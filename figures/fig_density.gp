# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: histograms of two long floating-point orbits of T on [t2, t3) (dynamics_gallery): an
# empirical measure of computed orbits, not a proved estimate of the invariant density (both computed
# orbits end on one cycle of the computed map; see the report's caption):
# the histogram of the pooled orbit points (filled), the histograms of the two orbits separately
# (lines), and the atom at t2 (every step with a stop sends its whole arc to t2) drawn as a spike
# (its mass is a macro of the report): the density integrates to one minus that mass.
load figdir."/style.gp"
set terminal cairolatex pdf input size 12cm,6.8cm
set output "fig_density.tex"
f = data."/dynamics_gallery-density.tsv"
s = data."/dynamics_gallery.tsv"
stats s using "b_over_a" name "B" nooutput
stats s using "q_over_a" name "Q" nooutput
stats s using "points" name "N" nooutput
stats f using "bin_lo" name "LO" nooutput
stats f using "bin_hi" name "HI" nooutput
stats f using "density" name "D" nooutput
t2 = LO_min; t3 = HI_max
set lmargin at screen 0.1; set rmargin at screen 0.97; set bmargin at screen 0.15; set tmargin at screen 0.88
set title sprintf('$b/a=%g$, $q/a=%g$: two orbits of %s points each', B_mean, Q_mean, gprintf('$%.0t\cdot10^{%T}$', N_mean)) offset 0,-0.4
set xlabel '$\theta$'
set ylabel 'fraction of points per unit $\theta$' offset 1,0
set xrange [t2 - 0.04*(t3 - t2):t3]
set yrange [0:D_max*1.15]
set xtics ('$t_2$' t2, '$\frac{5\pi}{4}$' 1.25*pi, '$\frac{3\pi}{2}$' 1.5*pi, '$\frac{7\pi}{4}$' 1.75*pi, '$t_3$' t3)
set format y '$%.1f$'
set grid noxtics noytics
set style fill solid 0.35 noborder
# the atom at t2: a spike of arbitrary height (a Dirac mass); its mass is given by the caption
set arrow 1 from t2, 0 to t2, graph 0.8 lw 2.5 lc rgb c_stop head filled size graph 0.015,25
# its label short, clear of the peak near 3 pi/2
set label 1 '\footnotesize atom at $t_2$' at t2, graph 0.84 left offset 0.3,0 front
set key top right samplen 2 spacing 1.1 nobox
plot f using "centre":"density":(column("bin_hi") - column("bin_lo")) w boxes lc rgb c_free title 'pooled', \
     f using "centre":"density_start1" w histeps lw 0.8 lc rgb "#000000" title 'start 1', \
     f using "centre":"density_start2" w histeps lw 1.2 dt 2 lc rgb c_prog title 'start 2'
