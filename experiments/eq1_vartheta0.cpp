// SPDX-License-Identifier: GPL-3.0-or-later
/// @file eq1_vartheta0.cpp
/// @brief Eq. (1): \f$\vartheta_0\f$ with \f$\pi - \vartheta_0 = \cot(\vartheta_0/2)\f$, its
/// uniqueness on \f$(0, \pi/2]\f$, and the digits the paper prints.
#include <algorithm>
#include <cmath>

#include "dfchaos/parameters.hpp"
#include "dfchaos/phase.hpp"
#include "kit/experiment.hpp"
#include "kit/format.hpp"

using namespace dfchaos;
using namespace dfchaos::kit;

const Experiment experiment{
    .title = "vartheta0 of Eq. (1), uniqueness and the paper's digits",
    .paper = {"Eq. (1)"},
    .tests = {"test_parameters"},
    .options = {count("samples", 100000, "grid points on (0, pi/2] for the uniqueness scan").range(10, 100'000'000).fast_value(2000)},
    .outputs = {data("", "residual of Eq. (1) on (0, pi/2] and its derivative"),
                latex("eq1_vartheta0", "vartheta0 and sin(vartheta0) beside the paper's digits")},
    .body = [](Run& run) {
      const int samples = run.count_int("samples");
      const double v = vartheta0(), s = sin_vartheta0(), r = eq1_residual(v);

      // Uniqueness: the residual pi - x - cot(x/2) has derivative -1 + 1/(2 sin^2(x/2)) > 0 on
      // (0, pi/2); sampled, it must increase and change sign exactly once.
      Table curve({"vartheta", "residual", "derivative"});
      int sign_changes = 0, non_increasing = 0;
      double min_derivative = INFINITY, prev = NAN;
      for (int i = 1; i <= samples; ++i) {
        const double x = (pi / 2) * i / samples;
        const double f = eq1_residual(x), d = -1 + 1 / (2 * std::sin(x / 2) * std::sin(x / 2));
        if (i > 1 && (prev < 0) != (f < 0)) ++sign_changes;
        if (i > 1 && !(f > prev)) ++non_increasing;
        if (i < samples) min_derivative = std::min(min_derivative, d);
        prev = f;
        if (i % std::max(1, samples / 400) == 0) curve.row({x, f, d});
      }
      run.table("", curve);

      run.out
          .claim("eq1.unique", "Eq. (1)", EvidenceKind::Sampled,
                 "pi - x = cot(x/2) has exactly one solution on (0, pi/2]: the residual increases strictly and changes sign once.")
          .evidence("samples", samples)
          .evidence("sign_changes", sign_changes)
          .evidence("non_increasing_steps", non_increasing)
          .evidence("min_derivative_on_open_interval", min_derivative)
          .holds(sign_changes == 1 && non_increasing == 0 && min_derivative > 0);

      run.out.claim("eq1.residual", "Eq. (1)", EvidenceKind::Analytic, "The computed vartheta0 satisfies Eq. (1) to within {tol}.")
          .evidence("vartheta0", v)
          .at_most("residual", r, 1e-15);

      run.out
          .claim("eq1.paper_digits", "Eq. (1)", EvidenceKind::Analytic,
                 "The printed values 0.81047 and 0.724611 are vartheta0 and sin(vartheta0) correctly rounded.")
          .evidence("vartheta0", v)
          .evidence("sin_vartheta0", s)
          .evidence("paper_vartheta0", 0.81047)
          .evidence("paper_sin_vartheta0", 0.724611)
          .holds(std::fabs(v - 0.81047) <= 0.5e-5 && std::fabs(s - 0.724611) <= 0.5e-6);

      run.out.macro("VarthetaZero", v, 16);
      run.out.macro("SinVarthetaZero", s, 16);
      run.out.macro("EqOneResidual", format_significant(r, 2));
      run.out.macro("EqOneSignChanges", std::to_string(sign_changes));
      run.latex("eq1_vartheta0", LatexTable("lll", {"quantity", "computed", "printed in the paper"})
                                     .row({"$\\vartheta_0$", format_significant(v, 16), "0.81047"})
                                     .row({"$\\sin\\vartheta_0$", format_significant(s, 16), "0.724611"})
                                     .row({"residual of (1)", format_significant(r, 2), "---"})
                                     .render());
    }};

DFCHAOS_EXPERIMENT_MAIN(experiment)
