#include "sweep/engine.hpp"

#include "sweep/cell.hpp"

namespace dfchaos::sweep {

std::vector<std::string> compute_rows(const Spec& spec, const std::vector<long long>& cells, kit::Progress* progress) {
  std::vector<std::string> rows(cells.size());
  const long long n = static_cast<long long>(cells.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (long long k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    rows[i] = format_row(spec, evaluate_cell(spec, cells[i]));  // never throws for a cell's failure
    if (progress) progress->step();
  }
  return rows;
}

int run_on_threads(Run& run) {
  for (std::size_t k = 0; k < run.chunks().size(); ++k) {
    std::string text;
    for (const auto& row : compute_rows(run.spec(), run.cells_of(run.chunks()[k]), &run.progress())) text += row;
    run.deliver(k, text);
  }
  return run.finish();
}

}  // namespace dfchaos::sweep
