// SPDX-License-Identifier: GPL-3.0-or-later
/// @file cover.hpp
/// @brief The one adaptive subdivision of the certified layer: a region is proved cell by cell,
/// and a cell whose check is undecided is split in two, until every cell is proved or one cell
/// can be neither proved nor split.
///
/// Every certified statement over a set (a phase interval, a box of (b, q), a ball x box) is
/// proved this way; only the check of a cell and the rule that splits it differ. The model is
/// Arb's `arb_calc_isolate_roots` (one subdivision routine, the test a callback).
///
/// The order is depth-first, left half first: the cells are proved in increasing order of their
/// place in the region, which is the order in which certificates record them.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "dfchaos/certified/outcome.hpp"
#include "dfchaos/stop.hpp"

namespace dfchaos::certified {

/// What the check of one cell decided.
struct CellVerdict {
  /// proved: the cell is done; split: undecided, try its halves; stop: the whole cover ends.
  enum class Kind { proved, split, stop };
  Kind kind = Kind::proved;  ///< the decision
  /// stop: the outcome of the whole cover (refuted, or a budget spent); split: the outcome of the
  /// whole cover if this cell cannot be split (too deep, or too narrow to halve).
  Outcome why = Outcome::ok();

  static CellVerdict proved() { return CellVerdict{}; }                                       ///< the cell is done
  static CellVerdict split(Outcome why) { return CellVerdict{Kind::split, std::move(why)}; }  ///< undecided: halve it
  static CellVerdict stop(Outcome why) { return CellVerdict{Kind::stop, std::move(why)}; }    ///< give up (or refuted)
};

/// Proves `check` on every cell of a subdivision of `whole`.
///
/// `check(const Cell&, int depth) -> CellVerdict` decides one cell (depth 0 for `whole`).
/// `split(const Cell&, int depth) -> std::optional<std::pair<Cell, Cell>>` halves an undecided
/// cell, left half first, or returns nothing when it cannot (too narrow to halve). A cell deeper
/// than `max_depth` is not split. Returns Outcome::ok() when every cell was proved, else the `why`
/// of the cell that stopped the cover. Bounded: at most 2^(max_depth + 1) - 1 checks; a stop
/// requested through stop.hpp is polled before each check.
template <class Cell, class Check, class Split>
Outcome cover(Cell whole, Check&& check, Split&& split, int max_depth) {
  struct Item {
    Cell cell;
    int depth;
  };
  std::vector<Item> todo;
  todo.push_back(Item{std::move(whole), 0});
  while (!todo.empty()) {
    poll_stop();  // stop.hpp: a caller may end the proof here
    Item it = std::move(todo.back());
    todo.pop_back();
    CellVerdict v = check(it.cell, it.depth);
    if (v.kind == CellVerdict::Kind::proved) continue;
    if (v.kind == CellVerdict::Kind::stop || it.depth >= max_depth) return std::move(v.why);
    std::optional<std::pair<Cell, Cell>> halves = split(it.cell, it.depth);
    if (!halves) return std::move(v.why);
    todo.push_back(Item{std::move(halves->second), it.depth + 1});
    todo.push_back(Item{std::move(halves->first), it.depth + 1});
  }
  return Outcome::ok();
}

/// An interval [first, second] of doubles (a phase interval, or a range of b).
using Span = std::pair<double, double>;

/// The split rule of most covers: the halves [lo, mid], [mid, hi] of a Span at its floating
/// midpoint, or nothing when the midpoint does not lie strictly inside (two adjacent doubles).
inline std::optional<std::pair<Span, Span>> halve(const Span& x, int /*depth*/) {
  const double mid = 0.5 * (x.first + x.second);
  if (!(mid > x.first && mid < x.second)) return std::nullopt;
  return std::make_pair(Span(x.first, mid), Span(mid, x.second));
}

}  // namespace dfchaos::certified
