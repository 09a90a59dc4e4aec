// SPDX-License-Identifier: GPL-3.0-or-later
#include "ball.hpp"

#include <algorithm>
#include <functional>

#include "paper.hpp"

namespace recheck {

std::vector<Piece> pieces(const json& j, const std::string& where) {
  if (!j.is_array()) throw Malformed("'" + where + "' is not an array");
  std::vector<Piece> v;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string w = where + "[" + std::to_string(i) + "]";
    if (!j[i].is_array() || j[i].size() != 3 || !j[i][2].is_string()) throw Malformed("'" + w + "' is not [x1, x2, test]");
    v.push_back({exact(j[i][0], w + "[0]"), exact(j[i][1], w + "[1]"), j[i][2].get<std::string>()});
    if (v.back().test != "envelope" && v.back().test != "taylor" && v.back().test != "monotone")
      throw Malformed("'" + w + "[2]' = '" + v.back().test + "' is not envelope, taylor or monotone");
  }
  return v;
}

/// Requires f < 0 on [X1, X2]: the pieces lie inside [X1, X2] and cover it, and on each piece
/// X = [x1, x2], with midpoint m in M and radius r <= R, the named test holds:
///   taylor:   f(m) + r |f'(m)| + (r^2/2) max(0, f''(X)) < 0 (Taylor's theorem at m);
///   monotone: f' lies in D = f'(M) + [-1, 1] r |f''(X)| (the mean-value theorem); D > 0 and
///             f(x2) < 0, or D < 0 and f(x1) < 0;
///   envelope: U(x1) < 0 and U(x2) < 0.
///   With `hole`, a gap (g1, g2) between the pieces is allowed where hole(g1, g2) holds (f < 0 is
///   proved there by another argument: Lemma 2's tangency window).
void negative_on(Steps& st, const std::vector<Piece>& ps, const Num& X1, const Num& X2, const Fn& fn, const std::string& what,
                 const std::function<bool(const Num&, const Num&)>& hole) {
  std::vector<const Piece*> order;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const Piece& p = ps[i];
    const std::string name = what + " piece " + std::to_string(i) + " ([" + hex(p.x1) + ", " + hex(p.x2) + "]) ";
    st.require(mpfr_cmp(X1.x, p.x1.x) <= 0 && mpfr_cmp(p.x1.x, p.x2.x) <= 0 && mpfr_cmp(p.x2.x, X2.x) <= 0,
               name + "lies inside [" + hex(X1) + ", " + hex(X2) + "]");
    order.push_back(&p);
    const Iv L(p.x1), H(p.x2), X(p.x1, p.x2), M = 0.5 * (L + H), R = upper(0.5 * (H - L));
    bool ok = false;
    if (p.test == "envelope") {
      ok = fn.envelope && fn.envelope(L).negative() && fn.envelope(H).negative();
    } else if (p.test == "taylor") {
      const Iv c = upper(fn.d2(X));
      ok = (fn.f(M) + R * abs(fn.d1(M)) + 0.5 * (R * R) * (c.negative() ? Iv(0.0) : c)).negative();
    } else {
      const Iv D = fn.d1(M) + Iv(-1.0, 1.0) * R * abs(fn.d2(X));
      ok = (D.positive() && fn.f(H).negative()) || (D.negative() && fn.f(L).negative());
    }
    st.require(ok, name + p.test + ": f < 0 not verified");
  }
  std::sort(order.begin(), order.end(), [](const Piece* x, const Piece* y) { return mpfr_cmp(x->x1.x, y->x1.x) < 0; });
  Num reach = X1;
  bool started = false;
  for (const Piece* p : order) {
    if (mpfr_cmp(p->x1.x, reach.x) > 0 && !(hole && hole(reach, p->x1))) break;  // (reach, x1) is covered by nothing
    if (mpfr_cmp(p->x2.x, reach.x) >= 0) reach = p->x2, started = true;
  }
  st.require(started && mpfr_cmp(reach.x, X2.x) >= 0,
             what + ": the pieces cover [" + hex(X1) + ", " + hex(X2) + "] (no gap" + (hole ? " outside the window)" : ")"));
}

/// A number of whole turns k (JSON integer, |k| < 10^9; an unsigned JSON value is not wrapped).
long long turn(const json& jk, const std::string& where) {
  const bool small =
      jk.is_number_unsigned() ? jk.get<unsigned long long>() < 1000000000ULL : jk.is_number_integer() && jk.get<long long>() > -1000000000LL;
  if (!small) throw Malformed("'" + where + "' is not an integer of absolute value below 10^9");
  return jk.get<long long>();
}

/// Reads the T1 witnesses {"s0", "t_lo", "t_hi", "no_contact", "simple_root"} of a ball into w.
void read_T1(const json& jt, const std::string& wt, BallWitness& w) {
  w.s0 = exact(field(jt, "s0", wt), wt + "s0"), w.t_lo = exact(field(jt, "t_lo", wt), wt + "t_lo"),
  w.t_hi = exact(field(jt, "t_hi", wt), wt + "t_hi");
  w.no_contact = pieces(field(jt, "no_contact", wt), wt + "no_contact");
  w.simple_root = pieces(field(jt, "simple_root", wt), wt + "simple_root");
}

/// Reads a ball; `allow_none`: its case may be "none" (only the steps up to the first stop are
/// checked, nothing about T is concluded; the erratum to Theorem 2); `long_theta`: its phases may be
/// exact binary numbers that are not doubles (ball.th_lo, th_hi are then NaN: no cover of doubles).
BallWitness read_ball(const json& j, const std::string& where, bool allow_none, bool long_theta) {
  BallWitness w;
  const std::vector<double> b = doubles(field(j, "b", where), 2, where + "b"), q = doubles(field(j, "q", where), 2, where + "q");
  const json& jth = field(j, "theta", where);
  w.ball = {0, 0, {b[0], b[1], q[0], q[1]}};
  const auto phase = [&](const json& x, const std::string& wx, Num& n) {
    n = exact(x, wx);
    return long_theta ? NAN : exact_double(x, wx);
  };
  if (jth.is_array() && jth.size() == 2 && jth[0] == "t2") {
    w.ball.start = Start::FromT2;
    w.ball.th_hi = phase(jth[1], where + "theta[1]", w.th_hi);
  } else {
    if (!jth.is_array() || jth.size() != 2) throw Malformed("'" + where + "theta' is not an array of 2 numbers");
    w.ball.th_lo = phase(jth[0], where + "theta[0]", w.th_lo);
    w.ball.th_hi = phase(jth[1], where + "theta[1]", w.th_hi);
  }
  read_T1(field(j, "T1", where), where + "T1.", w);
  const json& jc = field(j, "case", where);
  if (jc != "AB" && jc != "BC" && !(allow_none && jc == "none"))
    throw Malformed("'" + where + "case' is not \"AB\" or \"BC\"" + (allow_none ? " or \"none\"" : ""));
  w.ab = jc == "AB";
  w.none = jc == "none";
  w.k = static_cast<double>(turn(field(j, "k", where), where + "k"));
  w.theta2 = j.contains("theta2");
  if (w.theta2 == j.contains("stop_arc")) throw Malformed("'" + where + "' has not exactly one of theta2 and stop_arc");
  if (w.theta2) {
    const json& ju = j["theta2"];
    const std::string wu = where + "theta2.";
    w.u_lo = exact(field(ju, "u_lo", wu), wu + "u_lo"), w.u_hi = exact(field(ju, "u_hi", wu), wu + "u_hi");
    w.no_earlier_stop = pieces(field(ju, "no_earlier_stop", wu), wu + "no_earlier_stop");
    w.simple_zero = pieces(field(ju, "simple_zero", wu), wu + "simple_zero");
  } else {
    const json& ja = j["stop_arc"];
    const std::string wa = where + "stop_arc.";
    w.tau = exact(field(ja, "tau", wa), wa + "tau");
    const json& from = field(ja, "from", wa);
    w.from_impact = from == "impact";
    if (!w.from_impact) {
      w.from = exact(from, wa + "from");
      w.no_stop_before_t3 = pieces(field(ja, "no_stop_before_t3", wa), wa + "no_stop_before_t3");
    }
  }
  return w;
}

Corners corners(const Iv& A, const BallWitness& w) {
  const Box& x = w.ball.box;
  Corners c{Iv(x.b_lo), Iv(x.b_hi), Iv(x.b_lo, x.b_hi), Iv(w.th_lo), Iv(w.th_hi), Iv()};
  if (w.ball.start == Start::FromT2) c.Thmin = t2(A, c.Blo);
  c.Th = hull(c.Thmin, c.Thmax);
  return c;
}

/// Step 1 of a ball, the start set: t2 <= theta < t3, so F(theta) <= 0 for every b <= b_hi, and with
/// t > theta the partial derivatives dG1/dtheta = -F(theta)(t - theta) >= 0, dG1/db = (t - theta)^2,
/// and of dG1 (= dG1/dt) d(dG1)/dtheta = -F(theta) >= 0, d(dG1)/db = 2(t - theta) > 0: G1 and dG1 are
/// least at (theta_lo, b_lo), greatest at (theta_hi, b_hi).
void start_set_step(Steps& st, const Iv& A, const BallWitness& w, const Corners& c, const std::string& who) {
  if (w.ball.start == Start::Interval)
    st.require(le(t2(A, c.Bhi), c.Thmin) && le(c.Thmin, c.Thmax) && lt(c.Thmax, t3(A, c.Bhi)),
               who + ": start set: t2(b_hi) <= theta_lo <= theta_hi < t3(b_hi)");
  if (w.ball.start == Start::FromT2)  // [t2(b), th_hi] for each b: the min corner t2(b_lo) by the family's monotonicity
    st.require(le(t2(A, c.Bhi), c.Thmax) && lt(c.Thmax, t3(A, c.Bhi)), who + ": start set: t2(b_hi) <= theta_hi < t3(b_hi)");
}

/// Steps 4 and 5 of a ball: G1(theta, t) < 0 for t in (theta, until] at every point of the ball
/// (`until_name` names `until` in messages), except inside the window `skip` when one is given.
void no_contact_steps(Steps& st, const Iv& A, const BallWitness& w, const Corners& c, const Iv& until, const std::string& until_name,
                      const Window* skip, const std::string& who) {
  const auto step = [&](const std::string& s) { return who + ": " + s; };
  const Iv S0(w.s0), &Thmin = c.Thmin, &Thmax = c.Thmax, &Th = c.Th, &B = c.B, &Bhi = c.Bhi;
  // 4. Departure: G1(theta, theta + s) = s^2 [b + (a/2) sin theta + s g], g = -a sin theta s E(s) -
  // a cos theta K(s), E = (1/2 - (1 - cos s)/s^2)/s^2 in [1/24 - s^2/720, 1/24], K = (sin s - s)/s^3
  // in [-1/6, -1/6 + s^2/120] for 0 < s <= 1 (alternating series); b + (a/2) sin theta <= 0 (step 1).
  // So G1 < 0 for s in (0, s0]; theta_hi - theta_lo <= s0 joins this to step 5.
  st.require(S0.positive() && le(S0, Iv(1.0)) && le(Thmax - Thmin, S0), step("departure: 0 < s0 <= 1 and theta_hi - theta_lo <= s0"));
  {
    const Iv S = hull(Iv(0.0), S0), s2 = S0 * S0, E = hull(Iv(1.0) / Iv(24.0) - s2 / Iv(720.0), Iv(1.0) / Iv(24.0)),
             K = hull(Iv(-1.0) / Iv(6.0), Iv(-1.0) / Iv(6.0) + s2 / Iv(120.0));
    const Iv g = -(A * sin(Th) * S * E) - A * cos(Th) * K;
    st.require(g.negative() || (B + 0.5 * A * sin(Th) + S * g).negative(), step("departure: G1(theta, theta + s) < 0 for s in (0, s0]"));
  }
  // 5. No contact: G1(theta_hi, theta_hi + s; b_hi) < 0 on [s0, s_end], theta_hi + s_end >= until;
  // by step 1 G1 < 0 on (theta, until] at every point. U(s) = b s^2 + a s cos theta + a sin theta + a
  // >= G1 (-a sin <= a), convex. With `skip`, a gap (g1, g2) of the pieces is allowed where
  // [theta_hi + g1, theta_hi + g2] lies inside the window.
  const std::vector<Piece>& nc = w.no_contact;
  st.require(!nc.empty(), step("T1 no contact: the list is not empty"));
  Num s_end = nc[0].x2;
  for (const Piece& p : nc)
    if (mpfr_cmp(p.x2.x, s_end.x) > 0) s_end = p.x2;
  st.require(le(until, Thmax + Iv(s_end)), step("T1 no contact: theta_hi + s_end >= " + until_name));
  std::function<bool(const Num&, const Num&)> hole;
  if (skip) hole = [&](const Num& g1, const Num& g2) { return le(skip->lo, Thmax + Iv(g1)) && le(Thmax + Iv(g2), skip->hi); };
  negative_on(
      st, nc, w.s0, s_end,
      {[&](const Iv& s) { return G1(A, Bhi, Thmax, Thmax + s); }, [&](const Iv& s) { return dG1(A, Bhi, Thmax, Thmax + s); },
       [&](const Iv& s) { return F(A, Bhi, Thmax + s); }, [&](const Iv& s) { return Bhi * sqr(s) + A * s * cos(Thmax) + A * sin(Thmax) + A; }},
      who + ": T1 no contact", hole);
}

/// Steps 1-5 of a ball (README.md), the part about T1: for every point of the ball, T1 is the only,
/// simple zero of G1 in [t_lo, t_hi] and G1 < 0 on (theta, t_lo] (outside the window `skip`, when
/// given); so T1 is continuous on the ball (where the window is proved free of zeros otherwise).
void check_T1(Steps& st, const Iv& A, const BallWitness& w, const std::string& who, const Window* skip) {
  const auto step = [&](const std::string& s) { return who + ": " + s; };
  const Corners c = corners(A, w);
  start_set_step(st, A, w, c, who);
  const Iv Tlo(w.t_lo), Thi(w.t_hi);
  // 2. The bracket: G1 < 0 at t_lo and > 0 at t_hi at every point (Eq. 11, the corners).
  st.require(lt(c.Thmax, Tlo) && lt(Tlo, Thi), step("T1 bracket: theta_hi < t_lo < t_hi"));
  st.require(G1(A, c.Bhi, c.Thmax, Tlo).negative(), step("T1 bracket: G1(theta_hi, t_lo; b_hi) < 0"));
  st.require(G1(A, c.Blo, c.Thmin, Thi).positive(), step("T1 bracket: G1(theta_lo, t_hi; b_lo) > 0"));
  // 3. dG1 > 0 on [t_lo, t_hi] at the min corner, so everywhere: the zero T1 is simple.
  negative_on(st, w.simple_root, w.t_lo, w.t_hi,
              {[&](const Iv& t) { return -dG1(A, c.Blo, c.Thmin, t); },
               [&](const Iv& t) { return -F(A, c.Blo, t); },
               [&](const Iv& t) { return -F_slope(A, t); },
               {}},
              who + ": T1 simple root");
  no_contact_steps(st, A, w, c, Tlo, "t_lo", skip, who);
}

/// One ball Theta x B x Q of a covering certificate (README.md): T1 is the only, simple zero of G1
/// in [t_lo, t_hi] and G1 < 0 before it; the first stop is the simple zero theta2 in (u_lo, u_hi) or
/// lies in [t3, t2 + 2 pi) + 2 pi k; the case then makes T = max(theta2 - 2 pi k, t2) (AB) or T = t2
/// (BC), continuous on the ball.
Outcome check_ball(Steps& st, const Iv& A, const BallWitness& w, const std::string& who) {
  check_T1(st, A, w, who);  // steps 1-5
  const auto step = [&](const std::string& s) { return who + ": " + s; };
  const Num &tlo = w.t_lo, &thi = w.t_hi;
  const Box& x = w.ball.box;
  const Iv Blo(x.b_lo), Bhi(x.b_hi), B(x.b_lo, x.b_hi), Qlo(x.q_lo), Qhi(x.q_hi), Q(x.q_lo, x.q_hi);
  const Corners c = corners(A, w);
  const Iv &Thmin = c.Thmin, &Thmax = c.Thmax, Tlo(tlo), Thi(thi);
  // 6. The first progression, Eq. (17). dG2/dtheta1 = q > 0, dG2/dtheta = -F(theta) >= 0, dG2/db =
  // 2(t - theta) > 0, dG2/dq = -(t - theta1) <= 0: for t >= T1, G2min(t) <= G2 and, for t >= t_hi,
  // G2 <= G2max(t).
  Outcome out;
  const double k = w.k;
  out.two_pi_k = 2.0 * pi() * Iv(k);
  const Iv next = 2.0 * pi() * Iv(k + 1);
  const auto G2min = [&](const Iv& t) { return G2(A, Blo, Qhi, Thmin, Tlo, t); };
  const auto G2max = [&](const Iv& t) { return G2(A, Bhi, Qlo, Thmax, Thi, t); };
  const Fn minus_G2min{
      [&](const Iv& t) { return -G2min(t); }, [&](const Iv& t) { return -(F(A, Blo, t) - Qhi); }, [&](const Iv& t) { return -F_slope(A, t); }, {}};
  out.ab = w.ab, out.theta2 = w.theta2;
  Iv L;  // the lower end of the first stop
  if (out.theta2) {
    // G2 > 0 on [T1, u_lo], < 0 at u_hi and decreasing on [u_lo, u_hi]: theta2 is its only, simple zero.
    const Num &ulo = w.u_lo, &uhi = w.u_hi;
    out.u_lo = Iv(ulo), out.u_hi = Iv(uhi), L = out.u_lo;
    st.require(lt(Thi, out.u_lo) && lt(out.u_lo, out.u_hi), step("theta2 bracket: t_hi < u_lo < u_hi"));
    st.require(G2min(out.u_lo).positive(), step("theta2 bracket: G2min(u_lo) > 0"));
    st.require(G2max(out.u_hi).negative(), step("theta2 bracket: G2max(u_hi) < 0"));
    negative_on(st, w.no_earlier_stop, tlo, ulo, minus_G2min, who + ": theta2 no earlier stop");
    negative_on(st, w.simple_zero, ulo, uhi,
                {[&](const Iv& t) { return F(A, Bhi, t) - Qlo; },
                 [&](const Iv& t) { return F_slope(A, t); },
                 [&](const Iv& t) { return F_curvature(A, t); },
                 {}},
                who + ": theta2 simple zero");
  } else {
    // G2 < 0 at tau: the stop lies after T1 (or after A, with G2 > 0 on [t_lo, A]) and before tau,
    // inside [t3, t2 + 2 pi) + 2 pi k.
    const Iv Tau(w.tau);
    st.require(lt(Thi, Tau), step("stop arc: t_hi < tau"));
    st.require(G2max(Tau).negative(), step("stop arc: G2max(tau) < 0"));
    st.require(lt(Tau, t2(A, B) + next), step("stop arc: tau < t2 + 2 pi (k + 1)"));
    if (w.from_impact) {
      L = Tlo;
      st.require(le(t3(A, B) + out.two_pi_k, Tlo), step("stop arc: t3 + 2 pi k <= t_lo"));
    } else {
      const Iv Av(w.from);
      L = t3(A, B) + out.two_pi_k;
      st.require(le(L, Av) && lt(Tlo, Av) && lt(Av, Tau), step("stop arc: t3 + 2 pi k <= A, t_lo < A < tau"));
      negative_on(st, w.no_stop_before_t3, tlo, w.from, minus_G2min, who + ": stop arc no stop before t3");
    }
  }
  if (w.none) return out;  // no case: nothing is concluded about T
  // 7. The case, over B x Q. AB: theta2 in [t1, t3) + 2 pi k, where F < q: the mass rests until t2
  // or is already in the start set, T = max(theta2 - 2 pi k, t2), continuous as theta2 is. BC: the
  // stop lies in [t3, t2 + 2 pi) + 2 pi k; T = t2, directly when the stop is after t1 + 2 pi (k + 1),
  // otherwise after a progression that Lemma 1 (Eq. 8) ends in (t1, t2) + 2 pi (k + 1).
  if (out.ab) {
    st.require(out.theta2, step("case AB needs theta2 (not stop_arc)"));
    st.require(le(t1(A, B, Q) + out.two_pi_k, out.u_lo) && lt(out.u_hi, t3(A, B) + out.two_pi_k),
               step("case AB: t1 + 2 pi k <= u_lo and u_hi < t3 + 2 pi k"));
  } else {
    if (out.theta2)
      st.require(le(t3(A, B) + out.two_pi_k, out.u_lo) && lt(out.u_hi, t2(A, B) + next),
                 step("case BC: t3 + 2 pi k <= u_lo and u_hi < t2 + 2 pi (k + 1)"));
    out.needs_lemma1 = !le(t1(A, B, Q) + next, L);
  }
  return out;
}

/// A T1 ball of Lemma 2 at the point b: {"theta": [x, y] (exact), "T1": {...}}; or, with `right`,
/// the right piece of a tangency {"theta", "s0", "no_contact"} (no bracket).
BallWitness read_t1_ball(const json& j, const std::string& where, double b, bool right) {
  BallWitness w;
  std::tie(w.th_lo, w.th_hi) = exact_pair(field(j, "theta", where), where + "theta");
  w.ball = {NAN, NAN, {b, b, 0, 0}};
  if (!right) {
    read_T1(field(j, "T1", where), where + "T1.", w);
  } else {
    w.s0 = exact(field(j, "s0", where), where + "s0");
    w.no_contact = pieces(field(j, "no_contact", where), where + "no_contact");
  }
  return w;
}

/// T = t2 on a ball: case BC, or case AB with u_hi - 2 pi k < t2 over B (then T = max(theta2 - 2 pi k,
/// t2) = t2).
bool proves_T_is_t2(const Iv& A, const Outcome& o, const Box& x) { return !o.ab || lt(o.u_hi - o.two_pi_k, t2(A, Iv(x.b_lo, x.b_hi))); }
/// T > t2 on a ball: case AB with u_lo - 2 pi k > t2 over B (T = theta2 - 2 pi k, scenario A).
bool proves_T_above_t2(const Iv& A, const Outcome& o, const Box& x) { return o.ab && o.theta2 && lt(t2(A, Iv(x.b_lo, x.b_hi)), o.u_lo - o.two_pi_k); }

/// The bracket {"lo", "hi"} (exact) of vartheta0, checked as in check_vartheta0; returns [lo, hi].
Iv vartheta0_bracket(Steps& st, const json& w, const std::string& where) {
  const json& br = field(w, "vartheta0", where);
  const Num lo = exact(field(br, "lo", where + "vartheta0."), where + "vartheta0.lo");
  const Num hi = exact(field(br, "hi", where + "vartheta0."), where + "vartheta0.hi");
  vartheta0_steps(st, lo, hi);
  return Iv(lo, hi);
}

/// The phase P = [u_lo, u_hi] - 2 pi k' of theta2 of a ball (which must have theta2).
Iv phase(Steps& st, const Outcome& o, const json& w, const std::string& where) {
  st.require(o.theta2, where + "at_t2 has theta2 (a bracketed stop)");
  const json& jk = field(w, "phase_turn", where);
  return hull(o.u_lo, o.u_hi) - 2.0 * pi() * Iv(static_cast<double>(turn(jk, where + "phase_turn")));
}

/// A ball ["t2", h] at the point (b, q), read from `j`: its outcome, after the ball's steps.
Outcome check_at_t2(Steps& st, const Iv& A, const json& j, double b, double q, const std::string& who, bool allow_none) {
  const BallWitness w = read_ball(j, who + ".", allow_none);
  st.require(w.ball.start == Start::FromT2, who + ": theta is [\"t2\", h]");
  st.require(w.ball.box.b_lo == b && w.ball.box.b_hi == b && w.ball.box.q_lo == q && w.ball.box.q_hi == q, who + ": at the parameter point");
  return check_ball(st, A, w, who);
}

/// A ball of a periodic certificate at the point (b, q) whose phases are exactly [lo, hi]: T is
/// continuous on it and, with the theta2 bracket above t2 + 2 pi k (case AB), T = theta2 - 2 pi k
/// lies in the bracket; returns that enclosure of T.
Iv T_on(Steps& st, const Iv& A, const json& j, double b, double q, const Num& lo, const Num& hi, const std::string& who) {
  const BallWitness w = read_ball(j, who + ".", false, true);
  st.require(w.ball.start == Start::Interval && mpfr_equal_p(w.th_lo.x, lo.x) && mpfr_equal_p(w.th_hi.x, hi.x),
             who + ": its phases are the set named");
  st.require(w.ball.box.b_lo == b && w.ball.box.b_hi == b && w.ball.box.q_lo == q && w.ball.box.q_hi == q, who + ": at the parameter point");
  const Outcome o = check_ball(st, A, w, who);
  st.require(o.ab && o.theta2, who + ": case AB with a theta2 bracket");
  const Iv T = hull(o.u_lo, o.u_hi) - o.two_pi_k;
  st.require(lt(t2(A, Iv(b)), T), who + ": u_lo - 2 pi k > t2, so T = theta2 - 2 pi k");
  return T;
}

}  // namespace recheck
