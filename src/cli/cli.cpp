// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>

#include "dfchaos/errors.hpp"
#include "kit/options.hpp"
#include "kit/provenance.hpp"

namespace dfchaos::cli {

void ModelOptions::add_to(CLI::App* app) {
  const std::string range = format_shortest(kMinParameter) + " <= X <= " + format_shortest(kMaxParameter);
  // a defaults to 1 (the paper's scaling: b and q are then b/a and q/a), as in sweep, certify and
  // the Python module's certify: one rule for every command.
  app->add_option("-a,--a", a, "forcing amplitude a, " + range + " [default 1]")->type_name("FLOAT");
  app->add_option("-b,--b", b, "half the constant force b, " + range + "; the return map needs b < a/2 and b/a >= " + format_shortest(kMinMapRatio))
      ->required()
      ->type_name("FLOAT");
  app->add_option("-q,--q", q, "maximal dry-friction force q, " + range + "; the return map needs q > 2b")->required()->type_name("FLOAT");
}

Parameters ModelOptions::model() const { return Parameters(number("a", a), number("b", b), number("q", q)); }

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
