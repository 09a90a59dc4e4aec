// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>

#include "dfchaos/errors.hpp"
#include "dfchaos/units.hpp"
#include "kit/options.hpp"
#include "kit/provenance.hpp"

namespace dfchaos::cli {

void ModelOptions::add_to(CLI::App* app) {
  const std::string range = format_shortest(kMinParameter) + " <= X <= " + format_shortest(kMaxParameter);
  // a defaults to 1 (the paper's scaling: b and q are then b/a and q/a), as in sweep, certify and
  // the Python module's certify: one rule for every command.
  auto* oa = app->add_option("-a,--a", a, "forcing amplitude a, " + range + " [default 1]")->type_name("FLOAT");
  auto* ob = app->add_option("-b,--b", b,
                             "half the constant force b, " + range + "; the return map needs b < a/2 and b/a >= " + format_shortest(kMinMapRatio))
                 ->type_name("FLOAT");
  auto* oq = app->add_option("-q,--q", q, "maximal dry-friction force q, " + range + "; the return map needs q > 2b")->type_name("FLOAT");
  auto* ph = app->add_option("--physical", physical,
                             "instead of --a --b --q: a drilling model in physical units, MASS (kg), OMEGA the forcing's angular "
                             "frequency (rad/s), AMPLITUDE of the harmonic force (N), STATIC force (N), FRICTION the delimiter's "
                             "largest dry friction (N); a = AMPLITUDE/(MASS OMEGA^2), b = STATIC/(2 MASS OMEGA^2), "
                             "q = FRICTION/(MASS OMEGA^2) (docs/units.md). Times are then in seconds, lengths in metres, "
                             "velocities in m/s, in the input and the output (columns named with their unit: elapsed_s, y_m)")
                 ->expected(5)
                 ->type_name("MASS OMEGA AMPLITUDE STATIC FRICTION");
  for (auto* o : {oa, ob, oq}) ph->excludes(o);
}

Parameters ModelOptions::model() const {
  if (!physical.empty())
    return from_physical(number("mass", physical[0]), number("omega", physical[1]), number("amplitude", physical[2]),
                         number("static_force", physical[3]), number("friction", physical[4]));
  if (b.empty() || q.empty())
    throw InvalidParameter(b.empty() ? "b" : "q", "give --b and --q (and --a, 1 by default), or --physical MASS OMEGA AMPLITUDE STATIC FRICTION");
  return Parameters(number("a", a), number("b", b), number("q", q));
}

Units ModelOptions::units() const {
  if (physical.empty()) return {};
  return {true, number("omega", physical[1])};
}

std::vector<Setting> ModelOptions::settings(const Parameters& p) const {
  std::vector<Setting> s = model_settings(p);
  if (!physical.empty()) {
    s.emplace_back("physical", physical[0] + " " + physical[1] + " " + physical[2] + " " + physical[3] + " " + physical[4] +
                                   "  (mass kg, omega rad/s, amplitude N, static force N, friction N; docs/units.md)");
    s.emplace_back("units", "times in seconds (t / omega), lengths in metres, velocities in m/s (omega dx/dt); phases in radians");
  }
  return s;
}

std::vector<Setting> model_settings(const Parameters& p) {
  return {{"a", format_shortest(p.a())}, {"b", format_shortest(p.b())}, {"q", format_shortest(p.q())}};
}

double number(const std::string& name, const std::string& text) { return kit::parse_number(name, text, false); }

long long count(const std::string& name, const std::string& text, long long lo, long long hi) { return kit::parse_count(name, text, lo, hi); }

Writer::Writer() { buffer_.reserve(1 << 16); }
Writer::~Writer() {
  try {
    flush();
  } catch (...) {
  }
}

void Writer::row(const std::vector<std::string>& cells) {
  for (std::size_t k = 0; k < cells.size(); ++k) {
    if (k) buffer_ += '\t';
    buffer_ += cells[k];
  }
  buffer_ += '\n';
  if (buffer_.size() >= (1 << 16)) flush();
}

void Writer::line(const std::string& text) {
  buffer_ += text;
  buffer_ += '\n';
  if (buffer_.size() >= (1 << 16)) flush();
}

std::string provenance_text(const std::string& title, const std::vector<Setting>& settings) {
  std::string text = "# dfchaos " + title + "\n# dfchaos " + kit::version() + " (" + kit::git_hash() + "), " + kit::compiler_id() + "\n";
  for (const auto& [name, value] : settings) text += "# " + name + " = " + value + "\n";
  return text;
}

void Writer::provenance(const std::string& title, const std::vector<Setting>& settings) {
  buffer_ += provenance_text(title, settings);
  if (buffer_.size() >= (1 << 16)) flush();
}

void Writer::flush() {
  if (!buffer_.empty()) {
    const std::size_t n = std::fwrite(buffer_.data(), 1, buffer_.size(), stdout);
    buffer_.clear();
    if (n == 0 || std::ferror(stdout)) throw WriteFailed(std::string("cannot write the output: ") + std::strerror(errno));
  }
  if (std::fflush(stdout) != 0) throw WriteFailed(std::string("cannot write the output: ") + std::strerror(errno));
}

}  // namespace dfchaos::cli
