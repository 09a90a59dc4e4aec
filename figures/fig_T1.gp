# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: the next-hit map T1 (Eq. 11) on [t2, t3) for two values of b/a, from sec4_next_hit.
load figdir."/style.gp"
set terminal cairolatex pdf input size 14cm,6.5cm
set output "fig_T1.tex"
# one panel per table sec4_next_hit-T1-*.tsv (larger b/a first); b and q from its description line
files = system("ls -r '".data."'/sec4_next_hit-T1-*.tsv")
if (words(files) < 1) { print "fig_T1: no table sec4_next_hit-T1-*.tsv"; exit status 1 }
set multiplot layout 1,words(files)
set xlabel '$\theta$'
set ylabel '$T_1(\theta)-\theta$'
set logscale y
set format y '$10^{%T}$'
set xrange [3.1:6.3]
set xtics ("$\\pi$" pi, "$\\frac{5\\pi}{4}$" 1.25*pi, "$\\frac{3\\pi}{2}$" 1.5*pi, "$\\frac{7\\pi}{4}$" 1.75*pi, "$2\\pi$" 2*pi)
do for [k=1:words(files)] {
  file = word(files, k)
  b = header_b(file); q = header_q(file)
  if (strlen(b) == 0 || strlen(q) == 0) { print "fig_T1: no 'at a=1 b=.. q=..' line in ".file; exit status 1 }
  set title '$b/a = '.b.'$, $q/a='.q.'$'
  if (k > 1) { unset ylabel }
  plot file using "theta":"flight" with points pt 7 ps 0.12 lc 1
}
unset multiplot
