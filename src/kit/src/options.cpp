// SPDX-License-Identifier: GPL-3.0-or-later
#include "kit/options.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "dfchaos/errors.hpp"

namespace dfchaos::kit {

namespace {
std::string bound_text(OptionType type, double v) {
  if (type == OptionType::Count) return std::to_string(static_cast<long long>(v));
  return format_shortest(v);
}
}  // namespace

std::string OptionSpec::condition() const { return bound_text(type, min) + " <= " + name + " <= " + bound_text(type, max); }

std::string OptionSpec::record_key() const {
  if (!record.empty()) return record;
  std::string k = name;
  for (auto& ch : k)
    if (ch == '-') ch = '_';
  return k;
}

Json OptionSpec::to_json() const {
  Json j = Json::object();
  j.set("name", name);
  j.set("type", type == OptionType::Count ? "count" : type == OptionType::Real ? "real" : "reals");
  j.set("help", help);
  auto list = [&](const std::vector<double>& v) {
    Json a = Json::array();
    for (double x : v) a.push(type == OptionType::Count ? Json(static_cast<long long>(x)) : Json(x));
    return a;
  };
  j.set("default", type == OptionType::Reals ? list(value) : (type == OptionType::Count ? Json(static_cast<long long>(value[0])) : Json(value[0])));
  j.set("min", type == OptionType::Count ? Json(static_cast<long long>(min)) : Json(min));
  j.set("max", type == OptionType::Count ? Json(static_cast<long long>(max)) : Json(max));
  if (fast)
    j.set("fast",
          type == OptionType::Reals ? list(*fast) : (type == OptionType::Count ? Json(static_cast<long long>((*fast)[0])) : Json((*fast)[0])));
  j.set("condition", condition());
  return j;
}

OptionSpec count(std::string name, long long default_value, std::string help) {
  OptionSpec s;
  s.name = std::move(name);
  s.type = OptionType::Count;
  s.help = std::move(help);
  s.value = {static_cast<double>(default_value)};
  s.min = 0;
  s.max = 1e9;
  return s;
}

OptionSpec real(std::string name, double default_value, std::string help) {
  OptionSpec s;
  s.name = std::move(name);
  s.type = OptionType::Real;
  s.help = std::move(help);
  s.value = {default_value};
  s.min = -1e300;
  s.max = 1e300;
  return s;
}

OptionSpec reals(std::string name, std::vector<double> default_values, std::string help) {
  OptionSpec s = real(std::move(name), 0, std::move(help));
  s.type = OptionType::Reals;
  s.value = std::move(default_values);
  return s;
}

long long parse_count(const std::string& name, const std::string& text, long long lo, long long hi) {
  const double v = parse_number(name, text, true);
  if (v < static_cast<double>(lo) || v > static_cast<double>(hi))
    throw InvalidParameter(name, format_shortest(static_cast<double>(lo)) + " <= " + name + " <= " + format_shortest(static_cast<double>(hi)), v);
  return static_cast<long long>(v);
}

double parse_number(const std::string& name, const std::string& text, bool integer) {
  if (text.empty()) throw InvalidParameter(name, "a number is required (got an empty value)");
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) throw InvalidParameter(name, "must be a number (got '" + text + "')");
  if (!std::isfinite(v)) throw InvalidParameter(name, "must be a finite number (got '" + text + "')");
  if (integer && (v != std::floor(v) || std::fabs(v) > 9e18)) throw InvalidParameter(name, "must be an integer (got '" + text + "')");
  return v;
}

const OptionValues::Entry& OptionValues::find(const std::string& name, OptionType type) const {
  for (const auto& e : entries_)
    if (e.spec->name == name) {
      if (e.spec->type != type) throw std::logic_error("option --" + name + " read with the wrong type");
      return e;
    }
  throw std::logic_error("option --" + name + " is not declared");
}

long long OptionValues::count(const std::string& name) const { return static_cast<long long>(find(name, OptionType::Count).value[0]); }
double OptionValues::real(const std::string& name) const { return find(name, OptionType::Real).value[0]; }
const std::vector<double>& OptionValues::reals(const std::string& name) const { return find(name, OptionType::Reals).value; }
bool OptionValues::given(const std::string& name) const {
  for (const auto& e : entries_)
    if (e.spec->name == name) return e.given;
  throw std::logic_error("option --" + name + " is not declared");
}

void OptionValues::set_defaults(const std::vector<OptionSpec>& specs, bool fast) {
  entries_.clear();
  for (const auto& s : specs) entries_.push_back(Entry{&s, fast && s.fast ? *s.fast : s.value, false});
}

void OptionValues::set(const OptionSpec& spec, const std::vector<std::string>& text) {
  std::vector<double> v;
  if (text.empty() || (spec.type != OptionType::Reals && text.size() != 1))
    throw InvalidParameter(spec.name, spec.type == OptionType::Reals ? "one or more numbers are required" : "exactly one number is required");
  for (const auto& t : text) {
    const double x = parse_number(spec.name, t, spec.type == OptionType::Count);
    if (x < spec.min || x > spec.max) throw InvalidParameter(spec.name, spec.condition(), x);
    v.push_back(x);
  }
  for (auto& e : entries_)
    if (e.spec == &spec) {
      e.value = std::move(v);
      e.given = true;
      return;
    }
  throw std::logic_error("option --" + spec.name + " set before its defaults");
}

}  // namespace dfchaos::kit
