# SPDX-License-Identifier: GPL-3.0-or-later
# Figure: the mechanical system (our drawing of the paper's Fig. 1): a unit mass driven by
# F(t) = a sin t + 2b, and a delimiter at y that resists with dry friction of at most q and
# never moves back. Pure geometry: reads no data.
load figdir."/style.gp"
set terminal cairolatex pdf input size 11cm,4.2cm
set output "fig_system.tex"
unset border; unset tics; unset grid
set xrange [0:11]; set yrange [0:4.2]
set size ratio -1
# ground and the walls of the bore
set object 1 rect from 0.3,0.6 to 10.7,0.75 fc rgb "#bbbbbb" fs solid noborder
set object 2 rect from 0.3,3.45 to 10.7,3.6 fc rgb "#bbbbbb" fs solid noborder
# the mass
set object 3 rect from 2.2,1.3 to 3.8,2.9 fc rgb c_sky fs solid border lc rgb "black" lw 1.5
set label 1 '$m=1$' at 3.0,2.1 center
# the delimiter, squeezed by the walls (friction pads)
set object 4 rect from 6.2,0.75 to 7.0,3.45 fc rgb c_alt fs solid border lc rgb "black" lw 1.5
do for [k=0:5] { set arrow from 6.2+0.13*k,3.45 to 6.33+0.13*k,3.3 nohead lw 0.8 }
do for [k=0:5] { set arrow from 6.2+0.13*k,0.75 to 6.33+0.13*k,0.9 nohead lw 0.8 }
set label 2 'delimiter' at 6.6,3.9 center
set label 3 '$F(t)=a\sin t+2b$' at 1.1,3.2 center front
set arrow 10 from 0.4,2.1 to 2.2,2.1 lw 2 filled
# gap and positions
set arrow 11 from 3.8,1.0 to 6.2,1.0 heads size 0.15,25 lw 1
set label 4 '$y-x\ge0$' at 5.0,1.35 center
set arrow 12 from 3.0,0.3 to 3.0,1.3 nohead dt 2
set arrow 13 from 6.2,0.3 to 6.2,0.75 nohead dt 2
set label 5 '$x$' at 3.0,0.15 center
set label 6 '$y$' at 6.2,0.15 center
set label 7 '$\dot y\ge0$, friction force $\le q$' at 7.3,2.3 left
set arrow 14 from 7.2,1.8 to 8.4,1.8 lw 1.5 filled
plot NaN
