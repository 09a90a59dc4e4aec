// SPDX-License-Identifier: GPL-3.0-or-later
/// @file next_hit.hpp
/// @brief Certified next-hit map \f$T_1\f$ (Section 4, Eq. 11) over a set of start phases and a
/// box of parameters: an enclosure of the first root of
/// \f$G_1(\theta, t) = b(t-\theta)^2 - a\sin t + a\cos\theta\,(t-\theta) + a\sin\theta\f$, with a
/// proof that it is the first root and that it is simple.
///
/// **Monotonicity used throughout** (for \f$\theta \in [t_2(b), t_3(b)]\f$, so \f$F(\theta) \le 0\f$,
/// and \f$t > \theta\f$): \f$\partial_\theta G_1 = -F(\theta)(t-\theta) \ge 0\f$ (proof of Lemma 2),
/// \f$\partial_b G_1 = (t-\theta)^2 > 0\f$, \f$\partial_\theta \partial_t G_1 = -F(\theta) \ge 0\f$ and
/// \f$\partial_b\partial_t G_1 = 2(t-\theta) > 0\f$. Along the family \f$\theta = t_2(b)\f$ the same
/// holds for the total derivative in b (\f$F(t_2) = 0\f$ kills the \f$\theta\f$ terms). So over a
/// start set \f$\Theta\f$ and a box \f$B\f$ of b, \f$G_1\f$ and \f$\partial_t G_1\f$ are smallest at the
/// *min corner* \f$(\theta_{\min}, b_{lo})\f$ and largest at the *max corner* \f$(\theta_{\max}, b_{hi})\f$:
/// every inequality over the whole set reduces to one at a corner, evaluated at (nearly) thin balls.
///
/// **The proof of \f$T_1\f$ over \f$\Theta \times B\f$**, as certify_T1() does it:
///  1. *departure*: \f$G_1(\theta,\theta+s) = s^2\,[\,(b + \tfrac a2\sin\theta) + s\,g(\theta,s)\,]\f$ with
///     \f$g = -a\sin\theta\, s\,E(s) - a\cos\theta\, K(s)\f$, \f$E(s) = (\tfrac12 - \tfrac{1-\cos s}{s^2})/s^2
///     \in [\tfrac1{24} - \tfrac{s^2}{720}, \tfrac1{24}]\f$, \f$K(s) = (\sin s - s)/s^3 \in [-\tfrac16, -\tfrac16 + \tfrac{s^2}{120}]\f$
///     (alternating series, \f$|s| \le 1\f$). \f$b + \tfrac a2\sin\theta \le 0\f$ on \f$[t_2, t_3]\f$, so
///     \f$g < 0\f$ on \f$\Theta \times [0, s_0]\f$ gives \f$G_1 < 0\f$ for \f$s \in (0, s_0]\f$ (the double zero at
///     \f$t = \theta\f$ divided out);
///  2. *no earlier root*: \f$G_1(\theta, t) \le G_1(\theta_{\max}, t; b_{hi}) < 0\f$ for \f$t \in (\theta_{\max}, t_{lo}]\f$,
///     the last by prove_negative() at the max corner (envelope skips the long middle of the flight);
///  3. *bracket*: \f$G_1(\theta_{\max}, t_{lo}; b_{hi}) < 0 < G_1(\theta_{\min}, t_{hi}; b_{lo})\f$;
///  4. *simple root*: \f$\partial_t G_1(\theta_{\min}, t; b_{lo}) > 0\f$ on \f$[t_{lo}, t_{hi}]\f$.
/// Then for every \f$(\theta, b)\f$ there is exactly one root in \f$[t_{lo}, t_{hi}]\f$, none before, and by
/// the implicit function theorem \f$T_1\f$ is continuous (and decreasing in \f$\theta\f$) on the set.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "dfchaos/certified/ball.hpp"
#include "dfchaos/certified/negativity.hpp"
#include "dfchaos/certified/outcome.hpp"
#include "dfchaos/certified/parameters.hpp"

namespace dfchaos::certified {

/// A set of start phases over the parameter box: either \f$\theta \in [lo, hi]\f$ for every b of the
/// box, or the family \f$\theta = t_2(b)\f$ (one start per b).
struct StartSet {
  /// Interval: \f$\theta \in [lo, hi]\f$ for every b; AtT2: \f$\theta = t_2(b)\f$.
  enum class Kind { Interval, AtT2 };
  Kind kind = Kind::Interval;  ///< which of the two
  Ball lo;                     ///< Interval: the lower end (exact, or the ball of t2 when lo_is_t2)
  Ball hi;                     ///< Interval: the upper end (exact)
  bool lo_is_t2 = false;       ///< Interval: the lower end is exactly \f$t_2(b)\f$ for each b (lo: the ball of \f$t_2\f$ over the box)

  /// \f$[lo, hi]\f$ with double ends.
  static StartSet interval(double lo, double hi);
  /// The single phase \f$\theta\f$.
  static StartSet point(double theta) { return interval(theta, theta); }
  /// \f$[lo, hi]\f$ with exact ball ends (their midpoints are used; radii must be 0).
  static StartSet balls(const Ball& lo, const Ball& hi);
  /// \f$[t_2(b), hi]\f$ for every b of the box (the neighbourhood of Theorem 2): at a point box, or
  /// over a box of b with \f$hi \ge t_2(b_{hi})\f$ (Theorem 2 at every b of a window).
  static StartSet from_t2(const ParameterBalls& m, double hi);
  /// \f$\{t_2(b)\}\f$, one start per b of the box (Section 8 as a function of b).
  static StartSet at_t2();

  /// \f$\theta\f$ at the min corner (with \f$b_{lo}\f$): where \f$G_1, \partial_t G_1, G_2\f$ are smallest.
  Ball theta_min(const ParameterBalls& m) const;
  /// \f$\theta\f$ at the max corner (with \f$b_{hi}\f$).
  Ball theta_max(const ParameterBalls& m) const;
  /// All start phases (a ball).
  Ball hull(const ParameterBalls& m) const;
  /// Proves \f$t_2(b) \le \theta \le t_3(b)\f$ for every start and every b (needed for the monotonicity).
  Outcome valid(const ParameterBalls& m) const;
  /// e.g. "theta in [3.16, 3.17]" or "theta = t2(b)".
  std::string describe() const;
};

/// \f$G_1(\theta, t; b)\f$ of Eq. (11) (a fixed by the model): model::G1 in ball arithmetic.
Ball G1(const ParameterBalls& m, const Ball& theta, const Ball& t, const Ball& b);
/// \f$\partial_t G_1 = 2b(t-\theta) - a\cos t + a\cos\theta\f$: the velocity of the mass (model::dG1_dt).
Ball dG1_dt(const ParameterBalls& m, const Ball& theta, const Ball& t, const Ball& b);

/// \f$E(s) = (\tfrac12 - \tfrac{1-\cos s}{s^2})/s^2\f$ of the departure factorisation (file comment) over
/// \f$s \in [0, s_{hi}]\f$, \f$0 \le s_{hi} \le 1\f$: \f$[\tfrac1{24} - \tfrac{s_{hi}^2}{720}, \tfrac1{24}]\f$ (alternating series).
Ball departure_E(const Ball& s_hi);
/// \f$K(s) = (\sin s - s)/s^3\f$ over \f$s \in [0, s_{hi}]\f$, \f$0 \le s_{hi} \le 1\f$: \f$[-\tfrac16, -\tfrac16 + \tfrac{s_{hi}^2}{120}]\f$.
Ball departure_K(const Ball& s_hi);
/// The departure step: \f$G_1(\theta,\theta+s;b) < 0\f$ for \f$s \in (0, s_0]\f$, every start of `set`
/// and every b of the box. `s0` must be in (0, 1].
Outcome prove_departure(const ParameterBalls& m, const StartSet& set, const Ball& s0);

/// No contact before \f$t_{end}\f$: \f$G_1(\theta, t; b) < 0\f$ for \f$t \in (\theta, t_{end}]\f$, every start and b
/// (steps 1 and 2 of the file comment: departure over the set, then prove_negative() at the max
/// corner), except on the `skip` windows of t (sorted, disjoint), which the caller proves otherwise.
/// With `s0`, the departure length used is stored there; with `record`, the pieces of the
/// negativity proof (in the variable s at the max corner) are appended to it.
Outcome certify_no_contact(const ParameterBalls& m, const StartSet& set, const Ball& t_end, Budget& budget,
                           const std::vector<std::pair<Ball, Ball>>& skip = {}, NegativityStats* stats = nullptr, Ball* s0 = nullptr,
                           NegativityRecord* record = nullptr);

/// Options of certify_T1().
struct FirstHitOptions {
  /// Windows \f$[w_{lo}, w_{hi}]\f$ of t excluded from the "no earlier root" check at the max corner:
  /// the caller proves \f$G_1 < 0\f$ there by another argument (a tangency, Lemma 2).
  std::vector<std::pair<Ball, Ball>> skip;
  /// Float guesses of \f$T_1\f$ at the max and min corners (NaN: ask the floating-point layer).
  double guess_at_max = 0.0 / 0.0;
  double guess_at_min = 0.0 / 0.0;  ///< the same at the min corner
  /// Keep the witnesses of the proof (FirstHitProof::s0, no_contact, simple_root) for a certificate.
  bool record = false;
};

/// The certified next hit over a start set and a parameter box.
struct FirstHitProof {
  Outcome verdict;        ///< proved: for every start and b, the first root of \f$G_1\f$ is simple and in [t_lo, t_hi]
  Ball t_lo;              ///< left end of the bracket (exact)
  Ball t_hi;              ///< right end of the bracket (exact)
  Ball enclosure;         ///< \f$[t_{lo}, t_{hi}]\f$
  Ball v1_at_max;         ///< \f$\partial_t G_1\f$ at the max corner's root side (impact velocity, for reports)
  NegativityStats stats;  ///< work of the negativity proofs
  // The witnesses, kept when FirstHitOptions::record (docs/certificates.md, statement covering):
  Ball s0;                       ///< the departure length: \f$G_1 < 0\f$ for \f$s \in (0, s_0]\f$ (step 1)
  NegativityRecord no_contact;   ///< step 2: \f$G_1(\theta_{\max}, \theta_{\max} + s; b_{hi}) < 0\f$ on these s-pieces
  NegativityRecord simple_root;  ///< step 4: \f$\partial_t G_1(\theta_{\min}, t; b_{lo}) > 0\f$ on these t-pieces
};

/// \f$T_1\f$ over `set` (Eq. 11), with the four steps of the file comment. Bounded by `budget`.
FirstHitProof certify_T1(const ParameterBalls& m, const StartSet& set, Budget& budget, const FirstHitOptions& opt = {});

/// Refines a simple root of \f$G_1(\theta, \cdot; b)\f$ near `guess` by Newton's method on the
/// midpoints (not a proof; the caller verifies a bracket). Returns NaN-free exact ball or the guess.
Ball newton_G1(const ParameterBalls& m, const Ball& theta, const Ball& b, const Ball& guess);

}  // namespace dfchaos::certified
