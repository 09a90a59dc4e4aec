// SPDX-License-Identifier: GPL-3.0-or-later
/// @file progression_stop.hpp
/// @brief Lemma 1: the progression that starts from rest at \f$t_0\f$, where it stops, and the
/// sufficient conditions (8), (9) used in the paper's proof.
///
/// From rest at \f$t_0\f$ the velocity is \f$\dot x(t) = -a(\cos t - \cos t_0) + 2c(t - t_0)\f$
/// (Eq. 7). Lemma 1 asserts that for \f$b < b_0(q)\f$ it vanishes at some \f$t_4 \in [t_1, t_2]\f$.
#pragma once

#include "dfchaos/motion.hpp"
#include "dfchaos/parameters.hpp"
#include "dfchaos/phase.hpp"

namespace dfchaos {

/// The progression from rest at \f$t_0\f$ and what follows it.
struct ProgressionFromT0 {
  Instant t4;                     ///< where the velocity first returns to 0 (turn 0 is \f$t_0\f$'s period)
  double t4_value = 0;            ///< \f$t_4\f$ as a real number (\f$t_0 < t_4\f$)
  double eq8_velocity_at_t2 = 0;  ///< the right-hand side of Eq. (8): \f$\dot x(t_2)\f$
  bool stops_in_t1_t2 = false;    ///< Lemma 1's conclusion \f$t_4 \in [t_1, t_2]\f$ (from the root search)
  /// The proof's bound \f$a + a\cos t_0 - (q - 2b)(\pi - t_0) < 0\f$, which implies (8) < 0.
  bool proof_bound = false;
  double proof_bound_value = 0;  ///< the left-hand side of that bound
  /// Inequality (9) evaluated at this \f$t_0\f$: \f$1 + \cos t_0 - \sin t_0(\pi - t_0) < 0\f$
  /// (equivalent to \f$t_0 > \vartheta_0\f$).
  bool eq9 = false;
  Regime next = Regime::Stop;  ///< regime after \f$t_4\f$: free if \f$t_4 \bmod 2\pi \in [t_2, t_3)\f$, else stop
  /// A stop after \f$t_4\f$ that lasts until the next \f$t_0\f$ (\f$t_4 \bmod 2\pi\f$ in \f$[t_3, t_0)\f$):
  /// the same progression then repeats every period and the mass never flies again.
  bool repeats_for_ever = false;
};

/// Computes the progression from rest at \f$t_0\f$.
/// @throws InvalidParameter unless \f$t_0, t_2\f$ exist (\f$|q - 2b| < a\f$, \f$2b < a\f$) and \f$q > 2b\f$.
ProgressionFromT0 progression_from_t0(const Parameters& p);

/// Which statement a threshold of Lemma 1 is about.
enum class Lemma1Criterion {
  StopsInT1T2,  ///< Lemma 1's conclusion: the progression from rest at \f$t_0\f$ stops in \f$[t_1, t_2]\f$
  ProofBound    ///< the proof's sufficient bound \f$a + a\cos t_0 - (q-2b)(\pi - t_0) < 0\f$
};

/// The threshold \f$b_0(q)\f$ of Lemma 1 (with \f$a = 1\f$): the boundary in \f$b/a\f$ between
/// `lo`, where the criterion holds, and `hi`, where it fails, located by bisection (60 halvings,
/// dfchaos::bisect). A b/a at or above \f$q/(2a)\f$ counts as failing (no return map there).
/// Assumes the criterion holds on an initial interval \f$(0, b_0)\f$ (checked on a grid by the
/// experiment lemma1_progression_stop).
/// @return 0 if the criterion fails at `lo`; `hi` if it holds there too; the boundary otherwise
///         (the last b/a of the bisection where it holds).
double lemma1_threshold(double q_over_a, double lo, double hi, Lemma1Criterion criterion);

}  // namespace dfchaos
