# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: numerical thresholds b0(q) of Lemma 1 and Lemma 4 against q/a.
# Left (lemma1_progression_stop): the largest b/a below which progression from rest at t0 stops in
# [t1, t2], and the same for the proof's sufficient bound (Eq. 9); both bisected between grid
# points, so drawn as curves; over them the closed form (q/a - sin(vartheta0))/2 of the proof's
# bound and the certified lower bounds of b0 at single q/a (certified_claims-b0.tsv, proved ones
# only): the three b0 thresholds of Lemma 1 in one panel. Where q/a < sin(vartheta0) assumption (2)
# fails (shaded).
# Right (lemma4_coverage): the (q/a, b/a) grid itself, every point marked by what holds there: the
# covering (b) found, and the paper's construction (a) going through. The thresholds of this panel
# are grid values (not bisected): b0 is the last grid point of an unbroken column, drawn as steps;
# beside them the band where certified_region proves the covering for every parameter of its boxes,
# and, per column of q/a (thm1_uniform_band), the whole range of b/a below the bound up to which the
# covering is proved for every b/a at once (light fill from the panel's floor, the bound a black step).
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,7cm
set output "fig_thresholds.tex"
set multiplot
set bmargin at screen 0.16; set tmargin at screen 0.9
s0 = sin_vartheta0   # Eq. (1), from eq1_vartheta0 (style.gp)
set xlabel '$q/a$'
# y labels placed by hand (label 90, per panel): gnuplot misjudges the width of TeX tick labels
unset ylabel
set logscale y
set format y '$10^{%T}$'
set format x '$%.2f$'

# ---- Lemma 1
set lmargin at screen 0.105; set rmargin at screen 0.42
set label 90 '$b_0/a$' at screen 0.02, graph 0.5 rotate center
set title 'Lemma 1'
set xrange [0.6:1]; set xtics 0.1
set yrange [1e-4:1]
set object 1 rect from graph 0, graph 0 to first s0, graph 1 fc rgb "#d9d9d9" fs solid 0.5 noborder back
set label 1 '\footnotesize (2) fails' at first (0.6+s0)/2, graph 0.5 center front
set label 2 '$\sin\vartheta_0$' at first s0, graph 0.92 left offset 0.4,0
# the key right of q/a = 0.78, clear of the curves' steep fall towards sin(theta0)
set key at graph 0.985, graph 0.03 right bottom samplen 1.5 spacing 1.05 box opaque width -3
f1 = data."/lemma1_progression_stop.tsv"
fb = data."/certified_claims-b0.tsv"
plot f1 using "q_over_a":(column("b0_lemma1") > 0 ? column("b0_lemma1") : NaN) w l lw 2 lc rgb c_free title '\footnotesize computed $b_0$', \
     f1 using "q_over_a":(column("b0_proof_bound") > 0 ? column("b0_proof_bound") : NaN) w l lw 2 dt 2 lc rgb c_prog title "\\footnotesize bound (9)", \
     [s0:1] (x - s0)/2 w l lw 0.8 dt 3 lc rgb "black" title '\footnotesize $(q-\sin\vartheta_0)/2$', \
     fb using "q_over_a":(column("proved") == 1 ? column("b0_lower_bound") : NaN) w p pt 4 ps 0.8 lw 1.5 lc rgb "black" title '\footnotesize certified'
unset object 1; unset label 1; unset label 2

# ---- Lemma 4, on its grid
set lmargin at screen 0.565; set rmargin at screen 0.79
set label 90 '$b_0/a$' at screen 0.475, graph 0.5 rotate center
set title 'Lemma 4 on the grid'
f4 = data."/lemma4_coverage.tsv"
g4 = data."/lemma4_coverage-grid.tsv"
# Lemma 4 proved for every parameter of boxes (certified_region): per column of q/a, from the band's
# lower edge up to the b/a its boxes reached
fc = data."/certified_region-columns.tsv"
set autoscale xy
stats data."/certified_region.tsv" using "b_lo" name "RB" nooutput
stats g4 using "b_over_a" name "B" nooutput
stats f4 using "q_over_a" name "NQ" nooutput
dq = (NQ_max - NQ_min) / (NQ_records - 1)
set xrange [NQ_min - dq/2 : NQ_max + dq/2]
set xtics 0.1
set mxtics 2
set yrange [B_min/2 : B_max*2]
# key outside the panel, on its right; the threshold of each q/a column is drawn over the width of its cell.
# The band of proved boxes is a few pixels high on this axis: one triangle per column at its height,
# so that in greyscale it is not taken for the solid black step of the column bounds.
set key at screen 0.805, graph 1 left top reverse Left samplen 1.5 spacing 1.2 nobox
fu = data."/thm1_uniform_band.tsv"
ylo = B_min/2
plot fu using (0.5*(column("q_lo") + column("q_hi"))):(column("proved") == 1 ? sqrt(ylo*column("b_over_a_max")) : NaN):"q_lo":"q_hi":(ylo):"b_over_a_max" \
        w boxxyerror fs transparent solid 0.3 noborder lc rgb c_sky title 'proved for all smaller $b/a$', \
     fu using "q_lo":(column("proved") == 1 ? column("b_over_a_max") : NaN):(column("q_hi") - column("q_lo")):(0) \
        w vectors nohead lw 2.5 lc rgb oi_black title 'its bound per column', \
     g4 using "q_over_a":(column("covering_holds") == 0 && column("literal_all") == 0 ? column("b_over_a") : NaN) w p pt 6 ps 0.45 lc rgb c_grey title 'neither', \
     g4 using "q_over_a":(column("covering_holds") == 1 && column("literal_all") == 0 ? column("b_over_a") : NaN) w p pt 7 ps 0.45 lc rgb c_free title 'covering (b) only', \
     g4 using "q_over_a":(column("literal_all") == 1 ? column("b_over_a") : NaN) w p pt 5 ps 0.5 lc rgb c_prog title "(a) and (b)", \
     f4 using "q_over_a":(column("b0_covering") > 0 ? column("b0_covering") : NaN):(column("q_over_a")-dq/2):(column("q_over_a")+dq/2) \
        w xerrorbars pt -1 lw 2 lc rgb c_free title '$b_0$ of (b)', \
     f4 using "q_over_a":(column("b0_literal") > 0 ? column("b0_literal") : NaN):(column("q_over_a")-dq/2):(column("q_over_a")+dq/2) \
        w xerrorbars pt -1 lw 2 dt 2 lc rgb c_prog title '$b_0$ of (a)', \
     fc using (0.5*(column("q_lo") + column("q_hi"))):(column("b_reached") > RB_min ? sqrt(RB_min*column("b_reached")) : NaN) \
        w p pt 9 ps 0.75 lc rgb c_stop title 'proved boxes'
unset multiplot
