# Figure: Section 10 (sec10_robustness): the perturbed return map T_eps near J0 and J1 for several
# eps, computed by integrating the perturbed equations of motion.
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,6.5cm
set output "fig_robustness.tex"
set multiplot layout 1,2 margins 0.09,0.98,0.16,0.9 spacing 0.09
set xlabel '$\theta$'; set ylabel '$T_\varepsilon(\theta)$'
set format x '$%.2f$'; set format y '$%.1f$'
set key bottom left box opaque samplen 1
set xtics 0.04
f = data."/sec10_robustness-graph.tsv"
do for [s=0:1] {
  set title sprintf('near $J_%d$', s)
  plot for [e in "0 0.001 0.01"] f using (column("segment") == s && abs(column("eps") - real(e)) < 1e-15 ? column("theta") : NaN):"T_eps" \
       w p pt 7 ps 0.2 title '$\varepsilon='.e.'$'
  unset ylabel
}
unset multiplot
