// SPDX-License-Identifier: GPL-3.0-or-later
/// @file perturbed.hpp
/// @brief Section 10: the return map under a small smooth perturbation of the force, and whether
/// the covering of Lemma 4 (Eq. 18) survives it.
///
/// **The perturbed system.** Section 10 replaces the free-flight equation (3) by
/// \f$\ddot x = F(t) + G(t, x, \dot x)\f$ and the progression equation (4) by
/// \f$\ddot x = F(t) + G(t, x, \dot x) - q\f$, for a \f$C^2\f$ function \f$G\f$ that is small together with
/// its first derivatives, and asserts that the conclusion of Theorem 1 persists for \f$G\f$ small
/// enough. We use the one-parameter family
/// \f[ G_\varepsilon(t, x, v) = \varepsilon\Big(\cos(2t + 1) + \frac{v}{1 + v^2}\Big), \f]
/// which is smooth, \f$2\pi\f$-periodic in \f$t\f$, bounded by \f$\tfrac32\varepsilon\f$, has first
/// derivatives bounded by \f$2\varepsilon\f$ (\f$|\partial_t G| \le 2\varepsilon\f$,
/// \f$|\partial_v G| \le \varepsilon\f$, \f$\partial_x G = 0\f$), and does not depend on \f$x\f$, so the
/// motion is still invariant under shifts of \f$x\f$ and still reduces to a map of the phase at
/// which free flights start.
///
/// **The perturbed map** \f$T_\varepsilon\f$ has no closed form: it is computed by integrating the
/// equations of motion (ode_map.hpp, GSL rk8pd with located contact, velocity-zero and
/// stop-release events). A stop that begins in \f$[t_1, t_2)\f$ now ends at the first zero
/// \f$t_2^\varepsilon\f$ after \f$\pi\f$ of the contact force at rest
/// \f$a\sin t + 2b + G_\varepsilon(t, x, 0)\f$, which replaces \f$t_2 = \pi + \arcsin(2b/a)\f$.
///
/// **Persistence of the covering.** Near each segment \f$J_i\f$ of Lemma 4 we look for a phase
/// \f$u\f$ with \f$T_\varepsilon(u) = t_2^\varepsilon\f$ (a stop arc, near the end of \f$J_i\f$ where
/// \f$T = t_2\f$), a phase \f$w\f$ with \f$T_\varepsilon(w) \ge 3\pi/2\f$ (near the other end), and check
/// that \f$T_\varepsilon\f$ is continuous between them; then by intermediate values
/// \f$T_\varepsilon([u, w]) \supseteq [t_2^\varepsilon, 3\pi/2]\f$, the perturbed form of inclusion (18).
/// The continuity check is sampled: a jump narrower than the grid step whose two sides differ by
/// less than the suspicion threshold can be missed.
#pragma once

#include <limits>
#include <utility>
#include <vector>

#include "dfchaos/covering.hpp"
#include "dfchaos/parameters.hpp"

namespace dfchaos {

/// The perturbation of Section 10 used by dfchaos:
/// \f$G_\varepsilon(t, x, v) = \varepsilon(\cos(2t + 1) + v/(1 + v^2))\f$ (independent of x).
double perturbation_G(double eps, double t, double x, double v);

/// \f$t_2^\varepsilon\f$: the first zero after \f$\pi\f$ of the contact force at rest
/// \f$a\sin t + 2b + G_\varepsilon(t, 0, 0)\f$, where a stop in \f$[t_1, t_2)\f$ ends under the
/// perturbation; found by bisection on \f$[\pi - \tfrac12, 3\pi/2]\f$ to a bracket of 1e-15.
/// At \f$\varepsilon = 0\f$ it is \f$t_2\f$.
/// @throws InvalidParameter (naming eps) if the force does not change sign from positive to
///         negative over that bracket (a perturbation too large for the stop to end near \f$t_2\f$).
double perturbed_stop_release(const Parameters& p, double eps);

/// Largest number of accepted integration steps for one evaluation of \f$T_\varepsilon\f$.
inline constexpr long kPerturbedMaxSteps = 5'000'000;

/// \f$T_\varepsilon(\theta)\f$ by numerical integration (ode_return_map_step with the perturbation
/// \f$G_\varepsilon\f$), for \f$t_2 \le \theta < t_3\f$.
/// @throws InvalidParameter for \f$\theta\f$ outside \f$[t_2, t_3)\f$; GaveUp when the integration
///         exceeds max_steps (e.g. a motion that never flies again).
double perturbed_T(const Parameters& p, double eps, double theta, long max_steps = kPerturbedMaxSteps);

/// One sampled value of \f$T_\varepsilon\f$ (the graph drawn by the continuity check).
struct PerturbedSample {
  int segment = 0;   ///< which covering segment (0: near \f$J_0\f$, 1: near \f$J_1\f$)
  double theta = 0;  ///< the phase
  double T = 0;      ///< \f$T_\varepsilon(\theta)\f$
};

/// Thresholds of the persistence search. The defaults are those of the sec10_robustness experiment.
struct PerturbedCoveringSearch {
  int grid = 400;               ///< grid points of the continuity check between u and w (at least 2)
  double margin = 0.25;         ///< u and w are searched within margin * |J_i| of the ends of J_i
  int ladder = 200;             ///< steps of the outward search on each side, up to that distance
  double release_match = 1e-9;  ///< \f$|T_\varepsilon(u) - t_2^\varepsilon|\f$ below this: u is on a stop arc
  double suspect_jump = 0.05;   ///< neighbours whose values differ by more are bisected
  int jump_halvings = 50;       ///< halvings of a suspect interval at most
  double jump_width = 1e-13;    ///< ... or until it is this narrow
  double jump = 1e-6;           ///< a difference above this left over the final interval is a jump
};

/// Whether \f$T_\varepsilon\f$ is continuous on \f$[x_0, x_1]\f$ as seen on a grid of `search.grid`
/// points: every pair of neighbours whose values differ by more than `suspect_jump` is bisected
/// towards the half with the larger change (at most `jump_halvings` times, or to `jump_width`);
/// a change above `jump` left over the final interval is a jump. The grid values after \f$x_0\f$
/// are appended to `graph` (if given) as they are computed, so they are there even if a later
/// evaluation throws. @throws GaveUp as perturbed_T.
bool perturbed_continuous_between(const Parameters& p, double eps, double x0, double x1, const PerturbedCoveringSearch& search = {},
                                  std::vector<PerturbedSample>* graph = nullptr, int segment = 0);

/// The perturbed covering near \f$J_0\f$ and \f$J_1\f$ (see the file comment).
struct PerturbedCovering {
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();  ///< "not computed"
  double t2_eps = nan;                                                     ///< \f$t_2^\varepsilon\f$ (NaN when the search did not get that far)
  bool covers[2] = {false, false};  ///< \f$T_\varepsilon([u_i, w_i]) \supseteq [t_2^\varepsilon, 3\pi/2]\f$ (u, w found, continuous between)
  /// the edge, on the side of w, of the stop arc (\f$T_\varepsilon = t_2^\varepsilon\f$) met nearest the \f$T = t_2\f$ end of
  /// \f$J_i\f$ (NaN: no such phase within the margin)
  double u[2] = {nan, nan};
  double w[2] = {nan, nan};                             ///< the phase with \f$T_\varepsilon \ge 3\pi/2\f$ nearest the other end (NaN: none)
  bool both() const { return covers[0] && covers[1]; }  ///< the covering persists
};

/// Searches the perturbed covering near the segments of an unperturbed Lemma 4 covering `c` of
/// the same parameters: for each \f$J_i\f$, the nearest phases u, w to its ends (outwards on a ladder
/// of `ladder` steps up to `margin` times its length, both sides, within \f$[t_2, 3\pi/2)\f$), and
/// the continuity of \f$T_\varepsilon\f$ between them. u is then moved to the edge of its stop arc
/// on the side of w (ladder steps towards w while \f$T_\varepsilon = t_2^\varepsilon\f$, then
/// bisection to `jump_width`), so that it marks where the arc ends even when the arc has grown over
/// the end of \f$J_i\f$. The grid values of the continuity checks go to
/// `graph` (if given), as in perturbed_continuous_between.
/// @throws InvalidParameter from perturbed_stop_release; GaveUp from perturbed_T.
PerturbedCovering perturbed_covering(const Parameters& p, const Lemma4Covering& c, double eps, const PerturbedCoveringSearch& search = {},
                                     std::vector<PerturbedSample>* graph = nullptr);

/// The perturbed covering searched over the whole target arc, not only near \f$J_0, J_1\f$.
struct PerturbedGlobalCovering {
  double t2_eps = PerturbedCovering::nan;  ///< \f$t_2^\varepsilon\f$
  int samples = 0;                         ///< grid phases of \f$[t_2, 3\pi/2)\f$ where \f$T_\varepsilon\f$ was evaluated
  int gave_up = 0;                         ///< of which the integration gave up (no next free flight within its bound)
  /// Disjoint segments \f$[lo, hi]\f$ with \f$T_\varepsilon = t_2^\varepsilon\f$ at one end, \f$\ge 3\pi/2\f$ at
  /// the other, and no jump between them (sampled check), in ascending order.
  std::vector<std::pair<double, double>> segments;
  bool both() const { return segments.size() >= 2; }  ///< two disjoint covering segments: the covering persists
};

/// Searches the perturbed covering on all of \f$[t_2, 3\pi/2)\f$: \f$T_\varepsilon\f$ on `grid` cell
/// centres; neighbours whose values differ by more than `search.suspect_jump` are bisected as in
/// perturbed_continuous_between, and a jump splits the arc into runs; in each run, every sample with
/// \f$T_\varepsilon = t_2^\varepsilon\f$ (to `search.release_match`) followed (or preceded) by one with
/// \f$T_\varepsilon \ge 3\pi/2\f$ closes a covering segment between the two nearest such samples; the
/// segments are taken greedily from the left, disjoint. A grid is sampled: stop arcs narrower than
/// its step can be missed. Work is bounded: `grid` evaluations plus the jump bisections; after
/// `max_gave_up` integrations that give up, the search stops (segments found so far are kept).
/// @throws InvalidParameter from perturbed_stop_release, or for grid < 2.
PerturbedGlobalCovering perturbed_covering_global(const Parameters& p, double eps, int grid, const PerturbedCoveringSearch& search = {},
                                                  int max_gave_up = 20);

}  // namespace dfchaos
