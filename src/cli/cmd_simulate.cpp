// SPDX-License-Identifier: GPL-3.0-or-later
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <string>

#include "cli.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/limits.hpp"
#include "dfchaos/simulator.hpp"

namespace dfchaos::cli {

namespace {

/// The sample table, spooled while the events stream to stdout (it is printed after them): rows in
/// an unnamed temporary file (std::tmpfile, removed when closed or when the process ends), so that
/// memory does not grow with the number of samples.
class SampleSpool {
 public:
  /// @throws WriteFailed if no temporary file can be created.
  SampleSpool() : file_(std::tmpfile()) {
    if (!file_) fail("cannot create a temporary file for the samples");
  }

  /// One row t x y v regime, as Writer::row writes it. @throws WriteFailed
  void row(const Sample& s) {
    line_ =
        format_double(s.t) + '\t' + format_double(s.x) + '\t' + format_double(s.y) + '\t' + format_double(s.v) + '\t' + regime_code(s.regime) + '\n';
    if (std::fwrite(line_.data(), 1, line_.size(), file_.get()) != line_.size()) fail("cannot write the samples to a temporary file");
  }

  /// Copies every spooled row to stdout, after what `w` holds. @throws WriteFailed
  void copy_to_stdout(Writer& w) {
    w.flush();
    if (std::fflush(file_.get()) != 0 || std::fseek(file_.get(), 0, SEEK_SET) != 0) fail("cannot read back the samples from their temporary file");
    std::unique_ptr<char[]> chunk(new char[kChunk]);
    std::size_t n;
    while ((n = std::fread(chunk.get(), 1, kChunk, file_.get())) > 0)
      if (std::fwrite(chunk.get(), 1, n, stdout) != n) fail("cannot write the output");
    if (std::ferror(file_.get())) fail("cannot read back the samples from their temporary file");
    w.flush();
  }

 private:
  static constexpr std::size_t kChunk = 1 << 16;
  [[noreturn]] static void fail(const char* what) { throw WriteFailed(std::string(what) + ": " + std::strerror(errno)); }

  struct Close {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  std::unique_ptr<std::FILE, Close> file_;
  std::string line_;
};

/// Streams the events to stdout as they are found and spools the samples (with --sample).
class Printer final : public SimulationSink {
 public:
  Printer(Writer& w, bool sampled) : w_(w), sampled_(sampled) {}

  void start(Regime initial_regime) override {
    w_.line(std::string("# initial regime: ") + regime_code(initial_regime));
    w_.row({"t", "phase", "before", "after", "kind", "x", "y", "v_before", "v_after"});
    if (sampled_) spool_.emplace();
  }
  void event(const SimulationEvent& e) override {
    w_.row({format_double(e.t), format_double(e.when.phase), regime_code(e.before), regime_code(e.after), transition_code(e.kind), format_double(e.x),
            format_double(e.y), format_double(e.v_before), format_double(e.v_after)});
  }
  void sample(const Sample& s) override { spool_->row(s); }

  /// After the last event: with --sample, two blank lines (gnuplot's 'index 1') and the sample table.
  void finish() {
    if (sampled_) {
      w_.line("");
      w_.line("");
      w_.row({"t", "x", "y", "v", "regime"});
      spool_->copy_to_stdout(w_);
    }
    w_.flush();
  }

 private:
  Writer& w_;
  bool sampled_;
  std::optional<SampleSpool> spool_;
};

}  // namespace

Command add_simulate(CLI::App& app) {
  auto* cmd = app.add_subcommand("simulate", "event-driven simulation of the full system (also outside the paper's assumptions)");
  struct Opts {
    ModelOptions m;
    std::string x0, y0, v0, t0, t_end, sample, max_events = "1000000";
  };
  auto o = std::make_shared<Opts>();
  o->m.add_to(cmd);
  const std::string state_range = "|.| <= " + dfchaos::format_double(dfchaos::kMaxParameter);
  const std::string time_range = "|.| <= " + dfchaos::format_double(dfchaos::kMaxSimulationTime);
  cmd->add_option("--x0", o->x0, "initial position of the mass, x0 <= y0, " + state_range)->required()->type_name("FLOAT");
  cmd->add_option("--y0", o->y0, "initial position of the delimiter, " + state_range)->required()->type_name("FLOAT");
  cmd->add_option("--v0", o->v0, "initial velocity of the mass, " + state_range)->required()->type_name("FLOAT");
  cmd->add_option("--t0", o->t0, "initial time, " + time_range)->required()->type_name("FLOAT");
  cmd->add_option("--t-end", o->t_end, "final time, t0 <= t-end, " + time_range)->required()->type_name("FLOAT");
  cmd->add_option("--sample", o->sample, "also print the state every DT time units (DT > 0; at most 5e6 samples) [default: no samples]")
      ->type_name("DT");
  cmd->add_option("--max-events", o->max_events, "give up after this many events, 1 <= N <= 1e8 [default 1000000]")->type_name("N");
  cmd->footer(
      "Output: '# initial regime: f|p|s', then the event log, one row per regime change (%.17g):\n"
      "  t, phase     the instant and its phase t mod 2 pi\n"
      "  before/after the regimes: f free flight (Eq. 3), p progression with the delimiter (Eq. 4), s stop (Eq. 5)\n"
      "  kind         fp: free flight ends by an impact and progression starts; is: an instantaneous stop (zero velocity\n"
      "               at the delimiter for an instant: the start or end of a stop, the end of a progression, or a grazing touch)\n"
      "  x, y         positions of the mass and of the delimiter\n"
      "  v_before, v_after  velocities of the mass just before and after\n"
      "With --sample, after two blank lines (gnuplot's 'index 1'): t x y v regime.\n"
      "Memory does not grow with the number of events or samples: events are streamed as found; sample rows are\n"
      "spooled to an unnamed temporary file (std::tmpfile, in /tmp: up to about 100 bytes a sample) and copied after the events.\n"
      "More than --max-events events before t-end: exit status 1, one 'gave up' line on stderr; stdout keeps the rows\n"
      "already streamed (the initial regime, the event header and the first --max-events events; no samples).\n"
      "Accuracy (docs/accuracy.md): |t0|, |t-end| <= " +
      format_double(kMaxSimulationTime) +
      " (refused beyond, exit 2); any b/a (no floor:\n"
      "flights end at t-end). Events are found by the root isolation of 'map' (phases agree with T to 1e-10,\n"
      "test_reduction); the t column is a double, the phase column is exact.");
  return {cmd, [o] {
            const Parameters p = o->m.model();
            SimulationOptions so;
            if (!o->sample.empty()) {
              so.sample_dt = number("sample", o->sample);
              if (!(so.sample_dt > 0)) throw InvalidParameter("sample", "sample > 0", so.sample_dt);
            }
            so.max_events = count("max-events", o->max_events, 1, kMaxSimulationEvents);
            const double x0 = number("x0", o->x0), y0 = number("y0", o->y0), v0 = number("v0", o->v0), t0 = number("t0", o->t0),
                         t_end = number("t-end", o->t_end);
            // Nothing is written before the library has checked the input (bad input: no output).
            Writer w;
            Printer printer(w, so.sample_dt > 0);
            simulate(p, x0, y0, v0, t0, t_end, so, printer);
            printer.finish();
            return 0;
          }};
}

}  // namespace dfchaos::cli
