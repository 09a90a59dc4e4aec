# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: time histories x(t) (mass) and y(t) (delimiter) of one simulated motion per scenario
# of Section 3, from rest at the delimiter at the phase theta; from sec3_scenarios (full
# event-driven simulator, sampled on a regular grid of 3000 steps per history).
#  - x drawn by regime (style.gp: free flight thin, progression thick, stop dotted), y dashed;
#  - a regime bar under the data of each panel: the regime at every sample;
#  - open circles at the switching instants, at the first sample of each new regime (within one
#    sample step of the event);
#  - the chain of regimes read off the data (f = free, p = progression, s = stop) in each panel;
#  - an inset magnifying the shortest contact phase: the contact of A (1 to 2 time units after a
#    flight of about 100), the stop that ends the progression of B, and the stop between the two
#    progressions of C and D (a few thousandths of a time unit); the inset's white ground covers its
#    tick labels too, so that they do not sit on the curves of the panel.
load figdir."/style.gp"
set terminal cairolatex pdf input size 15cm,13.5cm
set output "fig_scenarios.tex"
code(r) = (r == 0 ? "f" : (r == 1 ? "p" : "s"))
names = "A B C D Cprime Dprime"
# switch(r): 1 at the first sample of a new regime (not at the first sample of the file)
switch(r) = (column(0) == 0 ? (prev = r, 0) : (r != prev ? (prev = r, 1) : 0))
set multiplot
set grid noxtics noytics
set format x "$%g$"; set format y "$%g$"
pw = 0.39; ph = 0.215
px0(k) = ((k-1)%2 == 0 ? 0.1 : 0.6)
py0(k) = 0.685 - ((k-1)/2)*0.31
do for [k=1:6] {
  s = word(names, k)
  f = data."/sec3_scenarios-example-".s.".tsv"
  nm = (s eq "Cprime" ? "C$'$" : (s eq "Dprime" ? "D$'$" : s))
  # --- what the data say (before any range is set: stats obeys ranges)
  set autoscale xy
  stats f using "t_minus_start" name "TT" nooutput
  stats f using "x" name "XX" nooutput
  stats f using "y" name "YY" nooutput
  # the chain of regimes; the contact episode (first to last sample not in free flight after the
  # start); the shortest stop (its first and last sample)
  prev = -1; chain = ""; c_lo = NaN; c_hi = NaN; run_start = 0; run_r = -1; s_lo = NaN; s_hi = NaN; s_len = 1e300; last_t = 0
  stats f using (t = column("t_minus_start"), r = column("regime"), \
                 (r != 0 ? (c_lo = (c_lo == c_lo ? c_lo : t), c_hi = t) : 0), \
                 (r != run_r ? ((run_r == 2 && last_t - run_start < s_len && run_start > 0) ? (s_len = last_t - run_start, s_lo = run_start, s_hi = last_t) : 0, \
                               chain = chain.(strlen(chain) ? "\\,$\\to$\\," : "").code(r), run_r = r, run_start = t) : 0), \
                 last_t = t, 0) nooutput
  # the window of the inset: A, B the contact; C, D the shortest stop; none for C', D'
  inset = (s eq "A" || s eq "B" || s eq "C" || s eq "D")
  if (s eq "A") { w_lo = c_lo - 0.3*(c_hi - c_lo); w_hi = c_hi + 0.3*(c_hi - c_lo) }
  # B: its stop (from the end of the progression in [t1, t2) to the next t2) is shorter than one
  # sampling step, so the inset shows the last samples of the progression, the one stopped sample
  # and, dotted, the instant t2 = pi + asin(2b/a) at which the stop ends (phase theta and b/a from
  # the file's header).
  if (s eq "B") {
    hdr = system("sed -n 's/^# scenario B: a=\\([^ ]*\\) b=\\([^ ]*\\) q=[^ ]* theta=\\(.*\\)$/\\1 \\2 \\3/p' '".f."'")
    B_t2 = pi + asin(2*real(word(hdr, 2))/real(word(hdr, 1))); B_theta = real(word(hdr, 3))
    B_end = s_lo + (B_t2 - (B_theta + s_lo)) - 2*pi*floor((B_t2 - (B_theta + s_lo))/(2*pi))
    w_lo = s_lo - 10*(B_end - s_lo); w_hi = B_end + 6*(B_end - s_lo)
  }
  if (s eq "C" || s eq "D") { w_lo = s_lo - 4*(s_hi - s_lo) - 0.002; w_hi = s_hi + 4*(s_hi - s_lo) + 0.002 }
  if (inset) {
    stats f using (column("t_minus_start") >= w_lo && column("t_minus_start") <= w_hi ? column("x") : NaN) name "WX" nooutput
    stats f using (column("t_minus_start") >= w_lo && column("t_minus_start") <= w_hi ? column("y") : NaN) name "WY" nooutput
  }
  lo = (XX_min < YY_min ? XX_min : YY_min); hi = (XX_max > YY_max ? XX_max : YY_max); span = hi - lo
  bar = lo - 0.09*span

  # --- the panel
  set lmargin at screen px0(k); set rmargin at screen px0(k) + pw
  set bmargin at screen py0(k); set tmargin at screen py0(k) + ph
  set xrange [0:TT_max]
  set yrange [lo - 0.14*span : hi + 0.2*span]
  set xlabel '$t-\theta$' offset 0,0.5
  # y label placed by hand (gnuplot overestimates the width of TeX tick labels and drops it)
  unset ylabel
  set label 3 '$x$, $y$' at screen px0(k) - 0.08, graph 0.5 rotate center front
  set xtics auto; set ytics auto
  set label 1 sprintf('\small scenario %s: %s', nm, chain) at graph 0.02, graph 0.93 left front
  if (inset) { set object 1 rect from w_lo, WX_min to w_hi, WX_max fs empty border lc rgb "black" lw 0.6 front }
  plot f using "t_minus_start":"y" w l lw 1 dt 2 lc rgb "black" notitle, \
       for [r=0:2] f using "t_minus_start":(reg(r, column("x"))) w l lt 11+r notitle, \
       for [r=0:2] f using "t_minus_start":(reg(r, bar)) w l lt 11+r lw (r == 0 ? 1.5 : 5) notitle, \
       f using (switch(column("regime")) ? column("t_minus_start") : NaN):"x" w p pt 6 ps 0.55 lw 1 lc rgb "black" notitle
  unset label 1; unset label 3; unset object 1

  # --- the inset, in the part of the panel the motion leaves empty
  if (inset) {
    ix = (s eq "D" ? 0.04 : 0.28); iy = (s eq "C" ? 0.17 : (s eq "D" ? 0.45 : 0.42))
    set lmargin at screen px0(k) + (ix + 0.04)*pw; set rmargin at screen px0(k) + (ix + 0.44)*pw
    set bmargin at screen py0(k) + iy*ph; set tmargin at screen py0(k) + (iy + 0.38)*ph
    unset xlabel; unset ylabel
    set xrange [w_lo:w_hi]
    wspan = WX_max - WX_min; wspan = (wspan > 0 ? wspan : 1e-9)
    set yrange [WX_min - 0.35*wspan : WX_max + 0.6*wspan]
    # the window's two marked instants written inside the inset, above the motion (tick labels
    # below it would sit on the curves of the panel)
    i_a = w_lo + 0.1*(w_hi - w_lo); i_b = w_hi - 0.1*(w_hi - w_lo)
    set xtics (i_a, i_b) format "" scale 0.4
    set label 6 sprintf('\scriptsize $%.4g$, $%.4g$', i_a, i_b) at graph 0.5, graph 0.88 center front
    unset ytics
    set object 2 rect from graph 0, graph 0 to graph 1, graph 1 fc rgb "white" fs solid 1.0 noborder behind
    ibar = WX_min - 0.22*wspan
    if (s eq "B") {
      set arrow 5 from B_end, graph 0 to B_end, graph 1 nohead dt 3 lw 1 lc rgb c_stop front
      set label 5 '\scriptsize $t_2$' at B_end, graph 0.42 left offset 0.3,0 front
    }
    plot f using "t_minus_start":"y" w l lw 1 dt 2 lc rgb "black" notitle, \
         for [r=0:2] f using "t_minus_start":(reg(r, column("x"))) w l lt 11+r notitle, \
         for [r=0:2] f using "t_minus_start":(reg(r, ibar)) w l lt 11+r lw (r == 0 ? 1.5 : 5) notitle, \
         f using (switch(column("regime")) ? column("t_minus_start") : NaN):"x" w p pt 6 ps 0.55 lw 1 lc rgb "black" notitle
    unset object 2; unset arrow 5; unset label 5; unset label 6
    set tics scale 0.6; set xtics format '$%g$'
  }
}
# one key for the figure, drawn by hand in a strip above the panels
unset border; unset tics; unset xlabel; unset ylabel
set lmargin at screen 0; set rmargin at screen 1; set bmargin at screen 0; set tmargin at screen 1
set xrange [0:1]; set yrange [0:1]
ky = 0.975
do for [r=0:2] {
  kx = (r == 0 ? 0.01 : (r == 1 ? 0.25 : 0.47))
  set arrow 10+r from screen kx, screen ky to screen kx + 0.035, screen ky nohead lt 11+r
  set label (10+r) (r == 0 ? '\small $x$: free flight (f)' : (r == 1 ? '\small progression (p)' : '\small stop (s)')) at screen kx + 0.045, screen ky left front
}
set arrow 20 from screen 0.62, screen ky to screen 0.655, screen ky nohead dt 2 lc rgb "black"
set label 20 '\small delimiter $y$' at screen 0.665, screen ky left front
set object 21 circle at screen 0.81, screen ky size screen 0.005 fs empty border lc rgb "black" front
set label 21 '\small switch of regime' at screen 0.825, screen ky left front
plot NaN notitle
unset multiplot
