# Figure: Lemma 2 and Eq. (13). Left (lemma2_monotonicity): the number of discontinuities of T1
# on L0 times b/a, and the smallest jump, against b/a. Right (sec4_next_hit): the constant C of
# Eq. (13), min over theta of flight / ((a/b)|cos theta|), against b/a.
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,6.5cm
set output "fig_discontinuities.tex"
set multiplot layout 1,2 margins 0.09,0.98,0.16,0.9 spacing 0.1
set logscale x
set format x '$10^{%T}$'
set xlabel '$b/a$'
set key top left box opaque
set title 'Lemma 2: discontinuities of $T_1$ on $L_0$'
set format y '$%.2f$'
f = data."/lemma2_monotonicity.tsv"
plot f using "b_over_a":"count_times_b_over_a" w lp pt 7 ps 0.6 lc rgb c_free title '$(b/a)\times$count', \
     f using "b_over_a":"min_jump" w lp pt 5 ps 0.6 lc rgb c_prog title 'smallest jump'
set title 'Eq.~(13): $C_{\min}$'
set key bottom left
g = data."/sec4_next_hit-asymptotics.tsv"
plot g using "b_over_a":"C_min" w lp pt 7 ps 0.6 lc rgb c_free title '$\min_\theta (\theta_1-\theta)\,b/(a|\cos\theta|)$'
unset multiplot
