// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/certified/graph.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "dfchaos/certified/ball.hpp"
#include "dfchaos/stop.hpp"

namespace dfchaos::certified {

PerronPart perron_part(const std::vector<std::vector<int>>& succ) {
  const int n = static_cast<int>(succ.size());
  // Strongly connected components (Tarjan, iterative).
  std::vector<int> index(n, -1), low(n, 0), comp(n, -1), stack;
  std::vector<bool> on(n, false);
  int counter = 0, ncomp = 0;
  for (int s = 0; s < n; ++s) {
    if (index[s] >= 0) continue;
    std::vector<std::pair<int, std::size_t>> call{{s, 0}};
    index[s] = low[s] = counter++;
    stack.push_back(s);
    on[s] = true;
    while (!call.empty()) {
      poll_stop();  // stop.hpp: a caller may end the proof here
      auto& [u, e] = call.back();
      if (e < succ[u].size()) {
        const int w = succ[u][e++];
        if (index[w] < 0) {
          index[w] = low[w] = counter++;
          stack.push_back(w);
          on[w] = true;
          call.emplace_back(w, 0);
        } else if (on[w]) {
          low[u] = std::min(low[u], index[w]);
        }
      } else {
        const int done = u;
        call.pop_back();
        if (!call.empty()) low[call.back().first] = std::min(low[call.back().first], low[done]);
        if (low[done] == index[done]) {
          int w;
          do {
            w = stack.back();
            stack.pop_back();
            on[w] = false;
            comp[w] = ncomp;
          } while (w != done);
          ++ncomp;
        }
      }
    }
  }
  PerronPart best;
  for (int c = 0; c < ncomp; ++c) {
    std::vector<int> members;
    for (int i = 0; i < n; ++i)
      if (comp[i] == c) members.push_back(i);
    std::vector<int> pos(n, -1);
    for (std::size_t m = 0; m < members.size(); ++m) pos[members[m]] = static_cast<int>(m);
    // Power iteration on A + I (aperiodic, same Perron vector, root + 1).
    std::vector<double> v(members.size(), 1.0), w(members.size());
    double rho = 0;
    for (int it = 0; it < 2000; ++it) {
      for (std::size_t m = 0; m < members.size(); ++m) {
        w[m] = v[m];
        for (int k : succ[members[m]])
          if (pos[k] >= 0) w[m] += v[pos[k]];
      }
      const double norm = *std::max_element(w.begin(), w.end());
      const double previous = rho;
      rho = norm - 1;
      for (std::size_t m = 0; m < members.size(); ++m) v[m] = w[m] / norm;
      if (it > 20 && std::fabs(rho - previous) < 1e-13 * std::max(1.0, rho)) break;
    }
    if (rho > best.rho + 1e-12) {
      best.rho = rho;
      best.vertices = members;
      best.v = v;
    }
  }
  return best;
}

double greedy_collatz_wielandt(const std::vector<std::vector<int>>& succ, const std::vector<double>& w, std::vector<bool>& kept) {
  const std::size_t n = succ.size();
  std::vector<bool> in(n, true);
  auto ratio = [&](std::size_t j) {
    double sum = 0;
    for (int k : succ[j])
      if (in[k]) sum += w[k];
    return sum / w[j];
  };
  kept = in;
  double rho = 0;
  for (std::size_t left = n; left > 0; --left) {
    std::size_t worst = n;
    double least = 1e300;
    for (std::size_t j = 0; j < n; ++j)
      if (in[j] && ratio(j) < least) least = ratio(j), worst = j;
    if (worst == n) break;  // no ratio (NaN weights): nothing more to drop
    if (least > rho) rho = least, kept = in;
    in[worst] = false;
  }
  return rho;
}

long long BandMatrix::ones() const {
  long long s = 0;
  for (std::size_t j = 0; j < first.size(); ++j) s += std::max(0, last[j] - first[j] + 1);
  return s;
}

double collatz_wielandt_upper(const BandMatrix& M, int iterations) {
  const std::size_t n = M.first.size();
  double best = std::numeric_limits<double>::infinity();
  if (n == 0) return best;
  std::vector<double> v(n, 1.0), prefix(n + 1), w(n);
  auto row_sum = [&](std::size_t j) { return M.last[j] < M.first[j] ? 0.0 : prefix[M.last[j] + 1] - prefix[M.first[j]]; };
  for (int it = 0; it < iterations; ++it) {
    poll_stop();  // stop.hpp: a caller may end the proof here
    if (it % 10 == 0 || it + 1 == iterations) {
      // The exact check: (Mv)_j <= r v_j for every j, with r the largest ratio rounded up.
      Ball r(0.0);
      std::vector<Ball> sums(n + 1, Ball(0.0));
      for (std::size_t k = 0; k < n; ++k) sums[k + 1] = sums[k] + Ball(v[k]);
      for (std::size_t j = 0; j < n && r.upper() < best; ++j) {
        const Ball mv = M.last[j] < M.first[j] ? Ball(0.0) : sums[M.last[j] + 1] - sums[M.first[j]];
        r = max(r, mv / Ball(v[j]));
      }
      if (r.is_finite() && r.upper() < best) best = r.upper();
    }
    prefix[0] = 0;
    for (std::size_t k = 0; k < n; ++k) prefix[k + 1] = prefix[k] + v[k];
    double norm = 0;
    for (std::size_t j = 0; j < n; ++j) norm = std::max(norm, w[j] = v[j] + row_sum(j));
    // A floor keeps every component positive (the bound needs v > 0; its size only affects sharpness).
    for (std::size_t j = 0; j < n; ++j) v[j] = std::max(w[j] / norm, 1e-30);
  }
  return best;
}

}  // namespace dfchaos::certified
