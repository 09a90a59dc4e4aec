// SPDX-License-Identifier: GPL-3.0-or-later
/// @file app.cpp
/// @brief The `dfchaos` command-line tool as a function (dfchaos::cli::run), so that tests can drive
/// it in-process: thin subcommands over the library (cmd_*.cpp).
///
///   dfchaos info       --a A --b B --q Q
///   dfchaos map        --a A --b B --q Q (--theta X [X ...] | --grid LO:HI:N[:KIND] | --arc N)
///   dfchaos orbit      --a A --b B --q Q --theta0 X --steps N
///   dfchaos orbit-diagram --q-range R --b-range R [--transient N --steps N --keep K]
///   dfchaos periodic   --a A --b B --q Q --word W
///   dfchaos simulate   --a A --b B --q Q --x0 X --y0 Y --v0 V --t0 T --t-end E [--sample DT --samples-out F]
///   dfchaos provenance [--latex]
///   dfchaos certify STATEMENT [--a A --b B|LO:HI --q Q|LO:HI ...]   (certify.hpp)
///
/// Output is tab-separated, the column line first and '#' lines after it, numbers in %.17g. Bad input: one line
/// on stderr naming the parameter and the condition, exit status 2, nothing on stdout. A bounded
/// computation that gives up (e.g. a motion that never flies again): one line, exit status 1.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "cli.hpp"
#include "dfchaos/errors.hpp"
#include "kit/budget.hpp"
#include "kit/format.hpp"
#include "kit/output.hpp"
#include "kit/provenance.hpp"

namespace dfchaos::cli {

namespace {

int run_command(int argc, char** argv);

/// Set when a failed write was already reported (one line, not two).
bool g_write_failure_reported = false;

}  // namespace

int run(int argc, char** argv) {
  // A closed stdout or stderr (`dfchaos ... >&-`) would hand its number to the next file opened
  // (a sample or sweep file), and rows meant for stdout would land in it. Such a descriptor is
  // held by /dev/null opened read-only: writes to it fail, so the command ends with exit 1.
  for (int fd : {1, 2})
    if (::fcntl(fd, F_GETFD) == -1 && errno == EBADF) {
      const int held = ::open("/dev/null", O_RDONLY);
      if (held >= 0 && held != fd) {
        ::dup2(held, fd);
        ::close(held);
      }
    }
  kit::remove_temporaries_on_signals();
  const int status = run_command(argc, argv);
  // Every command's output must reach stdout (also --help and --version): a failed write is an
  // error (exit 1), never a silent success.
  const int err = kit::stdout_failure();
  if (err != 0 && !g_write_failure_reported) {
    std::fprintf(stderr, "dfchaos: error: cannot write the output: %s\n", std::strerror(err));
    return status == 2 ? 2 : 1;
  }
  return status;
}

namespace {

int run_command(int argc, char** argv) {
  CLI::App app{"dfchaos: the dry-friction oscillator of Begun & Kryzhevich (return map T, simulator)"};
  app.set_version_flag("--version", std::string(dfchaos::kit::version()) + " (" + dfchaos::kit::git_hash() + ")");
  app.require_subcommand(1);
  app.footer(
      "Exit status: 0 success, 1 a bounded computation gave up or writing failed, 2 bad input,\n"
      "3 a sweep stopped by --max-chunks before it was complete (rerun it to continue).\n"
      "'dfchaos COMMAND --help' describes each command's options and output columns.\n"
      "Tables (info, map, orbit, simulate, sweep, and the experiments' data files): tab-separated, the column line\n"
      "first, every other line that is not a row starting with '#'. One call reads one in Python:\n" +
      std::string(kit::kLoadInPython) +
      ".\nCertificates and 'certify' verdicts are JSON (json.load).\n"
      "One meaning per name, in every command and in the Python module: theta0 is a phase in [t2, t3) (orbit),\n"
      "theta0-fraction a fraction f of the arc, theta0 = t2 + f (t3 - t2) (sweep); a range is LO:HI:N[:lin|log|mid]\n"
      "with both ends included (sweep's axes, map --grid), or one value x (= x:x:1); orbit steps and transients are\n"
      "at most 1e8 (orbit, sweep); -a -b -q are --a --b --q.");
  const std::vector<Command> commands = {add_info(app),       add_map(app),      add_orbit(app),      add_orbit_diagram(app),   add_periodic(app),
                                         add_continue(app),   add_simulate(app), add_provenance(app), add_certify_command(app), add_sweep(app),
                                         add_sweep_merge(app)};

  if (argc > 1 && argv[1][0] != '-') {
    const std::string sub = argv[1];
    bool known = false;
    std::string names;
    for (const auto& c : commands) {
      known = known || c.app->get_name() == sub;
      names += (names.empty() ? "" : ", ") + c.app->get_name();
    }
    if (!known) {
      std::fprintf(stderr, "dfchaos: error: unknown subcommand '%s' (expected one of %s)\n", sub.c_str(), names.c_str());
      return 2;
    }
  }
  // An empty value would otherwise be read as missing or as 0: refuse it whatever the option.
  for (int i = 1; i < argc; ++i)
    if (argv[i][0] == '\0') {
      std::fprintf(stderr, "dfchaos: error: %s: empty value (a value is required)\n", i > 1 ? argv[i - 1] : "argument");
      return 2;
    }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    std::fprintf(stderr, "dfchaos: error: %s\n", kit::one_line(e.what()).c_str());
    return 2;
  }
  try {
    for (const auto& c : commands)
      if (c.app->parsed()) return c.run();
  } catch (const dfchaos::InvalidParameter& e) {
    std::fprintf(stderr, "dfchaos: error: %s\n", kit::one_line(e.what()).c_str());
    return 2;
  } catch (const dfchaos::GaveUp& e) {
    std::fflush(stdout);
    std::fprintf(stderr, "dfchaos: gave up: %s\n", kit::one_line(e.what()).c_str());
    return 1;
  } catch (const WriteFailed& e) {
    g_write_failure_reported = true;
    std::fprintf(stderr, "dfchaos: error: %s\n", kit::one_line(e.what()).c_str());
    return 1;
  } catch (const dfchaos::kit::OutputError& e) {  // an unusable output path is bad input; a failed write is not
    g_write_failure_reported = true;
    std::fprintf(stderr, "dfchaos: error: %s\n", kit::one_line(e.what()).c_str());
    return e.bad_path() ? 2 : 1;
  } catch (const std::bad_alloc&) {  // a memory budget (kit/budget.hpp) or the machine's memory ran out
    const std::string budget = kit::memory_budget_line();
    std::fprintf(stderr, "dfchaos: gave up: %s\n", budget.empty() ? "out of memory (an allocation failed)" : budget.c_str());
    return 1;
  }
  return 2;
}

}  // namespace

}  // namespace dfchaos::cli
