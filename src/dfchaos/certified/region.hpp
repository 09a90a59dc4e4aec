// SPDX-License-Identifier: GPL-3.0-or-later
/// @file region.hpp
/// @brief Theorem 1 over parameter boxes: tiles a band of the
/// \f$(q/a, b/a)\f$ plane by boxes on each of which Lemma 4's covering is proved for *every*
/// parameter of the box (prove_covering over a ParameterBox: the same J0, J1 for the whole box).
///
/// The band is cut into q-columns; in each, boxes \f$[b, b + w] \times [q_{lo}, q_{hi}]\f$ march up in b
/// with \f$w = c\,b^2/a\f$ (the scale at which \f$T_1\f$, of size \f$a/b\f$, moves by O(1) across the box),
/// c adapted: grown after a proved box, shrunk (and the box retried) after a failure; a box whose
/// proof fails at the smallest c is recorded as not proved and skipped. A failed box is first split
/// in b (up to `split_depth` times) keeping the candidates of the whole box. The work is bounded by
/// a number of boxes, not by time, so that the result is deterministic.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "dfchaos/certified/covering.hpp"

namespace dfchaos::certified {

/// What to tile and how much work to allow.
struct RegionOptions {
  double a = 1;            ///< forcing amplitude
  double b_lo = 1e-3;      ///< lower end of the band in b
  double b_hi = 2e-3;      ///< upper end of the band in b
  double q_lo = 0.76;      ///< lower end of the band in q
  double q_hi = 0.99;      ///< upper end of the band in q
  int q_columns = 23;      ///< columns of equal width in q
  double c_start = 0.05;   ///< initial box width in units of b^2/a
  double c_min = 0.003;    ///< smallest width tried before a box is given up (then fresh candidates are tried once)
  double c_max = 0.5;      ///< largest width
  int split_depth = 0;     ///< halvings in b of a failed box (same candidates)
  long max_boxes = 20000;  ///< boxes attempted in total (proved or not), all columns
  /// A column gives up after this many boxes in a row were not proved (0: never): beyond the edge of
  /// the region where coverings exist every box fails, and each failure costs several attempts.
  int max_failed_run = 0;
  bool progress = false;  ///< print progress on stderr
  long precision = 64;    ///< bits of the ball arithmetic (64: one limb, enough for b/a >= 1e-5)
};

struct RegionBox;
/// Called once per proved box with its proof, its witnesses recorded (CoveringOptions::record), and the
/// index of its column: for certificates. Columns run in parallel: calls for different columns may be
/// concurrent, calls for one column come in order from one thread.
using ProvedBoxSink = std::function<void(std::size_t column, const RegionBox& box, const CoveringProof& proof)>;

/// One box of the tiling.
struct RegionBox {
  double b_lo = 0;          ///< lower end of the box in b
  double b_hi = 0;          ///< upper end of the box in b
  double q_lo = 0;          ///< lower end of the box in q
  double q_hi = 0;          ///< upper end of the box in q
  bool proved = false;      ///< Lemma 4 proved for every parameter in it
  int sub_boxes = 0;        ///< sub-boxes of the proof (1 unless it was split)
  std::string failed_step;  ///< when not proved
  /// When proved: the candidate ends of the proved segment J0 (of the last sub-box when the box was
  /// split), so that the box can be re-proved alone (`dfchaos certify covering --J0 --J1`) without
  /// a fresh search for candidates.
  Candidate J0;
  Candidate J1;  ///< the same for J1
};

/// The tiling of one column.
struct RegionColumn {
  double q_lo = 0;               ///< lower end of the column in q
  double q_hi = 0;               ///< upper end of the column in q
  std::vector<RegionBox> boxes;  ///< in increasing b (proved and not proved)
  double b_reached = 0;          ///< the column is tiled (proved or not) from b_lo up to here
  double proved_length = 0;      ///< total b-length of proved boxes
  long attempts = 0;             ///< box proofs attempted (including retries)
  double seconds = 0;            ///< wall time of the column
  int failed_run = 0;            ///< unproved boxes in a row at the column's end
  bool gave_up = false;          ///< stopped after RegionOptions::max_failed_run unproved boxes in a row
};

/// The whole region.
struct RegionResult {
  RegionOptions options;              ///< as given
  std::vector<RegionColumn> columns;  ///< by increasing q
  long boxes_proved = 0;              ///< proved boxes
  long boxes_failed = 0;              ///< boxes given up
  bool complete = false;              ///< every column reached b_hi within max_boxes (none gave up)
  double seconds = 0;                 ///< wall time (all threads)
};

/// Tiles the band. Columns run in parallel (OpenMP) when available; the result does not depend on
/// the number of threads (each column is independent and its box budget fixed in advance).
/// With `sink`, every proved box's proof is recorded and handed to it (the proofs are the same).
RegionResult certify_region(const RegionOptions& opt, const ProvedBoxSink& sink = {});

/// Lemma 4 over `box` with the candidates `c`, splitting the b-range into halves up to `depth`
/// times on failure; `sub_boxes` receives the number of boxes proved.
CoveringProof prove_covering_split(const ParameterBox& box, const std::vector<Candidate>& c, int depth, int& sub_boxes,
                                   const CoveringOptions& opt = {});

}  // namespace dfchaos::certified
