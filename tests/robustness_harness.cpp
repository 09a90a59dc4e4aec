// SPDX-License-Identifier: GPL-3.0-or-later
// Randomised robustness harness: seeded draws over the dfchaos tool's argument parsing,
// driven in-process through dfchaos::cli::run, and over (a, b, q, theta) with edge values (t2, t3
// and their neighbouring doubles, subnormals, huge values, b/a near its floor) through the library.
// Every draw must end in one of three ways: success with finite output, a refusal (exit 2, exactly
// one line on stderr, nothing on stdout; InvalidParameter in the library), or a bounded computation
// that gives up (exit 1, one line; GaveUp). A crash, a hang (CTest's timeout), a NaN or inf in
// successful output, or any other exception fails the harness.
//
// Usage: robustness_harness [DRAWS] [SEED]   (DRAWS defaults to 100000)
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/return_map.hpp"

namespace {

using namespace dfchaos;

/// Runs the tool in-process with stdout and stderr captured into files.
struct Captured {
  int status = 0;
  std::string out, err;
};

std::string slurp(const char* path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

Captured run_tool(const std::vector<std::string>& args, const std::string& dir) {
  const std::string out_path = dir + "/out", err_path = dir + "/err";
  std::fflush(stdout);
  std::fflush(stderr);
  const int saved_out = ::dup(1), saved_err = ::dup(2);
  const int fo = ::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644), fe = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  ::dup2(fo, 1);
  ::dup2(fe, 2);
  std::vector<std::string> storage = args;
  storage.insert(storage.begin(), "dfchaos");
  std::vector<char*> argv;
  for (auto& a : storage) argv.push_back(a.data());
  argv.push_back(nullptr);
  Captured c;
  c.status = dfchaos::cli::run(static_cast<int>(storage.size()), argv.data());
  std::fflush(stdout);
  std::fflush(stderr);
  std::clearerr(stdout);
  ::dup2(saved_out, 1);
  ::dup2(saved_err, 2);
  ::close(saved_out);
  ::close(saved_err);
  ::close(fo);
  ::close(fe);
  c.out = slurp(out_path.c_str());
  c.err = slurp(err_path.c_str());
  return c;
}

int lines(const std::string& s) {
  int n = 0;
  for (char ch : s) n += ch == '\n';
  return n;
}

/// Edge values for a, b, q: ordinary, tiny, subnormal, huge, and malformed texts.
const std::vector<std::string> kNumbers = {"1",
                                           "2",
                                           "0.5",
                                           "0.85",
                                           "0.01",
                                           "0.001",
                                           "1e-5",
                                           "1e-8",
                                           "1e-12",
                                           "1e-13",
                                           "1e-16",
                                           "1e-300",
                                           "4.9e-324",
                                           "1e-320",
                                           "2.2250738585072014e-308",
                                           "1e100",
                                           "1e101",
                                           "1e300",
                                           "1.7976931348623157e308",
                                           "0",
                                           "-0",
                                           "-1",
                                           "nan",
                                           "inf",
                                           "-inf",
                                           "1e999",
                                           "x",
                                           "0x1p-3",
                                           "1.5e",
                                           " 1",
                                           "+0.3",
                                           "0.49999999999999994",
                                           "0.5000000000000001",
                                           "0.7246113537767085",
                                           "0.7246113537767086",
                                           "0.99999999999999989"};
const std::vector<std::string> kCounts = {"1", "2", "5", "1e1", "0", "-1", "1.5", "1e9", "1e300", "x", "nan", "3"};

}  // namespace

int main(int argc, char** argv) {
  const long draws = argc > 1 ? std::atol(argv[1]) : 100000;
  const unsigned long seed = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 20130214UL;
  if (draws < 1 || draws > 100'000'000) {
    std::fprintf(stderr, "robustness_harness: error: draws: must satisfy 1 <= draws <= 1e8\n");
    return 2;
  }
  char dir_template[] = "/tmp/dfchaos-robustness-XXXXXX";
  const char* dir = ::mkdtemp(dir_template);
  if (!dir) {
    std::perror("mkdtemp");
    return 1;
  }
  std::mt19937_64 rng(seed);
  auto pick = [&](const std::vector<std::string>& v) { return v[std::uniform_int_distribution<std::size_t>(0, v.size() - 1)(rng)]; };
  auto coin = [&](double p) { return std::uniform_real_distribution<double>(0, 1)(rng) < p; };
  long failures = 0, ok = 0, refused = 0, gave_up = 0, library_ok = 0, library_refused = 0, library_gave_up = 0;
  auto fail = [&](const std::string& what) {
    if (++failures <= 20) std::printf("FAIL: %s\n", what.c_str());
  };

  // Phases near the ends of [t2, t3) at a few valid parameter sets, as text with 17 digits.
  auto edge_phase = [&](double a, double b, double q, bool text_only) {
    (void)q;
    const double s = std::asin(2 * b / a);
    const double t2 = 3.141592653589793 + s, t3 = 6.283185307179586 - s;
    std::vector<double> v = {t2,
                             std::nextafter(t2, 0.0),
                             std::nextafter(t2, 10.0),
                             t3,
                             std::nextafter(t3, 0.0),
                             std::nextafter(std::nextafter(t3, 0.0), 0.0),
                             std::nextafter(t3, 10.0),
                             t3 - 1e-13,
                             1.5 * 3.141592653589793,
                             0.5 * (t2 + t3),
                             1.0,
                             7.0};
    (void)text_only;
    return v[std::uniform_int_distribution<std::size_t>(0, v.size() - 1)(rng)];
  };

  const long cli_draws = draws / 2;
  for (long k = 0; k < cli_draws; ++k) {
    std::vector<std::string> args;
    const int sub = std::uniform_int_distribution<int>(0, 6)(rng);
    const char* subs[] = {"info", "map", "orbit", "simulate", "provenance", "nosuch", ""};
    if (sub < 6) args.push_back(subs[sub]);
    const bool valid_model = coin(0.6);
    const double a = valid_model ? (coin(0.5) ? 1.0 : 2.0) : 1.0, b = valid_model ? (coin(0.5) ? 0.01 : 0.003) : 0.01,
                 q = valid_model ? 0.85 * a : 0.85;
    auto model_arg = [&](const char* name, double v) {
      args.push_back(name);
      char buf[40];
      std::snprintf(buf, sizeof buf, "%.17g", v);
      args.push_back(valid_model || coin(0.5) ? std::string(buf) : pick(kNumbers));
    };
    if (!coin(0.05)) model_arg("--a", a);
    if (!coin(0.05)) model_arg("--b", b);
    if (!coin(0.05)) model_arg("--q", q);
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", edge_phase(a, b, q, false));
    const std::string phase = coin(0.8) ? std::string(buf) : pick(kNumbers);
    switch (sub) {
      case 1:  // map
        if (coin(0.6))
          args.insert(args.end(), {"--theta", phase});
        else if (coin(0.5))
          args.insert(args.end(), {"--arc", coin(0.8) ? pick({"1", "2", "7", "10"}) : pick(kCounts)});
        else
          args.insert(args.end(), {"--grid", phase + ":" + (coin(0.5) ? "4.5" : pick(kNumbers)) + ":" + (coin(0.8) ? "5" : pick(kCounts)) +
                                                 (coin(0.2) ? ":mid" : "")});
        break;
      case 2:  // orbit
        args.insert(args.end(), {"--theta0", phase, "--steps", coin(0.8) ? pick({"1", "3", "10", "1e1"}) : pick(kCounts)});
        break;
      case 3:  // simulate
        args.insert(args.end(), {"--x0", coin(0.8) ? "0" : pick(kNumbers), "--y0", "0", "--v0", coin(0.8) ? "0" : pick(kNumbers), "--t0",
                                 coin(0.8) ? "4" : pick(kNumbers), "--t-end", coin(0.8) ? pick({"10", "50", "4"}) : pick(kNumbers)});
        if (coin(0.3)) {
          args.insert(args.end(), {"--sample", coin(0.7) ? "0.5" : pick(kNumbers)});
          if (coin(0.9)) args.insert(args.end(), {"--samples-out", std::string(dir) + "/samples.tsv"});
        }
        if (coin(0.2)) args.insert(args.end(), {"--max-events", pick(kCounts)});
        break;
      default: break;
    }
    if (coin(0.03)) args.insert(args.end(), {"--no-such-option", "1"});
    if (coin(0.02)) args.push_back("");
    const Captured c = run_tool(args, dir);
    std::string shown;
    for (const auto& x : args) shown += " '" + x + "'";
    if (c.status == 0) {
      ++ok;
      const bool help = c.out.find("Usage:") != std::string::npos || c.out.find("Options:") != std::string::npos;
      if (c.out.empty()) fail("exit 0 without output:" + shown);
      // the rows, without the '#' lines (provenance, in words: "info" is no inf)
      std::string rows;
      for (std::size_t at = 0; at < c.out.size();) {
        const std::size_t end = std::min(c.out.find('\n', at), c.out.size());
        if (c.out[at] != '#') rows += c.out.substr(at, end - at + 1);
        at = end + 1;
      }
      if (!help && (rows.find("nan") != std::string::npos || rows.find("inf") != std::string::npos)) fail("nan or inf in the output:" + shown);
    } else if (c.status == 2) {
      ++refused;
      if (!c.out.empty() || lines(c.err) != 1) fail("refusal not one line on stderr with nothing on stdout:" + shown + " -> " + c.err);
    } else if (c.status == 1) {
      ++gave_up;
      if (lines(c.err) != 1) fail("give-up not one line:" + shown + " -> " + c.err);
    } else {
      fail("exit status " + std::to_string(c.status) + ":" + shown);
    }
  }

  // The library: T at edge values of (a, b, q, theta).
  const std::vector<double> ratios = {0.3, 0.1, 1e-2, 1e-3, 1e-5, 1e-7, 1e-9, 1e-11, 1e-12, 1.1e-12, 9e-13, 1e-13};
  const std::vector<double> scales = {1.0, 2.0, 1e-100, 1e100, 1e-300, 4.9e-324, 1e300, DBL_MAX, DBL_MIN};
  for (long k = cli_draws; k < draws; ++k) {
    const double a = scales[std::uniform_int_distribution<std::size_t>(0, scales.size() - 1)(rng)];
    const double ratio = ratios[std::uniform_int_distribution<std::size_t>(0, ratios.size() - 1)(rng)];
    const double qa = std::uniform_real_distribution<double>(0.05, 1.2)(rng);
    const double b = a * ratio, q = a * qa;
    try {
      const Parameters p(a, b, q);
      double th = 0;
      if (p.t2() && p.t3()) th = edge_phase(a, b, q, false);
      if (coin(0.3) && p.t2()) th = *p.t2() + (*p.t3() - *p.t2()) * std::uniform_real_distribution<double>(0, 1)(rng);
      const MapStep s = return_map_step(p, th);
      ++library_ok;
      if (!std::isfinite(s.T) || !(s.T >= *p.t2() && s.T < *p.t3()) || !std::isfinite(s.elapsed) || !(s.elapsed >= 0) ||
          !std::isfinite(s.penetration) || s.penetration < 0)
        fail("T out of [t2, t3) or a non-finite step at a=" + format_double(a) + " b=" + format_double(b) + " q=" + format_double(q) +
             " theta=" + format_double(th) + ": T=" + format_double(s.T));
    } catch (const InvalidParameter& e) {
      ++library_refused;
      const std::string m = e.what();
      if (m.empty() || m.find('\n') != std::string::npos) fail("a refusal that is not one line: " + m);
    } catch (const GaveUp& e) {
      ++library_gave_up;
    } catch (const std::exception& e) {
      fail(std::string("unexpected exception: ") + e.what() + " at a=" + format_double(a) + " b=" + format_double(b) + " q=" + format_double(q));
    }
  }
  std::string cleanup = std::string("rm -rf ") + dir;
  if (std::system(cleanup.c_str()) != 0) std::fprintf(stderr, "robustness_harness: could not remove %s\n", dir);
  std::printf(
      "robustness_harness: %ld draws (seed %lu): tool %ld ok, %ld refused, %ld gave up; library %ld ok, %ld refused, %ld gave up; %ld failures\n",
      draws, seed, ok, refused, gave_up, library_ok, library_refused, library_gave_up, failures);
  return failures == 0 ? 0 : 1;
}
