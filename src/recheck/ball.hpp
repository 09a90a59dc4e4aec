// SPDX-License-Identifier: GPL-3.0-or-later
/// @file ball.hpp
/// @brief One ball of start phases and parameters through the map: the first contact T1 (no contact
/// before a bracket, a simple zero inside it), the progression's stop theta2, Lemma 3's cases, and
/// what that proves about T on the ball.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "interval.hpp"
#include "reading.hpp"
#include "steps.hpp"

namespace recheck {

/// A piece [x1, x2] of a negativity list and the test named for it.
struct Piece {
  Num x1, x2;
  std::string test;
};
/// A function f of one variable with its derivatives, and (for the no-contact list only) an upper
/// envelope U >= f that is convex, so that U < 0 at both ends of a piece gives f < 0 on it.
struct Fn {
  std::function<Iv(const Iv&)> f, d1, d2, envelope;
};
/// What one ball proves about T: its case, k, the theta2 bracket if any, whether Lemma 1 is needed.
struct Outcome {
  bool ab = false, theta2 = false, needs_lemma1 = false;
  Iv two_pi_k, u_lo, u_hi;
};
/// The witnesses of one ball, all read before anything is checked (so that a malformed certificate
/// is reported as such whichever step would fail first).
struct BallWitness {
  Ball ball;
  Num th_lo, th_hi;                           // the start phases exactly (ball.th_lo, th_hi: the same as doubles, when they are)
  Num s0, t_lo, t_hi, u_lo, u_hi, tau, from;  // u_lo, u_hi: theta2; tau, from (unless impact): stop_arc
  std::vector<Piece> no_contact, simple_root, no_earlier_stop, simple_zero, no_stop_before_t3;
  bool ab = false, none = false, theta2 = false, from_impact = false;
  double k = 0;
};
/// A window [lo, hi] of t on which G1 < 0 is proved by another argument (Lemma 2's tangencies): a
/// no-contact list may leave a gap inside it.
struct Window {
  Iv lo, hi;
};
/// A ball's b range and start phases: at the min corner (with b_lo), at the max corner (with b_hi),
/// all of them. From t2 exactly, [t2(b), th_hi]: the least start t2(b) is least at b_lo, and along
/// the family theta = t2(b) the total b-derivatives of G1 and dG1 are those at fixed theta, as
/// F(t2) = 0 removes the theta terms; so the min corner is (t2(b_lo), b_lo).
struct Corners {
  Iv Blo, Bhi, B, Thmin, Thmax, Th;
};

std::vector<Piece> pieces(const json& j, const std::string& where);
/// Requires f < 0 on [X1, X2]: the pieces lie inside [X1, X2] and cover it, and on each piece
/// X = [x1, x2], with midpoint m in M and radius r <= R, the named test holds:
///   taylor:   f(m) + r |f'(m)| + (r^2/2) max(0, f''(X)) < 0 (Taylor's theorem at m);
///   monotone: f' lies in D = f'(M) + [-1, 1] r |f''(X)| (the mean-value theorem); D > 0 and
///             f(x2) < 0, or D < 0 and f(x1) < 0;
///   envelope: U(x1) < 0 and U(x2) < 0.
///   With `hole`, a gap (g1, g2) between the pieces is allowed where hole(g1, g2) holds (f < 0 is
///   proved there by another argument: Lemma 2's tangency window).
void negative_on(Steps& st, const std::vector<Piece>& ps, const Num& X1, const Num& X2, const Fn& fn, const std::string& what,
                 const std::function<bool(const Num&, const Num&)>& hole = {});
/// A number of whole turns k (JSON integer, |k| < 10^9; an unsigned JSON value is not wrapped).
long long turn(const json& jk, const std::string& where);
/// Reads the T1 witnesses {"s0", "t_lo", "t_hi", "no_contact", "simple_root"} of a ball into w.
void read_T1(const json& jt, const std::string& wt, BallWitness& w);
/// Reads a ball; `allow_none`: its case may be "none" (only the steps up to the first stop are
/// checked, nothing about T is concluded; the erratum to Theorem 2); `long_theta`: its phases may be
/// exact binary numbers that are not doubles (ball.th_lo, th_hi are then NaN: no cover of doubles).
BallWitness read_ball(const json& j, const std::string& where, bool allow_none = false, bool long_theta = false);
Corners corners(const Iv& A, const BallWitness& w);
/// Step 1 of a ball, the start set: t2 <= theta < t3, so F(theta) <= 0 for every b <= b_hi, and with
/// t > theta the partial derivatives dG1/dtheta = -F(theta)(t - theta) >= 0, dG1/db = (t - theta)^2,
/// and of dG1 (= dG1/dt) d(dG1)/dtheta = -F(theta) >= 0, d(dG1)/db = 2(t - theta) > 0: G1 and dG1 are
/// least at (theta_lo, b_lo), greatest at (theta_hi, b_hi).
void start_set_step(Steps& st, const Iv& A, const BallWitness& w, const Corners& c, const std::string& who);
/// Steps 4 and 5 of a ball: G1(theta, t) < 0 for t in (theta, until] at every point of the ball
/// (`until_name` names `until` in messages), except inside the window `skip` when one is given.
void no_contact_steps(Steps& st, const Iv& A, const BallWitness& w, const Corners& c, const Iv& until, const std::string& until_name,
                      const Window* skip, const std::string& who);
/// Steps 1-5 of a ball (README.md), the part about T1: for every point of the ball, T1 is the only,
/// simple zero of G1 in [t_lo, t_hi] and G1 < 0 on (theta, t_lo] (outside the window `skip`, when
/// given); so T1 is continuous on the ball (where the window is proved free of zeros otherwise).
void check_T1(Steps& st, const Iv& A, const BallWitness& w, const std::string& who, const Window* skip = nullptr);
/// One ball Theta x B x Q of a covering certificate (README.md): T1 is the only, simple zero of G1
/// in [t_lo, t_hi] and G1 < 0 before it; the first stop is the simple zero theta2 in (u_lo, u_hi) or
/// lies in [t3, t2 + 2 pi) + 2 pi k; the case then makes T = max(theta2 - 2 pi k, t2) (AB) or T = t2
/// (BC), continuous on the ball.
Outcome check_ball(Steps& st, const Iv& A, const BallWitness& w, const std::string& who);
/// A T1 ball of Lemma 2 at the point b: {"theta": [x, y] (exact), "T1": {...}}; or, with `right`,
/// the right piece of a tangency {"theta", "s0", "no_contact"} (no bracket).
BallWitness read_t1_ball(const json& j, const std::string& where, double b, bool right = false);
/// T = t2 on a ball: case BC, or case AB with u_hi - 2 pi k < t2 over B (then T = max(theta2 - 2 pi k,
/// t2) = t2).
bool proves_T_is_t2(const Iv& A, const Outcome& o, const Box& x);
/// T > t2 on a ball: case AB with u_lo - 2 pi k > t2 over B (T = theta2 - 2 pi k, scenario A).
bool proves_T_above_t2(const Iv& A, const Outcome& o, const Box& x);
/// The bracket {"lo", "hi"} (exact) of vartheta0, checked as in check_vartheta0; returns [lo, hi].
Iv vartheta0_bracket(Steps& st, const json& w, const std::string& where);
/// The phase P = [u_lo, u_hi] - 2 pi k' of theta2 of a ball (which must have theta2).
Iv phase(Steps& st, const Outcome& o, const json& w, const std::string& where);
/// A ball ["t2", h] at the point (b, q), read from `j`: its outcome, after the ball's steps.
Outcome check_at_t2(Steps& st, const Iv& A, const json& j, double b, double q, const std::string& who, bool allow_none = false);
/// A ball of a periodic certificate at the point (b, q) whose phases are exactly [lo, hi]: T is
/// continuous on it and, with the theta2 bracket above t2 + 2 pi k (case AB), T = theta2 - 2 pi k
/// lies in the bracket; returns that enclosure of T.
Iv T_on(Steps& st, const Iv& A, const json& j, double b, double q, const Num& lo, const Num& hi, const std::string& who);

}  // namespace recheck
