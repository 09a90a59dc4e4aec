// SPDX-License-Identifier: GPL-3.0-or-later
/// @file cli.hpp
/// @brief What the subcommands of the `dfchaos` tool share: the model options (a, b, q), strict
/// number parsing (one line naming the option, exit 2), a buffered writer that streams rows to
/// stdout and notices a failed write, and progress on stderr.
#pragma once

#include <CLI/CLI.hpp>

#include <memory>

#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "dfchaos/parameters.hpp"

namespace dfchaos::cli {

/// A subcommand: its CLI11 app and what runs it once parsed (returns the exit status).
struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

/// The units of a command's times, lengths and velocities (docs/units.md, "Back to physical
/// units"). Without --physical, the paper's: t in radians of the forcing, lengths as they are,
/// velocities dx/dt. With --physical MASS OMEGA ..., times in seconds (tau = t / omega), lengths in
/// metres (the same numbers), velocities in m/s (omega dx/dt); the columns then carry the unit in
/// their names (elapsed_s, y_m, v_m_per_s), so that a table never hides which units it holds.
/// Phases (theta, T, the phase of an event) stay in radians either way.
struct Units {
  bool physical = false;
  double omega = 1;  ///< the angular frequency (rad/s) of --physical
  std::string time(const std::string& name) const { return physical ? name + "_s" : name; }
  std::string length(const std::string& name) const { return physical ? name + "_m" : name; }
  std::string velocity(const std::string& name) const { return physical ? name + "_m_per_s" : name; }
  double seconds(double t) const { return physical ? t / omega : t; }            ///< a time t of the model, in the output's unit
  double metres_per_second(double v) const { return physical ? v * omega : v; }  ///< a velocity dx/dt, in the output's unit
  double model_time(double s) const { return physical ? s * omega : s; }         ///< an input time in the model's t
  double model_velocity(double v) const { return physical ? v / omega : v; }     ///< an input velocity as dx/dt
};

/// One setting of a run, for the provenance header: "# name = value".
using Setting = std::pair<std::string, std::string>;

/// The model options: --a (1 by default), --b, --q, or --physical MASS OMEGA AMPLITUDE STATIC
/// FRICTION instead of them (a, b, q by dfchaos::from_physical, docs/units.md), as typed.
struct ModelOptions {
  std::string a = "1", b, q;
  std::vector<std::string> physical;
  /// Registers the options on a subcommand.
  void add_to(CLI::App* app);
  /// The parameters. @throws InvalidParameter naming a, b, q or the physical quantity at fault.
  Parameters model() const;
  /// The units of the output: physical with --physical.
  Units units() const;
  /// The settings for the provenance header: a, b, q (shortest round-trip form) and, with
  /// --physical, the five quantities as typed and the units of the output.
  std::vector<Setting> settings(const Parameters& p) const;
};

/// The settings a, b, q of parameters (shortest round-trip form), first in every header.
std::vector<Setting> model_settings(const Parameters& p);
/// The provenance header that follows the column line of every table of the tool (as the sweep's),
/// each line ending in a newline: "# dfchaos TITLE", "# dfchaos VERSION (GIT), COMPILER", then
/// "# name = value" per setting.
std::string provenance_text(const std::string& title, const std::vector<Setting>& settings);

/// A number option: the whole text must be a finite number. @throws InvalidParameter naming it.
double number(const std::string& name, const std::string& text);
/// A count option in [lo, hi]; "1e8" is accepted. @throws InvalidParameter naming it.
long long count(const std::string& name, const std::string& text, long long lo, long long hi);

/// Rows streamed to stdout through a large buffer; a failed write (a closed pipe, a full disk)
/// throws WriteFailed instead of passing silently.
class Writer {
 public:
  Writer();
  ~Writer();
  void row(const std::vector<std::string>& cells);  ///< one tab-separated line
  void line(const std::string& text);               ///< one line as given
  /// provenance_text(title, settings), as lines.
  void provenance(const std::string& title, const std::vector<Setting>& settings);
  void flush();  ///< @throws WriteFailed

 private:
  std::string buffer_;
};

/// A write to stdout failed.
struct WriteFailed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The whole tool: parses argv, runs the subcommand, prints to stdout and stderr.
/// @return the exit status: 0 success, 1 a bounded computation gave up or writing failed, 2 bad input.
int run(int argc, char** argv);

/// The subcommands (cmd_*.cpp).
Command add_info(CLI::App& app);
Command add_map(CLI::App& app);
Command add_orbit(CLI::App& app);
Command add_orbit_diagram(CLI::App& app);  ///< cmd_orbit_diagram.cpp
Command add_periodic(CLI::App& app);       ///< cmd_periodic.cpp
Command add_continue(CLI::App& app);       ///< cmd_continue.cpp
Command add_simulate(CLI::App& app);
Command add_provenance(CLI::App& app);
Command add_certify_command(CLI::App& app);  ///< certify.cpp: proofs in ball arithmetic
Command add_sweep(CLI::App& app);            ///< cmd_sweep.cpp
Command add_sweep_merge(CLI::App& app);      ///< cmd_sweep.cpp

}  // namespace dfchaos::cli
