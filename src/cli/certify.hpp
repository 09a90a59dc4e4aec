// SPDX-License-Identifier: GPL-3.0-or-later
/// @file certify.hpp
/// @brief `dfchaos certify`: the options of the certified statements (certify/certify.hpp runs them).
///
///   dfchaos certify STATEMENT [OPTIONS]
///
/// One subcommand per statement of the registry (certify/statements.hpp), its options those of the
/// inputs the statement reads; `dfchaos certify --help` lists them.
///
/// With `--certificate FILE` a proved statement's certificate is written
/// to FILE whole or not at all (certify/certificate.hpp), and the record gets "certificate":
/// {"path", "bytes", "sha256"}; a statement not proved writes none ({"written": false}). A FILE
/// that cannot be created is bad input (exit 2, one line, no file).
///
/// Prints one JSON object: "proved", "statement", enclosures (decimal mid and radius), for covering
/// "J0" and "J1", and on failure "failed_step". Exit status 0 when proved, 1 when not proved (an
/// answer, not an error), 2 for bad input (one line on stderr naming the parameter, nothing on stdout).
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace dfchaos::cli {

/// The options of `certify`.
struct CertifyOptions {
  std::string what;                ///< the statement (a name of certify/statements.hpp)
  std::string a = "1";             ///< a (a number)
  std::string b;                   ///< b: a number or LO:HI
  std::string q;                   ///< q: a number or LO:HI
  int period = 0;                  ///< periodic: the minimal period m
  std::string word;                ///< periodic, instead of period: one period of the itinerary
  std::string segment = "L0";      ///< discontinuities: L0 = [101pi/100, 3pi/2] or L2 = [101pi/100, 51pi/50]
  std::string window;              ///< superstable: a window LO:HI in b (floating estimate) to certify with its edges
  std::string J0;                  ///< covering: the segment J0 as TOP:T2 (its candidate ends, as certified_region records them)
  std::string J1;                  ///< covering: the segment J1 as TOP:T2
  std::string certificate;         ///< --certificate FILE: where to write the certificate (empty: none)
  std::string max_seconds = "60";  ///< the time budget of the process (kit/budget.hpp)
  std::string max_memory = "2";    ///< the memory budget of the process in GiB (kit/budget.hpp)
};

/// Registers the `certify` subcommand on `app`, bound to `o`; returns it.
CLI::App* add_certify(CLI::App& app, CertifyOptions& o);

/// Runs `certify` within its time and memory budget (--max-seconds, --max-memory; kit/budget.hpp):
/// JSON on stdout; returns the exit status (0 proved, 1 not proved or a budget ran out, 2 bad input).
int run_certify(const CertifyOptions& o);

}  // namespace dfchaos::cli
