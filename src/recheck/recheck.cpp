// dfchaos-recheck: re-verifies the certificates that `dfchaos certify ... --certificate FILE` writes,
// in MPFI interval arithmetic, with its own formulas taken from the paper. It shares no code with the
// prover (no header or library of the rest of src/): only MPFI, MPFR, GMP, nlohmann-json and the
// C++ standard library. It only checks, it never searches. What it trusts and what it checks:
// README.md beside this file; the format: docs/certificates.md.
//
//   dfchaos-recheck FILE...
//
// Exit status: 0 every step of every file re-verified (one line per file: OK, the statement, the
// number of steps); 1 a step failed (named); 2 a malformed certificate (unreadable, not JSON, a
// missing field, another format or version, a number that is not an exact hexadecimal float).
#include <mpfi.h>
#include <mpfr.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace {

using json = nlohmann::json;

constexpr mpfr_prec_t kPrecision = 256;  // every number and interval of the checker
constexpr const char* kFormat = "dfchaos-certificate";
constexpr int kVersion = 1;

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
  Num& operator=(const Num& o) { mpfr_set(x, o.x, MPFR_RNDN); return *this; }
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
  Iv& operator=(const Iv& o) { mpfi_set(x, o.x); return *this; }
  ~Iv() { mpfi_clear(x); }
  bool negative() const { return !mpfi_nan_p(x) && mpfi_is_strictly_neg(x) > 0; }  // every point < 0
  bool positive() const { return !mpfi_nan_p(x) && mpfi_is_strictly_pos(x) > 0; }  // every point > 0
};

using Binary = int (*)(mpfi_ptr, mpfi_srcptr, mpfi_srcptr);
using Unary = int (*)(mpfi_ptr, mpfi_srcptr);
Iv apply(Binary f, const Iv& a, const Iv& b) { Iv r; f(r.x, a.x, b.x); return r; }
Iv apply(Unary f, const Iv& a) { Iv r; f(r.x, a.x); return r; }
Iv operator+(const Iv& a, const Iv& b) { return apply(mpfi_add, a, b); }
Iv operator-(const Iv& a, const Iv& b) { return apply(mpfi_sub, a, b); }
Iv operator*(const Iv& a, const Iv& b) { return apply(mpfi_mul, a, b); }
Iv operator/(const Iv& a, const Iv& b) { return apply(mpfi_div, a, b); }
Iv operator*(double k, const Iv& a) { return Iv(k) * a; }
Iv sin(const Iv& a) { return apply(mpfi_sin, a); }
Iv cos(const Iv& a) { return apply(mpfi_cos, a); }
Iv cot(const Iv& a) { return apply(mpfi_cot, a); }
Iv asin(const Iv& a) { return apply(mpfi_asin, a); }
Iv pi() { Iv r; mpfi_const_pi(r.x); return r; }

// ---- the formulas, from the paper ----------------------------------------------------------------

/// Eq. (1): f(x) = pi - x - cot(x/2); its zero in (0, pi/2] is vartheta0.
Iv f_eq1(const Iv& x) { return pi() - x - cot(0.5 * x); }
/// f'(x) = -1 + 1 / (2 sin^2(x/2)).
Iv f_eq1_slope(const Iv& x) {
  const Iv s = sin(0.5 * x);
  return Iv(1.0) / (2.0 * (s * s)) - Iv(1.0);
}
/// Eq. (8): the velocity at t2 of the progression from rest at t0 (Eq. 7 at t = t2),
/// u(t2) = a cos t0 - a cos t2 + 2c (t2 - t0), 2c = 2b - q, with (Section 2, F(t) = a sin t + 2b,
/// Eq. 3) t0 = arcsin((q - 2b)/a) where F = q rises and t2 = pi + arcsin(2b/a) where F = 0 falls.
Iv u_at_t2(const Iv& a, const Iv& b, const Iv& q) {
  const Iv two_b = 2.0 * b;
  const Iv t0 = asin((q - two_b) / a), t2 = pi() + asin(two_b / a);
  return a * cos(t0) - a * cos(t2) + (two_b - q) * (t2 - t0);
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
  if (*end != '\0' || !std::isfinite(d) || mpfr_cmp_d(n.x, d) != 0)
    throw Malformed("'" + where + "' = '" + s + "' is not exactly a double");
  return d;
}

/// A parameter {"hex": ..., "decimal": ...}: the hex string is the number (the decimal is for humans).
double parameter(const json& j, const std::string& key, const std::string& where) {
  return exact_double(field(field(j, key, where), "hex", where + key + "."), where + key + ".hex");
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

/// Whether the closed sub-boxes (each inside `box`) cover `box`: for each open slab of b between
/// consecutive b edges, the q ranges of the sub-boxes spanning the slab cover [q_lo, q_hi]; with
/// b_lo == b_hi, the q ranges of all sub-boxes do. Sub-boxes are closed, so the slabs' edges are
/// covered too.
bool covers(const std::vector<Box>& subs, const Box& box) {
  std::vector<double> edges{box.b_lo, box.b_hi};
  for (const Box& s : subs) edges.insert(edges.end(), {s.b_lo, s.b_hi});
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  auto q_ranges = [&](double x, double y) {
    std::vector<std::pair<double, double>> v;
    for (const Box& s : subs)
      if (s.b_lo <= x && s.b_hi >= y) v.emplace_back(s.q_lo, s.q_hi);
    return v;
  };
  if (edges.size() == 1) return covers(q_ranges(box.b_lo, box.b_hi), box.q_lo, box.q_hi);
  for (std::size_t i = 0; i + 1 < edges.size(); ++i)
    if (!covers(q_ranges(edges[i], edges[i + 1]), box.q_lo, box.q_hi)) return false;
  return true;
}

/// Eq. (1): f(lo) < 0 < f(hi) with 0 < lo < hi < pi/2 (f' > 0 on (0, pi/2): analytic, README.md);
/// then the correctly rounded doubles of vartheta0 and sin vartheta0, when given.
long check_vartheta0(const json& c) {
  Steps st;
  const json& w = field(c, "witnesses", "");
  const json& br = field(w, "bracket", "witnesses.");
  const Num lo = exact(field(field(br, "lo", "witnesses.bracket."), "hex", "witnesses.bracket.lo."), "witnesses.bracket.lo.hex");
  const Num hi = exact(field(field(br, "hi", "witnesses.bracket."), "hex", "witnesses.bracket.hi."), "witnesses.bracket.hi.hex");
  const Iv L(lo), H(hi);
  st.require(L.positive() && (H - L).positive() && (0.5 * pi() - H).positive(), "0 < lo < hi < pi/2");
  st.require(f_eq1(L).negative(), "Eq. (1): f(lo) < 0");
  st.require(f_eq1(H).positive(), "Eq. (1): f(hi) > 0");
  const Iv bracket(lo, hi);
  st.require(f_eq1_slope(bracket).positive(), "Eq. (1): f' > 0 on [lo, hi]");
  // A double d is the nearest to every point of X when X lies strictly between the midpoints of d
  // and its neighbours (exact at kPrecision bits).
  auto rounds_to = [](const Iv& X, double d) {
    const Iv D(d), below = 0.5 * (D + Iv(std::nextafter(d, -INFINITY))), above = 0.5 * (D + Iv(std::nextafter(d, INFINITY)));
    return (X - below).positive() && (above - X).positive();
  };
  if (w.contains("value_double"))
    st.require(rounds_to(bracket, parameter(w, "value_double", "witnesses.")), "vartheta0 rounds to value_double");
  if (w.contains("sine_double"))
    st.require(rounds_to(sin(bracket), parameter(w, "sine_double", "witnesses.")), "sin(vartheta0) rounds to sine_double");
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

/// Lemma 1 over {a} x [b_lo, b_hi] x [q_lo, q_hi]: the standing conditions on the box, the
/// sub-boxes inside it and covering it, Eq. (8) u(t2) < 0 on each.
long check_lemma1(const json& c) {
  Steps st;
  const json& p = field(c, "parameters", "");
  const double a = parameter(p, "a", "parameters.");
  const json& b = field(p, "b", "parameters."), &q = field(p, "q", "parameters.");
  const Box box{parameter(b, "lo", "parameters.b."), parameter(b, "hi", "parameters.b."), parameter(q, "lo", "parameters.q."),
                parameter(q, "hi", "parameters.q.")};
  st.require(box.b_lo <= box.b_hi && box.q_lo <= box.q_hi, "the box is not empty");
  const Iv A(a);
  standing(st, A, Iv(box.b_lo, box.b_hi), Iv(box.q_lo, box.q_hi), true);
  const json& list = field(field(c, "witnesses", ""), "sub_boxes", "witnesses.");
  if (!list.is_array()) throw Malformed("'witnesses.sub_boxes' is not an array");
  std::vector<Box> subs;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::vector<double> v = doubles(list[i], 4, "witnesses.sub_boxes[" + std::to_string(i) + "]");
    subs.push_back({v[0], v[1], v[2], v[3]});
    const Box& s = subs.back();
    st.require(s.b_lo <= s.b_hi && s.q_lo <= s.q_hi && box.b_lo <= s.b_lo && s.b_hi <= box.b_hi && box.q_lo <= s.q_lo && s.q_hi <= box.q_hi,
               "sub-box " + std::to_string(i) + " (" + describe(s) + ") lies inside the box");
  }
  st.require(covers(subs, box), "the sub-boxes cover the box (no gap)");
  for (std::size_t i = 0; i < subs.size(); ++i) {
    const Box& s = subs[i];
    st.require(u_at_t2(A, Iv(s.b_lo, s.b_hi), Iv(s.q_lo, s.q_hi)).negative(),
               "Eq. (8): u(t2) < 0 on sub-box " + std::to_string(i) + " (" + describe(s) + ")");
  }
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

/// Checks one file; returns its exit status after printing its line.
int check_file(const std::string& path) {
  std::string statement = "?";
  try {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Malformed("cannot be opened");
    json c;
    try {
      c = json::parse(in);
    } catch (const json::exception& e) {
      throw Malformed(std::string("not JSON: ") + e.what());
    }
    const json& format = field(c, "format", "");
    if (format != kFormat) throw Malformed("format is not \"" + std::string(kFormat) + "\"");
    const json& version = field(c, "version", "");
    if (!version.is_number_integer() || version.get<long long>() != kVersion)
      throw Malformed("version " + version.dump() + " (this checker reads version " + std::to_string(kVersion) + ")");
    const json& st = field(c, "statement", "");
    if (!st.is_string()) throw Malformed("'statement' is not a string");
    statement = st.get<std::string>();
    long steps = 0;
    if (statement == "vartheta0") steps = check_vartheta0(c);
    else if (statement == "lemma1") steps = check_lemma1(c);
    else if (statement == "b0") steps = check_b0(c);
    else throw Malformed("unknown statement '" + statement + "' (this checker reads vartheta0, lemma1, b0)");
    std::printf("OK %s: %s, %ld steps re-verified\n", path.c_str(), statement.c_str(), steps);
    return 0;
  } catch (const Failed& e) {
    std::printf("FAIL %s: %s: step not verified: %s\n", path.c_str(), statement.c_str(), e.what());
    return 1;
  } catch (const Malformed& e) {
    std::printf("MALFORMED %s: %s\n", path.c_str(), e.what());
    return 2;
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: dfchaos-recheck FILE...  (re-verifies dfchaos certificates in MPFI; exit 0 all verified, 1 a step failed, 2 malformed)\n");
    return 2;
  }
  int status = 0;
  for (int i = 1; i < argc; ++i) status = std::max(status, check_file(argv[i]));
  mpfr_free_cache();
  return std::fflush(stdout) == 0 ? status : 2;
}
