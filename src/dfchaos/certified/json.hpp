/// @file json.hpp
/// @brief The certified results as JSON (dfchaos::Json) with the statement each one proves, shared
/// by `dfchaos certify` and the experiment `certified_claims`.
///
/// Every object has `"proved"` (true/false), `"statement"` (what exactly is proved, and for which
/// parameters: the doubles given, or every parameter of a box), the enclosures as decimal strings
/// (`{"mid": ..., "rad": ...}`), and when not proved `"failed_step"` and `"detail"`.
#pragma once

#include <string>

#include "dfchaos/certified/covering.hpp"
#include "dfchaos/certified/discontinuities.hpp"
#include "dfchaos/certified/periodic.hpp"
#include "dfchaos/certified/progression.hpp"
#include "dfchaos/certified/superstable.hpp"
#include "dfchaos/certified/vartheta0.hpp"
#include "kit/json.hpp"

namespace dfchaos::certified {

using kit::Json;  ///< the certified results are written with the kit's JSON value

/// `{"mid": "<digits>", "rad": "<radius>"}` of a ball (mid with `digits` significant digits).
Json ball_json(const Ball& x, long digits = 25);
/// The shortest decimal that reads back as x (e.g. 0.8104702831753706).
std::string shortest_double(double x);
/// Adds "proved", and on failure "failed_step", "detail", "refuted" to an object.
void add_verdict(Json& j, const Verdict& v);

Json to_json(const Vartheta0& v);                                  ///< Eq. (1)
Json to_json(const ParamBox& box, const Lemma1Proof& p);           ///< Lemma 1 at a point or box
Json to_json(double a, double q, const Lemma1Bound& p);            ///< certified lower bound of b0(q)
Json to_json(double a, double b, const DiscontinuityProof& p, const std::string& segment);  ///< Lemma 2
Json to_json(const CoveringProof& p);                              ///< Lemma 4 / Theorem 1
Json to_json(const CoveringProof& c, const PeriodicProof& p);      ///< Sections 6-7
Json to_json(double a, double b, double q, const SuperstableProof& p);  ///< Theorem 2 at a point
Json to_json(double a, double q, const WindowProof& w);            ///< a superstability window

/// The statements, in words (what "proved" means for each result).
std::string statement_vartheta0();
std::string statement_lemma1(const ParamBox& box);
std::string statement_b0(double a, double q, double b_low);
std::string statement_discontinuities(const std::string& segment, std::size_t n);
std::string statement_covering(const ParamBox& box);
std::string statement_periodic(int m);
std::string statement_superstable();
std::string statement_window();

}  // namespace dfchaos::certified
