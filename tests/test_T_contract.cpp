// SPDX-License-Identifier: GPL-3.0-or-later
// The contract of the return map T (Section 3, Lemma 3), one property suite instantiated over every
// implementation of the map in the library (typed tests, as Sophus's LieGroupTests<G> and odeint's
// typed test cases):
//  - the closed form (return_map.hpp);
//  - the ODE map, which integrates the equations of motion with GSL (ode_map.hpp);
//  - the perturbed map of Section 10 at eps = 0 (perturbed.hpp);
//  - the certified enclosures (certified/return_map.hpp): the value is a ball, and every property
//    is checked for every point of it.
// The properties: T(theta) lies in [t2, t3); T has a plateau at t2 (an interval of phases mapped
// to t2: the stop arcs of scenarios B and C); T is continuous away from the jumps of the closed
// form; T agrees with a direct integration of the motion; T is unchanged when a, b and q are
// scaled together (only b/a and q/a matter, Section 2). The Python module runs the same suite
// (tests/python/test_contract.py).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "dfchaos/certified/parameters.hpp"
#include "dfchaos/certified/return_map.hpp"
#include "dfchaos/ode_map.hpp"
#include "dfchaos/perturbed.hpp"
#include "dfchaos/return_map.hpp"

using namespace dfchaos;

namespace {

/// What an implementation says of T(theta): every point of [lo, hi] (lo = hi for a floating value)
/// is T within the implementation's accuracy.
struct Enclosure {
  double lo = 0, hi = 0;
  double mid() const { return 0.5 * (lo + hi); }
};

/// Distance from the number x to the enclosure (0 inside it).
double distance(const Enclosure& e, double x) { return x < e.lo ? e.lo - x : (x > e.hi ? x - e.hi : 0.0); }

// ---- the implementations ----------------------------------------------------------------------

/// The closed form: root searches on the closed-form motions (Eqs. 3-17), accurate to 1e-10
/// (docs/accuracy.md), and exactly t2 on a stop arc.
struct ClosedForm {
  static constexpr double kAccuracy = 1e-10;
  static constexpr double kArcSlack = 0;  ///< its phases lie in the double arc [t2, t3) itself
  static std::optional<Enclosure> T(const Parameters& p, double theta) {
    const double v = dfchaos::T(p, theta);
    return Enclosure{v, v};
  }
};

/// GSL rk8pd with located events: its events are located to event_tol = 1e-12 in time, the
/// integration error per step is 1e-13, and a tangential contact magnifies both.
struct OdeMap {
  static constexpr double kAccuracy = 1e-7;
  static constexpr double kArcSlack = kAccuracy;  ///< how far outside [t2, t3) its phases may be
  static std::optional<Enclosure> T(const Parameters& p, double theta) {
    const double v = ode_return_map_step(p, theta).T;
    return Enclosure{v, v};
  }
};

/// Section 10's integrated map with the perturbation switched off.
struct PerturbedAtZero {
  static constexpr double kAccuracy = 1e-7;
  static constexpr double kArcSlack = kAccuracy;  ///< as OdeMap
  static std::optional<Enclosure> T(const Parameters& p, double theta) {
    const double v = perturbed_T(p, 0.0, theta);
    return Enclosure{v, v};
  }
};

/// The certified map at the point (a, b, q) and the single phase theta: a ball that contains the
/// exact T; nothing when the proof does not succeed (near a grazing or a jump of T).
struct Certified {
  static constexpr double kAccuracy = 0;
  /// The exact arc [t2, t3) lies within an ulp (below 1e-15 at 2 pi) of the doubles t2, t3: a ball
  /// of T = t2 reaches below the double t2 when the exact t2 does.
  static constexpr double kArcSlack = 1e-15;
  static std::optional<Enclosure> T(const Parameters& p, double theta) {
    const certified::ParameterBalls m(certified::ParameterBox::point(p));
    certified::Budget budget;
    const certified::MapStepProof t = certified::certify_T(m, certified::StartSet::point(theta), budget);
    if (!t.verdict) return std::nullopt;
    return Enclosure{t.T.lower(), t.T.upper()};
  }
};

// ---- the parameters and phases ------------------------------------------------------------------

/// Parameter sets (a = 1) with stop arcs, flights of tens of time units (the integrated maps take
/// milliseconds per phase) and both kinds of jump (of T1 and at t3).
const std::vector<std::pair<double, double>> kParameters = {{0.05, 0.85}, {0.03, 0.9}};
/// Phases per parameter set.
constexpr int kPhases = 40;
/// Share of the phases at which an implementation must give a value (the certified map may fail to
/// prove T close to a grazing or a jump).
constexpr double kMinShare = 0.8;

/// kPhases phases spread over [t2, t3) by the golden ratio (none equal to t2).
std::vector<double> phases(const Parameters& p) {
  const double t2 = *p.t2(), t3 = *p.t3();
  std::vector<double> out;
  for (int i = 0; i < kPhases; ++i) out.push_back(t2 + (t3 - t2) * std::fmod(0.5 + i * 0.6180339887498949, 1.0));
  return out;
}

/// Whether theta lies away from every jump of the closed form: the steps at theta -+ width follow the
/// same scenario, on the same branch of T1, and T stays away from t3 (where it wraps to t2).
bool away_from_jumps(const Parameters& p, double theta, double width = 1e-5) {
  const double t2 = *p.t2(), t3 = *p.t3();
  if (theta - width < t2 || theta + width >= t3) return false;
  const MapStep l = return_map_step(p, theta - width), r = return_map_step(p, theta + width);
  return l.scenario == r.scenario && t1_branch(p, l) == t1_branch(p, r) && t3 - l.T > 1e-3 && t3 - r.T > 1e-3;
}

/// The reference of direct integration: the ODE map with steps, error targets and event brackets
/// ten times finer than its defaults.
double integrated_T(const Parameters& p, double theta) {
  OdeMapOptions o;
  o.max_step = 0.005;
  o.eps_abs = o.eps_rel = 1e-14;
  o.event_tol = 1e-13;
  return ode_return_map_step(p, theta, o).T;
}

}  // namespace

template <class Map>
class TContract : public ::testing::Test {};

using Implementations = ::testing::Types<ClosedForm, OdeMap, PerturbedAtZero, Certified>;
struct ImplementationName {
  template <class Map>
  static std::string GetName(int) {
    if (std::is_same_v<Map, ClosedForm>) return "ClosedForm";
    if (std::is_same_v<Map, OdeMap>) return "OdeMap";
    if (std::is_same_v<Map, PerturbedAtZero>) return "PerturbedAtZero";
    return "Certified";
  }
};
TYPED_TEST_SUITE(TContract, Implementations, ImplementationName);

// T maps [t2, t3) into [t2, t3) (Lemma 3): the phase of the next start of free flight, where F < 0
// or F = 0 as the force falls.
TYPED_TEST(TContract, PhaseLiesInTheArc) {
  for (const auto& [b, q] : kParameters) {
    const Parameters p(1, b, q);
    const double t2 = *p.t2(), t3 = *p.t3();
    int given = 0;
    for (double th : phases(p)) {
      const auto e = TypeParam::T(p, th);
      if (!e) continue;
      ++given;
      EXPECT_GE(e->lo, t2 - TypeParam::kArcSlack) << p.describe() << " theta=" << th;
      EXPECT_LT(e->hi, t3 + TypeParam::kArcSlack) << p.describe() << " theta=" << th;
    }
    EXPECT_GE(given, kMinShare * kPhases) << p.describe();
  }
}

// A plateau at t2: some phase and its neighbours at distance 1e-5 are all mapped to t2 (a stop arc,
// scenario B or C), not merely a crossing of the value t2.
TYPED_TEST(TContract, PlateauAtT2) {
  for (const auto& [b, q] : kParameters) {
    const Parameters p(1, b, q);
    const double t2 = *p.t2();
    auto at_t2 = [&](double th) {
      const auto e = TypeParam::T(p, th);
      return e && distance(*e, t2) <= TypeParam::kAccuracy;
    };
    bool plateau = false;
    for (double th : phases(p)) {
      if (at_t2(th) && at_t2(th - 1e-5) && at_t2(th + 1e-5)) {
        plateau = true;
        break;
      }
    }
    EXPECT_TRUE(plateau) << p.describe();
  }
}

// Continuity away from the jumps of the closed form: at phases whose neighbourhood of width 1e-5
// follows one scenario on one branch of T1, a step of 1e-7 moves T by far less than any jump (a jump
// of T1 moves T by at least ~0.1 here; the slope of T is below 10^3).
TYPED_TEST(TContract, ContinuousAwayFromTheJumps) {
  constexpr double h = 1e-7, kMaxChange = 1e-3;
  for (const auto& [b, q] : kParameters) {
    const Parameters p(1, b, q);
    int checked = 0, candidates = 0;
    for (double th : phases(p)) {
      if (!away_from_jumps(p, th)) continue;
      ++candidates;
      const auto l = TypeParam::T(p, th), r = TypeParam::T(p, th + h);
      if (!l || !r) continue;
      ++checked;
      EXPECT_LE(std::max(r->hi - l->lo, l->hi - r->lo), kMaxChange + 2 * TypeParam::kAccuracy) << p.describe() << " theta=" << th;
    }
    EXPECT_GE(candidates, kPhases / 2) << p.describe();
    EXPECT_GE(checked, kMinShare * candidates) << p.describe();
  }
}

// Agreement with a direct integration of the motion (GSL rk8pd, finer than the ODE map's defaults),
// away from the jumps, within the accuracy of both.
TYPED_TEST(TContract, AgreesWithDirectIntegration) {
  constexpr double kReferenceAccuracy = 1e-7;
  for (const auto& [b, q] : kParameters) {
    const Parameters p(1, b, q);
    int checked = 0;
    const std::vector<double> all = phases(p);
    for (int i = 0; i < kPhases; i += 4) {  // a tenth of the phases: the reference costs ~10x the ODE map
      const double th = all[i];
      if (!away_from_jumps(p, th)) continue;
      const auto e = TypeParam::T(p, th);
      if (!e) continue;
      ++checked;
      const double ref = integrated_T(p, th);
      EXPECT_LE(distance(*e, ref), TypeParam::kAccuracy + kReferenceAccuracy) << p.describe() << " theta=" << th << " reference " << ref;
    }
    EXPECT_GE(checked, 3) << p.describe();
  }
}

// Only b/a and q/a matter (Section 2: divide x by a): T at (s a, s b, s q) is T at (a, b, q), for a
// scale s that is a power of two (the scaled parameters are exact) and for others (rounded).
TYPED_TEST(TContract, InvariantUnderScalingABQ) {
  for (const auto& [b, q] : kParameters) {
    const Parameters p(1, b, q);
    for (double s : {0.25, 3.0, 1e3, 1e-7}) {
      const Parameters ps(s, s * b, s * q);
      int checked = 0;
      const std::vector<double> all = phases(p);
      for (int i = 0; i < kPhases; i += 2) {
        const double th = all[i];
        if (!(th >= *ps.t2() && th < *ps.t3()) || !away_from_jumps(p, th)) continue;
        const auto e = TypeParam::T(p, th), es = TypeParam::T(ps, th);
        if (!e || !es) continue;
        ++checked;
        // The rounding of s b and s q moves T by about 1e-16 |T'|, far below 1e-10.
        EXPECT_LE(std::fabs(e->mid() - es->mid()), 2 * TypeParam::kAccuracy + 1e-10 + (e->hi - e->lo) + (es->hi - es->lo))
            << p.describe() << " scale " << s << " theta=" << th;
      }
      EXPECT_GE(checked, kPhases / 4) << p.describe() << " scale " << s;
    }
  }
}
