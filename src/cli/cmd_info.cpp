// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>

#include "cli.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/units.hpp"

namespace dfchaos::cli {

Command add_info(CLI::App& app) {
  auto* cmd = app.add_subcommand("info", "the phases t0..t3, vartheta0 and which of the paper's assumptions hold");
  auto m = std::make_shared<ModelOptions>();
  m->add_to(cmd);
  auto physical = std::make_shared<std::vector<std::string>>();
  auto* ph = cmd->add_option("--physical", *physical,
                             "instead of --a --b --q: a drilling model in physical units, MASS (kg), OMEGA the forcing's angular "
                             "frequency (rad/s), AMPLITUDE of the harmonic force (N), STATIC force (N), FRICTION the delimiter's "
                             "largest dry friction (N); a = AMPLITUDE/(MASS OMEGA^2), b = STATIC/(2 MASS OMEGA^2), "
                             "q = FRICTION/(MASS OMEGA^2), lengths in metres (docs/units.md)")
                 ->expected(5)
                 ->type_name("MASS OMEGA AMPLITUDE STATIC FRICTION");
  for (const char* name : {"--a", "--b", "--q"}) {
    CLI::Option* o = cmd->get_option(name);
    o->required(false);
    ph->excludes(o);
  }
  cmd->footer(
      "Output: a table 'quantity value' (after the column line, # lines: the version and the settings). t0 < t1 are the zeros of F - q, t2 < t3 the "
      "zeros of F = a sin t + 2b on [0, 2 pi) "
      "(Section 2); vartheta0 solves Eq. (1); the assumptions are Eq. (2) (a > 0, 0 < b < a/2, a sin(vartheta0) < q < a) "
      "and Eq. (23) (a > 0, b > 0, 0 < q < a).");
  return {cmd, [m, physical] {
            if (physical->empty() && (m->b.empty() || m->q.empty()))
              throw InvalidParameter(m->b.empty() ? "b" : "q",
                                     "give --b and --q (and --a, 1 by default), or --physical MASS OMEGA AMPLITUDE STATIC FRICTION");
            const Parameters p = physical->empty() ? m->model()
                                                   : from_physical(number("mass", (*physical)[0]), number("omega", (*physical)[1]),
                                                                   number("amplitude", (*physical)[2]), number("static_force", (*physical)[3]),
                                                                   number("friction", (*physical)[4]));
            Writer w;
            auto opt = [](const std::optional<double>& v) { return v ? format_shortest(*v) : std::string("undefined"); };
            w.row({"quantity", "value"});
            std::vector<Setting> settings = model_settings(p);
            if (!physical->empty())
              settings.emplace_back("physical", (*physical)[0] + " " + (*physical)[1] + " " + (*physical)[2] + " " + (*physical)[3] + " " +
                                                    (*physical)[4] +
                                                    "  (mass, omega, amplitude, static force, friction; a, b, q from them, docs/units.md)");
            w.provenance("info: the phases and assumptions of (a, b, q)", settings);
            w.row({"a", format_shortest(p.a())});
            w.row({"b", format_shortest(p.b())});
            w.row({"q", format_shortest(p.q())});
            w.row({"b/a", format_shortest(p.b() / p.a())});
            w.row({"q/a", format_shortest(p.q() / p.a())});
            w.row({"t0", opt(p.t0())});
            w.row({"t1", opt(p.t1())});
            w.row({"t2", opt(p.t2())});
            w.row({"t3", opt(p.t3())});
            w.row({"vartheta0", format_shortest(vartheta0())});
            w.row({"a*sin(vartheta0)", format_shortest(p.a() * sin_vartheta0())});
            w.row({"assumptions", p.assumptions().describe()});
            std::string map = "defined";
            try {
              p.require_return_map();
            } catch (const InvalidParameter& e) {
              map = std::string("not computed: ") + e.what();  // e.g. b/a below the accuracy floor
            }
            w.row({"return_map", map});
            w.flush();
            return 0;
          }};
}

}  // namespace dfchaos::cli
