// SPDX-License-Identifier: GPL-3.0-or-later
/// @file return_map.hpp
/// @brief The return map \f$T : [t_2, t_3) \to [t_2, t_3)\f$ of Section 3 and Lemma 3, with the
/// delimiter's advance (the fiber of the skew product), the scenario of each step and Eq. (17).
///
/// \f$T(\theta)\f$ is the phase at which the motion, started at rest at the delimiter at phase
/// \f$\theta\f$ (Eq. 10), next switches to free flight. It is computed by following the general
/// chain of regimes (regime_chain.hpp) — progression, stop until \f$t_2\f$, stop until \f$t_0\f$ and
/// progress again, and so on — without assuming Lemma 1.
#pragma once

#include <string>

#include "dfchaos/next_hit.hpp"
#include "dfchaos/parameters.hpp"

namespace dfchaos {

/// The scenarios of Section 3, by the sequence of regimes between two free flights:
///  - A: f→p→f;  B: f→p→s→f;  C: f→p→s→p→s→f;  D: f→p→s→p→f (the only way a second progression
///    can end other than as in C: if it stops again before \f$t_2\f$, it restarts at \f$t_0\f$ from
///    the same state every period and the motion never flies again);
///  - C′: f→s→p→s→f and D′: f→s→p→f, after a zero-velocity contact at \f$t_3\f$;
///  - Grazing: f→f, a zero-velocity touch inside \f$[t_2, t_3)\f$ (then \f$T = T_1 \bmod 2\pi\f$, as
///    used in the proof of Lemma 4);
///  - Other: any other chain (possible only outside the paper's assumptions).
enum class Scenario { A, B, C, D, Cprime, Dprime, Grazing, Other };
const char* scenario_name(Scenario s);  ///< "A", "B", "C", "D", "C'", "D'", "G", "other"

/// One application of \f$T\f$.
struct MapStep {
  double theta = 0;  ///< the argument, a phase in \f$[t_2, t_3)\f$
  FirstHit hit;      ///< \f$T_1(\theta)\f$ and the impact velocity (Eq. 11); its branch label: t1_branch()
  /// \f$\theta_2\f$: where the first progression stops (first zero of \f$G_2\f$, Eq. 17); equal
  /// to the hit instant for a grazing or a zero-velocity touch (no progression).
  Instant theta2;
  double T = 0;                         ///< \f$T(\theta) \in [t_2, t_3)\f$
  Instant end;                          ///< \f$\widehat T(\theta)\f$: the instant of the switch to free flight
  double elapsed = 0;                   ///< \f$\widehat T(\theta) - \theta\f$
  double penetration = 0;               ///< advance of the delimiter during the step (sum over progressions)
  Scenario scenario = Scenario::Other;  ///< the scenario of Section 3 this step followed
  std::string chain;                    ///< the regimes visited, e.g. "f>p>s>f"
  int progressions = 0;                 ///< number of progression phases
  long pieces = 0;                      ///< root-search work (monotone pieces examined)
};

/// One step of \f$T\f$ from \f$\theta\f$.
/// @throws InvalidParameter unless \f$b < a/2\f$, \f$q > 2b\f$ and \f$\theta\in[t_2,t_3)\f$.
/// @throws GaveUp if the motion never returns to free flight (eternal stick-slip: a progression
///         from \f$t_0\f$ stopping again outside \f$[t_2, t_3)\f$, repeating every period).
MapStep return_map_step(const Parameters& p, double theta);

/// The label of the continuity branch of \f$T_1\f$ the step's first flight belongs to (the number of
/// local maxima of \f$G_1\f$ before the hit, next_hit.hpp's maxima_between): computed on demand, since
/// most uses of \f$T\f$ do not need it.
long long t1_branch(const Parameters& p, const MapStep& step);

/// \f$T(\theta)\f$ alone.
double T(const Parameters& p, double theta);

/// \f$G_2(\theta, \theta_1, \theta_2) = 2b(\theta_1 - \theta) + a\cos\theta + 2c(\theta_2 - \theta_1) - a\cos\theta_2\f$
/// (Eq. 17): the velocity at \f$\theta_2\f$ of the progression that starts with the impact at
/// \f$\theta_1 = T_1(\theta)\f$. Its first zero after \f$\theta_1\f$ ends that progression.
/// Instants are given as turn and phase, with \f$\theta\f$ in turn 0.
double G2(const Parameters& p, double theta, const Instant& theta1, const Instant& theta2);

}  // namespace dfchaos
