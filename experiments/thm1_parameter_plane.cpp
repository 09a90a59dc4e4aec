// SPDX-License-Identifier: GPL-3.0-or-later
/// @file thm1_parameter_plane.cpp
/// @brief Theorems 1 and 2 over the parameter plane: for q/a in (sin vartheta0, 1) and b/a
/// log-spaced in [1e-4, 0.1], whether the covering of Lemma 4 holds (the chaos witness of
/// Theorem 1), whether t2 is superstable (Theorem 2), both (coexistence), or neither.
/// The covering is searched branch by branch (CoveringMethod::Branchwise, about 100 evaluations of
/// T per cell); on a sub-grid (every `check-every`-th cell on both axes) the dense reference search
/// is run too and the two verdicts are compared (claim plane.branchwise_vs_dense).
/// Parallel over the grid (kit::sweep); every cell is independent, so the output does not depend
/// on the number of threads.
#include <algorithm>
#include <cmath>
#include <set>

#include "dfchaos/covering.hpp"
#include "kit/experiment.hpp"
#include "kit/grid.hpp"
#include "sweep/cell.hpp"

using namespace dfchaos;
using namespace dfchaos::kit;

namespace {
struct PlaneCell {
  int covering = 0, superstable = 0;
  double epsilon = 0, J0_lo = 0, J1_lo = 0;
  int dense = -1;           ///< the dense search's verdict on the cross-check sub-grid (-1 elsewhere)
  long long fallbacks = 0;  ///< the branchwise search fell back to the dense one
};
}  // namespace

const Experiment experiment{
    .title = "Theorems 1 and 2 over the (q/a, b/a) plane",
    .paper = {"Theorem 1", "Theorem 2", "Section 8"},
    .tests = {"test_covering", "test_symbolic"},
    .options =
        {count("nq", 400, "grid points of q/a in (sin vartheta0, 1)").range(1, 2000).fast_value(8),
         count("nb", 400, "grid points of b/a, log-spaced in [1e-4, 0.1]").range(2, 2000).fast_value(8),
         count("check-every", 16, "cross-check the covering against the dense search at every k-th cell of both axes").range(1, 2000).fast_value(2)},
    .outputs = {data("", "class: 0 neither, 1 covering (Theorem 1), 2 t2 superstable (Theorem 2), 3 both, -1 error")},
    .body = [](Run& run) {
      const int nq = run.count_int("nq"), nb = run.count_int("nb"), every = run.count_int("check-every");
      const int every_q = std::min(every, nq), every_b = std::min(every, nb);  // at least one row and column checked
      const double s0 = sin_vartheta0();
      const Axis q_axis = Axis::centres(s0, 1, nq), b_axis = Axis::log_ratio(1e-4, 1000.0, nb);
      const auto cells = kit::sweep<PlaneCell>(
          q_axis, b_axis,
          [every_q, every_b](const Cell2& c) {
            const Parameters p(1.0, c.y, c.x);
            PlaneCell r;
            CoveringSearchStats stats;
            const Lemma4Covering cov = sweep::plane_covering(p, kDefaultMaxCoveringBranches, &stats);
            r.fallbacks = stats.dense_fallbacks;
            r.covering = cov.holds;
            if (c.i % every_q == every_q / 2 && c.j % every_b == every_b / 2) r.dense = lemma4_covering(p).holds;
            r.J0_lo = cov.holds ? cov.J0.lo : NAN;
            r.J1_lo = cov.holds ? cov.J1.lo : NAN;
            const sweep::PlaneSuperstable s = sweep::plane_superstable(p, 400);
            r.superstable = s.superstable;
            r.epsilon = s.epsilon;
            return r;
          },
          "thm1_parameter_plane");
      Table t({"q_over_a", "b_over_a", "covering", "superstable", "class", "epsilon", "J0_lo", "J1_lo"});
      long long n_cov = 0, n_sup = 0, n_both = 0, n_err = 0, n_checked = 0, n_differ = 0, n_fallback = 0;
      double both_q = NAN, both_b = NAN, differ_q = NAN, differ_b = NAN;
      std::set<int> superstable_rows;  // the b/a rows holding a superstable cell
      for (int i = 0; i < nq; ++i)
        for (int j = 0; j < nb; ++j) {
          const auto& c = cells[static_cast<std::size_t>(i) * nb + j];
          const double qa = q_axis[i], ba = b_axis[j];
          const PlaneCell v = c.failed ? PlaneCell{} : c.value;                  // a failed cell counts as neither, class -1
          const long long cls = c.failed ? -1 : v.covering + 2 * v.superstable;  // 0 neither, 1 covering, 2 superstable, 3 both
          t.row({qa, ba, static_cast<long long>(v.covering), static_cast<long long>(v.superstable), cls, v.epsilon, v.J0_lo, v.J1_lo});
          n_cov += v.covering;
          n_sup += v.superstable;
          if (v.superstable) superstable_rows.insert(j);
          n_err += c.failed;
          n_fallback += v.fallbacks;
          if (v.dense >= 0) {
            ++n_checked;
            if (v.dense != v.covering) {
              if (n_differ++ == 0) {
                differ_q = qa;
                differ_b = ba;
              }
            }
          }
          if (v.covering && v.superstable) {
            ++n_both;
            if (std::isnan(both_q)) {
              both_q = qa;
              both_b = ba;
            }
          }
        }
      run.table("", t);
      const long long n_cells = static_cast<long long>(nq) * nb;
      // The superstable windows are far narrower in b/a than this grid's step (see thm2_superstable):
      // the plane resolves the covering region, and meets superstable cells only where a window
      // happens to fall on a grid column.
      auto& co = run.out.claim("thm1.coexistence", "Section 8, Theorems 1 and 2", EvidenceKind::Sampled,
                               "Somewhere on the grid the chaotic covering and a superstable t2 coexist (a concrete example; the superstable "
                               "windows are narrower than the grid step, so the plane undercounts them).");
      co.not_expected()
          .evidence("cells", n_cells)
          .evidence("covering", n_cov)
          .evidence("superstable", n_sup)
          .evidence("both", n_both)
          .evidence("errors", n_err);
      if (n_both > 0) co.evidence("example_q_over_a", both_q).evidence("example_b_over_a", both_b);
      co.holds(n_both > 0);
      run.out.claim("thm1.plane_computed", "Theorem 1", EvidenceKind::Sampled, "Every cell of the plane was classified without error.")
          .ours()
          .evidence("cells", n_cells)
          .evidence("errors", n_err)
          .holds(n_err == 0);
      auto& bw = run.out.claim("plane.branchwise_vs_dense", "Lemma 4", EvidenceKind::Sampled,
                               "On the cross-check sub-grid the branch-by-branch covering search gives the same verdict as the dense "
                               "reference search at every cell.");
      bw.ours().evidence("cells_checked", n_checked).evidence("disagreements", n_differ).evidence("dense_fallbacks", n_fallback);
      if (n_differ > 0) bw.evidence("first_disagreement_q_over_a", differ_q).evidence("first_disagreement_b_over_a", differ_b);
      bw.holds(n_checked > 0 && n_differ == 0);
      run.out.macro("PlaneNq", std::to_string(nq));
      run.out.macro("PlaneNb", std::to_string(nb));
      run.out.macro("PlaneBLo", b_axis[0], 6);
      run.out.macro("PlaneBHi", b_axis[nb - 1], 6);
      run.out.macro("PlaneCheckEvery", std::to_string(every));
      run.out.macro("PlaneChecked", std::to_string(n_checked));
      run.out.macro("PlaneDisagree", std::to_string(n_differ));
      run.out.macro("PlaneFallbacks", std::to_string(n_fallback));
      run.out.macro("PlaneSuperstableRows", std::to_string(superstable_rows.size()));
      run.out.macro("PlaneCells", std::to_string(n_cells));
      run.out.macro("PlaneCovering", std::to_string(n_cov));
      run.out.macro("PlaneSuperstable", std::to_string(n_sup));
      run.out.macro("PlaneBoth", std::to_string(n_both));
      if (n_both > 0) {
        run.out.macro("PlaneBothQ", both_q, 4);
        run.out.macro("PlaneBothB", both_b, 4);
      }
    }};

DFCHAOS_EXPERIMENT_MAIN(experiment)
