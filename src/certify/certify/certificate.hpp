// SPDX-License-Identifier: GPL-3.0-or-later
/// @file certificate.hpp
/// @brief Certificates: the witnesses of a certified proof as a JSON document that an independent
/// checker (`dfchaos-recheck`, src/recheck/, MPFI) verifies again without the prover's code.
///
/// A certificate holds the format name and version, the statement, the parameters as exact binary
/// numbers (hexadecimal floating-point strings such as `"0x1.0624dd2f1a9fcp-10"`, which denote a
/// binary number exactly, with a decimal beside them for humans) and every witness of the proof.
/// The format, statement by statement, and what the checker does with it: docs/certificates.md.
/// Every statement of `dfchaos certify` (certify/statements.hpp) has a certificate; the experiments
/// also write coverings, entropy, not_superstable, theorem2_counterexample and paper_construction.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "certify/certify.hpp"
#include "dfchaos/certified/arc_l1.hpp"
#include "dfchaos/certified/ball.hpp"
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

/// The format name written in every certificate (`"format"`).
inline constexpr const char* kCertificateFormat = "dfchaos-certificate";
/// The format version (`"version"`); a checker refuses any other.
inline constexpr int kCertificateVersion = 1;

/// The double x as a C99 hexadecimal floating-point string (`%a`: exactly x, e.g. "0x1p+0").
std::string hex_double(double x);
/// An exact ball (radius 0, finite) as a hexadecimal floating-point string with as many hex digits
/// as its binary midpoint needs ("0x1.<digits>p<exponent>", or "0x0p+0").
/// @throws std::logic_error if the ball is not exact and finite.
std::string hex_exact(const certified::Ball& x);
/// `{"hex": hex_double(x), "decimal": shortest decimal of x}`.
kit::Json exact_number(double x);

/// The certificate of Eq. (1): the bracket [lo, hi] around vartheta0 with exact ends, and the
/// correctly rounded doubles of vartheta0 and sin vartheta0 (when certified). `v` must be proved;
/// `claim` is the statement in words (the record's "statement"), as in every certificate below.
/// A printed decimal "0.d1...dn" of vartheta0 (`of` "vartheta0") or of sin vartheta0 ("sine") that the
/// certificate asserts to be the value correctly rounded to n decimals (the paper's digits).
struct PrintedDecimal {
  std::string of;     ///< "vartheta0" or "sine"
  std::string value;  ///< "0.81047"
};
/// With `decimals`, the certificate also asserts those roundings (witness "decimals").
kit::Json certificate_vartheta0(const certified::Vartheta0& v, const std::string& claim, const std::vector<PrintedDecimal>& decimals = {});
/// The certificate of Lemma 1 over {a} x b x q: the parameters and the sub-boxes on which Eq. (8)
/// u(t2) < 0 was shown. `p` must be proved.
kit::Json certificate_lemma1(double a, const Range& b, const Range& q, const certified::Lemma1Proof& p, const std::string& claim);
/// The certificate of a lower bound of b0(q): a, q, b_low and the b-intervals covering [0, b_low]
/// on which Eq. (8) u(t2) < 0 was shown. `p` must be proved.
kit::Json certificate_b0(double a, double q, const certified::Lemma1Bound& p, const std::string& claim);

/// The certificate of Lemma 4 over p.box: the two segments, every ball of their proofs with the
/// brackets of T1 and theta2 (or the stop arc), the departure length and the pieces of every
/// negativity proof with the test that closed each, and Lemma 1's sub-boxes over the box when a ball
/// needed it. `p` must be proved with CoveringOptions::record.
/// @throws std::logic_error if it was not, or if a witness is missing (a ball needed Lemma 1 and
/// p.lemma1 is not proved).
kit::Json certificate_covering(const certified::CoveringProof& p, const std::string& claim);

/// The certificate of the paper's construction in the proof of Lemma 4 (statement paper_construction):
/// at the point of `cov`, the covering's certificate and Lemma 2's on L2 = [101pi/100, 51pi/50] (`d`,
/// recorded), from which the checker shows each covering segment strictly between two consecutive
/// discontinuities z_i < z_(i+1) of T1 on L2, with at least three discontinuities.
/// @throws std::logic_error if either proof is not proved or not recorded.
kit::Json certificate_paper_construction(const certified::CoveringProof& cov, const certified::DiscontinuityProof& d, const std::string& claim);

/// One box of a region as a `covering` certificate in compact text (one line), for
/// certificate_coverings_text(): certificate_covering(p, statement_covering(p.box)).dump(0).
std::string covering_box_text(const certified::CoveringProof& p);
/// The certificate of Lemma 4 over a set of boxes (statement coverings, e.g. a column of the certified
/// region): parameters {a} x b x q (the set the boxes lie in) and witnesses.boxes, the `covering`
/// certificates of the boxes as covering_box_text() wrote them.
std::string certificate_coverings_text(double a, const Range& b, const Range& q, const std::vector<std::string>& boxes, const std::string& claim);

/// The certificate of periodic orbits at a parameter point (statement periodic): the covering's
/// segments J0, J1 and, per orbit of minimal period m with itinerary \f$(0^{m-1}1)^\infty\f$, its boxes
/// \f$X_j\f$ with the balls of T on each box and at its two ends (the covering relations
/// \f$T(X_j) \supseteq X_{j+1}\f$, periodic.hpp). Each orbit must be proved with PeriodicOptions::record.
/// @throws std::logic_error otherwise (the reason named).
kit::Json certificate_periodic(const certified::CoveringProof& c, const std::vector<certified::PeriodicProof>& orbits, const std::string& claim);

/// Statement `entropy` (Section 7 beyond two symbols, entropy.hpp) at a point: the segments
/// \f$I_j\f$ of the covering graph (exact double ends), each with the balls covering it (T
/// continuous), the balls of T at its two ends, its proved successors and its weight \f$v_j\f$,
/// and \f$\rho_{lower}\f$ with \f$\sum_{j \to k} v_k \ge \rho_{lower} v_j\f$ for every j.
/// @throws std::logic_error unless proved with EntropyOptions::record.
kit::Json certificate_entropy(const certified::EntropyProof& p, const std::string& claim);

/// The certificate of Theorem 2's conclusion at (a, b, q) (statement superstable): T = t2 on
/// [t2, theta_end] by closed balls from t2, the condition (21) or (22) from theta2(t2), and the
/// hypotheses (2), (23) that were certified, with the bracket of vartheta0. `p` must be proved with
/// its witnesses recorded. @throws std::logic_error otherwise.
kit::Json certificate_superstable(double a, double b, double q, const certified::SuperstableProof& p, const std::string& claim);
/// The certificate that t2 is not superstable at (a, b, q) (statement not_superstable): T(t2) is the
/// phase of theta2, strictly above t2 (scenario A). `p` must be refuted with its witnesses recorded.
kit::Json certificate_not_superstable(double a, double b, double q, const certified::SuperstableProof& p, const std::string& claim);
/// The certificate of a superstability window in b at (a, q) (statement window): T(t2(b)) = t2 on
/// b-boxes covering [left_in, right_in], T(t2) > t2 at left_out and right_out, and Theorem 2's
/// conclusion at the middle. `p` must be proved with its witnesses recorded.
kit::Json certificate_window(double a, double q, const certified::WindowProof& p, const std::string& claim);
/// The certificate of the erratum to Theorem 2 (statement theorem2_counterexample): (2) and (22)
/// hold at (a, b, q) but u(t2) > 0 > u(t3). `p` must be proved with its witnesses recorded.
kit::Json certificate_theorem2_counterexample(double a, double b, double q, const certified::Theorem2Counterexample& p, const std::string& claim);

/// The certificate of Lemma 2 at (a, b) on the segment "L0" or "L2" (statement discontinuities): the
/// covered segment, for each discontinuity z_k its k, the bracket of z_k, the window W around the
/// tangency t* on which F < 0, the T1 ball left of z_k (W skipped in its no-contact proof) and the
/// no-contact proof right of z_k up to W; and the T1 balls covering the rest. `p` must be proved with
/// `record`. @throws std::logic_error otherwise.
kit::Json certificate_discontinuities(double a, double b, const std::string& segment, const certified::DiscontinuityProof& p,
                                      const std::string& claim);

/// The certificate of the arc L1 of Lemma 4's proof (statement arc-l1, arc_l1.hpp): a and the box of
/// q with the ratios q/a it was proved for, b_over_a_max, and the witnesses S, W, the bounds of g and
/// H' and the grid (delta cuts x s cuts) on whose cells the checker re-encloses g and H'. `p` must be
/// proved. @throws std::logic_error otherwise.
kit::Json certificate_arc_l1(double a, const certified::ArcL1Proof& p, const std::string& claim);
/// The certificate of Lemma 4 for every small b/a (statement lemma4-uniform, lemma4_uniform.hpp): a,
/// the box of q/a, b_over_a_max = eps*, the number of pieces in w and u, and the `arc-l1` certificate
/// of (I8) as a witness. `p` must be proved. @throws std::logic_error otherwise.
kit::Json certificate_lemma4_uniform(double a, const certified::Lemma4UniformProof& p, const std::string& claim);
/// The text of a certificate as every writer stores it (the tool, Python and the experiments).
std::string certificate_text(const kit::Json& certificate);

/// What was written: where, how many bytes, and their SHA-256.
struct WrittenCertificate {
  std::string path;       ///< the path as given
  std::size_t bytes = 0;  ///< size of the file
  std::string sha256;     ///< SHA-256 of its bytes, 64 hexadecimal digits
};

/// Checks, before any proof, that a certificate can be written at `path`: not a directory, device or
/// FIFO (kit::output_target), and its directory exists (it is not created).
/// @throws kit::OutputError with bad_path() true, naming the option `certificate`.
void check_certificate_path(const std::filesystem::path& path);
/// Writes the certificate to `path` whole or not at all (a temporary beside it, then renamed;
/// kit::write_atomically). @throws kit::OutputError (bad_path() true when the place is unusable).
WrittenCertificate write_certificate(const std::filesystem::path& path, const kit::Json& certificate);

/// `{"path", "bytes", "sha256"}` of a written certificate, for the JSON record.
kit::Json to_json(const WrittenCertificate& w);

}  // namespace dfchaos::certify
