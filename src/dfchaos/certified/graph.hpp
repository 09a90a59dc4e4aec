// SPDX-License-Identifier: GPL-3.0-or-later
/// @file graph.hpp
/// @brief Spectral radius of a 0-1 transition matrix bounded from both sides (Collatz–Wielandt),
/// for the entropy bounds of Section 7 (entropy.hpp, laps.hpp).
///
/// For a nonnegative matrix A and any vector \f$v > 0\f$,
/// \f$\min_j (Av)_j / v_j \le \rho(A) \le \max_j (Av)_j / v_j\f$ (Collatz–Wielandt). A graph is given
/// by its successor lists (A has a one in row j, column k when k is a successor of j). The vector
/// v is chosen in floating point (a Perron vector); the bounds are then checked in ball arithmetic,
/// so any v gives valid bounds and only their sharpness depends on it.
#pragma once

#include <vector>

namespace dfchaos::certified {

/// The strongly connected part of a graph with the largest floating Perron root.
struct PerronPart {
  std::vector<int> vertices;  ///< its vertices, ascending (indices into the successor lists)
  std::vector<double> v;      ///< a floating Perron vector on them (power iteration on A + I), positive
  double rho = 0;             ///< its floating Perron root (0 when the graph has no cycle)
};

/// PerronPart of the graph with successor lists `succ` (Tarjan's components, then power iteration).
PerronPart perron_part(const std::vector<std::vector<int>>& succ);

/// A lower bound of \f$\rho\f$ over a subgraph: with positive weights w, greedily drops the vertex
/// of least ratio \f$\sum_{k \in succ(j)} w_k / w_j\f$ while that raises the least ratio, and returns
/// the best least ratio met (a floating number, to be checked exactly by the caller); `kept` marks
/// the subgraph that attains it (any subgraph's least ratio bounds its \f$\rho\f$, hence \f$\rho(A)\f$).
double greedy_collatz_wielandt(const std::vector<std::vector<int>>& succ, const std::vector<double>& w, std::vector<bool>& kept);

/// A 0-1 matrix whose row j has its ones in the contiguous columns [first[j], last[j]] (empty when
/// last[j] < first[j]).
struct BandMatrix {
  std::vector<int> first;  ///< first column of a one, per row
  std::vector<int> last;   ///< last column of a one, per row
  long long ones() const;  ///< the number of ones
};

/// An upper bound of \f$\rho(M)\f$, rounded up: \f$\max_j (Mv)_j / v_j\f$ evaluated in ball arithmetic for
/// positive vectors v from a power iteration on M + I (at most `iterations`), the least value kept.
/// Returns +infinity for an empty matrix row set with no vector tried.
double collatz_wielandt_upper(const BandMatrix& M, int iterations = 300);

}  // namespace dfchaos::certified
