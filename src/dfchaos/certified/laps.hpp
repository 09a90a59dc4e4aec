// SPDX-License-Identifier: GPL-3.0-or-later
/// @file laps.hpp
/// @brief The laps of T certified at a parameter point, and the topological entropy of T bounded
/// from both sides (Section 7 beyond \f$h_{top} \ge \ln 2\f$).
///
/// **Laps.** A lap of \f$T : [t_2, t_3) \to [t_2, t_3)\f$ is a maximal interval on which T is
/// continuous and monotone (constant allowed). T is piecewise monotone with finitely many pieces;
/// for such a map of an interval, continuous or not, \f$h_{top}(T) = \lim_n \frac1n \ln c_n\f$ with
/// \f$c_n\f$ the number of laps of \f$T^n\f$ (Misiurewicz–Szlenk 1980 for continuous maps,
/// Misiurewicz–Ziemian 1992 for piecewise continuous ones, where \f$h_{top}\f$ is the entropy of the
/// map's natural compact extension: the half-open arc with each discontinuity doubled).
///
/// **Where T breaks.** On a branch of \f$T_1\f$ (between two discontinuities of Lemma 2) the
/// implicit function theorem on Eqs. (11) and (17) gives, with \f$v_1 = \partial_t G_1(\theta, \theta_1) > 0\f$
/// the impact velocity,
/// \f[ \theta_2' = \frac{F(\theta) - q T_1'}{F(\theta_2) - q}, \quad T_1' = \frac{F(\theta)(\theta_1 - \theta)}{v_1},
///     \quad\text{so}\quad \operatorname{sign}\theta_2' = \operatorname{sign}\varphi,\ \ \varphi = v_1 - q(\theta_1 - \theta), \f]
/// because \f$F(\theta) < 0\f$ on \f$(t_2, t_3)\f$ and \f$F(\theta_2) < q\f$ at a simple stop. And
/// \f$\varphi' = (q - F(\theta)) + (F(\theta_1) - q)\,T_1'\f$. By Lemma 3, \f$T = \max(\theta_2 - 2\pi k, t_2)\f$ while
/// \f$\theta_2 \in [t_1, t_3) + 2\pi k\f$ and \f$T = t_2\f$ while \f$\theta_2 \in [t_3, t_2 + 2\pi) + 2\pi k\f$: a
/// nondecreasing function of \f$\theta_2\f$ except for a jump down at each \f$t_3 + 2\pi k\f$. So T breaks
/// only at a discontinuity of \f$T_1\f$, where \f$\theta_2\f$ crosses \f$t_3 \pmod{2\pi}\f$, and where
/// \f$\varphi\f$ changes sign.
///
/// **The certified partition.** \f$[t_2, t_3)\f$ is covered, left to right, by closed cells:
///  - *monotone cells*: certify_T proves T continuous and either \f$T \equiv t_2\f$ or \f$\varphi\f$ of one
///    sign over the cell (with \f$v_1 > 0\f$): T is monotone there, in the direction of \f$\varphi\f$;
///  - *turning cells*: \f$\varphi\f$ may vanish but \f$\varphi'\f$ has one sign: at most one turning point;
///  - *jump cells*: \f$\theta_2\f$ is proved simple and monotone but straddles one \f$t_3 + 2\pi k\f$ (and lies in
///    \f$[t_1 + 2\pi k, t_2 + 2\pi(k+1))\f$): one jump, T monotone on each side;
///  - at each discontinuity z of \f$T_1\f$ (prove_discontinuities): left of z the cells use the proof with
///    the tangency window skipped; right of z, on \f$[z, z + \eta]\f$, \f$T_1\f$ lies in \f$[t^* - \delta, t^*]\f$
///    (concavity of \f$G_1\f$ on the window), the progression stops within \f$\Delta\f$ of the impact (\f$G_2\f$
///    decreases there) with \f$\theta_2\f$ in \f$(t_2, t_3) \pmod{2\pi}\f$ and \f$\varphi < 0\f$: T decreases;
///  - the end \f$[x^*, t_3)\f$: starting at rest before \f$t_3\f$ the mass flies on until after \f$t_3\f$
///    (\f$F < 0\f$ before), returns by \f$t_{hit}\f$ (\f$G_1(x^*, t_{hit}) > 0\f$, \f$G_1\f$ increasing in \f$\theta\f$),
///    and its progression velocity \f$u(t) - q(t - \theta_1) \le u(t) - q(t - t_{hit})\f$ (u the velocity of a
///    flight from rest at \f$\theta\f$) is negative at some \f$t_{end} < t_2 + 2\pi\f$: the first stop is in the
///    stop arc, so \f$T \equiv t_2\f$ (Lemma 3, with Lemma 1 where the stop may precede \f$t_0\f$).
/// Adjacent cells whose T is continuous at the shared end and whose directions agree (a constant piece
/// agrees with either) are merged into one lap. Each lap is kept as a closed hull of exact doubles
/// that contains it and an enclosure of T on it; a break inside a cell is only known to lie in the
/// cell, so the hulls of two neighbouring laps may overlap there. Any error counts too many laps,
/// never too few.
///
/// **Entropy from both sides.** With N laps, \f$c_n \le\f$ the number of paths of length n-1 in the
/// graph "\f$T(I_j)\f$ meets \f$I_k\f$" (each n-cylinder is an interval on which \f$T^n\f$ is monotone), so
/// \f$h_{top}(T) \le \ln \rho(M) \le \ln N\f$, M its 0-1 matrix, \f$\rho(M)\f$ bounded above by Collatz–Wielandt
/// (graph.hpp). The lower bound is the covering graph of entropy.hpp on the laps: on the core of each
/// lap (a closed run of its cells with exact ends) T is continuous, with T at the two ends enclosed
/// by certify_T at those points; \f$j \to k\f$ when the core of lap k lies strictly between them.
#pragma once

#include <utility>
#include <vector>

#include "dfchaos/certified/ball.hpp"
#include "dfchaos/certified/outcome.hpp"

namespace dfchaos::certified {

/// How T behaves on a lap.
enum class LapShape {
  Increasing,  ///< nondecreasing, not constant as far as proved
  Decreasing,  ///< nonincreasing
  Constant     ///< \f$T \equiv t_2\f$ (a stop plateau)
};
const char* lap_shape_name(LapShape s);  ///< "increasing", "decreasing", "constant"

/// A closed cell of the cover, or the part of it on one side of a break inside it: T is continuous
/// and monotone on the part (which lies in [lo, hi]).
struct LapCell {
  double lo = 0;                            ///< the cell (exact ends)
  double hi = 0;                            ///< (see lo)
  Ball image;                               ///< enclosure of T on the part
  LapShape shape = LapShape::Constant;      ///< the direction of T on the part
  bool joins = true;                        ///< T is continuous from the previous part into this one
  bool full = false;                        ///< the part is the whole cell, whose ends are exact starts of T's proof
  std::vector<std::pair<Ball, Ball>> skip;  ///< windows of t skipped by the cell's proof of \f$T_1\f$ (left of a tangency)
};

/// One lap of T.
struct Lap {
  double lo = 0;                        ///< the lap lies in [lo, hi] (exact doubles; lo may be below t2 by rounding)
  double hi = 0;                        ///< (see lo)
  Ball image;                           ///< enclosure of T on the lap
  LapShape shape = LapShape::Constant;  ///< the direction of T on it
  bool has_core = false;                ///< the lap contains [core_lo, core_hi], covered by its proved cells
  double core_lo = 0;                   ///< (when has_core) exact left end of the core
  double core_hi = 0;                   ///< (when has_core) exact right end of the core
  Ball T_core_lo;                       ///< (when has_core) enclosure of T at core_lo
  Ball T_core_hi;                       ///< (when has_core) enclosure of T at core_hi
  std::size_t first_cell = 0;           ///< its parts are LapPartition::parts[first_cell, end_cell)
  std::size_t end_cell = 0;             ///< (see first_cell)
};

/// Options of the lap partition.
struct LapOptions {
  double min_width = 1e-14;         ///< cells are not split below this width (relative to the phase)
  long long max_cells = 4'000'000;  ///< proved cells, at most (else "not proved")
  int max_tangencies = 200'000;     ///< discontinuities of \f$T_1\f$, at most
  /// Both bounds also on the laps refined by the preimages of the laps (the laps of \f$T^2\f$), when
  /// on the laps \f$\ln\rho_{lower} < (1 - \text{target\_gap}) \ln\rho_{upper}\f$ and the number of laps
  /// squared is at most max_refined.
  bool refine = true;
  double target_gap = 0.01;        ///< (see refine)
  long long max_refined = 10'000;  ///< (see refine)
};

/// The certified laps of T at a point.
struct LapPartition {
  Outcome verdict;             ///< proved: every point of [t2, t3) lies in a lap, and T has at most laps.size() laps
  double a = 1;                ///< the parameter point: a
  double b = 0;                ///< b
  double q = 0;                ///< q
  std::vector<Lap> laps;       ///< ascending
  std::vector<LapCell> parts;  ///< the parts of the cells, ascending (each lap is a run of them)
  long long cells = 0;         ///< proved cells
  int tangencies = 0;          ///< discontinuities of \f$T_1\f$ (Lemma 2 on \f$(t_2, x^*]\f$)
  int jump_cells = 0;          ///< cells with a jump of T at \f$\theta_2 = t_3 \pmod{2\pi}\f$
  int turning_cells = 0;       ///< cells with at most one turning point
  double end = 0;              ///< \f$x^*\f$: \f$T \equiv t_2\f$ on \f$[x^*, t_3)\f$
  bool used_lemma1 = false;    ///< a stop before \f$t_0\f$ needed Lemma 1 (proved at the point)
  double seconds = 0;          ///< wall time
};

/// The laps of T at (a, b, q), as in the file comment.
LapPartition prove_laps(double a, double b, double q, const LapOptions& opt = {});

/// The entropy of T bounded from both sides at a point.
struct EntropyBracket {
  Outcome verdict;               ///< proved: both bounds hold (the lower one may be 0 when no cycle is proved)
  LapPartition partition;        ///< the laps
  Ball log_laps;                 ///< \f$\ln N\f$, N the number of laps: \f$h_{top} \le\f$ its upper end
  long long ones = 0;            ///< ones of M ("T(I_j) meets I_k"), on the partition that gave rho_upper
  long long refined_pieces = 0;  ///< pieces of the refined partition (0: not refined)
  double rho_upper = 0;          ///< a proved upper bound of \f$\rho(M)\f$
  Ball log_rho_upper;            ///< \f$\ln\f$ rho_upper: \f$h_{top} \le\f$ its upper end
  int lower_vertices = 0;        ///< laps in the subgraph of the lower bound
  long long lower_edges = 0;     ///< its proved edges
  double rho_lower = 0;          ///< a proved lower bound of the covering graph's \f$\rho\f$ (0: none above 1)
  Ball log_rho_lower;            ///< \f$\ln\f$ rho_lower: \f$h_{top} \ge\f$ its lower end
  double seconds = 0;            ///< wall time (partition included)
  double h_upper() const;        ///< the upper bound: min of the two upper ends
  double h_lower() const;        ///< the lower bound (0 when rho_lower <= 1)
};

/// Both bounds at (a, b, q).
EntropyBracket prove_entropy_bracket(double a, double b, double q, const LapOptions& opt = {});

}  // namespace dfchaos::certified
