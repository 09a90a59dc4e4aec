// SPDX-License-Identifier: GPL-3.0-or-later
/// @file parameters.hpp
/// @brief The parameters \f$(a, b, q)\f$ of the oscillator, their admissibility, the switching
/// phases \f$t_0, \dots, t_3\f$ and the constant \f$\vartheta_0\f$ of Eq. (1).
///
/// The mass obeys \f$\ddot x = F(t) = a\sin t + 2b\f$ in free flight (Eq. 3) and
/// \f$\ddot x = F(t) - q = a \sin t + 2c\f$, \f$2c = 2b - q\f$, while it drags the delimiter
/// (Eq. 4). Dividing \f$x\f$ by \f$a\f$ changes nothing, so only \f$b/a\f$ and \f$q/a\f$ matter.
#pragma once

#include <optional>
#include <string>

namespace dfchaos {

/// \f$\vartheta_0 \in (0, \pi/2]\f$, the unique solution of \f$\pi - \vartheta = \cot(\vartheta/2)\f$
/// (Eq. 1): bracketed by GSL's Brent solver, refined by Newton's method in long double, and rounded
/// to the nearest double (the certified layer proves it correctly rounded).
/// The threshold of assumption (2) is \f$q > a\sin\vartheta_0\f$.
double vartheta0();

/// \f$\sin\vartheta_0\f$, the threshold of assumption (2) for \f$q/a\f$, correctly rounded to double
/// (computed from the long-double \f$\vartheta_0\f$; `std::sin(vartheta0())` can differ by an ulp).
double sin_vartheta0();

/// The left-hand side minus the right-hand side of Eq. (1): \f$\pi - \vartheta - \cot(\vartheta/2)\f$.
/// It increases strictly on \f$(0, \pi/2]\f$ from \f$-\infty\f$ to \f$\pi/2 - 1 > 0\f$.
double eq1_residual(double vartheta);

/// Smallest and largest accepted \f$a\f$, \f$b\f$, \f$q\f$. The motion depends only on \f$b/a\f$ and
/// \f$q/a\f$ (Section 2: divide \f$x\f$ by \f$a\f$), so this loses nothing: rescale. Inside it every
/// intermediate quantity (\f$b s^2\f$ for flights up to \f$10^{12}\f$, Taylor terms of the gap near a
/// start at rest, products of two parameters) is a normal double, and \f$b/a\f$, \f$q/a\f$ are
/// finite normal numbers.
inline constexpr double kMinParameter = 1e-100;
inline constexpr double kMaxParameter = 1e100;  ///< see kMinParameter

/// The accuracy floor of the return map: \f$T\f$ is refused for \f$b/a < 10^{-12}\f$ (see
/// require_return_map() and docs/accuracy.md). Measured against a 40-digit reference (test
/// precision_reference) for \f$b/a \in [10^{-12}, 0.1]\f$, the error of \f$T\f$ stays below
/// \f$3\cdot 10^{-14}\f$ at random phases and below \f$10^{-10}\f$ at relative distance \f$10^{-11}\f$
/// from a discontinuity of \f$T_1\f$ (the contract: \f$10^{-11}\f$ and \f$10^{-9}\f$). The arithmetic
/// still holds at \f$b/a = 10^{-14}\f$, but below about \f$10^{-15}\f$ the shift \f$2b/a\f$ of
/// \f$t_2, t_3\f$ from \f$\pi, 2\pi\f$ drops under the resolution of a double phase, and the search
/// cost grows like \f$10^{-9} a/b\f$ pieces. The floor keeps a margin of 100 in \f$b/a\f$ to both.
inline constexpr double kMinMapRatio = 1e-12;

/// Which of the paper's standing assumptions a parameter set satisfies.
struct Assumptions {
  bool b_in_range;               ///< \f$0 < b < a/2\f$ (Eq. 2): the free regime exists (\f$t_2, t_3\f$ defined)
  bool q_above_threshold;        ///< \f$a \sin\vartheta_0 < q < a\f$ (Eq. 2)
  bool eq2;                      ///< all of Eq. (2)
  bool eq23;                     ///< \f$a > 0, b > 0, 0 < q < a\f$ (Eq. 23, Remark of Section 8)
  bool progression_ends;         ///< \f$q > 2b\f$, i.e. \f$c < 0\f$: every progression stops (Section 3)
  std::string describe() const;  ///< one line, e.g. "(2) holds; (23) holds"
};

/// The parameters of the system (non-dimensional, as in Section 2).
///
/// Construction checks only that all three lie in [kMinParameter, kMaxParameter]; the stronger
/// conditions of the paper are reported by assumptions() and demanded by the operations that need
/// them.
class Parameters {
 public:
  /// @throws InvalidParameter naming `a`, `b` or `q` if it is not finite or outside
  ///         [kMinParameter, kMaxParameter] (which also excludes zero, negative and subnormal values).
  Parameters(double a, double b, double q);

  double a() const { return a_; }  ///< amplitude of the harmonic forcing
  double b() const { return b_; }  ///< half the constant forcing component
  double q() const { return q_; }  ///< maximal dry-friction force of the delimiter
  /// \f$c = b - q/2\f$, so that the progression equation (4) reads \f$\ddot x = a\sin t + 2c\f$.
  double c() const { return b_ - 0.5 * q_; }

  /// \f$F(t) = a\sin t + 2b\f$ (Eq. 3).
  double F(double t) const;

  /// Zeros \f$t_0 < t_1\f$ of \f$F - q\f$: \f$t_0 = \arcsin((q-2b)/a)\f$ reduced to
  /// \f$[0, 2\pi)\f$, \f$t_1 = \pi - \arcsin((q-2b)/a)\f$. They exist iff \f$|q - 2b| < a\f$;
  /// \f$F > q\f$ exactly on the arc \f$(t_0, t_1)\f$.
  std::optional<double> t0() const { return t0_; }
  std::optional<double> t1() const { return t1_; }  ///< \f$t_1\f$, see t0()
  /// Zeros \f$t_2 = \pi + \arcsin(2b/a)\f$, \f$t_3 = 2\pi - \arcsin(2b/a)\f$ of \f$F\f$.
  /// They exist iff \f$2b < a\f$; \f$F < 0\f$ exactly on \f$(t_2, t_3)\f$.
  std::optional<double> t2() const { return t2_; }
  std::optional<double> t3() const { return t3_; }  ///< \f$t_3\f$, see t2()

  /// \f$t_2\f$ and \f$t_3\f$, demanded: @throws InvalidParameter on `b` unless \f$0 < b < a/2\f$.
  double t2_required() const;
  double t3_required() const;  ///< \f$t_3\f$, demanded as t2_required()

  /// Whether \f$\theta\f$ lies in \f$[t_2, t_3)\f$, the domain of the return map \f$T\f$ (Section 3):
  /// the one place this interval is tested. False for a NaN and when \f$t_2, t_3\f$ do not exist.
  bool in_map_domain(double theta) const { return t2_ && theta >= *t2_ && theta < *t3_; }

  /// Demands \f$t_2 \le \theta < t_3\f$ (in_map_domain()); `name` is the parameter as the caller
  /// spells it (`theta`, `theta0`, ...).
  /// @throws InvalidParameter on `b` as t2_required(), then on `name`, stating the interval's bounds.
  void require_in_map_domain(double theta, const std::string& name = "theta") const;

  /// Which assumptions of the paper hold.
  Assumptions assumptions() const;

  /// Demands assumption (2) of the paper: \f$0 < b < a/2\f$ and \f$a\sin\vartheta_0 < q < a\f$.
  /// @throws InvalidParameter naming `b` or `q`, whichever breaks it (b first).
  void require_eq2() const;

  /// Demands what the return map \f$T\f$ needs: \f$b < a/2\f$ (so that \f$t_2, t_3\f$ exist),
  /// \f$q > 2b\f$ (so that every progression stops) and \f$b/a \ge\f$ kMinMapRatio (the accuracy
  /// floor, docs/accuracy.md).
  /// @throws InvalidParameter naming `b` or `q`.
  void require_return_map() const;

  /// "a=... b=... q=..." with 17 significant digits.
  std::string describe() const;

 private:
  double a_, b_, q_;
  std::optional<double> t0_, t1_, t2_, t3_;
};

}  // namespace dfchaos
