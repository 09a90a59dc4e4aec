# Figure: the (q/a, b/a) parameter plane of thm1_parameter_plane: covering of Lemma 4 found
# (Theorem 1's chaos certificate), t2 superstable (Theorem 2), both, neither.
load figdir."/style.gp"
set terminal cairolatex pdf input size 12cm,8cm
set output "fig_plane.tex"
set xlabel '$q/a$'; set ylabel '$\log_{10}(b/a)$'
set format x '$%.2f$'; set format y '$%g$'
set palette maxcolors 4
set palette defined (0 "#f0f0f0", 1 "#6baed6", 2 "#fd8d3c", 3 "#d62728")
set cbrange [-0.5:3.5]
set cbtics ("neither" 0, "covering" 1, "superstable" 2, "both" 3)
set grid front
set yrange [-4.05:-0.95]
set xrange [0.72:1.0]
f = data."/thm1_parameter_plane.tsv"
plot f using "q_over_a":(log10(column("b_over_a"))):"class" with image
