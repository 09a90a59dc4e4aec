// SPDX-License-Identifier: GPL-3.0-or-later
/// @file symbolic.hpp
/// @brief Sections 6 and 7: inverse branches of T on the covering segments, points with a given
/// itinerary, periodic points, and the coding \f$H\f$ with \f$H\circ T = S\circ H\f$.
///
/// On a covering segment \f$J_\sigma\f$ (covering.hpp) there is a sub-segment \f$K_\sigma\f$ on which
/// \f$T\f$ is continuous and strictly monotone with \f$T(K_\sigma) = [t_2, 3\pi/2]\f$; its inverse
/// \f$g_\sigma : [t_2, 3\pi/2] \to K_\sigma\f$ is a contraction (T expands by \f$|T'| \gg 1\f$). A point whose
/// orbit visits \f$J_{w_0}, J_{w_1}, \dots, J_{w_{n-1}}\f$ is \f$g_{w_0}\circ\cdots\circ g_{w_{n-1}}(y)\f$; the
/// periodic point with itinerary \f$(w)^\infty\f$ is the fixed point of that composition. This is the
/// backward form of the nested segments of Section 6, and it stays well conditioned where the
/// forward segments \f$J_{w_0\dots w_k}\f$ shrink below double precision after a few steps.
#pragma once

#include <string>
#include <vector>

#include "dfchaos/covering.hpp"

namespace dfchaos {

/// \f$T\f$ restricted to \f$K_\sigma \subset J_\sigma\f$, monotone onto \f$[t_2, \text{top}]\f$, and its inverse.
struct InverseBranch {
  CoveringSegment J;      ///< the covering segment \f$J_\sigma\f$
  double k_at_t2 = 0;     ///< end of \f$K\f$ where \f$T = t_2\f$ (the edge of the arc where \f$T \equiv t_2\f$)
  double k_at_top = 0;    ///< end of \f$K\f$ where \f$T = \text{top}\f$
  double top = 0;         ///< upper end of the covered target \f$[t_2, \text{top}]\f$
  bool monotone = false;  ///< strict monotonicity verified on a grid of K
};

/// Builds the inverse branch on J. @throws GaveUp if no monotone K is found.
InverseBranch make_inverse_branch(const Parameters& p, const CoveringSegment& J, double top = 1.5 * 3.141592653589793, int check = 2000);

/// \f$g_\sigma(y)\f$: the \f$x \in K\f$ with \f$T(x) = y\f$, by bisection, for \f$y \in [t_2, \text{top}]\f$.
double inverse(const Parameters& p, const InverseBranch& g, double y);

/// An orbit segment with its checks.
struct ItineraryOrbit {
  std::string word;              ///< the itinerary, letters '0' and '1'
  std::vector<double> x;         ///< \f$x_0, \dots, x_{n-1}\f$ (periodic: \f$x_n = x_0\f$)
  double max_step_residual = 0;  ///< \f$\max_j |T(x_j) - x_{j+1}|\f$ (periodic: index mod n; else j < n-1)
  bool itinerary_ok = false;     ///< \f$x_j \in K_{w_j}\f$ for every j
  double log_expansion = 0;      ///< \f$\sum_j \ln|T'(x_j)|\f$ by central differences: how much a forward T^n amplifies errors
  double min_separation = 0;     ///< smallest distance between two orbit points
  /// The one-step residual that double precision alone can produce along this orbit:
  /// \f$\max_j 4(|T'(x_j)|\,2\epsilon|x_j| + \epsilon|x_{j+1}|)\f$ — each \f$x_j\f$ is known to about
  /// two ulp (the inverse branch bisects to adjacent doubles) and \f$T\f$ amplifies that by
  /// \f$|T'|\f$. A residual below it cannot tell a true orbit from a false one.
  double precision_floor = 0;
};

/// Visits every word of length n over {0, 1} with a point whose orbit follows it through
/// \f$K_0, K_1\f$, \f$x_w = g_{w_0}\circ\dots\circ g_{w_{n-1}}(y_0)\f$ (all from the same end point
/// \f$y_0\f$), sharing suffixes: \f$x_w = g_{w_0}(x_{w_1\dots})\f$, so the cost is
/// \f$2^{n+1}\f$ inverse evaluations instead of \f$n 2^n\f$. `visit` receives each checked orbit.
template <class Visit>
void for_each_word(const Parameters& p, const InverseBranch (&g)[2], int n, Visit&& visit);

/// The periodic point with itinerary \f$(\text{word})^\infty\f$: fixed point of the composed inverse
/// branches, by iteration (a contraction), to full double precision.
/// @throws GaveUp if 200 sweeps do not converge.
ItineraryOrbit periodic_orbit(const Parameters& p, const InverseBranch (&g)[2], const std::string& word);

/// Whether `word` is primitive: not a power \f$u^k\f$, \f$k \ge 2\f$, of a shorter word. As
/// \f$J_0 \cap J_1 = \emptyset\f$, the orbit with itinerary \f$(\text{word})^\infty\f$ then has least
/// period \f$|\text{word}|\f$ (the least period of the sequence).
bool is_primitive_word(const std::string& word);

/// Longest itinerary word that periodic_orbit(p, word) accepts.
inline constexpr std::size_t kMaxItineraryLength = 1000;

/// An itinerary as a user gives it: 1 to max_length letters 0 and 1, primitive.
/// @throws InvalidParameter naming `name`.
void require_itinerary_word(const std::string& name, const std::string& word, std::size_t max_length);

/// The periodic orbit with itinerary \f$(\text{word})^\infty\f$ at p: Lemma 4's covering
/// (require_lemma4_covering), its inverse branches, then periodic_orbit above.
/// @throws InvalidParameter naming word (require_itinerary_word with kMaxItineraryLength), or b or
/// q as require_lemma4_covering; GaveUp as periodic_orbit.
ItineraryOrbit periodic_orbit(const Parameters& p, const std::string& word);

namespace detail {
void check_itinerary_orbit(const Parameters& p, const InverseBranch (&g)[2], ItineraryOrbit& o, bool periodic);
}

template <class Visit>
void for_each_word(const Parameters& p, const InverseBranch (&g)[2], int n, Visit&& visit) {
  ItineraryOrbit o;
  o.word.assign(static_cast<std::size_t>(n), '0');
  o.x.assign(static_cast<std::size_t>(n), 0.0);
  // Fill positions n-1 down to 0; at depth 0 the orbit is complete.
  auto rec = [&](auto&& self, int j, double y) -> void {
    if (j < 0) {
      ItineraryOrbit copy = o;
      detail::check_itinerary_orbit(p, g, copy, false);
      visit(copy);
      return;
    }
    for (char letter : {'0', '1'}) {
      o.word[static_cast<std::size_t>(j)] = letter;
      const double x = inverse(p, g[letter == '1' ? 1 : 0], y);
      o.x[static_cast<std::size_t>(j)] = x;
      self(self, j - 1, x);
    }
  };
  rec(rec, n - 1, 0.5 * (*p.t2() + g[0].top));
}

}  // namespace dfchaos
