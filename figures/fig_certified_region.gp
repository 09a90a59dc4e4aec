# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: where Theorem 1's covering is *proved* for every parameter of a box
# (certified_region: green boxes proved, red boxes not proved), over the plane sampled in floating
# point by thm1_parameter_plane (left: the whole plane, the certified band drawn on it; right: the
# band enlarged, b/a linear).
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,7cm
set output "fig_certified_region.tex"
fp = data."/thm1_parameter_plane.tsv"
fr = data."/certified_region.tsv"
set multiplot layout 1,2
set xlabel '$q/a$'; set ylabel '$\log_{10}(b/a)$'
set format x '$%.2f$'; set format y '$%g$'
set palette maxcolors 4
set palette defined (0 "#f0f0f0", 1 "#c6dbef", 2 "#fdd0a2", 3 "#fcbba1")
set cbrange [-0.5:3.5]
unset colorbox
set yrange [-4.05:-0.95]
set xrange [0.72:1.0]
set style fill solid 1.0 border
color(p) = p == 1 ? 0x2ca02c : 0xd62728
plot fp using "q_over_a":(log10(column("b_over_a"))):"class" with image, \
     fr using ((column("q_lo")+column("q_hi"))/2):(log10((column("b_lo")+column("b_hi"))/2)):"q_lo":"q_hi":(log10(column("b_lo"))):(log10(column("b_hi")+1e-3*(column("b_hi")-column("b_lo"))+2e-5*column("b_hi"))):(color(column("proved"))) \
        with boxxyerror lc rgb variable
set ylabel '$b/a$'
set format y '$%.4g$'
set autoscale y
set xrange [*:*]
plot fr using ((column("q_lo")+column("q_hi"))/2):((column("b_lo")+column("b_hi"))/2):"q_lo":"q_hi":"b_lo":"b_hi":(color(column("proved"))) \
        with boxxyerror lc rgb variable
unset multiplot
