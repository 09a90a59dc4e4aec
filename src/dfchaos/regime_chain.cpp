// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/regime_chain.hpp"

#include <cmath>

namespace dfchaos {

const char* transition_code(TransitionKind k) { return k == TransitionKind::Impact ? "fp" : "is"; }

namespace {
/// Whether a mass at rest at the contact at phase phi flies off: phi in [t2, t3). The rounded t3
/// may exceed the true one by an ulp; the last doubles below it are therefore also required to
/// have F(phi) < 0, with F in long double (its sign is exact there: |F| >= a cos(t3) ulp/2).
constexpr double kNearT3 = 8 * 8.9e-16;  // 8 ulp of a phase in [4, 8)
bool in_free_arc(const Parameters& p, double phi) {
  if (!p.t2() || !phase_in_arc(phi, *p.t2(), *p.t3())) return false;
  if (*p.t3() - phi > kNearT3) return true;
  return p.a() * std::sin(static_cast<long double>(phi)) + 2.0L * p.b() < 0;
}
}  // namespace

Regime regime_at_contact(const Parameters& p, const Instant& t, double v) {
  if (v > 0) return Regime::Progression;
  const double F = p.F(t.phase);
  if (F > p.q() || (p.t0() && t.phase == *p.t0())) return Regime::Progression;
  if (p.t3() && t.phase == *p.t3()) return Regime::Stop;  // F = 0 rising: F rounds to either sign here
  if (F < 0 || (p.t2() && t.phase == *p.t2())) return Regime::Free;
  return Regime::Stop;
}

Regime classify(const Parameters& p, const Instant& t, double x, double y, double v) {
  if (x < y || v < 0) return Regime::Free;
  return regime_at_contact(p, t, v);
}

std::optional<Transition> next_transition(const Parameters& p, const MechanicalState& s, const SearchLimits& limits) {
  Transition tr;
  tr.from = s.regime;
  switch (s.regime) {
    case Regime::Free: {
      const FreeMotion m(p, s.t, s.x, s.v);
      const auto root = first_upcrossing(m.gap(s.y), limits);
      if (!root) return std::nullopt;
      tr.t = root->t;
      tr.pieces = root->pieces;
      tr.x = tr.y = s.y;
      tr.v_before = std::max(root->slope, 0.0);
      if (root->s == 0) {
        // The gap rises at once from a start at rest (F >= 0 there: at or just beyond t3): the
        // mass never leaves the delimiter. Zero-velocity contact (is) into stop, or progression
        // if F exceeds q.
        tr.kind = TransitionKind::InstantaneousStop;
        tr.v_before = 0;
        tr.to = (p.F(tr.t.phase) > p.q() || (p.t0() && tr.t.phase == *p.t0())) ? Regime::Progression : Regime::Stop;
      } else if (tr.v_before > 0) {
        tr.kind = TransitionKind::Impact;
        tr.to = Regime::Progression;
        tr.v_after = tr.v_before;
      } else {
        tr.kind = TransitionKind::InstantaneousStop;
        tr.to = in_free_arc(p, tr.t.phase) ? Regime::Free : Regime::Stop;
        tr.grazing = (tr.to == Regime::Free);
      }
      return tr;
    }
    case Regime::Progression: {
      const ProgressionMotion m(p, s.t, s.x, s.v);
      const auto root = first_upcrossing(m.minus_velocity(), limits);
      if (!root) return std::nullopt;
      tr.t = root->t;
      tr.pieces = root->pieces;
      tr.x = tr.y = m.position(root->t);
      tr.v_before = 0;
      tr.v_after = 0;
      tr.kind = TransitionKind::InstantaneousStop;
      tr.to = in_free_arc(p, tr.t.phase) ? Regime::Free : Regime::Stop;
      return tr;
    }
    case Regime::Stop: {
      std::optional<Instant> best;
      Regime to = Regime::Stop;
      if (p.t2()) {
        best = next_at_phase(s.t, *p.t2());
        to = Regime::Free;
      }
      if (p.t0()) {
        const Instant c = next_at_phase(s.t, *p.t0());
        if (!best || before(c, *best)) {
          best = c;
          to = Regime::Progression;
        }
      }
      if (!best || elapsed(s.t, *best) > limits.horizon) return std::nullopt;
      tr.t = *best;
      tr.to = to;
      tr.kind = TransitionKind::InstantaneousStop;
      tr.x = tr.y = s.y;
      return tr;
    }
  }
  return std::nullopt;
}

}  // namespace dfchaos
