# SPDX-License-Identifier: GPL-3.0-or-later
# Shared style of every dfchaos figure. Each figure script is run by `make figures` inside
# build/figures with two variables set on the command line:
#   data    the folder of the experiments' tables (build/data)
#   figdir  this folder (for `load`)
# It writes <name>.tex + <name>.pdf through the cairolatex terminal: the text of the figure is
# typeset by LaTeX, so its fonts are those of the report.
set encoding utf8
set datafile separator "\t"
set datafile commentschars "#"
set key noautotitle
set border lw 1.2
set tics nomirror out scale 0.6
set grid back lc rgb "#e0e0e0" lw 0.8
# Regime colours, used everywhere: free flight, progression, stop.
c_free = "#1f77b4"; c_prog = "#d62728"; c_stop = "#2ca02c"; c_alt = "#ff7f0e"; c_grey = "#7f7f7f"
set linetype 1 lc rgb c_free lw 1.5
set linetype 2 lc rgb c_prog lw 1.5
set linetype 3 lc rgb c_stop lw 1.5
set linetype 4 lc rgb c_alt lw 1.5
set linetype 5 lc rgb "#9467bd" lw 1.5
set linetype 6 lc rgb c_grey lw 1.5
# The first non-comment line of every table is its header: columns are used by name.
set datafile columnheaders
# Text placed by LaTeX: pi and phases as TeX.
set format x "$%g$"
set format y "$%g$"

# sin(vartheta0) of Eq. (1), as computed by experiment eq1_vartheta0 (its macro in build/tables):
# the figures mark the edge q/a = sin(vartheta0) of assumption (2) with the computed value.
sin_vartheta0 = real(system("sed -n 's/^\\\\newcommand{\\\\dfcSinVarthetaZero}{\\(.*\\)}$/\\1/p' '".data."/../tables/eq1_vartheta0-macros.tex'"))
if (!(sin_vartheta0 > 0.7 && sin_vartheta0 < 0.75)) { print "style.gp: no sin(vartheta0) in tables/eq1_vartheta0-macros.tex (run eq1_vartheta0)"; exit status 1 }
