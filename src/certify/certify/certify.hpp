// SPDX-License-Identifier: GPL-3.0-or-later
/// @file certify.hpp
/// @brief The certified statements as requests with typed arguments: one call checks the input,
/// runs the proof in ball arithmetic and returns the verdict with its JSON record.
///
/// This is what `dfchaos certify` and the Python function `dfchaos.certify` both call; neither
/// builds option strings nor reads JSON back. The statements, their inputs and their provers are
/// listed once, in the registry (statements.hpp).
#pragma once

#include <optional>
#include <string>

#include "kit/json.hpp"

namespace dfchaos::certify {

/// A parameter given either as one number (lo == hi) or as a box [lo, hi].
struct Range {
  double lo = 0;                                        ///< lower end
  double hi = 0;                                        ///< upper end
  static Range point(double x) { return Range{x, x}; }  ///< the degenerate range {x}
};

/// A covering segment given by its two candidate ends (as certified_region records them per box):
/// `theta_top`, where T should be at least 3pi/2, and `theta_t2`, where T should be t2 (either order).
struct SegmentEnds {
  double theta_top = 0;  ///< the end where T >= 3pi/2 is to be proved
  double theta_t2 = 0;   ///< the end where T = t2 is to be proved
};

/// A request: the statement and its parameters (each statement reads only the ones it needs).
struct Request {
  std::string what;             ///< the statement: a name of the registry (statements.hpp)
  double a = 1;                 ///< forcing amplitude a > 0
  std::optional<Range> b;       ///< dry friction b (a box for lemma1 and covering)
  std::optional<Range> q;       ///< constant force q (a box for lemma1 and covering)
  int period = 0;               ///< periodic: the minimal period m, 1..64, itinerary (0^(m-1)1)^infinity
  std::string word;             ///< periodic, instead of period: the itinerary (word)^infinity, a primitive word of 1..64 letters 0, 1
  std::string segment = "L0";   ///< discontinuities: L0 = [101pi/100, 3pi/2] or L2 = [101pi/100, 51pi/50]
  std::optional<Range> window;  ///< superstable: a window [lo, hi] in b (floating estimate) to certify with its edges
  /// covering: the segments to prove (both or neither; J0 left of J1). Given, no candidates are searched,
  /// so a box of certified_region can be re-proved alone with the J0, J1 it recorded.
  std::optional<SegmentEnds> J0, J1;
  /// Build the certificate (Result::certificate) when the statement has a format and is proved. A
  /// covering proof then keeps every ball's witnesses (more memory).
  bool certificate = false;
};

/// The result of a request: proved or not, and the record that says what was proved. (Not a
/// re-checkable proof document: it records the answer, not the proof.)
struct Result {
  bool proved = false;  ///< the statement was proved in ball arithmetic
  kit::Json record;     ///< statement, parameters, enclosures, verdict and on failure the failed step
  /// When asked (Request::certificate), proved and the statement has a certificate format
  /// (certificate.hpp): the certificate, the witnesses for the independent checker; else null.
  kit::Json certificate = kit::Json();
  /// Why `certificate` is null although it was asked for (empty otherwise).
  std::string no_certificate = "";
};

/// Whether `what` names a statement of the registry (statements.hpp). Lets a caller check the name
/// before reading other input.
/// @throws InvalidParameter naming "what" when it does not.
void check_statement(const std::string& what);

/// Checks the request and runs the proof of its statement (its entry in statements.hpp). Every number must be finite with |x| <= kMaxParameter.
/// @throws InvalidParameter (one line naming the parameter) for bad input, before any proof starts.
Result certify(const Request& r);

}  // namespace dfchaos::certify
