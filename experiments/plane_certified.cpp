// SPDX-License-Identifier: GPL-3.0-or-later
/// @file plane_certified.cpp
/// @brief Beyond the paper: a certified chaos map. Over the (q/a, b/a) plane of thm1_parameter_plane
/// (q/a the cell centres of (sin vartheta0, 1), b/a log-spaced in [1e-4, 0.1]) each cell carries the
/// sampled covering of Lemma 4 (the sweep's `covering`: found by the branchwise floating search) and
/// the certified one (the sweep's `certified`: the covering proved in ball arithmetic at the cell's
/// double parameters, certified::prove_covering, or the step where the proof stopped). The cells are
/// those of `dfchaos sweep --observables covering,certified`; the output does not depend on the
/// number of threads.
#include <cmath>
#include <string>
#include <vector>

#include "dfchaos/parameters.hpp"
#include "kit/experiment.hpp"
#include "kit/format.hpp"
#include "kit/grid.hpp"
#include "sweep/cell.hpp"
#include "sweep/spec.hpp"

using namespace dfchaos;
using namespace dfchaos::kit;

const Experiment experiment{
    .title = "A certified chaos map: the covering of Theorem 1 proved or only sampled over the (q/a, b/a) plane",
    .paper = {"Theorem 1", "Lemma 4"},
    .tests = {"test_sweep", "sweep_certified"},
    .options = {count("n", 40, "grid points on each axis (q/a cell centres of (sin vartheta0, 1); b/a log-spaced in [1e-4, 0.1])")
                    .range(2, 2000)
                    .fast_value(6)},
    .outputs = {data("",
                     "per cell: the sampled covering (0/1), the certified one (0/1) and the code of the step where its proof stopped "
                     "(0 proved; the sweep's certified_step legend); status ok, inadmissible or error")},
    .body = [](Run& run) {
      const long long n = run.count_int("n");
      const sweep::Spec spec = sweep::report_plane(n, "covering,certified");
      std::vector<long long> cells(static_cast<std::size_t>(spec.cells()));
      for (long long k = 0; k < spec.cells(); ++k) cells[static_cast<std::size_t>(k)] = k;
      const auto values = sweep_list<sweep::CellValues, long long>(
          cells, [&spec](const long long& k) { return sweep::evaluate_cell(spec, k); }, "plane_certified");

      Table t({"q_over_a", "b_over_a", "status", "covering", "certified", "certified_step"});
      long long proved = 0, sampled_only = 0, neither = 0, proved_not_sampled = 0, failed = 0;
      for (const auto& c : values) {
        const bool ok = !c.failed && c.value.status == sweep::CellStatus::Ok;
        const sweep::CellValues& v = c.value;
        t.row({v.q_over_a, v.b_over_a,
               std::string(ok         ? "ok"
                           : c.failed ? "error"
                                      : sweep::status_name(v.status)),
               v.covering, v.certified, v.certified_step});
        if (!ok || std::isnan(v.covering) || std::isnan(v.certified)) {
          ++failed;
          continue;
        }
        if (v.certified == 1 && v.covering == 1)
          ++proved;
        else if (v.certified == 1)
          ++proved_not_sampled;
        else if (v.covering == 1)
          ++sampled_only;
        else
          ++neither;
      }
      run.table("", t);
      const long long sampled = proved + sampled_only;
      // A statement about a grid of cells: sampled, although each cell's verdict is a proof at its point.
      run.out
          .claim("plane.certified_map", "Theorem 1", EvidenceKind::Sampled,
                 "Over the plane, the covering of Lemma 4 is proved in ball arithmetic at the cell's parameters in most of the cells "
                 "where the floating-point search finds it (at least 90%), and it is proved in no cell where that search finds none.")
          .ours()
          .evidence("cells", spec.cells())
          .evidence("proved", proved)
          .evidence("sampled_only", sampled_only)
          .evidence("neither", neither)
          .evidence("proved_not_sampled", proved_not_sampled)
          .evidence("failed_cells", failed)
          .holds(failed == 0 && proved_not_sampled == 0 && sampled > 0 && proved >= 0.9 * static_cast<double>(sampled));
      run.out.macro("PlaneCertN", std::to_string(n));
      run.out.macro("PlaneCertProved", std::to_string(proved));
      run.out.macro("PlaneCertSampledOnly", std::to_string(sampled_only));
      run.out.macro("PlaneCertNeither", std::to_string(neither));
      run.out.macro("PlaneCertFraction",
                    format_significant(sampled > 0 ? 100.0 * static_cast<double>(proved) / static_cast<double>(sampled) : 0.0, 3));
    }};

DFCHAOS_EXPERIMENT_MAIN(experiment)
