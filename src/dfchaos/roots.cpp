// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/roots.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dfchaos/errors.hpp"
#include "dfchaos/roots/piece_solver.hpp"
#include "dfchaos/roots/piecewise.hpp"
#include "dfchaos/roots/rest_start.hpp"

namespace dfchaos {

namespace {

using namespace roots_detail;

/// The piece that starts at the cursor: it ends at the next break (an inflection of f), or earlier
/// at the search's limit or at the start of the skip window.
struct Piece {
  Instant end;                    ///< where it ends
  long double s_end = 0;          ///< elapsed time from the origin there
  double L = 0;                   ///< its length
  bool end_trig = false;          ///< it ends at a break whose sine and cosine are known:
  double end_sn = 0, end_cs = 0;  ///< (end_trig) they
};

Piece next_piece(const QuadraticPlusHarmonic& f, const PieceBreaks& breaks, const SearchBounds& bounds, long double limit, const Cursor& cursor) {
  Piece p;
  int end_break = 0;
  p.end = breaks.next_after(cursor.t, end_break);
  p.s_end = elapsed(f.origin, p.end);
  long double cut = limit;
  if (bounds.we > 0 && bounds.ws > cursor.s) cut = std::min(cut, bounds.ws);
  p.end_trig = breaks.br[end_break].trig;
  p.end_sn = breaks.br[end_break].sn;
  p.end_cs = breaks.br[end_break].cs;
  if (p.s_end > cut) {
    p.end = advance(f.origin, cut);
    p.s_end = cut;
    p.end_trig = false;
  }
  p.L = static_cast<double>(elapsed(cursor.t, p.end));
  return p;
}

/// The cursor moved to the end of `piece`, where f is `piece_end` (when valid).
Cursor after(const Cursor& from, const Piece& piece, const PieceEnd& piece_end) {
  Cursor c;
  c.t = piece.end;
  c.s = piece.s_end;
  c.carried = piece_end;
  c.trig = piece.end_trig;
  c.sn = piece.end_trig ? piece.end_sn : from.sn;
  c.cs = piece.end_trig ? piece.end_cs : from.cs;
  return c;
}

}  // namespace

// The steps follow the argument of roots.hpp: the envelope bounds the search, the inflections cut
// it into pieces on which f' is monotone, and the pieces are searched in time order, so that the
// first crossing found is the first root.
std::optional<UpCrossing> first_upcrossing(const QuadraticPlusHarmonic& f, const SearchLimits& limits) {
  if (f.alpha < 0) throw std::logic_error("first_upcrossing: alpha must be >= 0");
  // 1. The envelope alpha s^2 + beta s + gamma +- R: a window where f < 0 (skipped in one step),
  //    and the limit by which a root must have occurred.
  const long double R = amplitude(f.A, f.B);
  const SearchBounds bounds = search_bounds(f, R, limits.horizon);
  if (bounds.no_root) return std::nullopt;
  if (!std::isfinite(static_cast<double>(bounds.limit))) throw GaveUp("first_upcrossing: no horizon and no root bound; the search would not end");
  const long double limit = bounds.limit;
  // 2. The breaks between pieces: the inflections of f, in closed form.
  const PieceBreaks breaks = piece_breaks(f);
  // 3. An origin at rest: f is below the rounding noise next to it, so its Taylor coefficients
  //    decide what happens there; the scan resumes a little later.
  Cursor cursor = Cursor::at_origin(f);
  if (f.starts_at_rest) {
    const RestStart rs = rest_start(f, R, limit);
    if (rs.kind == RestStart::Root) return rs.root;
    if (rs.kind == RestStart::NoRoot) return std::nullopt;
    cursor = Cursor::unknown_at(f, kRestOffset);
    cursor.has_left_value = true;
    cursor.left_value = rs.left_value;
    cursor.falling_first_piece = rs.falling;
  }
  // 4. The pieces in time order, each searched by the piece solver.
  long pieces = 0;
  Recentring recentring;
  while (true) {
    if (bounds.in_window(cursor.s)) cursor = Cursor::unknown_at(f, std::min(bounds.we, limit));  // (a window may reach far beyond a horizon)
    if (cursor.s >= limit) break;
    if (++pieces > limits.max_pieces) throw GaveUp("first_upcrossing: gave up after " + std::to_string(limits.max_pieces) + " monotone pieces");
    const Piece piece = next_piece(f, breaks, bounds, limit, cursor);
    PieceFunction pf(f, cursor.t.phase);
    // The harmonic part at a break end, and at an uncarried start whose phase has a known sine and
    // cosine, without a sincos call (at the end from the break's own phase, where cursor.phase + L
    // would carry the rounding of L). (At most these two anchors come before search_piece's: the
    // carried start is added there only when no trig start was added here.)
    if (piece.end_trig) pf.add_anchor(pf.from_trig(piece.L, piece.end_sn, piece.end_cs));
    if (cursor.trig && !cursor.carried.valid) pf.add_anchor(pf.from_trig(0, cursor.sn, cursor.cs));
    recentring.coefficients(f, cursor.t, cursor.s, pf.base, pf.c1, pf.c0);
    PieceEnd piece_end;
    if (!cursor.falling_first_piece && piece.L > 0)
      if (auto root = search_piece(pf, cursor, piece.L, R, pieces, piece_end)) return root;
    if (pf.base == 0) recentring.carry(f, cursor.t, piece.end, pf.c0, pf.c1);  // re-centred: carry P0, P1 over
    cursor = after(cursor, piece, piece_end);
  }
  if (bounds.limit_is_bound && limit < limits.horizon) throw std::logic_error("first_upcrossing: no root found before the guaranteed bound (a bug)");
  return std::nullopt;
}

}  // namespace dfchaos
