# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: Lemma 2 and Eq. (13), one quantity per panel, each with its own labelled axis.
# Left and middle (lemma2_monotonicity): the number N of discontinuities of T1 on L0 times b/a,
# beside the closed-form growth rate cos(pi/100)/(2 pi); the smallest jump T1(z-0) - T1(z) beside
# the lower bound 2 (sin(pi/100) - 2b/a) checked by lemma2.jumps_bounded_below. Right
# (sec4_next_hit): the constant C of Eq. (13), min over theta of (theta1 - theta) b / (a |cos theta|).
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,5.6cm
set output "fig_discontinuities.tex"
set multiplot
# three panels, each with room on its left for its own tick labels and y label
pw = 0.215; px(i) = 0.105 + i*0.33
set bmargin at screen 0.19; set tmargin at screen 0.88
set logscale x
set format x '$10^{%T}$'
set xlabel '$b/a$' offset 0,0.3
f = data."/lemma2_monotonicity.tsv"
g = data."/sec4_next_hit-asymptotics.tsv"
# x ranges a little wider than the data, not more
stats f using "b_over_a" name "F" nooutput
stats g using "b_over_a" name "G" nooutput
set xrange [F_min/1.4:F_max*1.4]
set xtics 10
rate = cos(pi/100)/(2*pi)

set lmargin at screen px(0); set rmargin at screen px(0)+pw
set title 'Lemma 2: number $N$ on $L_0$'
set ylabel '$N\,b/a$' offset 1,0
set format y '$%.3f$'
set yrange [0.145:0.162]
set ytics 0.005
set label 1 sprintf('$\frac{\cos(\pi/100)}{2\pi}$') at graph 0.96, first rate right offset 0,0.9 tc rgb c_grey
plot f using "b_over_a":"count_times_b_over_a" w lp pt 7 ps 0.55 lc rgb c_free, \
     rate w l dt 2 lw 1.2 lc rgb c_grey
unset label 1

set lmargin at screen px(1); set rmargin at screen px(1)+pw
set title 'Lemma 2: jumps on $L_0$'
set ylabel 'smallest jump' offset 1,0
set logscale y
set format y '$10^{%T}$'
set yrange [0.01:2]
set ytics auto
set label 2 '$2(\sin\frac{\pi}{100}-\frac{2b}{a})$' at graph 0.06, first 0.032 left tc rgb c_grey
plot f using "b_over_a":"min_jump" w lp pt 5 ps 0.55 lc rgb c_prog, \
     [F_min:F_max] 2*(sin(pi/100) - 2*x) w l dt 2 lw 1.2 lc rgb c_grey
unset label 2
unset logscale y

set lmargin at screen px(2); set rmargin at screen px(2)+pw
set title 'Eq.~(13)'
set xrange [G_min/2:G_max*2]
set xtics 100
set ylabel '$C_{\min}$' offset 1,0
set format y '$%.2f$'
set yrange [0.92:1.01]
set ytics 0.02
plot g using "b_over_a":"C_min" w lp pt 7 ps 0.55 lc rgb c_free, \
     1 w l dt 2 lw 1.2 lc rgb c_grey
unset multiplot
