/// @file roots.hpp
/// @brief First-root isolation that cannot skip a root, for functions
/// \f$f(t) = \alpha s^2 + \beta s + \gamma + A\sin t + B\cos t\f$, \f$s = t - t_{\mathrm{origin}}\f$.
///
/// Both event functions of the model have this form:
///  - the free-flight gap \f$x(t) - y\f$ (Eq. 3, and \f$G_1\f$ of Eq. 11): \f$\alpha = b\f$,
///    \f$A = -a\f$, \f$B = 0\f$, with \f$f'' = a\sin t + 2b = F(t)\f$;
///  - minus the progression velocity \f$-\dot x(t)\f$ (Eqs. 7 and 17): \f$\alpha = 0\f$,
///    \f$\beta = q - 2b\f$, \f$A = 0\f$, \f$B = a\f$, with \f$f'' = -a\cos t\f$.
///
/// **Why no root is missed.** \f$f'' = 2\alpha - A\sin t - B\cos t\f$ vanishes at no more than two
/// phases per period, known in closed form (inflection_phases()). Between consecutive inflection
/// instants \f$f'\f$ is monotone, so it has at most one zero there, which splits the piece into at
/// most two sub-pieces on which \f$f\f$ itself is monotone. On a monotone sub-piece \f$f\f$ has a
/// zero iff its end values differ in sign, and the zero is unique: a bracketing solver finds it.
/// Scanning the sub-pieces in order therefore finds the *first* root, with no step size to guess.
///
/// **Why the cost does not grow as \f$b/a \to 0\f$.** With \f$R = \sqrt{A^2+B^2}\f$,
/// \f$f \le U(s) = \alpha s^2 + \beta s + \gamma + R\f$: on the interval where \f$U < 0\f$ there is no
/// root, and it is skipped in one step. Likewise \f$f \ge \alpha s^2 + \beta s + \gamma - R\f$ bounds
/// where the root must already have occurred. For a free flight of length \f$\sim (a/b)|\cos\theta|\f$
/// only \f$O(1)\f$ periods at each end are scanned.
#pragma once

#include <limits>
#include <optional>
#include <vector>

#include "dfchaos/phase.hpp"

namespace dfchaos {

/// \f$f(t) = \alpha s^2 + \beta s + \gamma + A\sin t + B\cos t\f$ with \f$s = t - \mathrm{origin}\f$,
/// \f$\alpha \ge 0\f$. The polynomial part is kept in long double: for small \f$b/a\f$ its terms
/// reach \f$10^6 a\f$ and cancel to \f$O(a)\f$ at the root.
struct QuadraticPlusHarmonic {
  Instant origin;              ///< \f$s = 0\f$
  long double alpha = 0;       ///< \f$\alpha\f$, coefficient of \f$s^2\f$
  long double beta = 0;        ///< \f$\beta\f$, coefficient of \f$s\f$
  long double gamma = 0;       ///< \f$\gamma\f$, constant term
  double A = 0;                ///< \f$A\f$, coefficient of \f$\sin t\f$
  double B = 0;                ///< \f$B\f$, coefficient of \f$\cos t\f$
  /// True when \f$f(\mathrm{origin}) = 0\f$ holds exactly by construction (a motion starting at rest
  /// at the contact). Near such an origin \f$f\f$ is \f$O(u^2)\f$ or \f$O(u^3)\f$, below rounding
  /// noise; the search then takes the direction of departure from the first non-negligible Taylor
  /// coefficient \f$f', f'', f'''\f$ at the origin: upward means a root at the origin itself,
  /// downward means \f$f < 0\f$ on \f$(0, 10^{-7}]\f$ and the scan starts there.
  bool starts_at_rest = false;

  /// \f$f\f$ at elapsed time \f$s\f$ whose phase is \f$\varphi\f$.
  long double value_at(long double s, double phi) const;
  /// \f$f' = 2\alpha s + \beta + A\cos\varphi - B\sin\varphi\f$.
  long double slope_at(long double s, double phi) const;
  /// \f$f'' = 2\alpha - A\sin\varphi - B\cos\varphi\f$.
  long double curvature_at(double phi) const;
  /// \f$f\f$ at an instant.
  long double value(const Instant& t) const;
  /// \f$f'\f$ at an instant.
  long double slope(const Instant& t) const;
  /// The phases in \f$[0, 2\pi)\f$ where \f$f''\f$ changes sign (zero, one or two), ascending.
  std::vector<double> inflection_phases() const;
};

/// The first instant after the origin at which \f$f\f$ reaches 0 from below.
struct UpCrossing {
  Instant t;            ///< the root
  long double s = 0;    ///< elapsed time from the origin
  double slope = 0;     ///< \f$f'\f$ at the root (\f$\ge 0\f$ up to rounding; 0 at a tangency)
  long pieces = 0;      ///< monotone pieces examined (work done; independent of \f$b/a\f$)
};

/// Bounds of a search. Every search is bounded: it ends at the horizon or after max_pieces
/// pieces, whichever comes first; reaching max_pieces throws GaveUp.
struct SearchLimits {
  long double horizon = std::numeric_limits<long double>::infinity();  ///< max elapsed time
  long max_pieces = 20'000'000;  ///< max monotone pieces examined
};

/// The first root \f$t > \mathrm{origin}\f$ of \f$f\f$ reached from below, assuming
/// \f$f < 0\f$ just after the origin (or starts_at_rest with \f$f'' < 0\f$ there).
/// @return nothing when \f$f < 0\f$ on the whole horizon.
/// @throws GaveUp when max_pieces is reached, or when neither the horizon nor a root bound
///         limits the search.
std::optional<UpCrossing> first_upcrossing(const QuadraticPlusHarmonic& f, const SearchLimits& limits = {});

/// Safeguarded Newton iteration for an increasing function on \f$[lo, hi]\f$ with
/// \f$g(lo) < 0 \le g(hi)\f$ (end values g_lo, g_hi, used for a secant start); `gd(x)` returns the
/// pair \f$(g(x), g'(x))\f$. Newton steps inside the bracket, bisection when a step would leave it
/// or fails to halve the previous one (as in Numerical Recipes' rtsafe). Stops when the Newton
/// correction or the bracket falls below the tolerance \f$4\epsilon(|x_0| + |hi| + 1)\f$, where
/// \f$x_0\f$ is the offset scale.
/// @throws std::logic_error if 400 iterations do not suffice.
template <class GD>
double solve_increasing(GD&& gd, double lo, double hi, double scale, long double g_lo, long double g_hi);

}  // namespace dfchaos

#include "dfchaos/roots_impl.hpp"
