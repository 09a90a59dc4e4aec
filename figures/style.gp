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
# ONE palette for every figure, safe for colour blindness (Okabe & Ito) and, with the line widths,
# dash types and point types below, readable in greyscale too: categories never differ by hue alone.
oi_black = "#000000"; oi_orange = "#E69F00"; oi_sky = "#56B4E9"; oi_green = "#009E73"
oi_yellow = "#F0E442"; oi_blue = "#0072B2"; oi_verm = "#D55E00"; oi_purple = "#CC79A7"
# Regimes, used everywhere: free flight, progression, stop (until t2), stop until t0 / other.
c_free = oi_blue; c_prog = oi_verm; c_stop = oi_green; c_alt = oi_orange; c_grey = "#7f7f7f"
c_sky = oi_sky; c_purple = oi_purple; c_yellow = oi_yellow
set linetype 1 lc rgb c_free lw 1.5
set linetype 2 lc rgb c_prog lw 1.5
set linetype 3 lc rgb c_stop lw 1.5
set linetype 4 lc rgb c_alt lw 1.5
set linetype 5 lc rgb c_purple lw 1.5
set linetype 6 lc rgb c_grey lw 1.5
# A motion drawn by regime: free flight thin solid, progression thick solid, stop thick dotted
# (linetypes 11, 12, 13 = regime 0, 1, 2). reg(r, v) is v on the samples of regime r and on the
# first sample after such a run, so that the pieces of the three curves join; NaN elsewhere.
set linetype 11 lc rgb c_free lw 1.5 dt solid
set linetype 12 lc rgb c_prog lw 3.5 dt solid
set linetype 13 lc rgb c_stop lw 4 dt (1, 1)
reg_now = -1; reg_before = -1
reg(r, v) = (reg_before = reg_now, reg_now = column("regime"), (reg_now == r || reg_before == r) ? v : NaN)
regrgb(r) = (r == 0 ? 0x0072B2 : (r == 1 ? 0xD55E00 : 0x009E73))
# Continuous quantities: viridis (perceptually uniform, monotone in lightness, so greyscale-safe).
set palette defined (0 '#440154', 1 '#472d7b', 2 '#3b528b', 3 '#2c728e', 4 '#21918c', 5 '#28ae80', \
                     6 '#5ec962', 7 '#addc30', 8 '#fde725')
# The first non-comment line of every table is its header: columns are used by name.
set datafile columnheaders
# Text placed by LaTeX: pi and phases as TeX.
set format x "$%g$"
set format y "$%g$"

# sin(vartheta0) of Eq. (1), as computed by experiment eq1_vartheta0 (its macro in build/tables):
# the figures mark the edge q/a = sin(vartheta0) of assumption (2) with the computed value.
sin_vartheta0 = real(system("sed -n 's/^\\\\newcommand{\\\\dfcSinVarthetaZero}{\\(.*\\)}$/\\1/p' '".data."/../tables/eq1_vartheta0-macros.tex'"))
if (!(sin_vartheta0 > 0.7 && sin_vartheta0 < 0.75)) { print "style.gp: no sin(vartheta0) in tables/eq1_vartheta0-macros.tex (run eq1_vartheta0)"; exit status 1 }

# A number an experiment computed or chose, read from its macros (build/tables/EXP-macros.tex) into the
# string variable VAR: `eval tex_macro("VAR", "EXP", "Name")` sets VAR = '<value of \dfcName>'. When
# the macro is missing VAR stays undefined and its first use stops the figure (nothing typed here).
tex_macro(var, exp, name) = system(sprintf('sed -n "s/^\\\\newcommand{\\\\dfc%s}{\\(.*\\)}\$/%s = ''\\1''/p" "%s/../tables/%s-macros.tex"', name, var, data, exp))
# b and q of a data table whose description line ends in 'at a=1 b=B q=Q' (Parameters::describe()),
# as strings in their shortest form.
header_b(file) = system("sed -n 's/^# .* at a=1 b=\\([^ ]*\\) q=\\([^ ]*\\)$/\\1/p' '".file."' | head -1")
header_q(file) = system("sed -n 's/^# .* at a=1 b=\\([^ ]*\\) q=\\([^ ]*\\)$/\\2/p' '".file."' | head -1")

# The (q/a, b/a) plane figures share one axis convention: q/a linear with ticks every 0.05, b/a on a
# logarithmic axis plotted as log10(b/a) with ticks at the powers of ten. `eval plane_axes` after
# setting the ranges.
plane_axes = "set xlabel '$q/a$'; set ylabel '$b/a$' offset 0.5,0; set xtics 0.05 format '$%.2f$'; set mxtics 5; " . \
             "set ytics ('$10^{-5}$' -5, '$10^{-4}$' -4, '$10^{-3}$' -3, '$10^{-2}$' -2, '$10^{-1}$' -1, '$1$' 0); set mytics 10"
