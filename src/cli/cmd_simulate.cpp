#include "cli.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/simulator.hpp"

namespace dfchaos::cli {

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
      "Exit status 1 if more than --max-events events occur before t-end.\n"
      "Accuracy (docs/accuracy.md): |t0|, |t-end| <= " + format_double(kMaxSimulationTime) + " (refused beyond, exit 2); any b/a (no floor:\n"
      "flights end at t-end). Events are found by the root isolation of 'map' (phases agree with T to 1e-10,\n"
      "test_reduction); the t column is a double, the phase column is exact.");
  return {cmd, [o] {
            const Parameters p = o->m.model();
            SimulationOptions so;
            if (!o->sample.empty()) {
              so.sample_dt = number("sample", o->sample);
              if (!(so.sample_dt > 0)) throw InvalidParameter("sample", "sample > 0", so.sample_dt);
            }
            so.max_events = count("max-events", o->max_events, 1, 100'000'000);
            const auto r = simulate(p, number("x0", o->x0), number("y0", o->y0), number("v0", o->v0), number("t0", o->t0),
                                    number("t-end", o->t_end), so);
            Writer w;
            w.line(std::string("# initial regime: ") + regime_code(r.initial_regime));
            w.row({"t", "phase", "before", "after", "kind", "x", "y", "v_before", "v_after"});
            for (const auto& e : r.events)
              w.row({num(e.t), num(e.when.phase), regime_code(e.before), regime_code(e.after), transition_code(e.kind), num(e.x), num(e.y),
                     num(e.v_before), num(e.v_after)});
            if (so.sample_dt > 0) {
              w.line("");
              w.line("");
              w.row({"t", "x", "y", "v", "regime"});
              for (const auto& s : r.samples) w.row({num(s.t), num(s.x), num(s.y), num(s.v), regime_code(s.regime)});
            }
            w.flush();
            return 0;
          }};
}

}  // namespace dfchaos::cli
