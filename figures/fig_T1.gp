# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: the next-hit map T1 (Eq. 11) on [t2, t3) for two values of b/a, from sec4_next_hit.
load figdir."/style.gp"
set terminal cairolatex pdf input size 14cm,6.5cm
set output "fig_T1.tex"
set multiplot layout 1,2
set xlabel '$\theta$'
set ylabel '$T_1(\theta)-\theta$'
set logscale y
set format y '$10^{%T}$'
set xrange [3.1:6.3]
set xtics ("$\\pi$" pi, "$\\frac{5\\pi}{4}$" 1.25*pi, "$\\frac{3\\pi}{2}$" 1.5*pi, "$\\frac{7\\pi}{4}$" 1.75*pi, "$2\\pi$" 2*pi)
set title '$b/a = 0.05$, $q/a=0.85$'
plot data."/sec4_next_hit-T1-b0.05.tsv" using "theta":"flight" with points pt 7 ps 0.12 lc 1
set title '$b/a = 0.01$, $q/a=0.85$'
unset ylabel
plot data."/sec4_next_hit-T1-b0.01.tsv" using "theta":"flight" with points pt 7 ps 0.12 lc 1
unset multiplot
