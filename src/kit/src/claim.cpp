// SPDX-License-Identifier: GPL-3.0-or-later
#include "kit/claim.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "kit/format.hpp"

namespace dfchaos::kit {

const char* evidence_kind_name(EvidenceKind k) {
  switch (k) {
    case EvidenceKind::Analytic: return "analytic";
    case EvidenceKind::Sampled: return "sampled";
    case EvidenceKind::Certified: return "certified";
    case EvidenceKind::CertifiedArgument: return "certified+argument";
    case EvidenceKind::PrecisionLimited: return "precision-limited";
  }
  return "?";
}

const char* origin_name(Origin o) { return o == Origin::Paper ? "paper" : o == Origin::Ours ? "ours" : "erratum"; }

const char* verdict_name(Verdict v) {
  switch (v) {
    case Verdict::Holds: return "holds";
    case Verdict::Fails: return "fails";
    case Verdict::Inconclusive: return "inconclusive";
    case Verdict::Undecided: return "undecided";
  }
  return "?";
}

Claim::Claim(std::string id, std::string reference, EvidenceKind kind, std::string statement)
    : id_(std::move(id)), reference_(std::move(reference)), statement_(std::move(statement)), kind_(kind) {
  if (id_.empty()) throw std::logic_error("claim id must not be empty");
  for (char ch : id_)
    if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '.' || ch == '_'))
      throw std::logic_error("claim id must use letters, digits, '.' and '_' only: " + id_);
}

Claim& Claim::ours() {
  origin_ = Origin::Ours;
  return *this;
}
Claim& Claim::erratum() {
  origin_ = Origin::Erratum;
  return *this;
}
const char* Claim::report_verdict() const { return origin_ == Origin::Erratum && verdict_ == Verdict::Holds ? "refutes" : verdict_name(verdict_); }
Claim& Claim::not_expected() {
  expected_ = false;
  return *this;
}
Claim& Claim::parameter(const std::string& key, Json value) {
  parameters_.set(key, std::move(value));
  return *this;
}
Claim& Claim::evidence(const std::string& key, Json value) {
  evidence_.set(key, std::move(value));
  return *this;
}
Claim& Claim::parameter_object(const Json& object) {
  if (!object.is_object()) throw std::logic_error("claim " + id_ + ": parameters must be a JSON object");
  parameters_ = object;
  return *this;
}
Claim& Claim::evidence_object(const Json& object) {
  if (!object.is_object()) throw std::logic_error("claim " + id_ + ": evidence must be a JSON object");
  evidence_ = object;
  if (has_tolerance_) evidence_.set("tolerance", tolerance_);
  return *this;
}

Claim& Claim::tolerance(double tol) {
  has_tolerance_ = true;
  tolerance_ = tol;
  evidence_.set("tolerance", tol);
  return *this;
}
Claim& Claim::holds(bool verdict) {
  if (verdict_ == Verdict::Inconclusive) return *this;  // precision-limited stays inconclusive
  if (cases_recorded_) {
    // cases() decided; a later verdict may add a failure of its own, never erase a counterexample.
    if (!verdict) verdict_ = Verdict::Fails;
    return *this;
  }
  verdict_ = verdict ? Verdict::Holds : Verdict::Fails;
  return *this;
}
Claim& Claim::cases(long long checked, long long counterexamples, long long undecided) {
  if (checked < 0 || counterexamples < 0 || undecided < 0 || counterexamples + undecided > checked)
    throw std::logic_error("claim " + id_ + ": cases need 0 <= counterexamples, undecided and counterexamples + undecided <= checked");
  evidence("checked", checked).evidence("counterexamples", counterexamples).evidence("precision_undecided", undecided);
  cases_recorded_ = true;
  if (verdict_ == Verdict::Fails) return *this;  // an earlier failure stands
  if (counterexamples > 0) {
    verdict_ = Verdict::Fails;
    return *this;
  }
  if (undecided > 0) {
    return inconclusive(std::to_string(undecided) + " of " + std::to_string(checked) +
                        " cases could not be decided in double precision; none is a counterexample");
  }
  verdict_ = Verdict::Holds;
  return *this;
}
Claim& Claim::at_most(const std::string& name, double measured, double tol) {
  evidence(name, measured);
  tolerance(tol);
  return holds(std::fabs(measured) <= tol);
}
Claim& Claim::inconclusive(const std::string& reason) {
  kind_ = EvidenceKind::PrecisionLimited;
  verdict_ = Verdict::Inconclusive;
  evidence_.set("inconclusive_because", reason);
  return *this;
}

std::string format_tolerance(double tol) {
  char buf[40];
  if (tol != 0 && std::fabs(tol) < 1e-3) {
    // The shortest exponent form that reads back as the same double: 1e-4, 2.5e-7.
    for (int digits = 0; digits <= 17; ++digits) {
      std::snprintf(buf, sizeof buf, "%.*e", digits, tol);
      if (std::strtod(buf, nullptr) == tol) break;
    }
  } else {
    std::snprintf(buf, sizeof buf, "%g", tol);
  }
  std::string t = buf;
  // "1e-08" -> "1e-8": the exponent as one writes it.
  const auto e = t.find('e');
  if (e != std::string::npos) {
    std::size_t k = e + 1;
    if (k < t.size() && t[k] == '+') t.erase(k, 1);
    if (k < t.size() && t[k] == '-') ++k;
    while (k + 1 < t.size() && t[k] == '0') t.erase(k, 1);
  }
  return t;
}

std::string Claim::statement() const {
  const auto at = statement_.find("{tol}");
  if (at == std::string::npos) {
    if (has_tolerance_) throw std::logic_error("claim " + id_ + ": a tolerance is set but the statement has no {tol}");
    return statement_;
  }
  if (!has_tolerance_) throw std::logic_error("claim " + id_ + ": the statement has {tol} but no tolerance is set");
  return statement_.substr(0, at) + format_tolerance(tolerance_) + statement_.substr(at + 5);
}

Json Claim::to_json() const {
  Json j = Json::object();
  j.set("id", id_).set("reference", reference_).set("reference_tex", latex_escape(reference_)).set("statement", statement());
  j.set("origin", origin_name(origin_)).set("evidence_kind", evidence_kind_name(kind_));
  j.set("parameters", parameters_).set("evidence", evidence_);
  j.set("verdict", verdict_name(verdict_)).set("report_verdict", report_verdict()).set("expected_to_hold", expected_);
  return j;
}

}  // namespace dfchaos::kit
