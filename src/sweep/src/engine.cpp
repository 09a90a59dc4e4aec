// SPDX-License-Identifier: GPL-3.0-or-later
#include "sweep/engine.hpp"

#include <atomic>
#include <new>

#include "dfchaos/stop.hpp"
#include "sweep/cell.hpp"

namespace dfchaos::sweep {

std::vector<CellValues> compute_cells(const Spec& spec, const std::vector<long long>& cells, kit::Progress* progress) {
  std::vector<CellValues> values(cells.size());
  const long long n = static_cast<long long>(cells.size());
  std::atomic<bool> out_of_memory{false};  // an exception cannot leave a parallel region
  // The caller's stop token (dfchaos/stop.hpp), installed in every thread: once a stop is requested
  // the remaining cells are skipped and the chunk is not delivered.
  const StopToken* token = current_stop_token();
#pragma omp parallel for schedule(dynamic, 1)
  for (long long k = 0; k < n; ++k) {
    if (out_of_memory.load() || (token != nullptr && token->requested())) continue;
    const StopScope scope(token);
    const auto i = static_cast<std::size_t>(k);
    try {
      values[i] = evaluate_cell(spec, cells[i]);  // never throws for a cell's failure
    } catch (const std::bad_alloc&) {
      out_of_memory.store(true);
    } catch (const Stopped&) {  // only with a token, which is then set: poll_stop() below throws again
    }
    if (progress) progress->step();
  }
  if (out_of_memory.load()) throw std::bad_alloc();  // the chunk is not delivered: the run gives up (exit 1)
  poll_stop();                                       // a stopped chunk is not delivered either
  return values;
}

std::vector<std::string> compute_rows(const Spec& spec, const std::vector<long long>& cells, kit::Progress* progress) {
  const std::vector<CellValues> values = compute_cells(spec, cells, progress);
  std::vector<std::string> rows;
  rows.reserve(values.size());
  for (const CellValues& v : values) rows.push_back(format_row(spec, v));
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
