# Figure: numerical thresholds b0(q) of Lemma 1 and Lemma 4 against q/a. Lemma 1 (from
# lemma1_progression_stop): largest b/a below which progression from rest at t0 stops in
# [t1, t2], and the same for the proof's sufficient bound (Eq. 9). Lemma 4 (from lemma4_coverage):
# the paper's literal construction, and the covering itself (a lower estimate).
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,6.8cm
set output "fig_thresholds.tex"
set multiplot layout 1,2 margins 0.09,0.98,0.15,0.9 spacing 0.1
set xlabel '$q/a$'; set ylabel '$b_0/a$'
set logscale y
set format y '$10^{%T}$'
set format x '$%.2f$'
set key top left samplen 2 box opaque
set title 'Lemma 1'
set xrange [0.6:1]
set xtics 0.1
set arrow 1 from 0.7246113537767086,graph 0 to 0.7246113537767086,graph 1 nohead dt 3 lc rgb c_grey
set label 1 '$\sin\vartheta_0$' at 0.7246113537767086,graph 0.92 right offset -0.3,0
f1 = data."/lemma1_progression_stop.tsv"
plot f1 using "q_over_a":(column("b0_lemma1") > 0 ? column("b0_lemma1") : NaN) w l lw 2 lc rgb c_free title 'computed', \
     f1 using "q_over_a":(column("b0_proof_bound") > 0 ? column("b0_proof_bound") : NaN) w l lw 2 dt 2 lc rgb c_prog title 'proof (9)'
set title 'Lemma 4'
unset arrow 1; unset label 1; unset ylabel
set xtics 0.05
f4 = data."/lemma4_coverage.tsv"
set xrange [0.72:1]
plot f4 using "q_over_a":(column("b0_covering") > 0 ? column("b0_covering") : NaN) w lp pt 7 ps 0.5 lw 2 lc rgb c_free title 'covering (b)', \
     f4 using "q_over_a":(column("b0_literal") > 0 ? column("b0_literal") : NaN) w lp pt 5 ps 0.5 lw 2 dt 2 lc rgb c_prog title "proof's steps (a)"
unset multiplot
