// SPDX-License-Identifier: GPL-3.0-or-later
/// @file arc_l1.hpp
/// @brief The arc \f$L_1 = [197\pi/100, t_3)\f$ of the proof of Lemma 4, for every small b/a at once:
/// a start at rest on \f$L_1\f$ flies, hits the delimiter once, and its progression stops inside the
/// stop arc \f$(t_3, t_0 + 2\pi)\f$ — with an explicit bound on b/a instead of "b/a sufficiently small".
///
/// The proof of Lemma 4 argues at b = 0 and appeals to continuity in b. Here the statement is proved
/// for every \f$\varepsilon = b/a \in (0, \varepsilon_{\max}]\f$ and every \f$q/a\f$ of a box in one
/// computation, because after a change of variables the inequalities that decide it do not contain
/// \f$\varepsilon\f$ at all. Take a = 1 (the model depends on b/a and q/a only), write
/// \f$\theta = 2\pi - \delta\f$ with \f$\delta \in (\delta_3, \Delta]\f$, \f$\Delta = 3\pi/100\f$,
/// \f$\delta_3 = \arcsin 2\varepsilon\f$ (so \f$\theta = t_3\f$ at \f$\delta = \delta_3\f$), and s = t − θ.
/// The factorisation of the departure step of next_hit.hpp reads
/// \f[ G_1(\theta, \theta + s) = s^2 H(s), \qquad H(s) = -A + s\,g(\delta, s), \qquad
///     A = \tfrac12(\sin\delta - \sin\delta_3) > 0, \f]
/// \f$g(\delta, s) = \sin\delta\, s\,E(s) - \cos\delta\, K(s)\f$ (E, K of next_hit.hpp), and g does not
/// depend on \f$\varepsilon\f$. Shown in ball arithmetic on pieces of \f$[0, \Delta] \times [0, S]\f$
/// (S = 0.3): \f$0 < g_{lo} \le g \le g_{hi}\f$ and \f$H' = g + s\,\partial_s g \in [h_{lo}, h_{hi}]\f$,
/// \f$h_{lo} > 0\f$; and \f$A_{\max}/g_{lo} \le S\f$, \f$A_{\max} = \tfrac12\sin\Delta\f$. Then:
///  1. the first contact \f$\theta_1 = \theta + s^*\f$ has \f$s^* \in [A/g_{hi}, A/g_{lo}]\f$ (H < 0 before,
///     H ≥ 0 after, by the bounds on g), and it is simple: \f$\partial_t G_1 = s^{*2} H'(s^*) > 0\f$;
///  2. \f$\theta_1 > t_3\f$: \f$A \ge \tfrac12(\delta - \delta_3)\cos\delta\f$ (mean value theorem), so
///     \f$s^* \ge (\delta - \delta_3)\cos\Delta/(2g_{hi}) > \delta - \delta_3\f$ once \f$\cos\Delta > 2g_{hi}\f$;
///  3. the progression starts with velocity \f$x_1 = s^{*2}H'(s^*) \le (A_{\max}/g_{lo})^2 h_{hi}\f$ and,
///     while \f$t - 2\pi \le S + W \le \pi/2\f$, decelerates: \f$\partial_t G_2 = 2\varepsilon - q/a + \sin t
///     \le 2\varepsilon_{\max} - \kappa_{lo} + \sin(S + W) = -\gamma < 0\f$ (Eq. 17);
///     so it stops at \f$\theta_2 \in (\theta_1, \theta_1 + W)\f$ when \f$\gamma W > x_1\f$;
///  4. \f$\theta_2 < 2\pi + S + W \le 2\pi + t_0\f$ when \f$S + W < \arcsin(\kappa_{lo} - 2\varepsilon_{\max}) \le t_0\f$.
/// So \f$\theta_2 \in (t_3, t_0 + 2\pi)\f$: the mass waits for \f$t_0 + 2\pi\f$, and T = t2 wherever
/// Lemma 1 holds (certified separately: progression.hpp). \f$\varepsilon_{\max}\f$ is the largest
/// double with \f$2\varepsilon_{\max} \le \sin\Delta\f$: beyond it \f$L_1\f$ is empty (\f$t_3 < 197\pi/100\f$).
/// The paper's other uses of "b/a sufficiently small" in Lemma 4: docs/certified.md.
#pragma once

#include <vector>

#include "dfchaos/certified/ball.hpp"
#include "dfchaos/certified/outcome.hpp"

namespace dfchaos::certified {

/// Options of prove_arc_l1(): the defaults prove the paper's statement on its arc.
struct ArcL1Options {
  /// \f$\Delta\f$: the arc is \f$[2\pi - \Delta, t_3)\f$. NaN: \f$3\pi/100\f$ (the paper's \f$L_1\f$, the grid ending at the
  /// double just above it); else a double in (0, 0.5].
  double delta_max = 0.0 / 0.0;
  /// The bound of b/a. NaN: the largest double with \f$2\varepsilon \le \sin\Delta\f$ (beyond it the arc is empty).
  double eps_max = 0.0 / 0.0;
  double S = 0.3;  ///< flights considered: \f$s \in [0, S]\f$, S <= 1
  /// false: the paper's conclusion, the stop lies in \f$(t_3, t_0 + 2\pi)\f$ (steps 3-4 of the file comment).
  /// true: the weaker \f$\theta_2 \in (t_3, 2\pi + \tau) \subset (t_3, t_2 + 2\pi)\f$, the stop arc, shown per row of the
  /// grid by a time \f$\tau < \pi\f$ at which the progression's velocity
  /// \f$u = x_1 + (2\varepsilon - q/a)(2\pi + \tau - \theta_1) - \cos\tau + \cos\theta_1 < 0\f$ (Eq. 17; increasing in
  /// \f$\varepsilon\f$ and \f$x_1\f$, decreasing in q/a). Enough for lemma4_uniform.hpp, and it reaches larger \f$\Delta\f$.
  bool stop_arc = false;
  int delta_pieces = 16;  ///< rows of the grid (pieces of \f$[0, \Delta]\f$)
  int s_pieces = 16;      ///< columns (pieces of [0, S])
};

/// One piece \f$[\delta_1, \delta_2] \times [s_1, s_2]\f$ of the cover and the enclosures of g and H' on it.
struct ArcL1Piece {
  double delta_lo = 0;  ///< \f$\delta_1\f$
  double delta_hi = 0;  ///< \f$\delta_2\f$
  double s_lo = 0;      ///< \f$s_1\f$
  double s_hi = 0;      ///< \f$s_2\f$
  Ball g;               ///< enclosure of g on the piece
  Ball dH;              ///< enclosure of H' on the piece
};

/// The statement of the file comment over \f$\varepsilon \in (0, \varepsilon_{\max}]\f$ and
/// \f$q/a \in [\kappa_{lo}, \kappa_{hi}]\f$.
struct ArcL1Proof {
  Outcome verdict;         ///< proved: every start of L1 ends its first progression in (t3, t0 + 2 pi)
  double kappa_lo = 0;     ///< the box of q/a: lower end
  double kappa_hi = 0;     ///< upper end
  double delta_max = 0;    ///< \f$\Delta\f$ as the double that ends the grid: the arc is \f$[2\pi - \Delta, t_3)\f$
  bool paper_arc = false;  ///< the arc is the paper's L1 (ArcL1Options::delta_max NaN): \f$\Delta = 3\pi/100\f$, enclosed
  bool stop_arc = false;   ///< the weaker conclusion (ArcL1Options::stop_arc) was proved
  double eps_max = 0;      ///< \f$\varepsilon_{\max}\f$: the statement holds for every \f$0 < b/a \le\f$ this
  double S = 0.3;          ///< the flights considered: \f$s \in [0, S]\f$
  double W = 0;            ///< the progression stops within W of the impact (the paper\'s conclusion)
  /// (stop_arc) per row of the grid, tau with the progression velocity u < 0 at 2pi + tau (the stop lies before)
  std::vector<double> tau;
  double g_lo = 0;                 ///< \f$\min g\f$ (a double below every enclosure)
  double g_hi = 0;                 ///< \f$\max g\f$
  double h_lo = 0;                 ///< \f$\min H'\f$
  double h_hi = 0;                 ///< \f$\max H'\f$
  Ball x1_max;                     ///< bound of the impact velocity \f$x_1\f$
  Ball gamma;                      ///< the deceleration bound \f$\gamma\f$
  Ball t0_min;                     ///< \f$\arcsin(\kappa_{lo} - \sin\Delta)\f$, below every \f$t_0\f$
  std::vector<ArcL1Piece> pieces;  ///< the cover of \f$[0, \Delta] \times [0, S]\f$ (the witnesses)
};

/// Proves the statement of the file comment for q/a in [kappa_lo, kappa_hi] (0 < kappa_lo <= kappa_hi <= 1),
/// on the grid of `opt`.
ArcL1Proof prove_arc_l1(double kappa_lo, double kappa_hi, const ArcL1Options& opt = {});

}  // namespace dfchaos::certified
