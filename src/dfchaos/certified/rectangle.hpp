// SPDX-License-Identifier: GPL-3.0-or-later
/// @file rectangle.hpp
/// @brief Theorem 1 over one rectangle \f$[b_{lo}, b_{hi}] \times [q_{lo}, q_{hi}]\f$ of parameters: how much
/// of it carries a proof that Lemma 4's covering exists at *every* parameter, by the two routes of
/// the certified layer together.
///
///  - **Uniform route** (lemma4_uniform.hpp): a proof of (I1)-(I9) for \f$q/a \in [\kappa_{lo}, \kappa_{hi}]\f$
///    holds for every \f$b/a \in (0, \varepsilon_*]\f$; where the rectangle's q range lies in
///    \f$[\kappa_{lo}, \kappa_{hi}]\f$, its part \f$b \le \varepsilon_* a\f$ is proved at no further cost.
///  - **Box route** (region.hpp): the rest, \f$[\max(b_{lo}, \varepsilon_* a), b_{hi}]\f$, tiled by parameter
///    boxes as one column of certify_region, with a budget of box proofs and a give-up after a run of
///    unproved boxes.
///
/// The proved part is measured as a b-length (every box spans the whole q range). Deterministic: the
/// work is bounded by counts, never by time.
#pragma once

#include "dfchaos/certified/lemma4_uniform.hpp"
#include "dfchaos/certified/region.hpp"

namespace dfchaos::certified {

/// The work allowed on one rectangle.
struct RectangleOptions {
  long max_boxes = 4000;    ///< box proofs attempted (proved or not), at least 1
  int max_failed_run = 16;  ///< give up after this many unproved boxes in a row (0: never)
};

/// Why a rectangle was not decided up to its top.
enum class RectangleStop {
  Decided = 0,    ///< every box up to b_hi was tried (proved or not)
  FailedRun = 1,  ///< gave up after RectangleOptions::max_failed_run unproved boxes in a row
  BoxBudget = 2   ///< RectangleOptions::max_boxes ran out
};

/// How much of a rectangle is proved, and by which route.
struct RectangleProof {
  double a = 1;                                 ///< forcing amplitude
  double b_lo = 0;                              ///< the rectangle: lower end of b
  double b_hi = 0;                              ///< upper end of b
  double q_lo = 0;                              ///< lower end of q
  double q_hi = 0;                              ///< upper end of q
  double uniform_bound = 0;                     ///< \f$\varepsilon_*\f$ of the uniform proof used (b/a), 0 when none applies
  double uniform_length = 0;                    ///< b-length proved by the uniform route
  double box_length = 0;                        ///< b-length proved by parameter boxes
  long boxes_proved = 0;                        ///< proved boxes
  long boxes_failed = 0;                        ///< boxes given up
  long attempts = 0;                            ///< box proofs attempted (including retries)
  double b_reached = 0;                         ///< the rectangle is decided (proved or not) from b_lo up to here
  RectangleStop stop = RectangleStop::Decided;  ///< why it was not decided up to b_hi
  /// Proved b-length over the rectangle's b-length, in [0, 1].
  double proved_fraction() const;
};

/// Theorem 1 over the rectangle of b in [b_lo, b_hi] and q in [q_lo, q_hi] (0 < b_lo < b_hi,
/// 0 < q_lo <= q_hi, all finite). `uniform` is used when it is proved and its box of q/a contains
/// [q_lo/a, q_hi/a]; otherwise (e.g. a default-constructed proof) only boxes are tried.
/// @throws std::invalid_argument on a rectangle that breaks these conditions or options out of range.
RectangleProof prove_rectangle(double a, double b_lo, double b_hi, double q_lo, double q_hi, const Lemma4UniformProof& uniform,
                               const RectangleOptions& opt = {});

}  // namespace dfchaos::certified
