// SPDX-License-Identifier: GPL-3.0-or-later
#include "sweep/range.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "dfchaos/errors.hpp"
#include "kit/options.hpp"

namespace dfchaos::sweep {

namespace {
/// Splits at ':' (at most `max_parts` + 1 parts are returned, so that too many parts is noticed).
std::vector<std::string> split(const std::string& text, std::size_t max_parts) {
  std::vector<std::string> parts(1);
  for (char ch : text) {
    if (ch == ':') {
      if (parts.size() > max_parts) break;
      parts.emplace_back();
    } else {
      parts.back() += ch;
    }
  }
  return parts;
}
const char* spacing_name(Spacing s) {
  switch (s) {
    case Spacing::Linear: return "lin";
    case Spacing::Log: return "log";
    case Spacing::Mid: return "mid";
  }
  return "?";
}
}  // namespace

Range Range::parse(const std::string& option, const std::string& text, long long max_points) {
  max_points = std::min(max_points, kMaxAxisPoints);
  constexpr std::size_t kMaxParts = 4;
  const auto parts = split(text, kMaxParts);
  const std::string form = "write x (one value), lo:hi:n or lo:hi:n:lin|log|mid";
  if (parts.size() == 1) {  // one value x: the same as x:x:1
    const double x = kit::parse_number(option, parts[0], false);
    return parse(option, format_double(x) + ":" + format_double(x) + ":1", max_points);
  }
  if (parts.size() < 3 || parts.size() > kMaxParts) throw InvalidParameter(option, form + " (got '" + text + "')");
  Range r;
  r.lo_ = kit::parse_number(option + " lo", parts[0], false);
  r.hi_ = kit::parse_number(option + " hi", parts[1], false);
  const double n = kit::parse_number(option + " n", parts[2], true);
  if (n < 1 || n > static_cast<double>(max_points))
    throw InvalidParameter(option + " n", "1 <= n <= " + format_shortest(static_cast<double>(max_points)), n);
  r.n_ = static_cast<long long>(n);
  if (parts.size() == kMaxParts) {
    if (parts[3] == "lin")
      r.spacing_ = Spacing::Linear;
    else if (parts[3] == "log")
      r.spacing_ = Spacing::Log;
    else if (parts[3] == "mid")
      r.spacing_ = Spacing::Mid;
    else
      throw InvalidParameter(option, "the spacing must be lin, log or mid (got '" + parts[3] + "')");
  }
  const bool single = r.n_ == 1 && r.spacing_ != Spacing::Mid;
  if (single && r.lo_ != r.hi_)
    throw InvalidParameter(option, "a single point (n = 1) needs lo = hi, or use lo:hi:1:mid (got " + r.canonical() + ")");
  if (!single && !(r.lo_ < r.hi_)) throw InvalidParameter(option, "lo < hi (got " + r.canonical() + ")");
  if (r.spacing_ == Spacing::Log && !(r.lo_ > 0)) throw InvalidParameter(option, "a log range needs lo > 0 (got " + r.canonical() + ")");
  const int ni = static_cast<int>(r.n_);
  if (single)
    r.axis_ = kit::Axis::centres(r.lo_, r.lo_, 1);  // the single value lo, exactly
  else if (r.spacing_ == Spacing::Linear)
    r.axis_ = kit::Axis::linear(r.lo_, r.hi_, ni);
  else if (r.spacing_ == Spacing::Log)
    r.axis_ = kit::Axis::log(r.lo_, r.hi_, ni);
  else
    r.axis_ = kit::Axis::centres(r.lo_, r.hi_, ni);
  for (long long i = 0; i < r.n_; ++i)  // rounding (e.g. of pow) must not leave a non-finite point
    if (!std::isfinite(r[i])) throw InvalidParameter(option, "every point must be finite (got " + r.canonical() + ")");
  return r;
}

void Range::require_within(const std::string& option, double open_lo, double open_hi, const std::string& what) const {
  // The axis is monotone (rounding is monotone too), so its extreme points are the first and the
  // last. The computed points are checked, not the ends as written: a mid range may touch a bound
  // (its points lie strictly inside), and a rounded end must not slip past one.
  if (!((*this)[0] > open_lo && (*this)[n_ - 1] < open_hi)) throw InvalidParameter(option, what + " (got " + canonical() + ")");
}

double Range::operator[](long long i) const { return axis_[static_cast<int>(i)]; }

std::pair<double, double> Range::extent(long long i) const {
  const double x = (*this)[i];
  if (spacing_ == Spacing::Mid) {
    const auto edge = [this](long long k) { return k == n_ ? hi_ : lo_ + (hi_ - lo_) * static_cast<double>(k) / static_cast<double>(n_); };
    return {edge(i), edge(i + 1)};
  }
  if (n_ == 1) return {x, x};
  if (i + 1 < n_) return {x, (*this)[i + 1]};
  const double before = (*this)[n_ - 2];
  return {x, spacing_ == Spacing::Log ? x * (x / before) : x + (x - before)};
}

std::string Range::canonical() const {
  return format_shortest(lo_) + ":" + format_shortest(hi_) + ":" + std::to_string(n_) + ":" + spacing_name(spacing_);
}

}  // namespace dfchaos::sweep
