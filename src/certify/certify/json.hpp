// SPDX-License-Identifier: GPL-3.0-or-later
/// @file json.hpp
/// @brief The certified results as JSON (kit::Json) with the statement each one proves: the records
/// of certify.hpp (`dfchaos certify`, `dfchaos.certify`) and the evidence of the experiment
/// `certified_claims`.
///
/// Every object has `"proved"` (true/false), `"statement"` (what exactly is proved, and for which
/// parameters: the doubles given, or every parameter of a box), the enclosures as decimal strings
/// (`{"mid": ..., "rad": ...}`), and when not proved `"failed_step"` and `"detail"`.
#pragma once

#include <string>

#include "dfchaos/certified/arc_l1.hpp"
#include "dfchaos/certified/covering.hpp"
#include "dfchaos/certified/discontinuities.hpp"
#include "dfchaos/certified/entropy.hpp"
#include "dfchaos/certified/lemma4_uniform.hpp"
#include "dfchaos/certified/periodic.hpp"
#include "dfchaos/certified/progression.hpp"
#include "dfchaos/certified/superstable.hpp"
#include "dfchaos/certified/vartheta0.hpp"
#include "kit/json.hpp"

namespace dfchaos::certify {

using kit::Json;  ///< the certified results are written with the kit's JSON value

/// `{"mid": "<digits>", "rad": "<radius>"}` of a ball (mid with `digits` significant digits). Every
/// enclosure of every record is written by this one function.
Json ball_json(const certified::Ball& x, long digits = 25);
/// The shortest decimal that reads back as x (e.g. 0.8104702831753706).
std::string shortest_double(double x);
/// Adds "proved", and on failure "failed_step", "detail", "refuted" to an object.
void add_verdict(Json& j, const certified::Outcome& v);

Json to_json(const certified::Vartheta0& v);                                                           ///< Eq. (1)
Json to_json(const certified::ParameterBox& box, const certified::Lemma1Proof& p);                     ///< Lemma 1 at a point or box
Json to_json(double a, double q, const certified::Lemma1Bound& p);                                     ///< certified lower bound of b0(q)
Json to_json(double a, double b, const certified::DiscontinuityProof& p, const std::string& segment);  ///< Lemma 2
Json to_json(const certified::CoveringProof& p);                                                       ///< Lemma 4 / Theorem 1
Json to_json(const certified::CoveringProof& c, const certified::PeriodicProof& p);                    ///< Sections 6-7
Json to_json(double a, double b, double q, const certified::SuperstableProof& p);                      ///< Theorem 2 at a point
Json to_json(double a, double q, const certified::WindowProof& w);                                     ///< a superstability window
Json to_json(double a, const certified::ArcL1Proof& p);                                                ///< the arc L1 of Lemma 4's proof
Json to_json(double a, const certified::Lemma4UniformProof& p);                                        ///< Lemma 4 for every small b/a
Json to_json(const certified::EntropyProof& p);                                                        ///< Section 7: h_top from a covering graph

/// The statements, in words (what "proved" means for each result).
std::string statement_vartheta0();
std::string statement_lemma1(const certified::ParameterBox& box);
std::string statement_b0(double a, double q, double b_low);
std::string statement_discontinuities(const std::string& segment, std::size_t n);
std::string statement_covering(const certified::ParameterBox& box);
std::string statement_periodic(const std::string& word);  ///< word: one period of the itinerary (its length is the least period)
std::string statement_superstable();
std::string statement_window();
std::string statement_arc_l1(const certified::ArcL1Proof& p);
std::string statement_lemma4_uniform(const certified::Lemma4UniformProof& p);
std::string statement_entropy(const certified::ParameterBox& box);  ///< box: the point (a, b, q)

}  // namespace dfchaos::certify
