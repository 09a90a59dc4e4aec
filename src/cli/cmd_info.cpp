// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>

#include "cli.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/phase.hpp"

namespace dfchaos::cli {

Command add_info(CLI::App& app) {
  auto* cmd = app.add_subcommand("info", "the phases t0..t3, vartheta0 and which of the paper's assumptions hold");
  auto m = std::make_shared<ModelOptions>();
  m->add_to(cmd);
  cmd->footer(
      "Output: a table 'quantity value' (after the column line, # lines: the version and the settings). t0 < t1 are the zeros of F - q, t2 < t3 the "
      "zeros of F = a sin t + 2b on [0, 2 pi) "
      "(Section 2); vartheta0 solves Eq. (1); the assumptions are Eq. (2) (a > 0, 0 < b < a/2, a sin(vartheta0) < q < a) "
      "and Eq. (23) (a > 0, b > 0, 0 < q < a). With --physical, also forcing_period_s: 2 pi / OMEGA seconds.");
  return {cmd, [m] {
            const Parameters p = m->model();
            Writer w;
            auto opt = [](const std::optional<double>& v) { return v ? format_shortest(*v) : std::string("undefined"); };
            w.row({"quantity", "value"});
            w.provenance("info: the phases and assumptions of (a, b, q)", m->settings(p));
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
            if (const Units u = m->units(); u.physical) w.row({"forcing_period_s", format_shortest(u.seconds(two_pi))});
            w.flush();
            return 0;
          }};
}

}  // namespace dfchaos::cli
