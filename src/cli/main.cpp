/// @file main.cpp
/// @brief The `dfchaos` command-line tool: thin subcommands over the library.
///
///   dfchaos info     --a A --b B --q Q
///   dfchaos map      --a A --b B --q Q (--theta X [X ...] | --grid LO HI N)
///   dfchaos orbit    --a A --b B --q Q --theta0 X --steps N
///   dfchaos simulate --a A --b B --q Q --x0 X --y0 Y --v0 V --t0 T --t-end E [--sample DT]
///   dfchaos provenance [--latex]   versions of dfchaos, the compiler and the libraries
///
/// Output is tab-separated with one header line per table, numbers in %.17g. Bad input: one line
/// on stderr naming the parameter and the condition, exit status 2, nothing on stdout. A bounded
/// computation that gives up (e.g. a motion that never flies again): one line, exit status 1.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "dfchaos/errors.hpp"
#include "dfchaos/io.hpp"
#include "dfchaos/parameters.hpp"
#include "dfchaos/return_map.hpp"
#include "dfchaos/simulator.hpp"
#include "dfchaos/version.hpp"
#include "certify.hpp"

namespace {

using dfchaos::format_double;

struct Common {
  double a = 1, b = 0, q = 0;
};

void add_common(CLI::App* cmd, Common& c) {
  cmd->add_option("--a", c.a, "forcing amplitude a > 0")->required();
  cmd->add_option("--b", c.b, "half the constant force, b > 0")->required();
  cmd->add_option("--q", c.q, "dry-friction force q > 0")->required();
}

std::string row(std::initializer_list<std::string> cols) {
  std::string out;
  for (const auto& c : cols) {
    if (!out.empty()) out += '\t';
    out += c;
  }
  return out + '\n';
}

std::string format_int(long long n) { return std::to_string(n); }

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"dfchaos: the dry-friction oscillator of Begun & Kryzhevich (return map, simulator)"};
  app.set_version_flag("--version", std::string(dfchaos::version) + " (" + dfchaos::git_hash + ")");
  app.require_subcommand(1);

  Common c;
  auto* info = app.add_subcommand("info", "phases t0..t3, vartheta0 and the assumptions that hold");
  add_common(info, c);

  auto* map = app.add_subcommand("map", "evaluate T1 and T at given phases");
  add_common(map, c);
  std::vector<double> thetas, grid;
  auto* opt_theta = map->add_option("--theta", thetas, "phases in [t2, t3)");
  auto* opt_grid = map->add_option("--grid", grid, "LO HI N: N phases LO + (HI-LO) i/N, i = 0..N-1")->expected(3);
  opt_theta->excludes(opt_grid);
  opt_grid->excludes(opt_theta);

  auto* orbit = app.add_subcommand("orbit", "iterate T, with elapsed time and penetration");
  add_common(orbit, c);
  double theta0 = 0;
  long long steps = 0;
  orbit->add_option("--theta0", theta0, "initial phase in [t2, t3)")->required();
  orbit->add_option("--steps", steps, "number of steps, 1 .. 10^8")->required();

  auto* sim = app.add_subcommand("simulate", "event-driven simulation of the full system");
  add_common(sim, c);
  double x0 = 0, y0 = 0, v0 = 0, t0 = 0, t_end = 0, sample = 0;
  long long max_events = 1'000'000;
  sim->add_option("--x0", x0, "initial position of the mass")->required();
  sim->add_option("--y0", y0, "initial position of the delimiter (x0 <= y0)")->required();
  sim->add_option("--v0", v0, "initial velocity of the mass")->required();
  sim->add_option("--t0", t0, "initial time")->required();
  sim->add_option("--t-end", t_end, "final time (>= t0)")->required();
  sim->add_option("--sample", sample, "also print the state every DT time units");
  sim->add_option("--max-events", max_events, "give up after this many events");

  auto* prov = app.add_subcommand("provenance", "versions of dfchaos, the compiler and the libraries it was built with");
  bool prov_latex = false;
  prov->add_flag("--latex", prov_latex, "print \\dfcbuildrow{name}{version} lines for the report");

  dfchaos::cli::CertifyOptions certify_opts;  // issue 14: certified verdicts (src/cli/certify.*)
  auto* certify = dfchaos::cli::add_certify(app, certify_opts);

  if (argc > 1 && argv[1][0] != '-') {
    const std::string sub = argv[1];
    if (sub != "info" && sub != "map" && sub != "orbit" && sub != "simulate" && sub != "provenance" && sub != "certify") {
      std::fprintf(stderr, "dfchaos: error: unknown subcommand '%s' (expected info, map, orbit, simulate, provenance or certify)\n", sub.c_str());
      return 2;
    }
  }
  // An empty value would be read as 0 by the option parser: refuse it whatever the option.
  for (int i = 1; i < argc; ++i)
    if (argv[i][0] == '\0') {
      std::fprintf(stderr, "dfchaos: error: %s: empty value (a number is required)\n", i > 1 ? argv[i - 1] : "argument");
      return 2;
    }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string msg = e.what();
    for (auto& ch : msg)
      if (ch == '\n') ch = ' ';
    std::fprintf(stderr, "dfchaos: error: %s\n", msg.c_str());
    return 2;
  }

  if (certify->parsed()) return dfchaos::cli::run_certify(certify_opts);

  if (prov->parsed()) {
    std::string text = prov_latex ? "% generated by dfchaos provenance; do not edit\n" : "name\tversion\n";
    for (const auto& [name, value] : dfchaos::build_info())
      text += prov_latex ? "\\dfcbuildrow{" + dfchaos::latex_escape(name) + "}{" + dfchaos::latex_escape(value) + "}\n" : name + "\t" + value + "\n";
    std::fputs(text.c_str(), stdout);
    return 0;
  }

  std::string out;
  try {
    const dfchaos::Parameters p(c.a, c.b, c.q);
    if (info->parsed()) {
      auto opt = [](const std::optional<double>& v) { return v ? format_double(*v) : std::string("undefined"); };
      out += row({"quantity", "value"});
      out += row({"a", format_double(p.a())}) + row({"b", format_double(p.b())}) + row({"q", format_double(p.q())});
      out += row({"b/a", format_double(p.b() / p.a())}) + row({"q/a", format_double(p.q() / p.a())});
      out += row({"t0", opt(p.t0())}) + row({"t1", opt(p.t1())}) + row({"t2", opt(p.t2())}) + row({"t3", opt(p.t3())});
      out += row({"vartheta0", format_double(dfchaos::vartheta0())});
      out += row({"a*sin(vartheta0)", format_double(p.a() * std::sin(dfchaos::vartheta0()))});
      out += row({"assumptions", p.assumptions().describe()});
    } else if (map->parsed()) {
      p.require_return_map();
      std::vector<double> th = thetas;
      if (!grid.empty()) {
        const double lo = grid[0], hi = grid[1], n = grid[2];
        const double t2 = p.t2_required(), t3 = p.t3_required();
        if (!std::isfinite(lo) || lo < t2 || lo >= t3)
          throw dfchaos::InvalidParameter("grid LO", "t2 <= LO < t3 = [" + format_double(t2) + ", " + format_double(t3) + ")", lo);
        if (!std::isfinite(hi) || hi <= lo || hi > t3)
          throw dfchaos::InvalidParameter("grid HI", "LO < HI <= t3 = " + format_double(t3), hi);
        if (!(n >= 1 && n <= 1e7 && n == std::floor(n)))
          throw dfchaos::InvalidParameter("grid N", "N an integer in [1, 10^7]", n);
        const long long N = static_cast<long long>(n);
        for (long long i = 0; i < N; ++i) th.push_back(lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(N));
      }
      if (th.empty()) throw dfchaos::InvalidParameter("theta", "give --theta X [X ...] or --grid LO HI N");
      out += row({"theta", "T1", "T", "scenario", "elapsed", "penetration"});
      for (double x : th) {
        const auto s = dfchaos::return_map_step(p, x);
        out += row({format_double(x), format_double(s.hit.theta1), format_double(s.T), dfchaos::scenario_name(s.scenario),
                    format_double(s.elapsed), format_double(s.penetration)});
      }
    } else if (orbit->parsed()) {
      p.require_return_map();
      if (steps < 1 || steps > 100'000'000)
        throw dfchaos::InvalidParameter("steps", "1 <= steps <= 10^8", static_cast<double>(steps));
      out += row({"n", "theta", "scenario", "elapsed", "penetration", "time", "y"});
      double theta = theta0;
      long double time = theta0, y = 0;
      for (long long n = 0; n < steps; ++n) {
        const auto s = dfchaos::return_map_step(p, theta);
        out += row({format_int(n), format_double(theta), dfchaos::scenario_name(s.scenario), format_double(s.elapsed),
                    format_double(s.penetration), format_double(static_cast<double>(time)), format_double(static_cast<double>(y))});
        time += s.elapsed;
        y += s.penetration;
        theta = s.T;
      }
    } else if (sim->parsed()) {
      dfchaos::SimulationOptions o;
      o.sample_dt = sample;
      if (max_events < 1) throw dfchaos::InvalidParameter("max-events", "max-events >= 1", static_cast<double>(max_events));
      o.max_events = max_events;
      const auto r = dfchaos::simulate(p, x0, y0, v0, t0, t_end, o);
      out += "# initial regime: " + std::string(dfchaos::regime_code(r.initial_regime)) + "\n";
      out += row({"t", "phase", "before", "after", "kind", "x", "y", "v_before", "v_after"});
      for (const auto& e : r.events)
        out += row({format_double(e.t), format_double(e.when.phase), dfchaos::regime_code(e.before), dfchaos::regime_code(e.after),
                    dfchaos::transition_code(e.kind), format_double(e.x), format_double(e.y), format_double(e.v_before),
                    format_double(e.v_after)});
      if (sample > 0) {
        out += "\n\n";
        out += row({"t", "x", "y", "v", "regime"});
        for (const auto& s : r.samples)
          out += row({format_double(s.t), format_double(s.x), format_double(s.y), format_double(s.v), dfchaos::regime_code(s.regime)});
      }
    }
  } catch (const dfchaos::InvalidParameter& e) {
    std::fprintf(stderr, "dfchaos: error: %s\n", e.what());
    return 2;
  } catch (const dfchaos::GaveUp& e) {
    std::fprintf(stderr, "dfchaos: gave up: %s\n", e.what());
    return 1;
  }
  std::fwrite(out.data(), 1, out.size(), stdout);
  return 0;
}
