// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "cli.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/limits.hpp"
#include "dfchaos/simulator.hpp"
#include "kit/format.hpp"
#include "sweep/stream.hpp"

namespace dfchaos::cli {

namespace {

/// The sample table, written to its own file (--samples-out) as the simulation runs: streamed into a
/// temporary beside it and renamed into place only when the simulation reached t-end, so that
/// memory does not grow with the number of samples and the file is whole or absent.
class SampleFile {
 public:
  /// @throws kit::OutputError when the path cannot be written (bad_path(): exit 2).
  SampleFile(const std::string& path, const std::string& comments, const Units& u) : file_(path, "samples-out"), u_(u) {
    file_.write(u.time("t") + '\t' + u.length("x") + '\t' + u.length("y") + '\t' + u.velocity("v") + "\tregime\n" + comments);
  }
  /// One row t x y v regime, in the number format of the event rows and the output's units.
  void row(const Sample& s) {
    line_ = format_double(u_.seconds(s.t)) + '\t' + format_double(s.x) + '\t' + format_double(s.y) + '\t' + format_double(u_.metres_per_second(s.v)) +
            '\t' + regime_code(s.regime) + '\n';
    file_.write(line_);
  }
  void commit() { file_.commit(); }

 private:
  sweep::AtomicFile file_;
  Units u_;
  std::string line_;
};

/// Streams the events to stdout as they are found and the samples to their file (--samples-out),
/// which is opened when the library has accepted the input (so that bad input is reported as the
/// library words it, as in the Python module).
class Printer final : public SimulationSink {
 public:
  /// `header`: the provenance lines after the column line; `samples_out` empty: no samples; else
  /// their file and its comment lines.
  Printer(Writer& w, const Units& u, std::string header, std::string samples_out, std::string comments)
      : w_(w), u_(u), header_(std::move(header)), samples_out_(std::move(samples_out)), comments_(std::move(comments)) {}

  void start(Regime initial_regime) override {
    if (!samples_out_.empty()) samples_.emplace(samples_out_, comments_, u_);
    w_.row({u_.time("t"), "phase", "before", "after", "kind", u_.length("x"), u_.length("y"), u_.velocity("v_before"), u_.velocity("v_after")});
    w_.line(header_.substr(0, header_.size() - 1));  // without its last newline
    w_.line(std::string("# initial regime: ") + regime_code(initial_regime));
  }
  void event(const SimulationEvent& e) override {
    w_.row({format_double(u_.seconds(e.t)), format_double(e.when.phase), regime_code(e.before), regime_code(e.after), transition_code(e.kind),
            format_double(e.x), format_double(e.y), format_double(u_.metres_per_second(e.v_before)), format_double(u_.metres_per_second(e.v_after))});
  }
  void sample(const Sample& s) override { samples_->row(s); }

  /// After the last event: the events flushed, the sample file put in place, then the state at
  /// t-end as a comment line (so that the final state on stdout means the whole run succeeded).
  void finish(const MechanicalState& end) {
    w_.flush();  // the events reached stdout (a failed write ends here: no samples file)
    if (samples_) samples_->commit();
    w_.line("# final state: " + u_.time("t") + " = " + format_double(u_.seconds(end.t.value())) + ", phase = " + format_double(end.t.phase) + ", " +
            u_.length("x") + " = " + format_double(end.x) + ", " + u_.length("y") + " = " + format_double(end.y) + ", " + u_.velocity("v") + " = " +
            format_double(u_.metres_per_second(end.v)) + ", regime = " + regime_code(end.regime));
    w_.flush();
  }

 private:
  Writer& w_;
  Units u_;
  std::string header_, samples_out_, comments_;
  std::optional<SampleFile> samples_;
};

}  // namespace

Command add_simulate(CLI::App& app) {
  auto* cmd = app.add_subcommand("simulate", "event-driven simulation of the full system (also outside the paper's assumptions)");
  struct Opts {
    ModelOptions m;
    std::string x0, y0, v0, t0, t_end, sample, samples_out, max_events = "1000000";
  };
  auto o = std::make_shared<Opts>();
  o->m.add_to(cmd);
  const std::string state_range = "|.| <= " + dfchaos::format_shortest(dfchaos::kMaxParameter);
  const std::string time_range = "|.| <= " + dfchaos::format_shortest(dfchaos::kMaxSimulationTime);
  cmd->add_option("--x0", o->x0, "initial position of the mass, x0 <= y0, " + state_range)->required()->type_name("FLOAT");
  cmd->add_option("--y0", o->y0, "initial position of the delimiter, " + state_range)->required()->type_name("FLOAT");
  cmd->add_option("--v0", o->v0, "initial velocity of the mass, " + state_range)->required()->type_name("FLOAT");
  cmd->add_option("--t0", o->t0, "initial time, " + time_range)->required()->type_name("FLOAT");
  cmd->add_option("--t-end", o->t_end, "final time, t0 <= t-end, " + time_range)->required()->type_name("FLOAT");
  cmd->add_option("--sample", o->sample, "also record the state every DT time units (DT > 0; at most 5e6 samples), with --samples-out")
      ->type_name("DT");
  cmd->add_option("--samples-out", o->samples_out, "with --sample: write the sample table to FILE (whole, or not at all)")->type_name("FILE");
  cmd->add_option("--max-events", o->max_events, "give up after this many events, 1 <= N <= 1e8 [default 1000000]")->type_name("N");
  cmd->footer(
      "Output: the column line, the provenance lines ('# dfchaos ...', '# name = value'), '# initial regime: f|p|s', then the event log, one row per "
      "regime change (%.17g),\n"
      "then '# final state: t = ..., phase = ..., x = ..., y = ..., v = ..., regime = ...' (the state at t-end).\n"
      "One call reads it: " +
      std::string(kit::kLoadInPython) +
      ".\nThe columns:\n"
      "  t, phase     the instant and its phase t mod 2 pi\n"
      "  before/after the regimes: f free flight (Eq. 3), p progression with the delimiter (Eq. 4), s stop (Eq. 5)\n"
      "  kind         fp: free flight ends by an impact and progression starts; is: an instantaneous stop (zero velocity\n"
      "               at the delimiter for an instant: the start or end of a stop, the end of a progression, or a grazing touch)\n"
      "  x, y         positions of the mass and of the delimiter\n"
      "  v_before, v_after  velocities of the mass just before and after\n"
      "With --physical: the times t0, t-end, DT and the t column in seconds (t_s), positions in metres (x_m, y_m), velocities\n"
      "v0 and v_before, v_after in m/s (v_before_m_per_s, ...); the phase stays in radians (docs/units.md).\n"
      "--sample DT --samples-out FILE: the state every DT time units goes to FILE, a table of its own read the same way\n"
      "(columns t x y v regime). Memory does not grow with the number of events or samples: events are streamed to\n"
      "stdout as found, samples into a temporary beside FILE, renamed into place when the simulation reaches t-end.\n"
      "More than --max-events events before t-end: exit status 1, one 'gave up' line on stderr; stdout keeps the rows\n"
      "already streamed (the column line, the initial regime and the first --max-events events; no final state, no samples file).\n"
      "Accuracy (docs/accuracy.md): |t0|, |t-end| <= " +
      format_shortest(kMaxSimulationTime) +
      " (refused beyond, exit 2); any b/a (no floor:\n"
      "flights end at t-end). Events are found by the root isolation of 'map' (phases agree with T to 1e-10,\n"
      "test_reduction); the t column is a double, the phase column is exact.");
  return {cmd, [o] {
            const Parameters p = o->m.model();
            SimulationOptions so;
            if (!o->sample.empty()) {
              so.sample_dt = number("sample", o->sample);
              if (!(so.sample_dt > 0)) throw InvalidParameter("sample", "sample > 0", so.sample_dt);
              if (o->samples_out.empty())
                throw InvalidParameter("sample", "the samples are a table of their own: give --samples-out FILE with --sample");
            } else if (!o->samples_out.empty()) {
              throw InvalidParameter("samples-out", "--samples-out needs --sample DT");
            }
            so.max_events = count("max-events", o->max_events, 1, kMaxSimulationEvents);
            // With --physical the input is in seconds, metres and m/s: t0, t-end, sample and v0 are taken to
            // the model's t and dx/dt (docs/units.md); the settings keep them as given.
            const Units u = o->m.units();
            const double x0 = number("x0", o->x0), y0 = number("y0", o->y0), v0_in = number("v0", o->v0), t0_in = number("t0", o->t0),
                         t_end_in = number("t-end", o->t_end);
            const double v0 = u.model_velocity(v0_in), t0 = u.model_time(t0_in), t_end = u.model_time(t_end_in);
            const double sample_in = so.sample_dt;
            so.sample_dt = u.model_time(so.sample_dt);
            if (u.physical) {
              // The library checks the model's values; in seconds and m/s its limits and messages would
              // name numbers the user did not type: the conditions on the given values, first.
              const std::string per = " (in seconds; the model's time is OMEGA times the seconds)";
              if (!(std::fabs(t0) <= kMaxSimulationTime))
                throw InvalidParameter("t0", "|t0| x OMEGA <= " + format_shortest(kMaxSimulationTime) + per, t0_in);
              if (!(std::fabs(t_end) <= kMaxSimulationTime))
                throw InvalidParameter("t-end", "|t-end| x OMEGA <= " + format_shortest(kMaxSimulationTime) + per, t_end_in);
              if (!(t_end_in >= t0_in)) throw InvalidParameter("t-end", "t-end >= t0 = " + format_shortest(t0_in), t_end_in);
              if (!std::isfinite(v0)) throw InvalidParameter("v0", "|v0| / OMEGA finite (m/s; the model's velocity is v0 / OMEGA)", v0_in);
              if (sample_in > 0 && !(so.sample_dt > 0))
                throw InvalidParameter("sample", "sample x OMEGA > 0 (seconds; it underflows to 0 in the model's time)", sample_in);
            }
            // Nothing is written before the library has checked the input (bad input: no output).
            std::vector<Setting> settings = o->m.settings(p);
            for (const auto& [name, value] : {std::pair{"x0", x0}, {"y0", y0}, {"v0", v0_in}, {"t0", t0_in}, {"t-end", t_end_in}})
              settings.emplace_back(name, format_shortest(value));
            settings.emplace_back("max-events", std::to_string(so.max_events));
            if (so.sample_dt > 0) settings.emplace_back("sample", format_shortest(sample_in));
            const std::string comments = so.sample_dt > 0 ? provenance_text("simulate: the state every sample time units", settings) : std::string();
            Writer w;
            Printer printer(w, u, provenance_text("simulate: the event log of the full system", settings),
                            so.sample_dt > 0 ? o->samples_out : std::string(), comments);
            const MechanicalState end = simulate(p, x0, y0, v0, t0, t_end, so, printer);
            printer.finish(end);
            return 0;
          }};
}

}  // namespace dfchaos::cli
