// SPDX-License-Identifier: GPL-3.0-or-later
/// @file return_map.hpp
/// @brief Certified return map T (Section 3, Lemma 3) over a start set and a parameter box: the
/// chain of regimes, an enclosure of T, and a proof that T is continuous on the set.
///
/// With \f$T_1\f$ (next_hit.hpp) and \f$\theta_2\f$ (progression.hpp) proved simple over the set, the
/// phase of \f$\theta_2\f$ decides the chain (Section 3):
///  - **Free** (TCase::ScenarioAB): \f$\theta_2 \in [t_1 + 2\pi k, t_3 + 2\pi k)\f$ for one k and every point. On
///    \f$[t_2, t_3)\f$ the mass flies at once (scenario A), \f$T = \theta_2 - 2\pi k\f$; on
///    \f$[t_1, t_2)\f$ it stops until \f$t_2\f$ (scenario B: there \f$0 < F < q\f$), \f$T = t_2\f$. So
///    \f$T = \max(\theta_2 - 2\pi k, t_2)\f$, continuous because \f$\theta_2\f$ is.
///  - **Stop** (TCase::ScenarioBC): \f$\theta_2 \in [t_3 + 2\pi k, t_2 + 2\pi(k+1))\f$. The mass stops (\f$F \ge 0\f$, \f$F < q\f$
///    off \f$(t_0, t_1)\f$, and \f$\theta_2\f$ cannot fall in \f$(t_0, t_1)\f$ where \f$\partial_t G_2 > 0\f$);
///    it waits for \f$t_2\f$ (scenario B) or for \f$t_0\f$ and then progresses from rest, which by a
///    certified Lemma 1 stops in \f$(t_1, t_2)\f$ and waits for \f$t_2\f$ (scenario C). So \f$T \equiv t_2\f$,
///    exactly; Lemma 1 is needed only if the enclosure meets \f$[t_3, t_0]\f$ (mod \f$2\pi\f$).
///  - otherwise (the enclosure straddles \f$t_3\f$, where T jumps from near \f$t_3\f$ to \f$t_2\f$, or is
///    wider than an arc) continuity is **not proved**.
/// On each closed set where one of the two holds T is continuous; finitely many closed sets that
/// cover a segment make T continuous on the segment (pasting lemma).
#pragma once

#include <string>

#include "dfchaos/certified/next_hit.hpp"
#include "dfchaos/certified/parameters.hpp"
#include "dfchaos/certified/progression.hpp"

namespace dfchaos::certified {

/// How T is determined over the set: which of the core's scenarios (return_map.hpp, Scenario) the
/// steps from the set can follow, decided by where the first progression stops (\f$\theta_2\f$,
/// Eq. 17). The printed names (t_case_name()) are "free", "stop" and "none".
enum class TCase {
  /// \f$\theta_2 \in [t_1, t_3)\f$ modulo \f$2\pi\f$: the mass flies at \f$\theta_2\f$ (scenario A) or
  /// waits for \f$t_2\f$ (scenario B), so \f$T = \max(\theta_2 \bmod 2\pi, t_2)\f$. Printed "free".
  ScenarioAB,
  /// \f$\theta_2 \in [t_3, t_2 + 2\pi)\f$ modulo \f$2\pi\f$: the mass stops and waits for \f$t_2\f$
  /// (scenario B) or progresses again from \f$t_0\f$ and stops in \f$(t_1, t_2)\f$ by Lemma 1
  /// (scenario C), so \f$T \equiv t_2\f$. Printed "stop".
  ScenarioBC,
  Unproved  ///< neither was proved (T may jump at \f$t_3\f$ on the set). Printed "none".
};
const char* t_case_name(TCase c);  ///< "free", "stop", "none"

/// The certified T over a start set.
struct MapStepProof {
  Outcome verdict;     ///< proved: T continuous on the set, in `T`
  FirstHitProof t1;    ///< the next hit
  Theta2Proof theta2;  ///< the first progression's stop
  /// When \f$\theta_2\f$ was not bracketed but the first stop was proved to lie in a stop arc (TCase::ScenarioBC):
  /// that proof (`stop_arc.verdict` proved); else not proved.
  StopArcProof stop_arc;
  TCase t_case = TCase::Unproved;  ///< which of the two cases
  long long turn = 0;              ///< k of the case (phase of \f$\theta_2\f$ is \f$\theta_2 - 2\pi k\f$)
  Ball theta2_phase;               ///< \f$\theta_2 - 2\pi k\f$ (ScenarioAB: in \f$[t_1, t_3)\f$; ScenarioBC: in \f$[t_3, t_2 + 2\pi)\f$)
  Ball T;                          ///< enclosure of T over the set (exactly the ball of \f$t_2\f$ when T ≡ t2)
  bool constant_t2 = false;        ///< T ≡ t2 on the whole set (proved)
  bool used_lemma1 = false;        ///< the ScenarioBC case met [t3, t0]: Lemma 1 was needed and proved
  long tests = 0;                  ///< interval tests of the negativity proofs
};

/// T over `set` (Lemma 3 with the general chain of Section 3). `lemma1` (optional): a proved
/// Lemma 1 over the same box, used when the ScenarioBC case needs it (else it is proved here on demand).
/// With `record`, the witnesses of the T1, theta2 and stop-arc proofs are kept (for a certificate).
/// `t1_options` (optional) are passed to certify_T1: e.g. windows of t skipped in its no-contact check,
/// left of a tangency of Lemma 2 (discontinuities.hpp); their `record` is replaced by `record`. With
/// them, certify_theta2 also retries from this proof's T1 when the floating guess fails.
MapStepProof certify_T(const ParameterBalls& m, const StartSet& set, Budget& budget, const Lemma1Proof* lemma1 = nullptr, bool record = false,
                       const FirstHitOptions* t1_options = nullptr);

/// One closed ball of a proof about T (a covering, Theorem 2): start phases over a sub-box of the
/// parameters, with the proof of T on it and its witnesses (for a certificate).
struct BallProof {
  Ball theta_lo;         ///< lower end of the start phases, exact (unless from_t2 or at_t2)
  Ball theta_hi;         ///< upper end, exact (unless at_t2)
  ParameterBox box;      ///< the sub-box
  MapStepProof T;        ///< T on the ball, with its witnesses
  bool from_t2 = false;  ///< the phases are \f$[t_2, \theta_{hi}]\f$, from \f$t_2\f$ exactly (a point box)
  bool at_t2 = false;    ///< the phases are the family \f$\theta = t_2(b)\f$, b in the box
  /// The ball of `set` over `box` with its proof (the kind of start set is kept).
  static BallProof of(const StartSet& set, const ParameterBox& box, MapStepProof T);
};

/// Enclosure of \f$T'\f$ over a set where `t` proved the case ScenarioAB with the phase of \f$\theta_2\f$
/// strictly inside \f$(t_2, t_3)\f$ (scenario A, T smooth), by the implicit function theorem on
/// Eqs. (11) and (17): \f$T_1' = F(\theta)(\theta_1 - \theta)/\partial_t G_1\f$,
/// \f$T' = (F(\theta) - q T_1')/(F(\theta_2) - q)\f$. Returns false (and leaves `dT`) if the set is not
/// of that kind.
bool derivative_T(const ParameterBalls& m, const StartSet& set, const MapStepProof& t, Ball& dT);

}  // namespace dfchaos::certified
