# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: where Theorem 1's covering is *proved* for every parameter of a box (certified_region),
# over the plane sampled in floating point by thm1_parameter_plane. Left: the whole plane (classes
# in the colours of fig_plane), the certified band outlined on it. Right: the band enlarged, b/a
# linear: boxes proved (bluish green), boxes not proved (vermilion, each marked by a cross so that
# even the thinnest is seen), and, per column of q/a, the part of the band above the b/a that the
# box budget reached (certified_region-columns.tsv, b_reached): not reached, hatched grey; and,
# hatched dark blue, what the columns of thm1_uniform_band prove for every b/a below their bound.
# One key under both panels, with the counts read from the data. Axes: the plane convention
# (plane_axes, style.gp) on the left; b/a linear on the right.
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,8.6cm
set output "fig_certified_region.tex"
fp = data."/thm1_parameter_plane.tsv"
fr = data."/certified_region.tsv"
fc = data."/certified_region-columns.tsv"
fu = data."/thm1_uniform_band.tsv"   # columns of q/a proved for every b/a below a bound (Section 7)
c_columns = "#003F6F"
c_ok = oi_green; c_bad = oi_verm; c_unreached = "#bdbdbd"
# counts and extents (stats obeys ranges: before any is set)
stats fr using (column("proved") == 1 ? 1 : 0) name "NP" nooutput
stats fr using (column("proved") == 1 ? 0 : 1) name "NF" nooutput
stats fr using "b_lo" name "BL" nooutput
stats fr using "b_hi" name "BH" nooutput
stats fr using "q_lo" name "QL" nooutput
stats fr using "q_hi" name "QH" nooutput
stats fc using (column("b_reached") < BH_max ? 1 : 0) name "NU" nooutput
stats fp using "q_over_a" name "Q" nooutput
stats fp using (log10(column("b_over_a"))) name "B" nooutput
stats fp using (abs(column("q_over_a") - Q_min) <= 1e-12*abs(Q_min) ? 1 : 0) name "NBQ" nooutput
nb = int(NBQ_sum); nq = int(Q_records / nb + 0.5)
dq = (Q_max - Q_min) / (nq > 1 ? nq - 1 : 1); db = (B_max - B_min) / (nb > 1 ? nb - 1 : 1)
# the classes of fig_plane: 0 neither, 1 covering, 2 superstable, 3 both, -1 failed
rgbof(c) = (c == 0 ? 0xe8e8e8 : (c == 1 ? 0x56B4E9 : (c == 2 ? 0xD55E00 : (c == 3 ? 0x003F6F : 0x000000))))  # as fig_plane.gp
red(c) = int(rgbof(c)) >> 16 & 255; green(c) = int(rgbof(c)) >> 8 & 255; blue(c) = int(rgbof(c)) & 255

set multiplot
set grid noxtics noytics
# ---- left: the whole plane
set lmargin at screen 0.1; set rmargin at screen 0.46; set bmargin at screen 0.34; set tmargin at screen 0.97
set xrange [Q_min - dq/2 : Q_max + dq/2]; set yrange [B_min - db/2 : B_max + db/2]
eval plane_axes
set xlabel offset 0,0.6
set xtics 0.1 format '$%.1f$'
set object 1 rect from QL_min, log10(BL_min) to QH_max, log10(BH_max) fs empty border lc rgb "black" lw 1.2 front
set label 1 '\footnotesize the band' at QL_min, log10(BH_max) left offset 0,0.6 front
plot fp using "q_over_a":(log10(column("b_over_a"))):(red(column("class"))):(green(column("class"))):(blue(column("class"))) with rgbimage pixels notitle
unset object 1; unset label 1
# ---- right: the band, b/a linear; over it, hatched and outlined, the part of each column of q/a below
# the bound for which that column is proved for every smaller b/a at once (thm1_uniform_band)
qclip(x) = (x < QL_min ? QL_min : (x > QH_max ? QH_max : x))
min(x, y) = (x < y ? x : y)
set lmargin at screen 0.65; set rmargin at screen 0.97
set xrange [QL_min - 0.005 : QH_max + 0.005]; set yrange [BL_min : BH_max]
set xtics 0.05 format '$%.2f$'; set mxtics 5
set ytics auto format '$%.5f$'; set mytics 2
set ylabel '$b/a$' offset 0.5,0
plot fc using (0.5*(column("q_lo") + column("q_hi"))):(column("b_reached") < BH_max ? 0.5*(column("b_reached") + BH_max) : NaN):"q_lo":"q_hi":"b_reached":(BH_max) \
        w boxxyerror fc rgb c_unreached fs pattern 4 border lc rgb c_unreached notitle, \
     fr using (0.5*(column("q_lo") + column("q_hi"))):(column("proved") == 1 ? 0.5*(column("b_lo") + column("b_hi")) : NaN):"q_lo":"q_hi":"b_lo":"b_hi" \
        w boxxyerror fs solid 1.0 noborder fc rgb c_ok notitle, \
     fr using (0.5*(column("q_lo") + column("q_hi"))):(column("proved") != 1 ? 0.5*(column("b_lo") + column("b_hi")) : NaN):"q_lo":"q_hi":"b_lo":"b_hi" \
        w boxxyerror fs solid 1.0 noborder fc rgb c_bad notitle, \
     fr using (0.5*(column("q_lo") + column("q_hi"))):(column("proved") != 1 ? 0.5*(column("b_lo") + column("b_hi")) : NaN) \
        w p pt 2 ps 0.5 lw 1 lc rgb "black" notitle, \
     fu using (0.5*(column("q_lo") + column("q_hi"))):(column("proved") == 1 && column("b_over_a_max") > BL_min ? BL_min : NaN) \
          :(qclip(column("q_lo"))):(qclip(column("q_hi"))):(BL_min):(min(column("b_over_a_max"), BH_max)) \
        w boxxyerror fs transparent pattern 5 border lc rgb c_columns lw 1.2 fc rgb c_columns notitle

# ---- the key, drawn by hand under the panels
unset border; unset tics; unset xlabel; unset ylabel; unset grid
set lmargin at screen 0; set rmargin at screen 1; set bmargin at screen 0; set tmargin at screen 1
set xrange [0:1]; set yrange [0:1]
k1 = 0.165; k2 = 0.1; k3 = 0.035
key_box(n, x, y, colour) = sprintf("set object %d rect center screen %g, screen %g size screen 0.016, screen 0.03 fc rgb '%s' fs solid border lc rgb '#808080' front", n, x, y, colour)
eval key_box(11, 0.03, k1, "#56B4E9")
set label 11 '\small covering only (sampled)' at screen 0.045, screen k1 left front
eval key_box(12, 0.03, k2, "#003F6F")
set label 12 '\small covering and $t_2$ superstable' at screen 0.045, screen k2 left front
eval key_box(13, 0.36, k1, "#D55E00")
set label 13 '\small $t_2$ superstable only' at screen 0.375, screen k1 left front
eval key_box(14, 0.36, k2, "#e8e8e8")
set label 14 '\small neither' at screen 0.375, screen k2 left front
eval key_box(15, 0.65, k1, c_ok)
set label 15 sprintf('\small box proved: %d', int(NP_sum)) at screen 0.665, screen k1 left front
eval key_box(16, 0.65, k2, c_bad)
set label 26 '' at screen 0.65, screen k2 front point pt 2 ps 0.5 lw 1 lc rgb "black"
set label 16 sprintf('\small box not proved: %d', int(NF_sum)) at screen 0.665, screen k2 left front
set object 17 rect center screen 0.65, screen k3 size screen 0.016, screen 0.03 fc rgb c_unreached fs pattern 4 border lc rgb c_unreached front
set label 17 sprintf('\small not reached by the boxes (%d columns)', int(NU_sum)) at screen 0.665, screen k3 left front
set object 18 rect center screen 0.03, screen k3 size screen 0.016, screen 0.03 fc rgb c_columns fs pattern 5 border lc rgb c_columns front
set label 18 '\small proved for every smaller $b/a$ in its column of $q/a$ (Section 7)' at screen 0.045, screen k3 left front
plot NaN notitle
unset multiplot
