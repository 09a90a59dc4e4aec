// SPDX-License-Identifier: GPL-3.0-or-later
/// @file claim.hpp
/// @brief A claim checked by an experiment: what is claimed, where the paper says it (or that it is
/// ours), the kind of evidence behind the verdict, the numbers the verdict rests on, and the verdict.
///
/// Kinds of evidence (docs/architecture.md), in decreasing strength:
///  - **certified**: proved in interval or ball arithmetic for the stated parameters;
///  - **certified+argument**: inequalities proved in ball arithmetic (and re-checked), from which the
///    statement follows by an argument written on paper (docs/certified.md, the report), which no
///    program checks;
///  - **analytic**: an identity or closed form, checked to rounding;
///  - **sampled**: a grid or scan in floating point — it can miss what lies between samples;
///  - **precision-limited**: double precision cannot decide; the verdict is *inconclusive*, never
///    "fails".
#pragma once

#include <string>

#include "kit/json.hpp"

namespace dfchaos::kit {

/// The kind of evidence behind a verdict.
enum class EvidenceKind { Analytic, Sampled, Certified, CertifiedArgument, PrecisionLimited };
/// "analytic", "sampled", "certified", "certified+argument" or "precision-limited".
const char* evidence_kind_name(EvidenceKind k);

/// Who makes the claim: the paper asserts it, or it is ours (a hypothesis, a finding, or a
/// cross-check of this implementation).
/// Whose statement a claim is: the paper's, ours (a hypothesis, finding or cross-check), or an
/// erratum (ours: when it holds, a statement of the paper is refuted).
enum class Origin { Paper, Ours, Erratum };
/// "paper" or "ours".
const char* origin_name(Origin o);

/// The computed verdict. Undecided is a programming error at the time of writing.
enum class Verdict { Undecided, Holds, Fails, Inconclusive };
/// "holds", "fails", "inconclusive" ("undecided" for the error state).
const char* verdict_name(Verdict v);

/// A tolerance as written in a statement: %g with the exponent's leading zeros dropped ("1e-8").
std::string format_tolerance(double tol);

/// One claim. Built by chaining: \code
///   out.claim("eq1.residual", "Eq. (1)", EvidenceKind::Analytic,
///             "The computed vartheta0 satisfies Eq. (1) to within {tol}.")
///      .at_most("residual", std::fabs(r), 1e-15);
/// \endcode
/// The placeholder `{tol}` in the statement is replaced by the tolerance actually used (format_tolerance), so
/// the statement cannot drift from the check.
class Claim {
 public:
  /// @param id         short stable identifier: letters, digits, '.' and '_' (e.g. "eq1.unique")
  /// @param reference  where in the paper ("Eq. (1)", "Lemma 2"), or what it goes beyond
  /// @param kind       the kind of evidence the verdict will rest on
  /// @param statement  the claim in our words; may contain `{tol}`
  /// @throws std::logic_error on a malformed id
  Claim(std::string id, std::string reference, EvidenceKind kind, std::string statement);

  /// Marks the claim as ours (a hypothesis, finding or cross-check), not the paper's.
  Claim& ours();
  /// Marks the claim as an erratum: ours, and when it holds the paper's statement it names is refuted
  /// (the report shows "refutes the paper", never "holds").
  Claim& erratum();
  /// The experiment does not assert this claim: its failure is reported, not an error (exit 0).
  Claim& not_expected();
  /// Records a parameter the claim was checked at.
  Claim& parameter(const std::string& key, Json value);
  /// Records a number (or text) the verdict rests on.
  Claim& evidence(const std::string& key, Json value);
  /// Replaces all recorded parameters by the keys of a JSON object. @throws std::logic_error otherwise.
  Claim& parameter_object(const Json& object);
  /// Replaces all recorded evidence by the keys of a JSON object (e.g. a certified result's record).
  /// @throws std::logic_error if it is not an object.
  Claim& evidence_object(const Json& object);
  /// Sets the tolerance of the check: recorded as evidence "tolerance" and written into `{tol}`.
  Claim& tolerance(double tol);
  /// Sets the verdict: holds or fails.
  Claim& holds(bool verdict);
  /// Records `measured` under `name`, sets the tolerance, and the verdict |measured| <= tol.
  Claim& at_most(const std::string& name, double measured, double tol);
  /// Double precision cannot decide this claim here: verdict inconclusive, kind
  /// precision-limited, with the reason recorded as evidence.
  Claim& inconclusive(const std::string& reason);
  /// Records the cases a claim about "every case" rests on (evidence `checked`, `counterexamples`,
  /// `precision_undecided`) and sets the verdict from them: fails when some case is a counterexample
  /// decided in double precision; otherwise inconclusive (kind precision-limited) when some case could
  /// not be decided in double precision; otherwise holds. An earlier failure stands; a later holds()
  /// can add a failure but never erase a counterexample, and leaves an inconclusive claim inconclusive
  /// (double precision losing a case is not a failure of the claim).
  /// @throws std::logic_error unless 0 <= counterexamples, undecided and their sum <= checked.
  Claim& cases(long long checked, long long counterexamples, long long undecided);

  const std::string& id() const { return id_; }                ///< the identifier
  const std::string& reference() const { return reference_; }  ///< where in the paper
  std::string statement() const;                               ///< the statement, tolerance filled in
  EvidenceKind kind() const { return kind_; }                  ///< kind of evidence
  Origin origin() const { return origin_; }                    ///< paper, ours or erratum
  /// The verdict as the report words it: verdict_name(), except that an erratum that holds is
  /// "refutes" (the paper's statement is refuted).
  const char* report_verdict() const;
  Verdict verdict() const { return verdict_; }  ///< the verdict
  bool expected() const { return expected_; }   ///< asserted by the experiment
  /// The claim as a JSON object (id, reference, statement, origin, evidence_kind, parameters,
  /// evidence, verdict, expected_to_hold).
  Json to_json() const;

 private:
  std::string id_, reference_, statement_;
  EvidenceKind kind_;
  Origin origin_ = Origin::Paper;
  Json parameters_ = Json::object(), evidence_ = Json::object();
  Verdict verdict_ = Verdict::Undecided;
  bool expected_ = true;
  bool has_tolerance_ = false;
  double tolerance_ = 0;
  bool cases_recorded_ = false;  // cases() was called: holds() may add a failure, never erase one
};

}  // namespace dfchaos::kit
