// SPDX-License-Identifier: GPL-3.0-or-later
/// @file cmd_periodic.cpp
/// @brief `dfchaos periodic`: the periodic orbit of T with a given itinerary over Lemma 4's covering
/// segments J0, J1, in floating point (symbolic.hpp, periodic_orbit), with its multiplier and its
/// checks; `dfchaos certify periodic --word` proves it.
#include <cmath>
#include <string>

#include "cli.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/return_map.hpp"
#include "dfchaos/symbolic.hpp"

namespace dfchaos::cli {

Command add_periodic(CLI::App& app) {
  auto* cmd = app.add_subcommand("periodic", "the periodic orbit of T with itinerary (W)^infinity over Lemma 4's J0, J1, in floating point");
  struct Opts {
    ModelOptions m;
    std::string word;
  };
  auto o = std::make_shared<Opts>();
  o->m.add_to(cmd);
  cmd->add_option("--word", o->word,
                  "one period W of the itinerary: 1.." + std::to_string(kMaxItineraryLength) +
                      " letters, 0 for J0 and 1 for J1, primitive (no power of a shorter word); the orbit's least period is |W|")
      ->required()
      ->type_name("W");
  cmd->footer(
      "Output (tab-separated, %.17g; after the column line, # lines: the version, the settings and the orbit's checks):\n"
      "  j        0 .. |W| - 1\n"
      "  letter   W[j]: the orbit point lies in J0 or J1\n"
      "  x        x_j, the orbit point: x_(j+1) = T(x_j), x_|W| = x_0\n"
      "  T        T(x_j) as the map computes it (differs from x_(j+1) by the step residual)\n"
      "The # lines give log_multiplier = ln|(T^m)'(x_0)| = sum of ln|T'(x_j)| (central differences), the largest step\n"
      "residual |T(x_j) - x_(j+1)|, the residual that double precision alone can produce along this orbit\n"
      "(precision_floor: below it a residual cannot tell a true orbit from a false one), and whether every x_j lies in\n"
      "the branch of its letter. The orbit is the fixed point of the composed inverse branches of T on J0, J1 (a\n"
      "contraction; Section 6), found where Lemma 4's covering is found (b or q refused, exit 2, where it is not).\n"
      "'dfchaos certify periodic --word W' encloses it in ball arithmetic, with a certificate.");
  return {cmd, [o] {
            const Parameters p = o->m.model();
            p.require_return_map();
            const ItineraryOrbit orb = periodic_orbit(p, o->word);
            std::vector<Setting> settings = o->m.settings(p);
            settings.emplace_back("word", orb.word);
            settings.emplace_back("least_period", std::to_string(orb.word.size()));
            settings.emplace_back("log_multiplier", format_double(orb.log_expansion) + "  (ln|(T^m)'(x_0)|, central differences)");
            settings.emplace_back("max_step_residual", format_double(orb.max_step_residual));
            settings.emplace_back("precision_floor", format_double(orb.precision_floor));
            settings.emplace_back("itinerary_checked", orb.itinerary_ok ? "yes: every x_j in the branch K of its letter" : "no");
            Writer w;
            w.row({"j", "letter", "x", "T"});
            w.provenance("periodic: the periodic orbit of T with itinerary (W)^infinity", settings);
            for (std::size_t j = 0; j < orb.x.size(); ++j)
              w.row({std::to_string(j), std::string(1, orb.word[j]), format_double(orb.x[j]), format_double(return_map_step(p, orb.x[j]).T)});
            w.flush();
            return 0;
          }};
}

}  // namespace dfchaos::cli
