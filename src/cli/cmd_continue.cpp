// SPDX-License-Identifier: GPL-3.0-or-later
/// @file cmd_continue.cpp
/// @brief `dfchaos continue`: a periodic orbit of T, given by its itinerary over Lemma 4's J0, J1 at
/// the start, followed in b (a and q fixed) until it ends in a border collision (continuation.hpp),
/// each step's existence proved over its interval of b with --certify (certified/periodic.hpp).
#include <cmath>
#include <string>

#include "cli.hpp"
#include "dfchaos/certified/periodic.hpp"
#include "dfchaos/continuation.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/symbolic.hpp"
#include "kit/options.hpp"

namespace dfchaos::cli {

Command add_continue(CLI::App& app) {
  auto* cmd = app.add_subcommand("continue", "a periodic orbit of T followed in b until it ends in a border collision");
  struct Opts {
    ModelOptions m;
    std::string word, to, step = "1e-3", min_step = "1e-12", max_steps = "10000";
    bool certify = false;
  };
  auto o = std::make_shared<Opts>();
  o->m.add_to(cmd);
  cmd->add_option("--word", o->word,
                  "the orbit at the start: itinerary (W)^infinity over Lemma 4's J0, J1 (as 'dfchaos periodic'), 1.." +
                      std::to_string(kMaxContinuedPeriod) + " letters, primitive")
      ->required()
      ->type_name("W");
  cmd->add_option("--to", o->to, "follow b from --b towards B_END (either side), with a and q fixed")->required()->type_name("B_END");
  cmd->add_option("--step", o->step, "first relative step in b, 0 < H <= 0.1 (default 1e-3; halved where a step fails, doubled back)")
      ->type_name("H");
  cmd->add_option("--min-step", o->min_step, "the end is located to this relative width in b, 1e-15..H (default 1e-12)")->type_name("H");
  cmd->add_option("--max-steps", o->max_steps, "most accepted steps, 1..1e6 (default 10000)")->type_name("N");
  cmd->add_flag("--certify", o->certify,
                "prove, for every b between each row and the one before it, that the cycle exists (covering relations over the\n"
                "parameter interval, ball arithmetic); column certified");
  cmd->footer(
      "Output (tab-separated, %.17g; after the column line, # lines: the version, the settings; the last # lines say\n"
      "how the orbit ends):\n"
      "  b               the parameter (rows in the order followed)\n"
      "  certified       with --certify: 1 if the cycle is proved to exist for every b between this row's and the\n"
      "                  previous row's (0 if not proved, - on the first row or without --certify)\n"
      "  log_multiplier  ln|(T^m)'| along the cycle (T' by its formula, map_derivative)\n"
      "  residual        the largest |T(x_j) - x_(j+1)| after Newton's method\n"
      "  x0 .. x(m-1)    the cycle, x0 continued from the start's x_0\n"
      "The end ('# end = KIND'): plateau (a point's step enters a stop plateau: T' = 0), reaches_t2 / reaches_t3 (a\n"
      "point reaches an end of [t2, t3); a fixed point reaching t2 opens a window of Theorem 2), grazing (a point's\n"
      "first flight changes branch of T1: the flight grazes the delimiter), fold (Newton fails as the multiplier\n"
      "(T^m)' nears 1), no_convergence (Newton fails otherwise), range_end (B_END reached), step_budget\n"
      "(--max-steps used up); with the point j,\n"
      "the last b followed and the first b lost (relatively --min-step apart). The start is 'dfchaos periodic'\n"
      "at --b; the continuation itself does not need Lemma 4's covering. Exit 2: bad input, or no covering at --b.");
  return {cmd, [o] {
            if (!o->m.physical.empty()) throw InvalidParameter("physical", "continue takes --a --b --q (b is the parameter followed)");
            const Parameters p = o->m.model();
            p.require_return_map();
            require_itinerary_word("word", o->word, kMaxContinuedPeriod);
            ContinuationSettings s;
            s.step = kit::parse_number("step", o->step, false);
            s.min_step = kit::parse_number("min-step", o->min_step, false);
            s.max_steps = static_cast<long long>(kit::parse_number("max-steps", o->max_steps, true));  // bounds: validate()
            s.validate();
            const double b_end = kit::parse_number("to", o->to, false);
            Parameters(p.a(), b_end, p.q()).require_return_map();
            const ItineraryOrbit start = periodic_orbit(p, o->word);
            const OrbitBranch br = follow_periodic_orbit(p.a(), p.q(), p.b(), start.x, b_end, s);

            std::vector<Setting> settings = o->m.settings(p);
            settings.emplace_back("word", o->word);
            settings.emplace_back("to", format_double(b_end));
            settings.emplace_back("step", format_double(s.step));
            settings.emplace_back("min_step", format_double(s.min_step));
            settings.emplace_back("max_steps", std::to_string(s.max_steps));
            settings.emplace_back("certify", o->certify ? "yes" : "no");
            Writer w;
            std::vector<std::string> head = {"b", "certified", "log_multiplier", "residual"};
            for (std::size_t j = 0; j < start.x.size(); ++j) head.push_back("x" + std::to_string(j));
            w.row(head);
            w.provenance("continue: a periodic orbit of T followed in b", settings);
            const std::vector<int> proved = o->certify ? certified::prove_branch_steps(p.a(), p.q(), br) : std::vector<int>(br.points.size(), -1);
            long long n_proved = 0;
            for (std::size_t k = 0; k < br.points.size(); ++k) {
              const BranchPoint& pt = br.points[k];
              n_proved += proved[k] == 1 ? 1 : 0;
              std::vector<std::string> row = {format_double(pt.b), proved[k] < 0 ? "-" : std::to_string(proved[k]), format_double(pt.log_multiplier),
                                              format_double(pt.residual)};
              for (double x : pt.x) row.push_back(format_double(x));
              w.row(row);
            }
            w.line(std::string("# end = ") + branch_end_name(br.end));
            w.line("# end_point = " + std::to_string(br.end_point) + "  (the j of the point that met the break; -1: none)");
            w.line("# b_last = " + format_double(br.points.back().b));
            w.line("# b_lost = " + format_double(br.b_lost) + "  (the first b tried past b_last; nan: none)");
            w.line("# detail = " + br.detail);
            if (o->certify)
              w.line("# certified_intervals = " + std::to_string(n_proved) + " of " + std::to_string(br.points.size() - 1) +
                     "  (the cycle exists for every b of each proved interval)");
            w.flush();
            return 0;
          }};
}

}  // namespace dfchaos::cli
