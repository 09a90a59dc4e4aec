// SPDX-License-Identifier: GPL-3.0-or-later
#include "sweep/observables.hpp"

#include "dfchaos/errors.hpp"

namespace dfchaos::sweep {

const char* observable_name(Observable o) {
  switch (o) {
    case Observable::Covering: return "covering";
    case Observable::Superstable: return "superstable";
    case Observable::Lyapunov: return "lyapunov";
    case Observable::Rate: return "rate";
    case Observable::Period: return "period";
    case Observable::Certified: return "certified";
    case Observable::Region: return "region";
    case Observable::Entropy: return "entropy";
  }
  return "?";
}

std::string observable_names(const char* separator) {
  std::string s;
  for (Observable o : kAllObservables) s += (s.empty() ? "" : separator) + std::string(observable_name(o));
  return s;
}

namespace {
std::string known_names() { return observable_names(", "); }
}  // namespace

ObservableSet ObservableSet::parse(const std::string& option, const std::string& text) {
  if (text.empty()) throw InvalidParameter(option, "a comma-separated list of " + known_names() + " is required (got an empty list)");
  ObservableSet set;
  std::string name;
  // One pass over the text plus a final separator: bounded by its length.
  for (std::size_t k = 0; k <= text.size(); ++k) {
    if (k < text.size() && text[k] != ',') {
      name += text[k];
      continue;
    }
    if (name.empty()) throw InvalidParameter(option, "empty name in the list '" + text + "' (known: " + known_names() + ")");
    bool found = false;
    for (Observable o : kAllObservables)
      if (name == observable_name(o)) {
        if (set.has(o)) throw InvalidParameter(option, "'" + name + "' is listed twice");
        set.bits_ |= 1U << static_cast<int>(o);
        found = true;
      }
    if (!found) throw InvalidParameter(option, "unknown observable '" + name + "' (known: " + known_names() + ")");
    name.clear();
  }
  return set;
}

std::string ObservableSet::canonical() const {
  std::string s;
  for (Observable o : kAllObservables)
    if (has(o)) s += (s.empty() ? "" : ",") + std::string(observable_name(o));
  return s;
}

std::vector<std::string> ObservableSet::columns() const {
  std::vector<std::string> c;
  for (Observable o : kAllObservables)
    if (has(o)) {
      if (o == Observable::Entropy) {  // two bounds and a count: no column is "the" entropy
        for (const char* name : {"entropy_lower", "entropy_upper", "entropy_laps"}) c.emplace_back(name);
        continue;
      }
      c.emplace_back(observable_name(o));
      if (o == Observable::Superstable) c.emplace_back("epsilon");
      if (o == Observable::Certified) c.emplace_back("certified_step");
      if (o == Observable::Region)
        for (const char* name : {"region_uniform", "region_boxes", "region_stop"}) c.emplace_back(name);
    }
  return c;
}

}  // namespace dfchaos::sweep
