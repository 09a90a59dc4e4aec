// SPDX-License-Identifier: GPL-3.0-or-later
// dfchaos-recheck: re-verifies the certificates that `dfchaos certify ... --certificate FILE` writes,
// in MPFI interval arithmetic, with its own formulas taken from the paper. It shares no code with the
// prover (no header or library of the rest of src/): only MPFI, MPFR, GMP, nlohmann-json and the
// C++ standard library. It only checks, it never searches. What it trusts and what it checks:
// README.md beside this file; the format: docs/certificates.md.
//
//   dfchaos-recheck [--] FILE...      dfchaos-recheck --help | --version
//
// Exit status: 0 every step of every file re-verified (one line per file: OK, the statement, the
// number of steps); 1 a step failed (named); 2 a malformed certificate (not a regular file,
// unreadable, larger than kMaxBytes, not JSON, a duplicate key, a missing field, another format or
// version, embedded or not, a number that is not an exact hexadecimal float). Each file gets its
// line, written out as soon as it is decided; the status is the worst of them.
#include <fcntl.h>
#include <gmp.h>
#include <mpfi.h>
#include <mpfr.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace {

using json = nlohmann::json;

constexpr mpfr_prec_t kPrecision = 256;  // every number and interval of the checker
constexpr const char* kFormat = "dfchaos-certificate";
constexpr int kVersion = 1;
/// Largest certificate read (bytes): the largest that `make reproduce` writes is a few megabytes.
constexpr long long kMaxBytes = 256LL << 20;
#ifndef DFCHAOS_VERSION
#define DFCHAOS_VERSION "unknown"
#endif

/// The certificate cannot be read as one of the format (exit 2).
struct Malformed : std::runtime_error {
  using std::runtime_error::runtime_error;
};
/// A step of the proof was not re-verified (exit 1).
struct Failed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// An exact binary number (MPFR, kPrecision bits).
struct Num {
  mpfr_t x;
  Num() { mpfr_init2(x, kPrecision); }
  Num(const Num& o) : Num() { mpfr_set(x, o.x, MPFR_RNDN); }
  Num& operator=(const Num& o) {
    mpfr_set(x, o.x, MPFR_RNDN);
    return *this;
  }
  ~Num() { mpfr_clear(x); }
};

/// A closed interval (MPFI, kPrecision bits), outward rounded.
struct Iv {
  mpfi_t x;
  Iv() { mpfi_init2(x, kPrecision); }
  explicit Iv(const Num& n) : Iv() { mpfi_set_fr(x, n.x); }
  Iv(const Num& lo, const Num& hi) : Iv() { mpfi_interv_fr(x, lo.x, hi.x); }
  explicit Iv(double d) : Iv() { mpfi_set_d(x, d); }
  Iv(double lo, double hi) : Iv() { mpfi_interv_d(x, lo, hi); }
  Iv(const Iv& o) : Iv() { mpfi_set(x, o.x); }
  Iv& operator=(const Iv& o) {
    mpfi_set(x, o.x);
    return *this;
  }
  ~Iv() { mpfi_clear(x); }
  bool negative() const { return !mpfi_nan_p(x) && mpfi_is_strictly_neg(x) > 0; }  // every point < 0
  bool positive() const { return !mpfi_nan_p(x) && mpfi_is_strictly_pos(x) > 0; }  // every point > 0
};

using Binary = int (*)(mpfi_ptr, mpfi_srcptr, mpfi_srcptr);
using Unary = int (*)(mpfi_ptr, mpfi_srcptr);
Iv apply(Binary f, const Iv& a, const Iv& b) {
  Iv r;
  f(r.x, a.x, b.x);
  return r;
}
Iv apply(Unary f, const Iv& a) {
  Iv r;
  f(r.x, a.x);
  return r;
}
Iv operator+(const Iv& a, const Iv& b) { return apply(mpfi_add, a, b); }
Iv operator-(const Iv& a, const Iv& b) { return apply(mpfi_sub, a, b); }
Iv operator*(const Iv& a, const Iv& b) { return apply(mpfi_mul, a, b); }
Iv operator/(const Iv& a, const Iv& b) { return apply(mpfi_div, a, b); }
Iv operator*(double k, const Iv& a) { return Iv(k) * a; }
Iv operator-(const Iv& a) { return apply(mpfi_neg, a); }
Iv sqr(const Iv& a) { return apply(mpfi_sqr, a); }
Iv abs(const Iv& a) { return apply(mpfi_abs, a); }
Iv hull(const Iv& a, const Iv& b) { return apply(mpfi_union, a, b); }
Iv sin(const Iv& a) { return apply(mpfi_sin, a); }
Iv cos(const Iv& a) { return apply(mpfi_cos, a); }
Iv cot(const Iv& a) { return apply(mpfi_cot, a); }
Iv asin(const Iv& a) { return apply(mpfi_asin, a); }
Iv pi() {
  Iv r;
  mpfi_const_pi(r.x);
  return r;
}
/// The upper end of x, as a thin interval.
Iv upper(const Iv& x) {
  Num n;
  mpfi_get_right(n.x, x.x);
  return Iv(n);
}
/// Every point of x <= every point of y (resp. <).
bool le(const Iv& x, const Iv& y) {
  const Iv d = y - x;
  return !mpfi_nan_p(d.x) && mpfi_is_nonneg(d.x) > 0;
}
bool lt(const Iv& x, const Iv& y) { return (y - x).positive(); }

// ---- the formulas, from the paper ----------------------------------------------------------------

/// Eq. (1): f(x) = pi - x - cot(x/2); its zero in (0, pi/2] is vartheta0.
Iv f_eq1(const Iv& x) { return pi() - x - cot(0.5 * x); }
/// f'(x) = -1 + 1 / (2 sin^2(x/2)).
Iv f_eq1_slope(const Iv& x) {
  const Iv s = sin(0.5 * x);
  return Iv(1.0) / (2.0 * (s * s)) - Iv(1.0);
}
/// Section 2, Eq. (3): the force F(t) = a sin t + 2b, its slope F'(t) = a cos t and F''(t) = -a sin t.
Iv F(const Iv& a, const Iv& b, const Iv& t) { return a * sin(t) + 2.0 * b; }
Iv F_slope(const Iv& a, const Iv& t) { return a * cos(t); }
Iv F_curvature(const Iv& a, const Iv& t) { return -(a * sin(t)); }
/// Section 2: t0 = arcsin((q - 2b)/a) where F = q rises, t1 = pi - t0 where it falls;
/// t2 = pi + arcsin(2b/a) where F = 0 falls, t3 = 2 pi - arcsin(2b/a) where it rises.
Iv t0(const Iv& a, const Iv& b, const Iv& q) { return asin((q - 2.0 * b) / a); }
Iv t1(const Iv& a, const Iv& b, const Iv& q) { return pi() - t0(a, b, q); }
Iv t2(const Iv& a, const Iv& b) { return pi() + asin(2.0 * b / a); }
Iv t3(const Iv& a, const Iv& b) { return 2.0 * pi() - asin(2.0 * b / a); }
/// Eq. (7): the velocity of the progression from rest at t0, u(t) = a cos t0 - a cos t + 2c (t - t0),
/// 2c = 2b - q.
Iv u_from_t0(const Iv& a, const Iv& b, const Iv& q, const Iv& t) {
  const Iv s = t0(a, b, q);
  return a * cos(s) - a * cos(t) + (2.0 * b - q) * (t - s);
}
/// Eq. (8): u(t2), its value at t2.
Iv u_at_t2(const Iv& a, const Iv& b, const Iv& q) { return u_from_t0(a, b, q, t2(a, b)); }
/// Eq. (11): the flight from rest at theta, G1(theta, t) = b (t - theta)^2 - a sin t + a cos theta
/// (t - theta) + a sin theta (zero at the impact T1); its t-derivative is
/// dG1(theta, t) = 2b (t - theta) - a cos t + a cos theta, and d2G1/dt2 = F(t).
Iv G1(const Iv& a, const Iv& b, const Iv& th, const Iv& t) { return b * sqr(t - th) - a * sin(t) + a * cos(th) * (t - th) + a * sin(th); }
Iv dG1(const Iv& a, const Iv& b, const Iv& th, const Iv& t) { return 2.0 * b * (t - th) - a * cos(t) + a * cos(th); }
/// Eq. (17): the progression after the impact at theta1, G2(theta, theta1, t) = 2b (theta1 - theta)
/// + a cos theta + (2b - q)(t - theta1) - a cos t (zero at the stop theta2); dG2/dt = F(t) - q.
Iv G2(const Iv& a, const Iv& b, const Iv& q, const Iv& th, const Iv& th1, const Iv& t) {
  return 2.0 * b * (th1 - th) + a * cos(th) + (2.0 * b - q) * (t - th1) - a * cos(t);
}

// ---- reading ---------------------------------------------------------------------------------------

const json& field(const json& j, const std::string& key, const std::string& where) {
  if (!j.is_object() || !j.contains(key)) throw Malformed("missing field '" + where + key + "'");
  return j.at(key);
}

/// Whether s has the form -?0x H(.H+)? p[+-]?D{1,6} (H a hexadecimal digit, D a decimal digit).
bool is_hex_float(const std::string& s) {
  std::size_t i = 0;
  const auto digits = [&](auto is_digit, std::size_t at_most) {
    std::size_t n = 0;
    while (i < s.size() && n < at_most && is_digit(static_cast<unsigned char>(s[i]))) ++i, ++n;
    return n;
  };
  const auto hex = [](int c) { return std::isxdigit(c) != 0; };
  const auto dec = [](int c) { return std::isdigit(c) != 0; };
  if (i < s.size() && s[i] == '-') ++i;
  if (s.compare(i, 2, "0x") != 0) return false;
  i += 2;
  if (digits(hex, 1) != 1) return false;
  if (i < s.size() && s[i] == '.') {
    ++i;
    if (digits(hex, s.size()) == 0) return false;
  }
  if (i >= s.size() || s[i] != 'p') return false;
  ++i;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  const std::size_t e = digits(dec, 6);
  return e >= 1 && i == s.size();
}

/// An exact hexadecimal floating-point string ("0x1.8p-3"), parsed exactly at kPrecision bits.
Num exact(const json& j, const std::string& where) {
  if (!j.is_string()) throw Malformed("'" + where + "' is not a string");
  const std::string s = j.get<std::string>();
  if (!is_hex_float(s)) throw Malformed("'" + where + "' = '" + s + "' is not an exact hexadecimal float");
  Num n;
  char* end = nullptr;
  if (mpfr_strtofr(n.x, s.c_str(), &end, 16, MPFR_RNDN) != 0 || *end != '\0')
    throw Malformed("'" + where + "' = '" + s + "' is not exact at " + std::to_string(kPrecision) + " bits");
  return n;
}

/// An exact hexadecimal float that is a double: std::strtod reads it, and reads it exactly.
double exact_double(const json& j, const std::string& where) {
  const Num n = exact(j, where);
  const std::string s = j.get<std::string>();
  char* end = nullptr;
  const double d = std::strtod(s.c_str(), &end);
  if (*end != '\0' || !std::isfinite(d) || mpfr_cmp_d(n.x, d) != 0) throw Malformed("'" + where + "' = '" + s + "' is not exactly a double");
  return d;
}

/// A parameter {"hex": ..., "decimal": ...}: the hex string is the number (the decimal is for humans).
double parameter(const json& j, const std::string& key, const std::string& where) {
  return exact_double(field(field(j, key, where), "hex", where + key + "."), where + key + ".hex");
}

/// A certificate held inside another (`where` names it, e.g. "witnesses.arc_l1"): an object of this
/// format and version whose statement is `statement`, as a file of its own must be.
void require_embedded(const json& j, const std::string& statement, const std::string& where) {
  if (!j.is_object()) throw Malformed("'" + where + "' is not an embedded certificate (an object)");
  const json& f = field(j, "format", where + ".");
  if (!f.is_string() || f.get<std::string>() != kFormat) throw Malformed("'" + where + ".format' is not \"" + std::string(kFormat) + "\"");
  const json& v = field(j, "version", where + ".");
  if (!v.is_number_integer() || v.get<long long>() != kVersion)
    throw Malformed("'" + where + ".version' is " + v.dump() + " (this checker reads version " + std::to_string(kVersion) + ")");
  const json& st = field(j, "statement", where + ".");
  if (!st.is_string() || st.get<std::string>() != statement) throw Malformed("'" + where + "' is not a " + statement + " certificate");
}

/// Checks an embedded certificate with `check`; a malformed field or a failed step inside it is named
/// with the place of the embedded certificate ("witnesses.arc_l1: 'parameters.a' ...").
template <class Check>
long embedded(const std::string& where, Check&& check) {
  try {
    return check();
  } catch (const Failed& e) {
    throw Failed(where + ": " + e.what());
  } catch (const Malformed& e) {
    throw Malformed(where + ": " + e.what());
  }
}

/// The amplitude a of a certificate whose statement is about the ratios b/a and q/a only: still a
/// field of the format (docs/certificates.md), an exact double > 0.
void require_amplitude(const json& c) {
  const json& p = field(c, "parameters", "");
  if (!(parameter(p, "a", "parameters.") > 0)) throw Malformed("'parameters.a' is not a positive number");
}

/// An array of `n` exact doubles.
std::vector<double> doubles(const json& j, std::size_t n, const std::string& where) {
  if (!j.is_array() || j.size() != n) throw Malformed("'" + where + "' is not an array of " + std::to_string(n) + " numbers");
  std::vector<double> v;
  for (std::size_t i = 0; i < n; ++i) v.push_back(exact_double(j[i], where + "[" + std::to_string(i) + "]"));
  return v;
}

// ---- checking --------------------------------------------------------------------------------------

/// Counts the steps re-verified; the first that fails ends the check.
struct Steps {
  long n = 0;
  void require(bool ok, const std::string& step) {
    if (!ok) throw Failed(step);
    ++n;
  }
};

/// Whether the closed intervals cover [lo, hi] (lo == hi: contain the point).
bool covers(std::vector<std::pair<double, double>> v, double lo, double hi) {
  std::sort(v.begin(), v.end());
  double reach = lo;
  bool started = false;
  for (const auto& [l, h] : v) {
    if (l > reach) break;  // (reach, l) is covered by nothing
    if (h >= reach) {
      reach = h;
      started = true;
    }
  }
  return started && reach >= hi;
}

/// A sub-box [b_lo, b_hi] x [q_lo, q_hi].
struct Box {
  double b_lo, b_hi, q_lo, q_hi;
};

std::string describe(const Box& s) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "b in [%a, %a], q in [%a, %a]", s.b_lo, s.b_hi, s.q_lo, s.q_hi);
  return buf;
}

/// How a ball's start phases are given: [th_lo, th_hi] (doubles), or ["t2", th_hi], the phases
/// [t2(b), th_hi] from t2 exactly, for each b of the box.
enum class Start { Interval, FromT2 };

/// A closed set [th_lo, th_hi] x [b_lo, b_hi] x [q_lo, q_hi] (a ball of a covering certificate; a
/// Lemma 1 sub-box has th_lo = th_hi = 0).
struct Ball {
  double th_lo, th_hi;
  Box box;
  Start start = Start::Interval;
};

/// The sorted distinct values of `ends` clipped to [lo, hi], with lo and hi.
std::vector<double> edges(double lo, double hi, std::vector<double> ends) {
  for (double& e : ends) e = std::clamp(e, lo, hi);
  ends.insert(ends.end(), {lo, hi});
  std::sort(ends.begin(), ends.end());
  ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
  return ends;
}

/// Requires that the closed balls cover [th_lo, th_hi] x box, exactly in double comparisons: for each
/// open cell between consecutive theta edges (the point when th_lo == th_hi) and consecutive b edges
/// (likewise), the q ranges of the balls whose closed theta and b ranges contain the cell cover
/// [q_lo, q_hi]. Closed balls then cover the cells' edges too.
void require_cover(Steps& st, const std::vector<Ball>& balls, double th_lo, double th_hi, const Box& box, const std::string& step) {
  std::vector<double> th_ends, b_ends;
  for (const Ball& s : balls) th_ends.insert(th_ends.end(), {s.th_lo, s.th_hi}), b_ends.insert(b_ends.end(), {s.box.b_lo, s.box.b_hi});
  const std::vector<double> th = edges(th_lo, th_hi, th_ends), b = edges(box.b_lo, box.b_hi, b_ends);
  if (static_cast<double>(th.size()) * static_cast<double>(b.size()) * static_cast<double>(balls.size()) > 2e8)
    throw Failed(step + ": the cover is too large to check (" + std::to_string(th.size()) + " theta edges, " + std::to_string(b.size()) +
                 " b edges, " + std::to_string(balls.size()) + " balls)");
  const auto cells = [](const std::vector<double>& e) {
    std::vector<std::pair<double, double>> c;
    for (std::size_t i = 0; i + 1 < e.size(); ++i) c.emplace_back(e[i], e[i + 1]);
    if (e.size() == 1) c.emplace_back(e[0], e[0]);
    return c;
  };
  const auto covered = [&] {
    for (const auto& [x, y] : cells(th)) {
      std::vector<const Ball*> in;
      for (const Ball& s : balls)
        if (s.th_lo <= x && s.th_hi >= y) in.push_back(&s);
      for (const auto& [u, v] : cells(b)) {
        std::vector<std::pair<double, double>> q;
        for (const Ball* s : in)
          if (s->box.b_lo <= u && s->box.b_hi >= v) q.emplace_back(s->box.q_lo, s->box.q_hi);
        if (!covers(q, box.q_lo, box.q_hi)) return false;
      }
    }
    return true;
  };
  st.require(covered(), step);
}

/// Eq. (1): f(lo) < 0 < f(hi) with 0 < lo < hi < pi/2 (f' > 0 on (0, pi/2): analytic, README.md);
/// then the correctly rounded doubles of vartheta0 and sin vartheta0, when given.
void vartheta0_steps(Steps& st, const Num& lo, const Num& hi) {
  const Iv L(lo), H(hi);
  st.require(L.positive() && (H - L).positive() && (0.5 * pi() - H).positive(), "0 < lo < hi < pi/2");
  st.require(f_eq1(L).negative(), "Eq. (1): f(lo) < 0");
  st.require(f_eq1(H).positive(), "Eq. (1): f(hi) > 0");
  st.require(f_eq1_slope(Iv(lo, hi)).positive(), "Eq. (1): f' > 0 on [lo, hi]");
}

long check_vartheta0(const json& c) {
  Steps st;
  const json& w = field(c, "witnesses", "");
  const json& br = field(w, "bracket", "witnesses.");
  const Num lo = exact(field(field(br, "lo", "witnesses.bracket."), "hex", "witnesses.bracket.lo."), "witnesses.bracket.lo.hex");
  const Num hi = exact(field(field(br, "hi", "witnesses.bracket."), "hex", "witnesses.bracket.hi."), "witnesses.bracket.hi.hex");
  vartheta0_steps(st, lo, hi);
  const Iv bracket(lo, hi);
  // A double d is the nearest to every point of X when X lies strictly between the midpoints of d
  // and its neighbours (exact at kPrecision bits).
  auto rounds_to = [](const Iv& X, double d) {
    const Iv D(d), below = 0.5 * (D + Iv(std::nextafter(d, -INFINITY))), above = 0.5 * (D + Iv(std::nextafter(d, INFINITY)));
    return (X - below).positive() && (above - X).positive();
  };
  if (w.contains("value_double")) st.require(rounds_to(bracket, parameter(w, "value_double", "witnesses.")), "vartheta0 rounds to value_double");
  if (w.contains("sine_double"))
    st.require(rounds_to(sin(bracket), parameter(w, "sine_double", "witnesses.")), "sin(vartheta0) rounds to sine_double");
  // Printed decimals "0.d1...dn" (the paper's): the value lies in [x - 5e-(n+1), x + 5e-(n+1)), the
  // numbers that round to x at n decimals (the decimal ends enclosed by MPFI).
  if (w.contains("decimals")) {
    const json& list = w["decimals"];
    if (!list.is_array()) throw Malformed("'witnesses.decimals' is not an array");
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string where = "witnesses.decimals[" + std::to_string(i) + "].";
      const json& of = field(list[i], "of", where);
      const json& jv = field(list[i], "value", where);
      const std::string v = jv.is_string() ? jv.get<std::string>() : "";
      const std::size_t n = v.size() > 2 ? v.size() - 2 : 0;
      if ((of != "vartheta0" && of != "sine") || v.compare(0, 2, "0.") != 0 || n < 1 || n > 30 ||
          !std::all_of(v.begin() + 2, v.end(), [](char ch) { return std::isdigit(static_cast<unsigned char>(ch)) != 0; }))
        throw Malformed("'" + where + "' is not {\"of\": \"vartheta0\" or \"sine\", \"value\": \"0.<1 to 30 digits>\"}");
      Iv x, half(5.0);
      mpfi_set_str(x.x, v.c_str(), 10);
      for (std::size_t d = 0; d <= n; ++d) half = half / Iv(10.0);
      const Iv X = of == "vartheta0" ? bracket : sin(bracket);
      st.require(le(x - half, X) && lt(X, x + half),
                 "the printed " + v + " is " + of.get<std::string>() + " correctly rounded to " + std::to_string(n) + " decimals");
    }
  }
  return st.n;
}

/// The standing conditions of Section 2 on {a} x B x Q: 2b < a, q > 2b, q - 2b < a, and b > 0
/// unless B starts at 0 (b0's [0, b_low], whose statement is about (0, b_low]).
void standing(Steps& st, const Iv& A, const Iv& B, const Iv& Q, bool b_positive) {
  st.require(A.positive(), "a > 0");
  if (b_positive) st.require(B.positive(), "b > 0 on the box");
  st.require((A - 2.0 * B).positive(), "2b < a on the box");
  st.require((Q - 2.0 * B).positive(), "q > 2b on the box");
  st.require((A - (Q - 2.0 * B)).positive(), "q - 2b < a on the box");
}

/// The parameters {a} x [b_lo, b_hi] x [q_lo, q_hi] of a certificate.
std::pair<double, Box> read_box(const json& c) {
  const json& p = field(c, "parameters", "");
  const json &b = field(p, "b", "parameters."), &q = field(p, "q", "parameters.");
  return {parameter(p, "a", "parameters."),
          {parameter(b, "lo", "parameters.b."), parameter(b, "hi", "parameters.b."), parameter(q, "lo", "parameters.q."),
           parameter(q, "hi", "parameters.q.")}};
}

/// The box is not empty and the standing conditions hold on it; returns {a}.
Iv standing_box(Steps& st, double a, const Box& box) {
  st.require(box.b_lo <= box.b_hi && box.q_lo <= box.q_hi, "the box is not empty");
  const Iv A(a);
  standing(st, A, Iv(box.b_lo, box.b_hi), Iv(box.q_lo, box.q_hi), true);
  return A;
}

/// Lemma 1's witness {"sub_boxes": [[b_lo, b_hi, q_lo, q_hi], ...]}.
std::vector<Ball> read_sub_boxes(const json& w, const std::string& where) {
  const json& list = field(w, "sub_boxes", where);
  if (!list.is_array()) throw Malformed("'" + where + "sub_boxes' is not an array");
  std::vector<Ball> subs;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::vector<double> v = doubles(list[i], 4, where + "sub_boxes[" + std::to_string(i) + "]");
    subs.push_back({0, 0, {v[0], v[1], v[2], v[3]}});
  }
  return subs;
}

/// Lemma 1 over the box (its standing conditions already required): the sub-boxes inside the box
/// and covering it, Eq. (8) u(t2) < 0 on each.
void lemma1(Steps& st, const Iv& A, const Box& box, const std::vector<Ball>& subs) {
  for (std::size_t i = 0; i < subs.size(); ++i) {
    const Box& s = subs[i].box;
    st.require(s.b_lo <= s.b_hi && s.q_lo <= s.q_hi && box.b_lo <= s.b_lo && s.b_hi <= box.b_hi && box.q_lo <= s.q_lo && s.q_hi <= box.q_hi,
               "Lemma 1: sub-box " + std::to_string(i) + " (" + describe(s) + ") lies inside the box");
  }
  require_cover(st, subs, 0, 0, box, "Lemma 1: the sub-boxes cover the box (no gap)");
  for (std::size_t i = 0; i < subs.size(); ++i) {
    const Box& s = subs[i].box;
    st.require(u_at_t2(A, Iv(s.b_lo, s.b_hi), Iv(s.q_lo, s.q_hi)).negative(),
               "Lemma 1: Eq. (8): u(t2) < 0 on sub-box " + std::to_string(i) + " (" + describe(s) + ")");
  }
}

/// Lemma 1 over {a} x [b_lo, b_hi] x [q_lo, q_hi]: the standing conditions on the box, the
/// sub-boxes inside it and covering it, Eq. (8) u(t2) < 0 on each.
long check_lemma1(const json& c) {
  Steps st;
  const auto [a, box] = read_box(c);
  const std::vector<Ball> subs = read_sub_boxes(field(c, "witnesses", ""), "witnesses.");
  lemma1(st, standing_box(st, a, box), box, subs);
  return st.n;
}

/// A lower bound b_low of b0(q): the standing conditions on {a} x [0, b_low] x {q}, the
/// b-intervals inside [0, b_low] and covering it, Eq. (8) u(t2) < 0 on each.
long check_b0(const json& c) {
  Steps st;
  const json& p = field(c, "parameters", "");
  const double a = parameter(p, "a", "parameters."), q = parameter(p, "q", "parameters.");
  const json& w = field(c, "witnesses", "");
  const double b_low = parameter(w, "b_low", "witnesses.");
  const Iv A(a), Q(q);
  st.require(b_low > 0, "b_low > 0");
  standing(st, A, Iv(0.0, b_low), Q, false);
  const json& list = field(w, "b_pieces", "witnesses.");
  if (!list.is_array()) throw Malformed("'witnesses.b_pieces' is not an array");
  std::vector<std::pair<double, double>> pieces;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::vector<double> v = doubles(list[i], 2, "witnesses.b_pieces[" + std::to_string(i) + "]");
    pieces.emplace_back(v[0], v[1]);
    st.require(0 <= v[0] && v[0] <= v[1] && v[1] <= b_low,
               "b piece " + std::to_string(i) + " [" + describe({v[0], v[1], q, q}) + "] lies inside [0, b_low]");
  }
  st.require(covers(pieces, 0, b_low), "the b pieces cover [0, b_low] (no gap)");
  for (std::size_t i = 0; i < pieces.size(); ++i)
    st.require(u_at_t2(A, Iv(pieces[i].first, pieces[i].second), Q).negative(),
               "Eq. (8): u(t2) < 0 on b piece " + std::to_string(i) + " (" + describe({pieces[i].first, pieces[i].second, q, q}) + ")");
  return st.n;
}

// ---- covering: Lemma 4 (Theorem 1) ----------------------------------------------------------------

/// n as a normalised hexadecimal float ("0x1.8p-3", as certificates write it), exactly.
std::string hex(const Num& n) {
  if (mpfr_zero_p(n.x)) return "0x0p+0";
  mpfr_exp_t e = 0;
  char* bits = mpfr_get_str(nullptr, &e, 2, 0, n.x, MPFR_RNDN);  // n = 0.bits * 2^e, exact
  std::string b = bits, out = b[0] == '-' ? "-0x1" : "0x1";
  mpfr_free_str(bits);
  b = b.substr(b[0] == '-' ? 2 : 1);  // the bits after the leading 1
  while (!b.empty() && b.back() == '0') b.pop_back();
  if (!b.empty()) out += '.';
  for (std::size_t i = 0; i < b.size(); i += 4) out += "0123456789abcdef"[std::stoi((b.substr(i, 4) + "000").substr(0, 4), nullptr, 2)];
  return out + (e - 1 >= 0 ? "p+" : "p") + std::to_string(e - 1);
}

/// A piece [x1, x2] of a negativity list and the test named for it.
struct Piece {
  Num x1, x2;
  std::string test;
};

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

/// A function f of one variable with its derivatives, and (for the no-contact list only) an upper
/// envelope U >= f that is convex, so that U < 0 at both ends of a piece gives f < 0 on it.
struct Fn {
  std::function<Iv(const Iv&)> f, d1, d2, envelope;
};

/// Requires f < 0 on [X1, X2]: the pieces lie inside [X1, X2] and cover it, and on each piece
/// X = [x1, x2], with midpoint m in M and radius r <= R, the named test holds:
///   taylor:   f(m) + r |f'(m)| + (r^2/2) max(0, f''(X)) < 0 (Taylor's theorem at m);
///   monotone: f' lies in D = f'(M) + [-1, 1] r |f''(X)| (the mean-value theorem); D > 0 and
///             f(x2) < 0, or D < 0 and f(x1) < 0;
///   envelope: U(x1) < 0 and U(x2) < 0.
///   With `hole`, a gap (g1, g2) between the pieces is allowed where hole(g1, g2) holds (f < 0 is
///   proved there by another argument: Lemma 2's tangency window).
void negative_on(Steps& st, const std::vector<Piece>& ps, const Num& X1, const Num& X2, const Fn& fn, const std::string& what,
                 const std::function<bool(const Num&, const Num&)>& hole = {}) {
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
BallWitness read_ball(const json& j, const std::string& where, bool allow_none = false, bool long_theta = false) {
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
void check_T1(Steps& st, const Iv& A, const BallWitness& w, const std::string& who, const Window* skip = nullptr) {
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

/// Lemma 4 (Theorem 1): two disjoint segments J0 < J1 in [t2, 3 pi/2], each covered by balls on
/// which T is continuous, with T(theta_top) >= 3 pi/2 and T(theta_t2) = t2: T(J) contains [t2, 3 pi/2].
long check_covering(const json& c) {
  Steps st;
  const auto [a, box] = read_box(c);
  const json& w = field(c, "witnesses", "");
  const bool has_lemma1 = w.contains("lemma1");
  const std::vector<Ball> subs = has_lemma1 ? read_sub_boxes(w["lemma1"], "witnesses.lemma1.") : std::vector<Ball>{};
  const json& segs = field(w, "segments", "witnesses.");
  if (!segs.is_array() || segs.size() != 2) throw Malformed("'witnesses.segments' is not an array of two segments");
  const char* const lists[3] = {"top", "t2_end", "cover"};
  struct Segment {
    double lo, hi, top, bot;
    std::vector<BallWitness> balls[3];
  } J[2];
  for (std::size_t s = 0; s < 2; ++s) {
    const std::string ws(s == 0 ? "witnesses.segments[0]." : "witnesses.segments[1].");
    J[s].lo = exact_double(field(segs[s], "lo", ws), ws + "lo"), J[s].hi = exact_double(field(segs[s], "hi", ws), ws + "hi");
    J[s].top = exact_double(field(segs[s], "theta_top", ws), ws + "theta_top");
    J[s].bot = exact_double(field(segs[s], "theta_t2", ws), ws + "theta_t2");
    for (std::size_t l = 0; l < 3; ++l) {
      const json& jl = field(segs[s], lists[l], ws);
      if (!jl.is_array()) throw Malformed("'" + ws + lists[l] + "' is not an array");
      for (std::size_t i = 0; i < jl.size(); ++i) J[s].balls[l].push_back(read_ball(jl[i], ws + lists[l] + "[" + std::to_string(i) + "]."));
    }
  }
  // Everything is read: the checks.
  const Iv A = standing_box(st, a, box);
  if (has_lemma1) lemma1(st, A, box, subs);
  std::string needs_lemma1;  // the first ball that needs Lemma 1
  for (std::size_t s = 0; s < 2; ++s) {
    const std::string name(s == 0 ? "J0" : "J1");
    const Segment& seg = J[s];
    st.require(seg.lo == std::min(seg.top, seg.bot) && seg.hi == std::max(seg.top, seg.bot),
               name + ": lo = min(theta_top, theta_t2), hi = max(theta_top, theta_t2)");
    st.require(le(t2(A, Iv(box.b_hi)), Iv(seg.lo)) && le(Iv(seg.hi), 1.5 * pi()), name + ": t2(b_hi) <= lo and hi <= 3 pi/2");
    for (std::size_t l = 0; l < 3; ++l) {
      const double th_lo = l == 0 ? seg.top : l == 1 ? seg.bot : seg.lo, th_hi = l == 0 ? seg.top : l == 1 ? seg.bot : seg.hi;
      std::vector<Ball> balls;
      for (std::size_t i = 0; i < seg.balls[l].size(); ++i) {
        const BallWitness& bw = seg.balls[l][i];
        const Box& x = bw.ball.box;
        const std::string who = name + " " + lists[l] + " ball " + std::to_string(i);
        balls.push_back(bw.ball);
        st.require(x.b_lo <= x.b_hi && x.q_lo <= x.q_hi && box.b_lo <= x.b_lo && x.b_hi <= box.b_hi && box.q_lo <= x.q_lo && x.q_hi <= box.q_hi,
                   who + ": lies inside the parameter box (" + describe(x) + ")");
        st.require(th_lo <= bw.ball.th_lo && bw.ball.th_lo <= bw.ball.th_hi && bw.ball.th_hi <= th_hi,
                   who + ": theta range inside the list's theta range");
        const Outcome o = check_ball(st, A, bw, who);
        if (o.needs_lemma1 && needs_lemma1.empty()) needs_lemma1 = who;
        if (l == 0) st.require(o.ab && o.theta2 && le(1.5 * pi(), o.u_lo - o.two_pi_k), who + ": T >= 3 pi/2 (case AB, u_lo - 2 pi k >= 3 pi/2)");
        if (l == 1)
          st.require(!o.ab || lt(o.u_hi - o.two_pi_k, t2(A, Iv(x.b_lo, x.b_hi))), who + ": T = t2 (case BC, or AB with u_hi - 2 pi k < t2)");
      }
      require_cover(st, balls, th_lo, th_hi, box, name + " " + lists[l] + ": the balls cover the theta range x the parameter box (no gap)");
    }
  }
  st.require(needs_lemma1.empty() || has_lemma1, "Lemma 1 is needed (first by " + needs_lemma1 + ") and witnesses.lemma1 is given");
  st.require(J[0].hi < J[1].lo, "Lemma 4: J0.hi < J1.lo (disjoint segments)");
  return st.n;
}

// ---- Lemma 2: the discontinuities of T1 ------------------------------------------------------------

/// The symmetric tangencies (proof of Lemma 2, Eq. 14): h(z) = 2z - (a/b) cos z = (2k+1) pi.
Iv h_tangency(const Iv& a, const Iv& b, const Iv& z) { return 2.0 * z - a / b * cos(z); }
/// (2k+1) pi.
Iv odd_pi(long long k) { return Iv(static_cast<double>(2 * k + 1)) * pi(); }

/// A pair [x, y] of exact numbers.
std::pair<Num, Num> exact_pair(const json& j, const std::string& where) {
  if (!j.is_array() || j.size() != 2) throw Malformed("'" + where + "' is not an array of 2 numbers");
  return {exact(j[0], where + "[0]"), exact(j[1], where + "[1]")};
}

/// A T1 ball of Lemma 2 at the point b: {"theta": [x, y] (exact), "T1": {...}}; or, with `right`,
/// the right piece of a tangency {"theta", "s0", "no_contact"} (no bracket).
BallWitness read_t1_ball(const json& j, const std::string& where, double b, bool right = false) {
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

/// Lemma 2 at (a, b) on L = L0 or L2 (docs/certificates.md): the k listed are exactly those with
/// (2k+1) pi in h(L), k >= 2; each z_k is bracketed, its tangency t* = (2k+1) pi - z_k lies in a
/// window W where F < 0; left of z_k a T1 ball whose no-contact proof skips W, right of z_k no
/// contact up to W (then the concavity of G1 on W); T1 balls cover the rest of [lo, hi], which
/// contains L. So T1 is discontinuous exactly at the z_k on L.
long check_discontinuities(const json& c, std::string& what) {
  Steps st;
  const json& p = field(c, "parameters", "");
  const double a = parameter(p, "a", "parameters."), b = parameter(p, "b", "parameters.");
  const json& segment = field(p, "segment", "parameters.");
  if (segment != "L0" && segment != "L2") throw Malformed("'parameters.segment' is not \"L0\" or \"L2\"");
  const json& w = field(c, "witnesses", "");
  const double lo = exact_double(field(w, "lo", "witnesses."), "witnesses.lo"), hi = exact_double(field(w, "hi", "witnesses."), "witnesses.hi");
  struct Tangency {
    long long k;
    Num zl, zh, wl, wh;
    BallWitness left, right;
  };
  std::vector<Tangency> ts;
  std::vector<BallWitness> cover;
  const json &jt = field(w, "tangencies", "witnesses."), &jc = field(w, "cover", "witnesses.");
  if (!jt.is_array() || !jc.is_array()) throw Malformed("'witnesses.tangencies' or 'witnesses.cover' is not an array");
  for (std::size_t i = 0; i < jt.size(); ++i) {
    const std::string wi = "witnesses.tangencies[" + std::to_string(i) + "].";
    Tangency t;
    t.k = turn(field(jt[i], "k", wi), wi + "k");
    std::tie(t.zl, t.zh) = exact_pair(field(jt[i], "z", wi), wi + "z");
    std::tie(t.wl, t.wh) = exact_pair(field(jt[i], "window", wi), wi + "window");
    t.left = read_t1_ball(field(jt[i], "left", wi), wi + "left.", b);
    t.right = read_t1_ball(field(jt[i], "right", wi), wi + "right.", b, true);
    ts.push_back(std::move(t));
  }
  for (std::size_t i = 0; i < jc.size(); ++i) cover.push_back(read_t1_ball(jc[i], "witnesses.cover[" + std::to_string(i) + "].", b));
  // Everything is read: the checks. L and h' = 2 + (a/b) sin z < 0 on (t2, t3) (sin z < -2b/a there).
  const Iv A(a), B(b);
  st.require(A.positive() && B.positive() && lt(2.0 * B, A), "a > 0 and 0 < 2b < a");
  const Iv Llo = Iv(101.0) * pi() / Iv(100.0), Lhi = segment == "L0" ? 1.5 * pi() : Iv(51.0) * pi() / Iv(50.0);
  st.require(le(Iv(lo), Llo) && le(Lhi, Iv(hi)), "[lo, hi] contains L = " + segment.get<std::string>());
  st.require(lt(t2(A, B), Iv(lo)) && lt(Iv(hi), t3(A, B)), "t2 < lo and hi < t3 (h decreases on [lo, hi])");
  // (i) The count: the k listed are consecutive, descending as z ascends, and exactly those k >= 2
  // with h(L.hi) < (2k+1) pi < h(L.lo).
  const Iv Hlo = h_tangency(A, B, Lhi), Hhi = h_tangency(A, B, Llo);
  for (std::size_t i = 0; i < ts.size(); ++i)
    st.require(ts[i].k == ts[0].k - static_cast<long long>(i), "tangency " + std::to_string(i) + ": k = k_0 - " + std::to_string(i));
  if (ts.empty()) {  // h(L) lies between (2K-1) pi (or K = 2) and (2K+1) pi
    const long long K = turn(field(w, "k_above", "witnesses."), "witnesses.k_above");
    st.require(K >= 2 && lt(Hhi, odd_pi(K)) && (K == 2 || lt(odd_pi(K - 1), Hlo)),
               "count: none listed, and (2K-1) pi < h(L.hi) (or K = 2), h(L.lo) < (2K+1) pi for K = k_above");
  } else {
    const long long kmax = ts.front().k, kmin = ts.back().k;
    st.require(kmin >= 2 && lt(Hlo, odd_pi(kmin)) && (kmin == 2 || lt(odd_pi(kmin - 1), Hlo)),
               "count: the least k listed is the least k >= 2 with (2k+1) pi > h(L.hi)");
    st.require(lt(odd_pi(kmax), Hhi) && lt(Hhi, odd_pi(kmax + 1)), "count: the greatest k listed is the greatest with (2k+1) pi < h(L.lo)");
  }
  std::vector<std::pair<Num, Num>> pieces_of_L;  // the closed sets on which T1 is continuous (one-sided at z_k)
  Num reach;
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const Tangency& t = ts[i];
    const std::string who = "tangency " + std::to_string(i) + " (k = " + std::to_string(t.k) + ")";
    // (ii) z_k in (z_lo, z_hi) inside L; t* = z + s = (2k+1) pi - z with the flight s = -(a/b) cos z > 0
    // is a double root of G1(z_k, .) (analytic); F < 0 on W makes G1(z_k, .) <= 0 on W.
    const Iv Zl(t.zl), Zh(t.zh), Z(t.zl, t.zh), Wl(t.wl), Wh(t.wh), Tstar = odd_pi(t.k) - Z;
    st.require(lt(Llo, Zl) && lt(Zl, Zh) && lt(Zh, Lhi), who + ": L.lo < z_lo < z_hi < L.hi");
    st.require((h_tangency(A, B, Zl) - odd_pi(t.k)).positive() && (h_tangency(A, B, Zh) - odd_pi(t.k)).negative(),
               who + ": z bracket: h(z_lo) > (2k+1) pi > h(z_hi)");
    st.require(cos(Z).negative(), who + ": the flight -(a/b) cos z > 0");
    st.require(lt(Wl, Tstar) && lt(Tstar, Wh), who + ": window: wl < t* = (2k+1) pi - z < wh");
    st.require(F(A, B, Iv(t.wl, t.wh)).negative(), who + ": window: F < 0 on W (G1 concave in t there)");
    // (iii) Left: T1 on [theta_lo, z_k) (theta_hi >= z_hi), W skipped: for theta < z_k, G1(theta, .) <
    // G1(z_k, .) <= 0 on W; the bracket after W.
    st.require(mpfr_cmp(t.left.th_lo.x, t.zl.x) <= 0 && mpfr_cmp(t.left.th_hi.x, t.zh.x) >= 0,
               who + ": left ball: theta_lo <= z_lo, theta_hi >= z_hi");
    const Window W{Wl, Wh};
    check_T1(st, A, t.left, who + " left ball", &W);
    st.require(lt(Wh, Iv(t.left.t_lo)), who + ": left ball: wh < t_lo (T1(z_k - 0) > T1(z_k) = t*)");
    // (iv) Right: G1 < 0 on (theta, wl] on [theta_lo, theta_hi], which contains [z_k, z_hi], theta_hi < wl; for
    // theta >= z_k, G1(theta, t*) >= 0 and G1 concave on W: T1 is the one crossing in (wl, t*].
    st.require(mpfr_cmp(t.right.th_lo.x, t.zl.x) <= 0 && mpfr_cmp(t.right.th_hi.x, t.zh.x) >= 0 && lt(Iv(t.right.th_hi), Wl),
               who + ": right piece: theta_lo <= z_lo, z_hi <= theta_hi < wl");
    const Corners cr = corners(A, t.right);
    start_set_step(st, A, t.right, cr, who + " right piece");
    no_contact_steps(st, A, t.right, cr, Wl, "wl", nullptr, who + " right piece");
    st.require(i == 0 || mpfr_cmp(ts[i - 1].zh.x, t.zl.x) < 0, who + ": z ascending");
    pieces_of_L.emplace_back(t.left.th_lo, t.right.th_hi);
  }
  // (v) T1 balls cover the rest: with the tangencies' [left theta_lo, right theta_hi], [lo, hi].
  for (std::size_t i = 0; i < cover.size(); ++i) {
    check_T1(st, A, cover[i], "cover ball " + std::to_string(i));
    pieces_of_L.emplace_back(cover[i].th_lo, cover[i].th_hi);
  }
  std::sort(pieces_of_L.begin(), pieces_of_L.end(), [](const auto& x, const auto& y) { return mpfr_cmp(x.first.x, y.first.x) < 0; });
  mpfr_set_d(reach.x, lo, MPFR_RNDN);
  bool started = false;
  for (const auto& [x, y] : pieces_of_L) {
    if (mpfr_cmp(x.x, reach.x) > 0) break;  // (reach, x) is covered by nothing
    if (mpfr_cmp(y.x, reach.x) >= 0) reach = y, started = true;
  }
  st.require(started && mpfr_cmp_d(reach.x, hi) >= 0, "the tangencies' pieces and the cover balls cover [lo, hi] (no gap)");
  what = std::to_string(ts.size()) + " discontinuities of T1 on " + segment.get<std::string>();
  return st.n;
}

// ---- Theorem 2 (Section 8) --------------------------------------------------------------------------

/// The parameters (a, b, q) of a certificate at a point.
std::tuple<double, double, double> read_point(const json& c) {
  const json& p = field(c, "parameters", "");
  return {parameter(p, "a", "parameters."), parameter(p, "b", "parameters."), parameter(p, "q", "parameters.")};
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
Outcome check_at_t2(Steps& st, const Iv& A, const json& j, double b, double q, const std::string& who, bool allow_none = false) {
  const BallWitness w = read_ball(j, who + ".", allow_none);
  st.require(w.ball.start == Start::FromT2, who + ": theta is [\"t2\", h]");
  st.require(w.ball.box.b_lo == b && w.ball.box.b_hi == b && w.ball.box.q_lo == q && w.ball.box.q_hi == q, who + ": at the parameter point");
  return check_ball(st, A, w, who);
}

/// Theorem 2's conclusion at (a, b, q) from the witnesses `w` (statement superstable, or a window's
/// middle): the condition (21) or (22) named, T = t2 on [t2, theta_end] with theta_end > t2, and the
/// hypotheses listed. Returns a description of what holds.
std::string superstable_at(Steps& st, double a, double b, double q, const json& w, const std::string& where) {
  const Box point{b, b, q, q};
  const Iv A = standing_box(st, a, point), B(b), Q(q);
  const bool has_lemma1 = w.contains("lemma1");
  if (has_lemma1) lemma1(st, A, point, read_sub_boxes(w["lemma1"], where + "lemma1."));
  bool needs_lemma1 = false;
  // The condition, from theta2(t2) (Section 8): (21) t1 < P < t2, (22) t3 < P < t0 + 2 pi.
  const Outcome at = check_at_t2(st, A, field(w, "at_t2", where), b, q, where + "at_t2");
  needs_lemma1 = at.needs_lemma1;
  const Iv P = phase(st, at, w, where);
  const json& jc = field(w, "condition", where);
  if (jc != 21 && jc != 22) throw Malformed("'" + where + "condition' is not 21 or 22");
  const int condition = jc.get<int>();
  if (condition == 21)
    st.require(lt(t1(A, B, Q), P) && lt(P, t2(A, B)), where + "(21): t1 < theta2(t2) - 2 pi k' < t2");
  else
    st.require(lt(t3(A, B), P) && lt(P, t0(A, B, Q) + 2.0 * pi()), where + "(22): t3 < theta2(t2) - 2 pi k' < t0 + 2 pi");
  // T = t2 on [t2, theta_end]: balls from t2 or inside (t2, theta_end], each T = t2, covering it.
  const double end = exact_double(field(w, "theta_end", where), where + "theta_end");
  st.require(lt(t2(A, B), Iv(end)), where + "theta_end > t2");
  const json& cover = field(w, "cover", where);
  if (!cover.is_array()) throw Malformed("'" + where + "cover' is not an array");
  Num t2_lo;  // a double <= t2: the lower end of balls from t2, in the exact cover comparison
  mpfi_get_left(t2_lo.x, t2(A, B).x);
  const double t2_down = mpfr_get_d(t2_lo.x, MPFR_RNDD);
  std::vector<Ball> balls;
  for (std::size_t i = 0; i < cover.size(); ++i) {
    const std::string who = where + "cover[" + std::to_string(i) + "]";
    BallWitness bw = read_ball(cover[i], who + ".");
    st.require(bw.ball.box.b_lo == b && bw.ball.box.b_hi == b && bw.ball.box.q_lo == q && bw.ball.box.q_hi == q,
               who + ": phases at the parameter point");
    const Outcome o = check_ball(st, A, bw, who);
    st.require(proves_T_is_t2(A, o, point), who + ": T = t2 (case BC, or AB with u_hi - 2 pi k < t2)");
    needs_lemma1 = needs_lemma1 || o.needs_lemma1;
    if (bw.ball.start == Start::FromT2) bw.ball.th_lo = t2_down;
    st.require(bw.ball.th_hi <= end, who + ": inside [t2, theta_end]");
    balls.push_back(bw.ball);
  }
  require_cover(st, balls, t2_down, end, point, where + "cover: the balls cover [t2, theta_end] (no gap)");
  st.require(!needs_lemma1 || has_lemma1, where + "Lemma 1 is needed and lemma1 is given");
  // The hypotheses the certificate lists: (2) 2b < a, a sin(vartheta0) < q < a; (23) q < a.
  const json& hyp = field(w, "hypotheses", where);
  if (!hyp.is_array()) throw Malformed("'" + where + "hypotheses' is not an array");
  bool h2 = false, h23 = false;
  for (const json& h : hyp) {
    if (h == "(2)") {
      const Iv v0 = vartheta0_bracket(st, w, where);
      st.require(lt(2.0 * B, A) && lt(A * sin(v0), Q) && lt(Q, A), where + "(2): 2b < a, a sin(vartheta0) < q < a");
      h2 = true;
    } else if (h == "(23)") {
      st.require(lt(Q, A), where + "(23): q < a");
      h23 = true;
    } else {
      throw Malformed("'" + where + "hypotheses' holds " + h.dump() + " (not \"(2)\" or \"(23)\")");
    }
  }
  const bool theorem2 = (h2 && condition == 22) || (h23 && condition == 21);
  return std::string("T = t2 on [t2, t2 + eps], (") + std::to_string(condition) + ")" + (theorem2 ? ", Theorem 2's hypotheses hold" : "");
}

long check_superstable(const json& c, std::string& what) {
  Steps st;
  const auto [a, b, q] = read_point(c);
  what = superstable_at(st, a, b, q, field(c, "witnesses", ""), "witnesses.");
  return st.n;
}

/// T(t2) > t2 at (a, b, q): t2 is not a fixed point of T.
long check_not_superstable(const json& c) {
  Steps st;
  const auto [a, b, q] = read_point(c);
  const Box point{b, b, q, q};
  const Iv A = standing_box(st, a, point);
  const Outcome o = check_at_t2(st, A, field(field(c, "witnesses", ""), "at_t2", "witnesses."), b, q, "witnesses.at_t2");
  st.require(proves_T_above_t2(A, o, point), "T(t2) > t2 (case AB, u_lo - 2 pi k > t2)");
  return st.n;
}

/// A superstability window in b at (a, q): on b-boxes covering [left_in, right_in], T = t2 on
/// [t2(b), h] with h > t2(b_hi) (t2 superstable at every such b); T(t2) > t2 at left_out and
/// right_out; Theorem 2's conclusion at the middle.
long check_window(const json& c) {
  Steps st;
  const json& p = field(c, "parameters", "");
  const double a = parameter(p, "a", "parameters."), q = parameter(p, "q", "parameters.");
  const json& w = field(c, "witnesses", "");
  double e[4];
  const char* names[4] = {"left_out", "left_in", "right_in", "right_out"};
  for (int i = 0; i < 4; ++i) e[i] = exact_double(field(w, names[i], "witnesses."), std::string("witnesses.") + names[i]);
  st.require(0 < e[0] && e[0] < e[1] && e[1] < e[2] && e[2] < e[3], "0 < left_out < left_in < right_in < right_out");
  const Box range{e[0], e[3], q, q}, inner{e[1], e[2], q, q};
  const Iv A = standing_box(st, a, range);
  const json& outer = field(w, "outer", "witnesses.");
  if (!outer.is_array() || outer.size() != 2) throw Malformed("'witnesses.outer' is not an array of two balls");
  for (int side = 0; side < 2; ++side) {
    const double b = side == 0 ? e[0] : e[3];
    const std::string who = side == 0 ? "witnesses.outer[0] (left_out)" : "witnesses.outer[1] (right_out)";
    const Outcome o = check_at_t2(st, A, outer[side], b, q, who);
    st.require(proves_T_above_t2(A, o, {b, b, q, q}), who + ": T(t2) > t2");
  }
  const bool has_lemma1 = w.contains("lemma1");
  if (has_lemma1) lemma1(st, A, inner, read_sub_boxes(w["lemma1"], "witnesses.lemma1."));
  const json& boxes = field(w, "boxes", "witnesses.");
  if (!boxes.is_array()) throw Malformed("'witnesses.boxes' is not an array");
  std::vector<Ball> balls;
  bool needs_lemma1 = false;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const std::string who = "witnesses.boxes[" + std::to_string(i) + "]";
    const BallWitness bw = read_ball(boxes[i], who + ".");
    const Box& x = bw.ball.box;
    st.require(bw.ball.start == Start::FromT2 && e[1] <= x.b_lo && x.b_lo <= x.b_hi && x.b_hi <= e[2] && x.q_lo == q && x.q_hi == q,
               who + ": phases [t2(b), h], b inside [left_in, right_in]");
    st.require(lt(t2(A, Iv(x.b_hi)), Iv(bw.ball.th_hi)), who + ": h > t2(b_hi) (so eps_b = h - t2(b) > 0 for every b)");
    const Outcome o = check_ball(st, A, bw, who);
    st.require(proves_T_is_t2(A, o, x), who + ": T = t2 on [t2(b), h], every b (case BC, or AB with u_hi - 2 pi k < t2)");
    needs_lemma1 = needs_lemma1 || o.needs_lemma1;
    balls.push_back(bw.ball);
  }
  require_cover(st, balls, 0, 0, inner, "the b-boxes cover [left_in, right_in] (no gap)");
  st.require(!needs_lemma1 || has_lemma1, "Lemma 1 is needed by a box and witnesses.lemma1 is given");
  const json& inside = field(w, "inside", "witnesses.");
  const double b_mid = exact_double(field(inside, "b", "witnesses.inside."), "witnesses.inside.b");
  st.require(e[1] <= b_mid && b_mid <= e[2], "inside.b lies in [left_in, right_in]");
  superstable_at(st, a, b_mid, q, inside, "witnesses.inside.");
  return st.n;
}

/// The erratum to Theorem 2: (2) and (22) hold at (a, b, q), yet u(t2) > 0 > u(t3) (Eq. 7), so the
/// progression from rest at t0 stops at t4 in (t2, t3), where the mass flies: T(t2) = t4 != t2.
long check_theorem2_counterexample(const json& c) {
  Steps st;
  const auto [a, b, q] = read_point(c);
  const json& w = field(c, "witnesses", "");
  const Iv A = standing_box(st, a, {b, b, q, q}), B(b), Q(q);
  const Iv v0 = vartheta0_bracket(st, w, "witnesses.");
  st.require(lt(2.0 * B, A) && lt(A * sin(v0), Q) && lt(Q, A), "(2): 2b < a, a sin(vartheta0) < q < a");
  const Outcome at = check_at_t2(st, A, field(w, "at_t2", "witnesses."), b, q, "witnesses.at_t2", true);
  const Iv P = phase(st, at, w, "witnesses.");
  st.require(lt(t3(A, B), P) && lt(P, t0(A, B, Q) + 2.0 * pi()), "(22): t3 < theta2(t2) - 2 pi k' < t0 + 2 pi");
  st.require(u_from_t0(A, B, Q, t2(A, B)).positive(), "Eq. (7): u(t2) > 0");
  st.require(u_from_t0(A, B, Q, t3(A, B)).negative(), "Eq. (7): u(t3) < 0");
  return st.n;
}

/// Lemma 4 over a set of boxes (a column of the certified region): each element of witnesses.boxes is
/// a `covering` certificate, checked as one, whose box lies in the certificate's {a} x B x Q.
long check_coverings(const json& c) {
  Steps st;
  const auto [a, box] = read_box(c);
  const json& boxes = field(field(c, "witnesses", ""), "boxes", "witnesses.");
  if (!boxes.is_array() || boxes.empty()) throw Malformed("'witnesses.boxes' is not a non-empty array");
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const std::string who = "witnesses.boxes[" + std::to_string(i) + "]";
    require_embedded(boxes[i], "covering", who);
    const auto [ai, x] = read_box(boxes[i]);
    st.require(ai == a && box.b_lo <= x.b_lo && x.b_hi <= box.b_hi && box.q_lo <= x.q_lo && x.q_hi <= box.q_hi,
               who + ": its box lies in the parameters");
    try {
      st.n += check_covering(boxes[i]);
    } catch (const Failed& e) {
      throw Failed(who + " (" + describe(x) + "): " + e.what());
    } catch (const Malformed& e) {
      throw Malformed(who + ": " + e.what());
    }
  }
  return st.n;
}

/// The paper's construction in the proof of Lemma 4 at the point (a, b, q): a `covering` certificate
/// there and a `discontinuities` certificate on L2, each checked as such; at least three
/// discontinuities z_1 < ... < z_n of T1 on L2 (all of them, by the latter), and each segment J of
/// the covering inside a branch: z_i < J < z_(i+1) for consecutive i. The paper's remark that
/// T1(z_i) mod 2 pi = pi - z_i mod 2 pi lies in L1 = [197 pi/100, t3] holds as z_i is in L2 and
/// 199 pi/100 < t3 (checked).
long check_paper_construction(const json& c, std::string& what) {
  Steps st;
  const auto [a, b, q] = read_point(c);
  const json& w = field(c, "witnesses", "");
  const json &cov = field(w, "covering", "witnesses."), &dis = field(w, "discontinuities", "witnesses.");
  require_embedded(cov, "covering", "witnesses.covering");
  require_embedded(dis, "discontinuities", "witnesses.discontinuities");
  const auto [ac, box] = read_box(cov);
  const json& dp = field(dis, "parameters", "witnesses.discontinuities.");
  st.require(ac == a && box.b_lo == b && box.b_hi == b && box.q_lo == q && box.q_hi == q, "the covering is at the point (a, b, q)");
  st.require(parameter(dp, "a", "witnesses.discontinuities.parameters.") == a && parameter(dp, "b", "witnesses.discontinuities.parameters.") == b &&
                 field(dp, "segment", "witnesses.discontinuities.parameters.") == "L2",
             "the discontinuities are at (a, b), on L2");
  st.n += embedded("witnesses.covering", [&] { return check_covering(cov); });
  st.n += embedded("witnesses.discontinuities", [&] { return check_discontinuities(dis, what); });
  const json& ts = field(field(dis, "witnesses", ""), "tangencies", "witnesses.discontinuities.witnesses.");
  st.require(ts.size() >= 3, "at least three discontinuities on L2");
  std::vector<Num> zl, zh;
  for (const json& t : ts) zl.push_back(exact(t["z"][0], "z")), zh.push_back(exact(t["z"][1], "z"));
  for (std::size_t s = 0; s < 2; ++s) {
    const json& seg = cov["witnesses"]["segments"][s];
    const double lo = exact_double(seg["lo"], "lo"), hi = exact_double(seg["hi"], "hi");
    bool inside = false;
    for (std::size_t i = 0; i + 1 < zl.size(); ++i) inside = inside || (mpfr_cmp_d(zh[i].x, lo) < 0 && mpfr_cmp_d(zl[i + 1].x, hi) > 0);
    st.require(inside, std::string(s == 0 ? "J0" : "J1") + " lies strictly between two consecutive discontinuities");
  }
  st.require(lt(Iv(199.0) / Iv(100.0) * pi(), t3(Iv(a), Iv(b))), "199 pi/100 < t3 (T1(z_i) mod 2 pi in L1)");
  return st.n;
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

/// Sections 6-7: for each orbit, boxes X_0..X_(m-1) with X_j inside J_(w_j) (J0 < J1 disjoint, w a
/// word of m letters 0 and 1, checked here to be primitive: no power of a shorter word), T continuous
/// on X_j and T at the ends of X_j on opposite sides outside X_(j+1): then T(X_j) contains X_(j+1)
/// (intermediate values), and going back along the cycle a point x of X_0 has T^j x in X_j and
/// T^m x = x; its itinerary is w^infinity (J0, J1 disjoint), whose least period is m as w is primitive.
/// (The prover's default word is 0^(m-1)1.)
long check_periodic(const json& c, std::string& what) {
  Steps st;
  what =
      "re-verified: an orbit of least period m with itinerary (w)^infinity, w the orbit's primitive word of m letters, in the boxes of "
      "each orbit; not re-verified: "
      "that it is the only one there (the prover's Krawczyk test)";
  const auto [a, b, q] = read_point(c);
  const json& w = field(c, "witnesses", "");
  const Iv A = standing_box(st, a, {b, b, q, q});
  const std::vector<double> J0 = doubles(field(w, "J0", "witnesses."), 2, "witnesses.J0"),
                            J1 = doubles(field(w, "J1", "witnesses."), 2, "witnesses.J1");
  st.require(J0[0] <= J0[1] && J0[1] < J1[0] && J1[0] <= J1[1], "J0 and J1 are segments, J0 left of J1 (disjoint)");
  const json& orbits = field(w, "orbits", "witnesses.");
  if (!orbits.is_array() || orbits.empty()) throw Malformed("'witnesses.orbits' is not a non-empty array");
  for (std::size_t i = 0; i < orbits.size(); ++i) {
    const std::string wo = "witnesses.orbits[" + std::to_string(i) + "].";
    const json& jm = field(orbits[i], "period", wo);
    if (!jm.is_number_integer() || jm.get<long long>() < 1 || jm.get<long long>() > 64)
      throw Malformed("'" + wo + "period' is not an integer in 1..64");
    const std::size_t m = jm.get<std::size_t>();
    const json &word = field(orbits[i], "word", wo), &boxes = field(orbits[i], "boxes", wo);
    if (!word.is_string() || !boxes.is_array()) throw Malformed("'" + wo + "' has no word string or boxes array");
    const std::string wd = word.get<std::string>();
    // primitive: w occurs in ww only at 0 and m (a power u^k, k >= 2, also occurs at |u|)
    st.require(wd.size() == m && wd.find_first_not_of("01") == std::string::npos && (wd + wd).find(wd, 1) == m,
               wo + "word: m letters 0 and 1 (m = period), primitive, so that the least period is m");
    st.require(boxes.size() == m, wo + "boxes: one per point of the orbit (m of them)");
    std::vector<Num> lo(m), hi(m);
    std::vector<Iv> T_lo(m), T_hi(m);
    for (std::size_t j = 0; j < m; ++j) {
      const std::string wx = wo + "boxes[" + std::to_string(j) + "]";
      const json& X = field(boxes[j], "X", wx + ".");
      if (!X.is_array() || X.size() != 2) throw Malformed("'" + wx + ".X' is not [lo, hi]");
      lo[j] = exact(X[0], wx + ".X[0]"), hi[j] = exact(X[1], wx + ".X[1]");
      const std::vector<double>& Jw = wd[j] == '1' ? J1 : J0;
      st.require(mpfr_cmp(lo[j].x, hi[j].x) < 0 && mpfr_cmp_d(lo[j].x, Jw[0]) >= 0 && mpfr_cmp_d(hi[j].x, Jw[1]) <= 0,
                 wx + ": lo < hi, inside J" + wd[j]);
      T_on(st, A, field(boxes[j], "on", wx + "."), b, q, lo[j], hi[j], wx + ".on");
      T_lo[j] = T_on(st, A, field(boxes[j], "at_lo", wx + "."), b, q, lo[j], lo[j], wx + ".at_lo");
      T_hi[j] = T_on(st, A, field(boxes[j], "at_hi", wx + "."), b, q, hi[j], hi[j], wx + ".at_hi");
    }
    for (std::size_t j = 0; j < m; ++j) {
      const std::size_t n = (j + 1) % m;
      const Iv L(lo[n]), H(hi[n]);
      st.require((lt(T_lo[j], L) && lt(H, T_hi[j])) || (lt(H, T_lo[j]) && lt(T_hi[j], L)),
                 wo + "boxes[" + std::to_string(j) + "]: T at its ends lies on opposite sides outside box " + std::to_string(n));
    }
  }
  return st.n;
}

// ---- arc-l1: the arc L1 = [197pi/100, t3) of the proof of Lemma 4 ------------------------------------

/// A list of exact doubles (the grid's cuts: at least two; whether they increase from 0 is a step).
std::vector<double> cuts(const json& j, const std::string& where, bool grid = true) {
  if (!j.is_array() || j.size() < (grid ? 2U : 1U))
    throw Malformed("'" + where + "' is not an array of at least " + (grid ? "2 numbers" : "1 number"));
  std::vector<double> v;
  for (std::size_t i = 0; i < j.size(); ++i) v.push_back(exact_double(j[i], where + "[" + std::to_string(i) + "]"));
  return v;
}

/// With a = 1, theta = 2pi - delta, s = t - theta: G1(theta, theta + s) = s^2 (-A + s g(delta, s)),
/// A = (sin delta - 2b)/2, g = sin(delta) s E(s) - cos(delta) K(s), E = (1/2 - (1 - cos s)/s^2)/s^2,
/// K = (sin s - s)/s^3 (Taylor's formula of sin and cos at theta). For 0 <= s <= 1 the series of E,
/// K and of their derivatives alternate with decreasing terms, so on a cell s in [s1, s2]:
/// E in [1/24 - s2^2/720, 1/24], K in [-1/6, -1/6 + s2^2/120], E' in [-s/360, -s/360 + s2^3/10080],
/// K' in [s/60 - s2^3/1260, s/60]. H = -A + s g has H' = g + s g', g' = sin(delta)(E + s E') - cos(delta) K'.
/// The checker encloses g and H' on every cell of the grid and checks the stated bounds; then the
/// scalar inequalities of the argument (README.md): contact within S and after t3, the progression's
/// deceleration gamma, its stop within W, before t0 + 2pi.
long check_arc_l1(const json& c) {
  Steps st;
  require_amplitude(c);
  const json& p = field(c, "parameters", "");
  const json& k = field(p, "q_over_a", "parameters.");
  const double k_lo = parameter(k, "lo", "parameters.q_over_a."), k_hi = parameter(k, "hi", "parameters.q_over_a.");
  const double eps_max = parameter(p, "b_over_a_max", "parameters."), delta_max = parameter(p, "delta_max", "parameters.");
  const json& w = field(c, "witnesses", "");
  const json& concl = field(w, "conclusion", "witnesses.");
  if (!concl.is_string() || (concl.get<std::string>() != "stop_arc" && concl.get<std::string>() != "before_t0"))
    throw Malformed("'witnesses.conclusion' is neither \"stop_arc\" nor \"before_t0\"");
  const bool stop_arc = concl.get<std::string>() == "stop_arc";
  const double S = parameter(w, "S", "witnesses."), W = parameter(w, "W", "witnesses.");
  const double g_lo = parameter(w, "g_lo", "witnesses."), g_hi = parameter(w, "g_hi", "witnesses.");
  const double h_lo = parameter(w, "dH_lo", "witnesses."), h_hi = parameter(w, "dH_hi", "witnesses.");
  const std::vector<double> dc = cuts(field(w, "delta_cuts", "witnesses."), "witnesses.delta_cuts");
  const std::vector<double> sc = cuts(field(w, "s_cuts", "witnesses."), "witnesses.s_cuts");
  const Iv Delta(delta_max), sinD = sin(Delta), cosD = cos(Delta);
  st.require(0 < k_lo && k_lo <= k_hi && k_hi <= 1, "0 < q/a lo <= q/a hi <= 1");
  st.require(eps_max > 0 && eps_max < 0.25 && delta_max > 0 && delta_max <= 0.5, "0 < b_over_a_max < 1/4 and 0 < delta_max <= 1/2");
  st.require(S > 0 && S <= 1 && (stop_arc || W > 0), "0 < S <= 1, W > 0");
  bool grid = dc.front() == 0 && sc.front() == 0 && sc.back() == S && dc.back() == delta_max;
  for (std::size_t i = 1; i < dc.size(); ++i) grid = grid && dc[i] > dc[i - 1];
  for (std::size_t i = 1; i < sc.size(); ++i) grid = grid && sc[i] > sc[i - 1];
  st.require(grid, "the grid covers [0, delta_max] x [0, S] (cuts increasing from 0)");
  for (std::size_t i = 0; i + 1 < dc.size(); ++i) {
    const Iv d(dc[i], dc[i + 1]), sd = sin(d), cd = cos(d);
    for (std::size_t j = 0; j + 1 < sc.size(); ++j) {
      const Iv s(sc[j], sc[j + 1]), s2(sc[j + 1]), s2sq = sqr(s2), s2cu = s2sq * s2;
      const Iv E = hull(Iv(1.0) / Iv(24.0) - s2sq / Iv(720.0), Iv(1.0) / Iv(24.0));
      const Iv K = hull(Iv(-1.0) / Iv(6.0), Iv(-1.0) / Iv(6.0) + s2sq / Iv(120.0));
      const Iv dE = hull(-(s / Iv(360.0)), -(s / Iv(360.0)) + s2cu / Iv(10080.0));
      const Iv dK = hull(s / Iv(60.0) - s2cu / Iv(1260.0), s / Iv(60.0));
      const Iv g = sd * s * E - cd * K;
      const Iv dH = g + s * (sd * (E + s * dE) - cd * dK);
      const std::string cell = "cell delta in [" + std::to_string(dc[i]) + ", " + std::to_string(dc[i + 1]) + "], s in [" + std::to_string(sc[j]) +
                               ", " + std::to_string(sc[j + 1]) + "]";
      st.require(le(Iv(g_lo), g) && le(g, Iv(g_hi)), "g in [g_lo, g_hi] on " + cell);
      st.require(le(Iv(h_lo), dH) && le(dH, Iv(h_hi)), "H' in [dH_lo, dH_hi] on " + cell);
    }
  }
  st.require(g_lo > 0 && h_lo > 0, "g_lo > 0 and dH_lo > 0 (H increasing: one simple contact)");
  const Iv s_star = sinD / (2.0 * Iv(g_lo));
  st.require(le(s_star, Iv(S)), "the contact lies within S: sin(delta_max) / (2 g_lo) <= S");
  st.require(lt(2.0 * Iv(g_hi), cosD), "the contact is past t3: 2 g_hi < cos(delta_max)");
  const Iv room = Iv(k_lo) - 2.0 * Iv(eps_max);
  if (stop_arc) {  // per row: at 2pi + tau, l_hi < tau < pi, u = x1 + (2 b/a - q/a)(tau - l) - cos(tau) + cos(l) < 0, l = theta1 - 2pi
    const std::vector<double> tau = cuts(field(w, "tau", "witnesses."), "witnesses.tau", false);
    st.require(tau.size() + 1 == dc.size(), "one tau per row of the grid");
    for (std::size_t i = 0; i + 1 < dc.size(); ++i) {
      const Iv s_row = sin(Iv(dc[i + 1])) / (2.0 * Iv(g_lo));
      // s* >= A/g_hi, A = (sin(delta) - 2 b/a)/2 >= max(0, (sin(d1) - 2 b_over_a_max)/2)
      Iv a_min = 0.5 * (sin(Iv(dc[i])) - 2.0 * Iv(eps_max));
      if (!a_min.positive()) a_min = Iv(0.0);
      const Iv l = hull(a_min / Iv(g_hi) - Iv(dc[i + 1]), s_row - Iv(dc[i]));
      const Iv T(tau[i]);
      const Iv u = sqr(s_row) * Iv(h_hi) - room * (T - l) - cos(T) + cos(l);
      const std::string row = "the row delta in [" + std::to_string(dc[i]) + ", " + std::to_string(dc[i + 1]) + "]";
      st.require(lt(l, T) && lt(T, pi()), "the landing precedes 2pi + tau < 3pi on " + row);
      st.require(u.negative(), "the progression stops before 2pi + tau (u < 0) on " + row);
    }
    return st.n;
  }
  const Iv x1 = sqr(s_star) * Iv(h_hi), SW = Iv(S) + Iv(W), gamma = room - sin(SW);
  st.require(lt(SW, 0.5 * pi()), "S + W < pi/2");
  st.require(gamma.positive() && lt(x1, gamma * Iv(W)), "the progression stops within W: gamma W > x1_max, gamma > 0");
  st.require(room.positive() && lt(room, Iv(1.0)) && lt(SW, asin(room)), "the stop precedes t0 + 2pi: S + W < asin(q/a lo - 2 b_over_a_max)");
  return st.n;
}

// ---- lemma4-uniform: Lemma 4 for every b/a <= eps*, by the paper's construction on L2 ----------------

/// (I1)-(I7) of docs/certified.md for every eps in [0, eps*] (a = 1, theta = pi + w, w in [pi/100,
/// pi/50], s0 = cos(w)/eps), re-derived here: G1(theta, theta + s) = s^2 [eps - sin(w)/2 + s g],
/// g = sin(w) s E(s) + cos(w) K(s); G1 <= eps - cos w - sin w + 1 on [1, s0 - 1]; at a symmetric
/// tangency z (2z - cos(z)/eps = (2k+1) pi), G1(z, t* + u) = u^2 [eps - sin w (1/2 - u^2 E(u)) -
/// cos(w) u K(u)]; the closed-form count h(101pi/100) - h(51pi/50) >= 6 pi; s0 - 1 > 2 cot(pi/200)
/// (no tangency of the other family can be a first contact); (q/a - 2 eps)(s0 - 1) > 2 (theta2
/// decreases along a branch); and (I8), the arc L1, as the embedded arc-l1 certificate for the same
/// q/a with a bound >= eps*. The argument from these to Lemma 4 is trusted (README.md).
long check_lemma4_uniform(const json& c) {
  Steps st;
  const json& p = field(c, "parameters", "");
  const json& k = field(p, "q_over_a", "parameters.");
  const double k_lo = parameter(k, "lo", "parameters.q_over_a."), k_hi = parameter(k, "hi", "parameters.q_over_a.");
  const double eps_star = parameter(p, "b_over_a_max", "parameters.");
  const json& w = field(c, "witnesses", "");
  const json& np = field(w, "pieces", "witnesses.");
  if (!np.is_number_integer() || np.get<long long>() < 1 || np.get<long long>() > 4096)
    throw Malformed("'witnesses.pieces' is not an integer in 1..4096");
  const int n = static_cast<int>(np.get<long long>());
  const json& arc = field(w, "arc_l1", "witnesses.");
  require_amplitude(c);
  require_embedded(arc, "arc-l1", "witnesses.arc_l1");
  st.n += embedded("witnesses.arc_l1", [&] { return check_arc_l1(arc); });
  const json& ap = field(arc, "parameters", "witnesses.arc_l1.");
  const json& ak = field(ap, "q_over_a", "witnesses.arc_l1.parameters.");
  const double w_lo = parameter(p, "w_lo", "parameters."), w_hi = parameter(p, "w_hi", "parameters.");
  st.require(parameter(ak, "lo", "witnesses.arc_l1.parameters.q_over_a.") <= k_lo &&
                 parameter(ak, "hi", "witnesses.arc_l1.parameters.q_over_a.") >= k_hi &&
                 parameter(ap, "b_over_a_max", "witnesses.arc_l1.parameters.") >= eps_star &&
                 parameter(ap, "delta_max", "witnesses.arc_l1.parameters.") >= w_hi,
             "(I8) the arc [2pi - w_hi, t3) is proved for these q/a and every b/a <= b_over_a_max");
  st.require(0 < k_lo && k_lo <= k_hi && k_hi <= 1 && eps_star > 0, "0 < q/a lo <= q/a hi <= 1, b_over_a_max > 0");
  st.require(0 < w_lo && w_lo < w_hi && w_hi <= 0.5, "0 < w_lo < w_hi <= 1/2: the segment [pi + w_lo, pi + w_hi]");
  const Iv PI = pi(), w1(w_lo), w2(w_hi), E(eps_star), eps(0.0, eps_star);
  st.require(le(6.0 * PI, (cos(w1) - cos(w2)) / E - 2.0 * (w2 - w1)),
             "(I5) h(pi + w_lo) - h(pi + w_hi) >= 6 pi at b_over_a_max (so for every smaller b/a)");
  st.require(lt(2.0 * E, sin(w1)), "(I1) 2 b_over_a_max < sin(w_lo)");
  const double a0 = w_lo, b0 = w_hi;
  for (int i = 0; i < n; ++i) {
    const double a = a0 + (b0 - a0) * i / n, b = i + 1 == n ? b0 : a0 + (b0 - a0) * (i + 1) / n;
    const Iv W(a, b), sw = sin(W), cw = cos(W);
    const std::string cell = "w in [" + std::to_string(a) + ", " + std::to_string(b) + "]";
    st.require((eps - 0.5 * sw).negative(), "(I2) b/a - sin(w)/2 < 0 on " + cell);
    // 1 - cos w - sin w decreases on [0, pi/4] (derivative sin w - cos w < 0): its largest value is at w = a.
    st.require(b <= 0.75 && (eps + Iv(1.0) - cos(Iv(a)) - sin(Iv(a))).negative(), "(I3) b/a + 1 - cos w - sin w < 0 on " + cell);
    st.require(le(2.0 * E, cw), "(I3) s0 = cos(w)/(b/a) >= 2 on " + cell);
    for (int j = 0; j < n; ++j) {
      const double s1 = static_cast<double>(j) / n, s2 = j + 1 == n ? 1.0 : static_cast<double>(j + 1) / n;
      const Iv s(s1, s2), h(s2), h2 = sqr(h);
      const Iv Es = hull(Iv(1.0) / Iv(24.0) - h2 / Iv(720.0), Iv(1.0) / Iv(24.0));
      const Iv Ks = hull(Iv(-1.0) / Iv(6.0), Iv(-1.0) / Iv(6.0) + h2 / Iv(120.0));
      st.require((sw * s * Es + cw * Ks).negative(), "(I2) g < 0 on " + cell + ", s in [" + std::to_string(s1) + ", " + std::to_string(s2) + "]");
      const Iv u = -s;  // E and K are even
      st.require((eps - sw * (Iv(0.5) - sqr(u) * Es) - cw * u * Ks).negative(),
                 "(I4) the end-window bracket < 0 on " + cell + ", u in [" + std::to_string(-s2) + ", " + std::to_string(-s1) + "]");
    }
  }
  const Iv s_min = cos(w2) / E - Iv(1.0);
  st.require(lt(2.0 * cot(0.5 * w1), s_min), "(I6) s0 - 1 > 2 cot(w_lo/2)");
  // (I9) Lemma 1 on [0, b_over_a_max] x [q/a lo, q/a hi]: cells inside, covering, u(t2) < 0 on each; q > 2b.
  st.require(2.0 * eps_star < k_lo, "(I9) q/a > 2 b/a on the box");
  lemma1(st, Iv(1.0), Box{0.0, eps_star, k_lo, k_hi}, read_sub_boxes(field(w, "lemma1", "witnesses."), "witnesses.lemma1."));
  st.require(lt(Iv(2.0), (Iv(k_lo) - 2.0 * E) * s_min), "(I7) (q/a - 2 b/a)(s0 - 1) > 2");
  return st.n;
}

/// Section 7 beyond two symbols: disjoint segments I_1 < ... < I_n of [t2, t3), each covered by balls
/// on which T is continuous, with T at both ends enclosed (case AB above t2); an edge j -> k only where
/// I_k lies strictly between the enclosures at the ends of I_j (so T(I_j) contains I_k); weights v > 0
/// with sum_{j -> k} v_k >= rho v_j for every j. Then rho(A) >= rho (Collatz-Wielandt) and
/// h_top(T) >= ln rho on the compact invariant set of orbits that stay in the union.
long check_entropy(const json& c, std::string& what) {
  Steps st;
  const auto [a, b, q] = read_point(c);
  const Box box{b, b, q, q};
  const json& w = field(c, "witnesses", "");
  const bool has_lemma1 = w.contains("lemma1");
  const std::vector<Ball> subs = has_lemma1 ? read_sub_boxes(w["lemma1"], "witnesses.lemma1.") : std::vector<Ball>{};
  const json& segs = field(w, "segments", "witnesses.");
  if (!segs.is_array() || segs.empty()) throw Malformed("'witnesses.segments' is not a non-empty array");
  const double rho = exact_double(field(w, "rho_lower", "witnesses."), "witnesses.rho_lower");
  const std::size_t n = segs.size();
  struct Segment {
    double lo, hi, v;
    Num lo_n, hi_n;
    std::vector<std::size_t> succ;
    std::vector<BallWitness> cover;
  };
  std::vector<Segment> I(n);
  for (std::size_t j = 0; j < n; ++j) {
    const std::string ws = "witnesses.segments[" + std::to_string(j) + "].";
    const json& ji = field(segs[j], "I", ws);
    if (!ji.is_array() || ji.size() != 2) throw Malformed("'" + ws + "I' is not [lo, hi]");
    I[j].lo = exact_double(ji[0], ws + "I[0]"), I[j].hi = exact_double(ji[1], ws + "I[1]");
    I[j].lo_n = exact(ji[0], ws + "I[0]"), I[j].hi_n = exact(ji[1], ws + "I[1]");
    I[j].v = exact_double(field(segs[j], "weight", ws), ws + "weight");
    const json& js = field(segs[j], "successors", ws);
    if (!js.is_array()) throw Malformed("'" + ws + "successors' is not an array");
    for (const json& k : js) {
      if (!k.is_number_integer() || k.get<long long>() < 0 || k.get<long long>() >= static_cast<long long>(n))
        throw Malformed("'" + ws + "successors' holds something other than a segment index");
      I[j].succ.push_back(k.get<std::size_t>());
    }
    const json& jc = field(segs[j], "cover", ws);
    if (!jc.is_array() || jc.empty()) throw Malformed("'" + ws + "cover' is not a non-empty array");
    for (std::size_t i = 0; i < jc.size(); ++i) I[j].cover.push_back(read_ball(jc[i], ws + "cover[" + std::to_string(i) + "]."));
  }
  const Iv A = standing_box(st, a, box);
  if (has_lemma1) lemma1(st, A, box, subs);
  std::string needs_lemma1;
  std::vector<Iv> T_lo(n), T_hi(n);
  for (std::size_t j = 0; j < n; ++j) {
    const std::string name = "I" + std::to_string(j);
    const Segment& g = I[j];
    st.require(g.lo < g.hi && (j == 0 || I[j - 1].hi < g.lo), name + ": lo < hi, right of the previous segment (disjoint)");
    st.require(le(t2(A, Iv(b)), Iv(g.lo)) && lt(Iv(g.hi), t3(A, Iv(b))), name + ": inside [t2, t3)");
    st.require(g.v > 0, name + ": weight > 0");
    std::vector<Ball> balls;
    for (std::size_t i = 0; i < g.cover.size(); ++i) {
      const BallWitness& bw = g.cover[i];
      const std::string who = name + " cover ball " + std::to_string(i);
      st.require(bw.ball.start == Start::Interval && bw.ball.box.b_lo == b && bw.ball.box.b_hi == b && bw.ball.box.q_lo == q &&
                     bw.ball.box.q_hi == q && g.lo <= bw.ball.th_lo && bw.ball.th_lo <= bw.ball.th_hi && bw.ball.th_hi <= g.hi,
                 who + ": phases inside the segment, at the parameter point");
      const Outcome o = check_ball(st, A, bw, who);
      if (o.needs_lemma1 && needs_lemma1.empty()) needs_lemma1 = who;
      balls.push_back(bw.ball);
    }
    require_cover(st, balls, g.lo, g.hi, box, name + ": the balls cover the segment (no gap)");
    const std::string ws = "witnesses.segments[" + std::to_string(j) + "]";
    T_lo[j] = T_on(st, A, field(segs[j], "at_lo", ws + "."), b, q, g.lo_n, g.lo_n, ws + ".at_lo");
    T_hi[j] = T_on(st, A, field(segs[j], "at_hi", ws + "."), b, q, g.hi_n, g.hi_n, ws + ".at_hi");
  }
  st.require(needs_lemma1.empty() || has_lemma1, "Lemma 1 is needed (first by " + needs_lemma1 + ") and witnesses.lemma1 is given");
  std::size_t edges_n = 0;
  for (std::size_t j = 0; j < n; ++j) {
    Iv sum(0.0);
    std::vector<bool> seen(n, false);
    for (std::size_t k : I[j].succ) {
      const std::string e = "edge I" + std::to_string(j) + " -> I" + std::to_string(k);
      st.require(!seen[k], e + ": listed once");
      seen[k] = true;
      const Iv L(I[k].lo), H(I[k].hi);
      st.require((lt(T_lo[j], L) && lt(H, T_hi[j])) || (lt(T_hi[j], L) && lt(H, T_lo[j])), e + ": I_k lies strictly between T at the ends of I_j");
      sum = sum + Iv(I[k].v);
      ++edges_n;
    }
    st.require(le(Iv(rho) * Iv(I[j].v), sum), "I" + std::to_string(j) + ": sum of the successors' weights >= rho_lower * weight");
  }
  st.require(rho > 1, "rho_lower > 1");
  char buf[160];
  std::snprintf(buf, sizeof buf, "rho(A) >= %.17g, so h_top >= ln of it, from a covering graph of %zu segments and %zu edges", rho, n, edges_n);
  what = buf;
  return st.n;
}

/// A file name as the verdict line shows it: as it is when every byte is printable ASCII other than
/// space, '"' and '\\'; otherwise in double quotes with C escapes (\\n, \\t, \\", \\\\, \\xHH), so
/// that every verdict stays on one line and a name can be told from the text after it.
std::string shown(const std::string& path) {
  bool plain = !path.empty();
  for (unsigned char ch : path) plain = plain && ch > 0x20 && ch < 0x7f && ch != '"' && ch != '\\';
  if (plain) return path;
  std::string q = "\"";
  for (unsigned char ch : path) {
    if (ch == '"' || ch == '\\') {
      q += '\\';
      q += static_cast<char>(ch);
    } else if (ch == '\n') {
      q += "\\n";
    } else if (ch == '\t') {
      q += "\\t";
    } else if (ch < 0x20 || ch >= 0x7f) {
      char buf[5];
      std::snprintf(buf, sizeof buf, "\\x%02x", ch);
      q += buf;
    } else {
      q += static_cast<char>(ch);
    }
  }
  return q + "\"";
}

/// A message on one line: control bytes (a line break in a file's text) as C escapes.
std::string one_line(const std::string& text) {
  std::string r;
  for (unsigned char ch : text) {
    if (ch < 0x20 || ch == 0x7f) {
      char buf[5];
      std::snprintf(buf, sizeof buf, "\\x%02x", ch);
      r += buf;
    } else {
      r += static_cast<char>(ch);
    }
  }
  return r;
}

/// What a file that is not a regular file is, for the refusal.
const char* kind_of(mode_t m) {
  if (S_ISDIR(m)) return "a directory";
  if (S_ISFIFO(m)) return "a FIFO or pipe";
  if (S_ISSOCK(m)) return "a socket";
  if (S_ISCHR(m) || S_ISBLK(m)) return "a device";
  return "not a regular file";
}

/// The whole text of a certificate file. Anything but a regular file (a directory, a FIFO, a
/// device) is refused before it is read, so that nothing blocks; so is a file over kMaxBytes.
std::string read_certificate(const std::string& path) {
  struct stat sb {};
  if (::stat(path.c_str(), &sb) != 0) throw Malformed(std::string("cannot be opened: ") + std::strerror(errno));
  if (!S_ISREG(sb.st_mode)) throw Malformed(std::string("is ") + kind_of(sb.st_mode) + ", not a regular file: not read");
  // O_NONBLOCK: should the name be replaced by a FIFO after stat, open does not wait for a writer
  // (fstat below then refuses it).
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw Malformed(std::string("cannot be opened: ") + std::strerror(errno));
  std::string text;
  try {
    if (::fstat(fd, &sb) != 0 || !S_ISREG(sb.st_mode)) throw Malformed(std::string("is ") + kind_of(sb.st_mode) + ", not a regular file: not read");
    if (sb.st_size > kMaxBytes) throw Malformed("is larger than " + std::to_string(kMaxBytes >> 20) + " MiB (the checker's limit): not read");
    char buf[1 << 16];
    for (;;) {
      const ssize_t n = ::read(fd, buf, sizeof buf);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) throw Malformed(std::string("cannot be read: ") + std::strerror(errno));
      if (n == 0) break;
      if (static_cast<long long>(text.size()) + n > kMaxBytes)
        throw Malformed("is larger than " + std::to_string(kMaxBytes >> 20) + " MiB (the checker's limit): not read");
      text.append(buf, static_cast<std::size_t>(n));
    }
  } catch (...) {
    ::close(fd);
    throw;
  }
  ::close(fd);
  return text;
}

/// The JSON of a certificate; a key twice in one object is refused (which one a reader keeps is
/// not defined by JSON: a certificate must not depend on it).
json parse_certificate(const std::string& text) {
  std::vector<std::set<std::string>> keys;  // the keys seen in each open object
  std::string duplicate;
  const json::parser_callback_t cb = [&](int /*depth*/, json::parse_event_t event, json& parsed) {
    if (event == json::parse_event_t::object_start) {
      keys.emplace_back();
    } else if (event == json::parse_event_t::object_end) {
      if (!keys.empty()) keys.pop_back();
    } else if (event == json::parse_event_t::key && !keys.empty() && duplicate.empty()) {
      const std::string k = parsed.get<std::string>();
      if (!keys.back().insert(k).second) duplicate = k;
    }
    return true;
  };
  json c;
  try {
    c = json::parse(text, cb);
  } catch (const json::exception& e) {
    throw Malformed(std::string("not JSON: ") + e.what());
  }
  if (!duplicate.empty()) throw Malformed("the key '" + duplicate + "' appears twice in one object (JSON leaves its value undefined)");
  return c;
}

/// Checks one file; returns its exit status after printing its line (flushed at once).
int check_file(const std::string& path) {
  std::string statement = "?", what;
  const std::string name = shown(path);
  try {
    const json c = parse_certificate(read_certificate(path));
    const json& format = field(c, "format", "");
    if (format != kFormat) throw Malformed("format is not \"" + std::string(kFormat) + "\"");
    const json& version = field(c, "version", "");
    if (!version.is_number_integer() || version.get<long long>() != kVersion)
      throw Malformed("version " + version.dump() + " (this checker reads version " + std::to_string(kVersion) + ")");
    const json& st = field(c, "statement", "");
    if (!st.is_string()) throw Malformed("'statement' is not a string");
    statement = st.get<std::string>();
    long steps = 0;
    if (statement == "vartheta0")
      steps = check_vartheta0(c);
    else if (statement == "lemma1")
      steps = check_lemma1(c);
    else if (statement == "b0")
      steps = check_b0(c);
    else if (statement == "covering")
      steps = check_covering(c);
    else if (statement == "coverings")
      steps = check_coverings(c);
    else if (statement == "periodic")
      steps = check_periodic(c, what);
    else if (statement == "superstable")
      steps = check_superstable(c, what);
    else if (statement == "not_superstable")
      steps = check_not_superstable(c);
    else if (statement == "window")
      steps = check_window(c);
    else if (statement == "theorem2_counterexample")
      steps = check_theorem2_counterexample(c);
    else if (statement == "discontinuities")
      steps = check_discontinuities(c, what);
    else if (statement == "paper_construction")
      steps = check_paper_construction(c, what);
    else if (statement == "entropy")
      steps = check_entropy(c, what);
    else if (statement == "arc-l1")
      steps = check_arc_l1(c);
    else if (statement == "lemma4-uniform")
      steps = check_lemma4_uniform(c);
    else
      throw Malformed("unknown statement '" + statement +
                      "' (this checker reads vartheta0, lemma1, b0, covering, coverings, periodic, superstable, not_superstable, window, "
                      "theorem2_counterexample, discontinuities, paper_construction, entropy, arc-l1, lemma4-uniform)");
    std::printf("OK %s: %s, %ld steps re-verified%s\n", name.c_str(), statement.c_str(), steps, what.empty() ? "" : one_line("; " + what).c_str());
    std::fflush(stdout);
    return 0;
  } catch (const Failed& e) {
    std::printf("FAIL %s: %s: step not verified: %s\n", name.c_str(), shown(statement).c_str(), one_line(e.what()).c_str());
  } catch (const Malformed& e) {
    std::printf("MALFORMED %s: %s\n", name.c_str(), one_line(e.what()).c_str());
    std::fflush(stdout);
    return 2;
  } catch (const std::bad_alloc&) {
    std::printf("MALFORMED %s: the checker ran out of memory reading it\n", name.c_str());
    std::fflush(stdout);
    return 2;
  } catch (const std::exception& e) {  // a defect of the checker: never taken for a verdict of OK
    std::printf("MALFORMED %s: could not be checked: %s\n", name.c_str(), one_line(e.what()).c_str());
    std::fflush(stdout);
    return 2;
  }
  std::fflush(stdout);
  return 1;
}

constexpr const char* kUsage =
    "usage: dfchaos-recheck [--] FILE...\n"
    "       dfchaos-recheck --help | --version\n"
    "Re-verifies certificates written by `dfchaos certify ... --certificate FILE`, in MPFI interval\n"
    "arithmetic, with its own formulas from the paper (docs/certificates.md, src/recheck/README.md).\n"
    "One line per file, printed as soon as it is decided:\n"
    "  OK NAME: STATEMENT, N steps re-verified[; what was proved]\n"
    "  FAIL NAME: STATEMENT: step not verified: STEP\n"
    "  MALFORMED NAME: WHY   (not a regular file, unreadable, over 256 MiB, not JSON, a duplicate key,\n"
    "                        a missing field, another format or version, an inexact number)\n"
    "NAME is the file name as given, in double quotes with C escapes if it holds a space, a quote, a\n"
    "backslash or a byte that is not printable ASCII. A file whose name starts with '-' follows '--'.\n"
    "Exit status: 0 every file verified; 1 a step failed in some file; 2 some file malformed, or bad\n"
    "usage. Every file is checked whatever the others give.\n";

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> files;
  bool options = true;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (options && arg == "--") {
      options = false;
    } else if (options && (arg == "--help" || arg == "-h" || arg == "--version")) {
      // Only alone: exit 0 is the verdict "every file verified", which a file named --help that a
      // glob picked up among bad certificates must not earn.
      if (argc != 2) {
        std::fprintf(stderr, "dfchaos-recheck: %s takes no other argument (a file named so follows --)\n", arg.c_str());
        return 2;
      }
      if (arg == "--version")
        std::printf("dfchaos-recheck %s (MPFI %s, MPFR %s, GMP %s)\n", DFCHAOS_VERSION, mpfi_get_version(), mpfr_get_version(), gmp_version);
      else
        std::fputs(kUsage, stdout);
      return std::fflush(stdout) == 0 ? 0 : 2;
    } else if (options && arg.size() > 1 && arg[0] == '-') {
      std::fprintf(stderr, "dfchaos-recheck: unknown option %s (a file named so follows --; see --help)\n", shown(arg).c_str());
      return 2;
    } else {
      files.push_back(arg);
    }
  }
  if (files.empty()) {
    std::fputs("dfchaos-recheck: no FILE given (usage: dfchaos-recheck [--] FILE...; see --help)\n", stderr);
    return 2;
  }
  int status = 0;
  for (const std::string& f : files) status = std::max(status, check_file(f));
  mpfr_free_cache();
  return std::fflush(stdout) == 0 ? status : 2;
}
