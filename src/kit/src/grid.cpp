// SPDX-License-Identifier: GPL-3.0-or-later
#include "kit/grid.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace dfchaos::kit {

Axis Axis::linear(double lo, double hi, int n) {
  if (n < 2) throw std::logic_error("Axis::linear needs n >= 2");
  Axis a;
  a.kind_ = Kind::Linear;
  a.lo_ = lo;
  a.hi_ = hi;
  a.n_ = n;
  return a;
}
Axis Axis::centres(double lo, double hi, int n) {
  if (n < 1) throw std::logic_error("Axis::centres needs n >= 1");
  Axis a;
  a.kind_ = Kind::Centres;
  a.lo_ = lo;
  a.hi_ = hi;
  a.n_ = n;
  return a;
}
Axis Axis::log(double lo, double hi, int n) { return log_ratio(lo, hi / lo, n); }
Axis Axis::log_ratio(double lo, double ratio, int n) {
  if (n < 2 || !(lo > 0) || !(ratio > 0)) throw std::logic_error("Axis::log needs n >= 2 and positive ends");
  Axis a;
  a.kind_ = Kind::Log;
  a.lo_ = lo;
  a.ratio_ = ratio;
  a.hi_ = lo * ratio;
  a.n_ = n;
  return a;
}

double Axis::operator[](int i) const {
  switch (kind_) {
    case Kind::Linear: return lo_ + (hi_ - lo_) * i / (n_ - 1);
    case Kind::Centres: return lo_ + (hi_ - lo_) * (i + 0.5) / n_;
    case Kind::Log: return lo_ * std::pow(ratio_, static_cast<double>(i) / (n_ - 1));
  }
  return 0;
}

std::vector<double> Axis::values() const {
  std::vector<double> v;
  v.reserve(static_cast<std::size_t>(n_));
  for (int i = 0; i < n_; ++i) v.push_back((*this)[i]);
  return v;
}

namespace {
double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
}  // namespace

Progress::Progress(std::string label, long long total, bool always)
    : label_(std::move(label)), total_(total), enabled_(always || ::isatty(2)), start_(now()), last_(start_) {}

Progress::~Progress() { done(); }

void Progress::step(long long n) {
  if (!enabled_) return;
#pragma omp critical(dfchaos_kit_progress)
  {
    done_ += n;
    const double t = now();
    if (t - last_ >= 0.5 && done_ < total_) {
      last_ = t;
      const double rate = done_ / (t - start_);
      const double left = rate > 0 ? (total_ - done_) / rate : 0;
      std::fprintf(stderr, "\r%s: %lld/%lld (%.0f%%), about %.0f s left   ", label_.c_str(), done_, total_, 100.0 * done_ / total_, left);
      std::fflush(stderr);
    }
  }
}

void Progress::done() {
  if (!enabled_ || finished_) return;
  finished_ = true;
  std::fprintf(stderr, "\r%s: %lld/%lld in %.1f s%30s\n", label_.c_str(), done_, total_, now() - start_, "");
}

}  // namespace dfchaos::kit
