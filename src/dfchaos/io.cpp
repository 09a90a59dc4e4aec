#include "dfchaos/io.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include <CLI/Version.hpp>
#include <Eigen/Core>
#include <gsl/gsl_version.h>

#include "dfchaos/errors.hpp"
#include "dfchaos/version.hpp"

namespace dfchaos {

void write_atomically(const std::filesystem::path& path, const std::string& content) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  const std::filesystem::path tmp = path.string() + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) throw std::runtime_error("cannot write " + tmp.string());
    f << content;
    if (!f.flush()) throw std::runtime_error("cannot write " + tmp.string());
  }
  std::filesystem::rename(tmp, path);
}

Json Json::array() {
  Json j;
  j.v_ = std::make_shared<Array>();
  return j;
}
Json Json::object() {
  Json j;
  j.v_ = std::make_shared<Object>();
  return j;
}
Json& Json::set(const std::string& key, Json value) {
  auto* o = std::get_if<std::shared_ptr<Object>>(&v_);
  if (!o) throw std::logic_error("Json::set on a non-object");
  for (auto& kv : **o)
    if (kv.first == key) {
      kv.second = std::move(value);
      return *this;
    }
  (*o)->emplace_back(key, std::move(value));
  return *this;
}
Json& Json::push(Json value) {
  auto* a = std::get_if<std::shared_ptr<Array>>(&v_);
  if (!a) throw std::logic_error("Json::push on a non-array");
  (*a)->push_back(std::move(value));
  return *this;
}

namespace {
std::string escape(const std::string& s) {
  std::string out = "\"";
  for (char ch : s) {
    switch (ch) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(ch) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", ch);
          out += buf;
        } else {
          out += ch;
        }
    }
  }
  return out + "\"";
}
}  // namespace

void Json::dump_to(std::string& out, int indent, int depth) const {
  const std::string pad(static_cast<std::size_t>(indent * (depth + 1)), ' '), pad_end(static_cast<std::size_t>(indent * depth), ' ');
  const char* nl = indent > 0 ? "\n" : "";
  if (std::holds_alternative<std::nullptr_t>(v_)) out += "null";
  else if (auto* b = std::get_if<bool>(&v_)) out += *b ? "true" : "false";
  else if (auto* d = std::get_if<double>(&v_)) out += std::isfinite(*d) ? format_double(*d) : "null";
  else if (auto* i = std::get_if<long long>(&v_)) out += std::to_string(*i);
  else if (auto* s = std::get_if<std::string>(&v_)) out += escape(*s);
  else if (auto* a = std::get_if<std::shared_ptr<Array>>(&v_)) {
    if ((*a)->empty()) { out += "[]"; return; }
    out += "[";
    out += nl;
    for (std::size_t k = 0; k < (*a)->size(); ++k) {
      out += pad;
      (**a)[k].dump_to(out, indent, depth + 1);
      if (k + 1 < (*a)->size()) out += ",";
      out += nl;
    }
    out += pad_end + "]";
  } else if (auto* o = std::get_if<std::shared_ptr<Object>>(&v_)) {
    if ((*o)->empty()) { out += "{}"; return; }
    out += "{";
    out += nl;
    for (std::size_t k = 0; k < (*o)->size(); ++k) {
      out += pad + escape((**o)[k].first) + (indent > 0 ? ": " : ":");
      (**o)[k].second.dump_to(out, indent, depth + 1);
      if (k + 1 < (*o)->size()) out += ",";
      out += nl;
    }
    out += pad_end + "}";
  }
}

std::string Json::dump(int indent) const {
  std::string out;
  dump_to(out, indent, 0);
  return out + "\n";
}

Table::Table(std::vector<std::string> columns) : columns_(std::move(columns)) {}

Table& Table::row(std::vector<Cell> cells) {
  if (cells.size() != columns_.size()) throw std::logic_error("Table::row: wrong number of cells");
  rows_.push_back(std::move(cells));
  return *this;
}

std::string Table::render() const {
  std::string out;
  for (std::size_t k = 0; k < columns_.size(); ++k) out += (k ? "\t" : "") + columns_[k];
  out += "\n";
  for (const auto& r : rows_) {
    for (std::size_t k = 0; k < r.size(); ++k) {
      if (k) out += "\t";
      if (auto* d = std::get_if<double>(&r[k])) out += format_double(*d);
      else if (auto* i = std::get_if<long long>(&r[k])) out += std::to_string(*i);
      else out += std::get<std::string>(r[k]);
    }
    out += "\n";
  }
  return out;
}

std::string format_significant(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

std::string compiler_id() {
#if defined(__clang__)
  return std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  return std::string("g++ ") + __VERSION__;
#else
  return "unknown";
#endif
}

std::vector<std::pair<std::string, std::string>> build_info() {
  return {{"dfchaos", version},
          {"git", git_hash},
          {"compiler", compiler_id()},
          {"Eigen", std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) + "." + std::to_string(EIGEN_MINOR_VERSION)},
          {"GSL", GSL_VERSION},
          {"CLI11", CLI11_VERSION}};
}

std::string latex_number(const std::string& text) {
  // Only a whole number in exponent notation is rewritten, e.g. "1.4e-13" -> 1.4 x 10^{-13}.
  char* end = nullptr;
  std::strtod(text.c_str(), &end);
  const auto e = text.find_first_of("eE");
  if (text.empty() || end != text.c_str() + text.size() || e == std::string::npos) return text;
  const std::string mantissa = text.substr(0, e);
  const int exponent = std::atoi(text.c_str() + e + 1);
  const std::string power = "10^{" + std::to_string(exponent) + "}";
  return "\\ensuremath{" + (mantissa == "1" ? power : mantissa + "\\times " + power) + "}";
}

std::string latex_escape(const std::string& text) {
  std::string out;
  for (char ch : text) {
    switch (ch) {
      case '\\': out += "\\textbackslash{}"; break;
      case '^': out += "\\textasciicircum{}"; break;
      case '~': out += "\\textasciitilde{}"; break;
      case '<': out += "$<$"; break;
      case '>': out += "$>$"; break;
      case '|': out += "$|$"; break;
      case '&': case '%': case '$': case '#': case '_': case '{': case '}':
        out += '\\';
        out += ch;
        break;
      default: out += ch;
    }
  }
  return out;
}

ExperimentOutput::ExperimentOutput(std::string name, std::filesystem::path root) : name_(std::move(name)), root_(std::move(root)) {}

void ExperimentOutput::parameter(const std::string& key, const std::string& value) { parameters_.emplace_back(key, value); }
void ExperimentOutput::parameter(const std::string& key, double value) { parameters_.emplace_back(key, format_double(value)); }

std::string ExperimentOutput::header() const {
  std::string h = "# experiment: " + name_ + "\n# dfchaos " + version + " (" + git_hash + "), " + compiler_id() + "\n";
  for (const auto& [k, v] : parameters_) h += "# " + k + " = " + v + "\n";
  return h;
}

void ExperimentOutput::table(const std::string& part, const Table& t, const std::string& description) {
  const std::string file = part.empty() ? name_ : name_ + "-" + part;
  files_.emplace_back(root_ / "data" / (file + ".tsv"), header() + "# " + description + "\n" + t.render());
}

void ExperimentOutput::latex(const std::string& file, const std::string& tex) {
  files_.emplace_back(root_ / "tables" / (file + ".tex"), "% generated by experiment " + name_ + "; do not edit\n" + tex);
}

void ExperimentOutput::macro(const std::string& name, const std::string& value) {
  for (char ch : name)
    if (!std::isalpha(static_cast<unsigned char>(ch))) throw std::logic_error("macro name must be letters only: " + name);
  macros_.emplace_back(name, value);
}
void ExperimentOutput::macro(const std::string& name, double value, int digits) { macro(name, format_significant(value, digits)); }

void ExperimentOutput::claim(Claim c) {
  for (char ch : c.id)
    if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '.' || ch == '_'))
      throw std::logic_error("claim id must use letters, digits, '.' and '_' only: " + c.id);
  claims_.push_back(std::move(c));
}

int ExperimentOutput::finish() const {
  auto files = files_;
  if (!macros_.empty()) {
    std::string tex = "% generated by experiment " + name_ + "; do not edit\n";
    for (const auto& [k, v] : macros_) tex += "\\newcommand{\\dfc" + k + "}{" + latex_number(v) + "}\n";
    files.emplace_back(root_ / "tables" / (name_ + "-macros.tex"), tex);
  }
  Json doc = Json::object();
  doc.set("experiment", name_);
  doc.set("version", std::string(version));
  doc.set("git", std::string(git_hash));
  doc.set("compiler", compiler_id());
  Json params = Json::object();
  for (const auto& [k, v] : parameters_) params.set(k, v);
  doc.set("run_parameters", params);
  Json list = Json::array();
  int failed_expected = 0;
  for (const auto& c : claims_) {
    Json j = Json::object();
    j.set("id", c.id).set("reference", c.reference).set("statement", c.statement);
    j.set("parameters", c.parameters).set("evidence", c.evidence);
    j.set("evidence_kind", c.evidence_kind.empty() ? std::string("unspecified") : c.evidence_kind);
    j.set("verdict", c.holds ? "holds" : "fails").set("expected_to_hold", c.expected);
    list.push(j);
    if (c.expected && !c.holds) ++failed_expected;
  }
  doc.set("claims", list);
  files.emplace_back(root_ / "claims" / (name_ + ".json"), doc.dump());

  std::string rows = "% generated by experiment " + name_ + "; do not edit\n";
  for (const auto& c : claims_) {
    const char* verdict = c.holds ? "holds" : "fails";
    rows += "\\dfcsetverdict{" + c.id + "}{" + verdict + "}\n";
    rows += "\\dfcclaimrow{" + c.id + "}{" + latex_escape(c.reference) + "}{" + latex_escape(c.statement) + "}{" +
            verdict + "}\n";
  }
  files.emplace_back(root_ / "tables" / (name_ + "-claims.tex"), rows);
  std::string prow = "% generated by experiment " + name_ + "; do not edit\n";
  for (const auto& [k, v] : parameters_) prow += "\\dfcparamrow{" + latex_escape(k) + "}{" + latex_escape(v) + "}\n";
  files.emplace_back(root_ / "tables" / (name_ + "-params.tex"), prow);
  for (const auto& [path, content] : files) write_atomically(path, content);
  for (const auto& c : claims_)
    std::fprintf(stderr, "  %-5s %-28s %s\n", c.holds ? "holds" : "FAILS", c.id.c_str(), c.reference.c_str());
  for (const auto& c : claims_)
    if (c.expected && !c.holds) std::fprintf(stderr, "%s: claim %s (%s) expected to hold but fails\n", name_.c_str(), c.id.c_str(), c.reference.c_str());
  return failed_expected ? 1 : 0;
}

}  // namespace dfchaos
