# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: the return map T of Lemma 3 on [t2, t3), each point coloured by its scenario; from
# lemma3_return_map (colour and marker per scenario), at two of its parameter sets (the left one where Lemma 1
# holds, the right one where it fails, the first of each in the order of the file names). Each panel reads b and q from its data file's description line and
# whether Lemma 1 holds from the experiment's summary table (column lemma1_holds): nothing is typed here.
# Grey: theta2, where the first progression ends (Eq. 17), wherever it is not T itself, unwrapped
# into [t1, t0 + 2 pi): in [t1, t2) the mass stops until t2 (B), in [t3, t0 + 2 pi) it stops
# until t0 and progresses again (C, D). The phases t0..t3 (closed form, docs/architecture.md) are marked on
# the T axis; T = theta (dashed) and theta = 3 pi / 2 (dotted) are drawn. Each panel's key lists
# only the scenarios present in its data.
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,7.6cm
set output "fig_T.tex"
set multiplot
set bmargin at screen 0.14; set tmargin at screen 0.83
set xlabel '$\theta$' offset 0,0
set ylabel '$T(\theta)$' offset 1.5,0
set grid noxtics noytics
sc_col(s) = (s eq "A" ? c_free : (s eq "B" ? c_stop : (s eq "C" ? c_alt : (s eq "D" ? c_prog : c_grey))))
# and a marker per scenario, so that the key reads in greyscale too (circle for theta2): the points
# are dots in the scenario's colour, and points spread along each scenario's pieces carry its marker
# (function marked below), large enough to tell the shapes apart where the dots overlap
sc_pt(s) = (s eq "A" ? 5 : (s eq "B" ? 9 : (s eq "C" ? 13 : 11)))
summary = data."/lemma3_return_map.tsv"
# The panels: of the graphs the experiment wrote (in the order of their names), the first at which
# Lemma 1 holds and the first at which it fails; a = 1 in this experiment, b and q from each graph's
# line '# T on [t2, t3) at a=1 b=B q=Q'.
lemma1(file) = (b = real(header_b(file)), q = real(header_q(file)), 0)
all = system("ls '".data."'/lemma3_return_map-graph-*.tsv")
pick = ""
do for [want in "1 0"] {
  do for [g in all] {
    dummy = lemma1(g)
    set autoscale xy  # stats keeps to the ranges of the previous panel otherwise
    stats summary using ((abs(column("b_over_a") - b) < 1e-12 && abs(column("q_over_a") - q) < 1e-12) ? column("lemma1_holds") : NaN) \
          name "L1" nooutput
    if (L1_records != 1) { print "fig_T: no single row of ".summary." at b = ".sprintf("%g", b).", q = ".sprintf("%g", q); exit status 1 }
    if (words(pick) < (want eq "1" ? 1 : 2) && L1_max == real(want)) { pick = pick." ".g }
  }
}
if (words(pick) != 2) { print "fig_T: need one graph where Lemma 1 holds and one where it fails"; exit status 1 }
do for [k=1:2] {
  file = word(pick, k)
  dummy = lemma1(file)
  verdict = (k == 1 ? "holds" : "fails")
  t0 = asin(q - 2*b); t1 = pi - t0; t2 = pi + asin(2*b); t3 = 2*pi - asin(2*b)
  # which scenarios are present (keys list only those)
  set autoscale xy
  present = ""
  do for [s in "A B C D"] {
    stats file using (strcol("scenario") eq s ? 1 : 0) name "N" nooutput
    if (N_sum > 0) { present = present." ".s }
  }
  set lmargin at screen (k == 1 ? 0.085 : 0.595); set rmargin at screen (k == 1 ? 0.475 : 0.985)
  set title sprintf('\small (%s) $b/a=%g$, $q/a=%g$: Lemma~1 %s', (k == 1 ? "a" : "b"), b, q, verdict) offset 0,1.5
  set xrange [t2:t3]
  set yrange [t1-0.12:t0+2*pi+0.12]
  set xtics ('$t_2$' t2, '$\frac{5\pi}{4}$' 1.25*pi, '$\frac{3\pi}{2}$' 1.5*pi, '$\frac{7\pi}{4}$' 1.75*pi, '$t_3$' t3)
  set ytics ('$t_1$' t1, '$t_2$' t2, '$\frac{3\pi}{2}$' 1.5*pi, '$t_3$' t3, '$t_0{+}2\pi$' t0+2*pi)
  # arcs of the phase circle where a progression may end: bands across the panel
  set object 1 rect from graph 0, first t1 to graph 1, first t2 fc rgb c_stop fs transparent solid 0.12 noborder back
  set object 2 rect from graph 0, first t3 to graph 1, first t0+2*pi fc rgb c_alt fs transparent solid 0.12 noborder back
  set label 1 '\footnotesize stop until $t_2$' at graph 0.02, first (t1+t2)/2 left front
  set label 2 '\footnotesize stop until $t_0$, then progression' at graph 0.02, first (t3+t0+2*pi)/2 left front
  set arrow 1 from 1.5*pi, graph 0 to 1.5*pi, graph 1 nohead dt 3 lc rgb c_grey
  do for [y in "1 2 3 4"] { set arrow 1+y from graph 0, first (y == 1 ? t1 : (y == 2 ? t2 : (y == 3 ? t3 : t0+2*pi))) \
        to graph 1, first (y == 1 ? t1 : (y == 2 ? t2 : (y == 3 ? t3 : t0+2*pi))) nohead lw 0.6 lc rgb "#bbbbbb" back }
  set key at graph 0.5, graph 1.0 center bottom horizontal reverse Left samplen 0.8 spacing 1 width -1.5 maxrows 1 noopaque nobox
  unwrap(p) = (p < t0 + 1e-12 ? p + 2*pi : p)
  # the marked points: the first of the scenario at least a gap after the last marked one, a gap of
  # a twelfth of [t2, t3) for A, a fortieth for the short pieces of B, C and D
  marked(th, s) = (th >= next_mark ? (next_mark = th + (t3 - t2) / (s eq "A" ? 12 : 40), 1) : 0)
  plot file using "theta":(strcol("scenario") ne "A" && abs(column("theta2_phase") - column("T")) > 1e-12 ? unwrap(column("theta2_phase")) : NaN) \
            w p pt 7 ps 0.15 lc rgb "#909090" notitle, \
       NaN w p pt 6 ps 1.0 lw 1.5 lc rgb "#909090" title '$\theta_2$', \
       for [s in present] file using "theta":(strcol("scenario") eq s ? column("T") : NaN) w p pt 7 ps 0.15 lc rgb sc_col(s) notitle, \
       for [s in present] file using "theta":(column(0) == 0 ? next_mark = -1e9 : 0, \
                                              strcol("scenario") eq s && marked(column("theta"), s) ? column("T") : NaN) \
            w p pt sc_pt(s) ps (s eq "A" ? 0.6 : 0.8) lc rgb sc_col(s) notitle, \
       for [s in present] NaN w p pt sc_pt(s) ps 1.0 lc rgb sc_col(s) title s, \
       x w l dt 2 lw 1 lc rgb "black" title '$T=\theta$'
  unset ylabel
}
unset multiplot
