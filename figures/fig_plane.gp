# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: the (q/a, b/a) parameter plane of thm1_parameter_plane: covering of Lemma 4 found
# (Theorem 1's chaos certificate), t2 superstable (Theorem 2), both, neither, or a cell whose
# computation failed. Categories, so a discrete colour per class and a key with the number of
# cells of each (a class with no cell is listed with 0), not a colour bar.
load figdir."/style.gp"
set terminal cairolatex pdf input size 14cm,7.6cm
set output "fig_plane.tex"
f = data."/thm1_parameter_plane.tsv"
# class: 0 neither, 1 covering, 2 superstable, 3 both, -1 error (header of the table)
# Colours (Okabe-Ito hues, style.gp) that differ in lightness too, under both usual greyscale
# conversions (luminance 0.299R+0.587G+0.114B, and the mean of R, G, B): neither very light (232),
# covering sky blue (158; mean 166), t2 superstable only vermilion (119; 102), both a dark shade of
# the Okabe-Ito blue (50; 58), failed black.
col0 = 0xe8e8e8; col1 = 0x56B4E9; col2 = 0xD55E00; col3 = 0x003F6F; colE = 0x000000
rgbof(c) = (c == 0 ? col0 : (c == 1 ? col1 : (c == 2 ? col2 : (c == 3 ? col3 : colE))))
red(c) = int(rgbof(c)) >> 16 & 255; green(c) = int(rgbof(c)) >> 8 & 255; blue(c) = int(rgbof(c)) & 255
do for [c=-1:3] {
  stats f using (column("class") == c ? 1 : 0) name "K" nooutput
  eval sprintf("n%d = %d", c + 1, int(K_sum))
}
stats f using "q_over_a" name "Q" nooutput
stats f using (log10(column("b_over_a"))) name "B" nooutput
# cell sizes: a product grid, so the cells at the smallest q/a count the b/a values
stats f using (abs(column("q_over_a") - Q_min) <= 1e-12*abs(Q_min) ? 1 : 0) name "NBQ" nooutput
nb = int(NBQ_sum); nq = int(Q_records / nb + 0.5)
dq = (Q_max - Q_min) / (nq > 1 ? nq - 1 : 1); db = (B_max - B_min) / (nb > 1 ? nb - 1 : 1)
set lmargin at screen 0.11; set rmargin at screen 0.66; set bmargin at screen 0.15; set tmargin at screen 0.97
set xrange [Q_min - dq/2 : Q_max + dq/2]; set yrange [B_min - db/2 : B_max + db/2]
eval plane_axes
set grid front lc rgb "#ffffff" lw 0.5
set key at screen 0.68, screen 0.93 left top reverse Left samplen 1 spacing 1.4 nobox
set style fill solid 1.0 border lc rgb "#404040"
# the superstable classes (and failed cells) lie on lines one cell high: drawn `big` cells high
# over the image so that they can be seen (the key counts the cells themselves)
big = 3
plot f using "q_over_a":(log10(column("b_over_a"))):(red(column("class"))):(green(column("class"))):(blue(column("class"))) with rgbimage pixels notitle, \
     f using "q_over_a":(column("class") == 2 || column("class") == 3 ? log10(column("b_over_a")) : NaN):(dq/2):(big*db/2):(rgbof(column("class"))) \
       w boxxyerror fs solid 1.0 noborder lc rgb variable notitle, \
     f using "q_over_a":(column("class") == -1 ? log10(column("b_over_a")) : NaN):(big*dq/2):(big*db/2) w boxxyerror fs solid 1.0 noborder lc rgb "black" notitle, \
     NaN w boxes lc rgb sprintf("#%06x", col1) title sprintf('covering only (%d)', n2), \
     NaN w boxes lc rgb sprintf("#%06x", col2) title sprintf('$t_2$ superstable only (%d)', n3), \
     NaN w boxes lc rgb sprintf("#%06x", col3) title sprintf('both (%d)', n4), \
     NaN w boxes lc rgb sprintf("#%06x", col0) title sprintf('neither (%d)', n1), \
     NaN w boxes lc rgb sprintf("#%06x", colE) title sprintf('computation failed (%d)', n0)
