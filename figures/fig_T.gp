# Figure: the return map T of Lemma 3 on [t2, t3), each point coloured by its scenario; from
# lemma3_return_map. Left: Lemma 1 holds (b/a = 0.01, q/a = 0.85); right: it fails (q/a = 0.7).
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,6.8cm
set output "fig_T.tex"
set multiplot layout 1,2 margins 0.09,0.98,0.15,0.9 spacing 0.09
set xlabel '$\theta$'; set ylabel '$T(\theta)$'
set xtics ("$\\pi$" pi, "$\\frac{5\\pi}{4}$" 1.25*pi, "$\\frac{3\\pi}{2}$" 1.5*pi, "$\\frac{7\\pi}{4}$" 1.75*pi, "$2\\pi$" 2*pi)
set ytics ("$\\pi$" pi, "$\\frac{5\\pi}{4}$" 1.25*pi, "$\\frac{3\\pi}{2}$" 1.5*pi, "$\\frac{7\\pi}{4}$" 1.75*pi, "$2\\pi$" 2*pi)
col(s) = (s eq "A" ? 0x1f77b4 : (s eq "B" ? 0x2ca02c : (s eq "C" ? 0xff7f0e : (s eq "D" ? 0xd62728 : 0x7f7f7f))))
set key top right samplen 0.5 spacing 1.0 box opaque width -1
set yrange [3.0:*]
do for [f in "b0.01-q0.85 b0.05-q0.7"] {
  file = data."/lemma3_return_map-graph-".f.".tsv"
  set title (f eq "b0.01-q0.85" ? '$b/a=0.01$, $q/a=0.85$ (Lemma 1 holds)' : '$b/a=0.05$, $q/a=0.7$ (Lemma 1 fails)')
  plot file using "theta":(strcol("scenario") eq "A" ? column("T") : NaN) w p pt 7 ps 0.2 lc rgb "#1f77b4" notitle, \
       file using "theta":(strcol("scenario") eq "B" ? column("T") : NaN) w p pt 7 ps 0.35 lc rgb "#2ca02c" notitle, \
       file using "theta":(strcol("scenario") eq "C" ? column("T") : NaN) w p pt 7 ps 0.35 lc rgb "#ff7f0e" notitle, \
       file using "theta":(strcol("scenario") eq "D" ? column("T") : NaN) w p pt 7 ps 0.35 lc rgb "#d62728" notitle, \
       NaN w p pt 7 ps 1 lc rgb "#1f77b4" title "A", NaN w p pt 7 ps 1 lc rgb "#2ca02c" title "B", \
       NaN w p pt 7 ps 1 lc rgb "#ff7f0e" title "C", NaN w p pt 7 ps 1 lc rgb "#d62728" title "D"
}
unset multiplot
