// SPDX-License-Identifier: GPL-3.0-or-later
/// @file parameters.hpp
/// @brief The parameters of the oscillator (dfchaos/parameters.hpp) over a box, in ball arithmetic: \f$a\f$ fixed, \f$b \in
/// [b_{lo}, b_{hi}]\f$, \f$q \in [q_{lo}, q_{hi}]\f$ (a point when the ends coincide), with enclosures
/// of the switching phases \f$t_0, \dots, t_3\f$ (Section 2) valid for every parameter of the box.
///
/// Parameters are doubles, hence exact binary numbers: a proof "at b = 0.001" is a proof at the
/// double nearest to 0.001 (or, with a box, for every b of the box).
#pragma once

#include <string>

#include "dfchaos/certified/ball.hpp"
#include "dfchaos/certified/outcome.hpp"
#include "dfchaos/parameters.hpp"

namespace dfchaos::certified {

/// A box of parameters \f$\{a\} \times [b_{lo}, b_{hi}] \times [q_{lo}, q_{hi}]\f$: the box form of
/// dfchaos::Parameters (Section 2).
struct ParameterBox {
  double a = 1;     ///< forcing amplitude (exact)
  double b_lo = 0;  ///< lower end of b
  double b_hi = 0;  ///< upper end of b
  double q_lo = 0;  ///< lower end of q
  double q_hi = 0;  ///< upper end of q
  /// The single parameter point (a, b, q).
  static ParameterBox point(double a, double b, double q) { return ParameterBox{a, b, b, q, q}; }
  /// The single parameter point of `p`.
  static ParameterBox point(const Parameters& p) { return point(p.a(), p.b(), p.q()); }
  bool is_point() const { return b_lo == b_hi && q_lo == q_hi; }  ///< both ranges degenerate
  std::string describe() const;                                   ///< "a=1 b=[..] q=[..]" or "a=1 b=.. q=.."
};

/// The balls of one parameter box, computed once: a, b, q, \f$2c\f$ and the switching phases, each
/// enclosing its value for every parameter of the box.
///
/// Phases (Section 2), the ball instantiations of dfchaos/model.hpp: \f$t_0 = \arcsin((q-2b)/a)\f$, \f$t_1 = \pi - t_0\f$,
/// \f$t_2 = \pi + \arcsin(2b/a)\f$, \f$t_3 = 2\pi - \arcsin(2b/a)\f$, each enclosed over the box.
class ParameterBalls {
 public:
  /// @throws InvalidParameter (dfchaos/errors.hpp) unless a > 0, 0 < b_lo <= b_hi, 0 < q_lo <= q_hi,
  ///         all finite.
  explicit ParameterBalls(const ParameterBox& box);

  const ParameterBox& box() const { return box_; }  ///< the parameters
  /// Proves the standing conditions of the return map on the whole box: \f$2b < a\f$ (so
  /// \f$t_2, t_3\f$ exist), \f$q > 2b\f$ (every progression stops, \f$c < 0\f$) and \f$q - 2b < a\f$
  /// (\f$t_0, t_1\f$ exist).
  Outcome admissible() const;

  Ball a;           ///< a (exact)
  Ball b;           ///< the whole range of b
  Ball q;           ///< the whole range of q
  Ball b_lo;        ///< lower end of the b range, exact
  Ball b_hi;        ///< upper end of the b range, exact
  Ball q_lo;        ///< lower end of the q range, exact
  Ball q_hi;        ///< upper end of the q range, exact
  Ball two_c;       ///< \f$2c = 2b - q\f$ over the box
  Ball t0;          ///< \f$t_0\f$ over the box
  Ball t1;          ///< \f$t_1\f$ over the box
  Ball t2;          ///< \f$t_2\f$ over the box
  Ball t3;          ///< \f$t_3\f$ over the box
  Ball t2_at_b_lo;  ///< \f$t_2\f$ at the lower end of the b range (a thin ball)
  Ball t2_at_b_hi;  ///< \f$t_2\f$ at the upper end of the b range (a thin ball)
  Ball pi;          ///< \f$\pi\f$
  Ball two_pi;      ///< \f$2\pi\f$

  /// \f$F(t) = a\sin t + 2b\f$ over the box.
  Ball F(const Ball& t) const;
  /// \f$t_2(b) = \pi + \arcsin(2b/a)\f$ for a ball of b.
  Ball t2_of(const Ball& bb) const;

 private:
  ParameterBox box_;
};

}  // namespace dfchaos::certified
