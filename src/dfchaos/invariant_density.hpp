// SPDX-License-Identifier: GPL-3.0-or-later
/// @file invariant_density.hpp
/// @brief The invariant density of the return map \f$T\f$ on \f$[t_2, t_3)\f$, estimated from one
/// long orbit (the empirical measure \f$\frac1N\sum_{n<N}\delta_{\theta_n}\f$, Birkhoff), as a
/// histogram; the atom at \f$t_2\f$ counted apart.
///
/// Every step with a stop (scenarios B, C, C′, D′ of Section 3) sends a whole arc to the single
/// phase \f$t_2\f$ (Lemma 3), so an orbit that meets a stop arc visits \f$t_2\f$ exactly, and the
/// empirical measure can have an atom there (all of it on a superstable cycle through \f$t_2\f$,
/// Theorem 2). The histogram of the other points, divided by \f$N h\f$ (h the bin width), estimates
/// the density of the continuous part; with the atom's mass \f$N_{t_2}/N\f$ it integrates to one:
/// \f[ \sum_k f_k\,h + \frac{N_{t_2}}{N} = 1, \qquad f_k = \frac{\#\{n : \theta_n \in B_k,\ \theta_n \ne t_2\}}{N h}, \f]
/// with \f$B_k = [t_2 + kh, t_2 + (k+1)h)\f$, \f$h = (t_3 - t_2)/K\f$, provided every orbit point
/// lies in \f$[t_2, t_3)\f$ (T maps the arc into itself; points outside are counted, never binned).
#pragma once

#include <vector>

#include "dfchaos/parameters.hpp"

namespace dfchaos {

/// The histogram of an orbit of \f$T\f$ over \f$[t_2, t_3)\f$ (see the file comment).
struct OrbitHistogram {
  double lo = 0;                  ///< \f$t_2\f$
  double hi = 0;                  ///< \f$t_3\f$
  std::vector<long long> counts;  ///< orbit points in bin k, not counting those equal to \f$t_2\f$
  long long at_t2 = 0;            ///< orbit points exactly equal to \f$t_2\f$ (the atom)
  long long outside = 0;          ///< orbit points outside \f$[t_2, t_3)\f$ (0 when T maps the arc into itself)
  long long steps = 0;            ///< N, the orbit points counted (after the transient)
  /// Index of the first orbit point equal to \f$t_2\f$, counted from \f$\theta_0\f$ (index 0; the
  /// transient included), or -1. From there on the computed orbit is the computed orbit of
  /// \f$t_2\f$ (see t2_return).
  long long first_t2 = -1;
  /// Steps from the first visit of \f$t_2\f$ to the second, or 0 (fewer than two visits).
  /// T is a function, so once the computed orbit returns to \f$t_2\f$ it repeats with this
  /// period: every later point lies on one computed periodic orbit through \f$t_2\f$. For a
  /// chaotic T the computed orbit of \f$t_2\f$ follows the exact one only for a few dozen steps, so
  /// a long period says nothing about whether the exact orbit of \f$t_2\f$ is periodic.
  long long t2_return = 0;

  double bin_width() const;     ///< \f$h = (t_3 - t_2)/K\f$
  double bin_lo(int k) const;   ///< left end of bin k
  double density(int k) const;  ///< \f$f_k = \mathrm{counts}_k/(N h)\f$
  double atom_mass() const;     ///< \f$N_{t_2}/N\f$
  /// \f$\sum_k f_k h + N_{t_2}/N\f$, summed in long double: 1 up to rounding when outside is 0.
  double total_mass() const;
};

/// Iterates \f$T\f$ from \f$\theta_0\f$: `transient` steps discarded, then the next `steps` points
/// \f$\theta_n\f$ (starting with the point reached after the transient) binned into `bins` equal
/// bins of \f$[t_2, t_3)\f$, with the first two visits of \f$t_2\f$ recorded (first_t2, t2_return).
/// Exactly transient + steps evaluations of T.
/// @throws InvalidParameter unless the return map is defined, \f$\theta_0\in[t_2,t_3)\f$,
///         0 <= transient <= 10^9, 1 <= steps <= 10^9 and 1 <= bins <= 10^6;
///         GaveUp as return_map_step.
OrbitHistogram orbit_histogram(const Parameters& p, double theta0, long long transient, long long steps, int bins);

/// The \f$L^1\f$ distance of the two empirical measures as histograms on the same bins:
/// \f$\sum_k |f_k - g_k|\,h + |N_{t_2}/N - M_{t_2}/M|\f$ (at most 2).
/// @throws InvalidParameter (`bins`) if the two histograms have different bins.
double l1_distance(const OrbitHistogram& f, const OrbitHistogram& g);

}  // namespace dfchaos
