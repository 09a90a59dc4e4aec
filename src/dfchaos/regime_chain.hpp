// SPDX-License-Identifier: GPL-3.0-or-later
/// @file regime_chain.hpp
/// @brief The transition rules between regimes (Section 3): from any state, the next regime change.
///
/// This is the one place where the switching logic lives; both the return map \f$T\f$
/// (return_map.hpp) and the full simulator (simulator.hpp) step through it.
///
/// Rules (phases as in parameters.hpp; \f$F<0\f$ exactly on \f$(t_2, t_3)\f$, \f$F>q\f$ on \f$(t_0, t_1)\f$):
///  - **free** ends at the first contact \f$x = y\f$ (first up-crossing of the gap). With a
///    positive impact velocity the mass drags the delimiter: progression (transition *fp*). With
///    zero velocity (a grazing touch) it flies on if the phase is in \f$[t_2, t_3)\f$, otherwise
///    it stops (an instantaneous stop *is*; the degenerate Scenarios C′, D′ start at \f$t_3\f$). A
///    flight from rest whose gap rises at once (\f$F \ge 0\f$ at the start, i.e. at or beyond the
///    true \f$t_3\f$) has length 0: the mass never leaves and stops (or progresses if \f$F > q\f$).
///    The free arc \f$[t_2, t_3)\f$ excludes the last doubles below the rounded \f$t_3\f$ where
///    \f$F \ge 0\f$ (long-double sign test).
///  - **progression** ends when \f$\dot x\f$ returns to 0: free if the phase is in \f$[t_2, t_3)\f$,
///    stop otherwise.
///  - **stop** ends at the next phase \f$t_2\f$ (free) or \f$t_0\f$ (progression from rest),
///    whichever comes first; with neither defined it lasts for ever.
#pragma once

#include <optional>

#include "dfchaos/motion.hpp"
#include "dfchaos/parameters.hpp"
#include "dfchaos/roots.hpp"

namespace dfchaos {

/// Position of mass and delimiter, velocity of the mass, and regime, at an instant.
struct MechanicalState {
  Instant t;                     ///< the instant
  Regime regime = Regime::Free;  ///< regime starting at t
  double x = 0;                  ///< position of the mass
  double y = 0;                  ///< position of the delimiter
  double v = 0;                  ///< velocity of the mass
};

/// Kinds of transition instant in Section 2: *fp* (free to progression by an impact) and *is*
/// (instantaneous stop: the velocity is zero at the contact for an instant).
enum class TransitionKind { Impact, InstantaneousStop };
const char* transition_code(TransitionKind k);  ///< "fp" or "is"

/// One regime change.
struct Transition {
  Instant t;                                                ///< the instant of the change
  Regime from = Regime::Free;                               ///< regime before
  Regime to = Regime::Free;                                 ///< regime after
  TransitionKind kind = TransitionKind::InstantaneousStop;  ///< fp or is
  double x = 0;                                             ///< position of the mass at the transition
  double y = 0;                                             ///< position of the delimiter (x = y: always at the contact)
  double v_before = 0;                                      ///< velocity just before (the impact velocity for fp)
  double v_after = 0;                                       ///< velocity just after
  bool grazing = false;                                     ///< a free flight touched the delimiter with zero velocity and flew on
  long pieces = 0;                                          ///< root-search work
  /// The state just after the transition.
  MechanicalState after() const { return MechanicalState{t, to, x, y, v_after}; }
};

/// The regime at contact (\f$x = y\f$) with velocity \f$v \ge 0\f$ at instant t: progression if
/// \f$v > 0\f$ or \f$F > q\f$ (or the phase is \f$t_0\f$); free if \f$v = 0\f$ and \f$F < 0\f$ (or the
/// phase is \f$t_2\f$); otherwise stop.
Regime regime_at_contact(const Parameters& p, const Instant& t, double v);

/// The regime of an arbitrary admissible state (\f$x \le y\f$): free when \f$x < y\f$ or when
/// \f$x = y\f$, \f$v < 0\f$; otherwise regime_at_contact().
Regime classify(const Parameters& p, const Instant& t, double x, double y, double v);

/// The next regime change after `s`, searched up to `limits.horizon` (elapsed time); nothing if
/// the regime lasts beyond it.
std::optional<Transition> next_transition(const Parameters& p, const MechanicalState& s, const SearchLimits& limits = {});

}  // namespace dfchaos
