// SPDX-License-Identifier: GPL-3.0-or-later
#include "sweep/shard.hpp"

#include <algorithm>

#include "dfchaos/errors.hpp"
#include "kit/options.hpp"

namespace dfchaos::sweep {

Shard Shard::parse(const std::string& option, const std::string& text, long long cells) {
  const auto slash = text.find('/');
  if (slash == std::string::npos || text.find('/', slash + 1) != std::string::npos)
    throw InvalidParameter(option, "write i/N with 0 <= i < N (got '" + text + "')");
  const double i = kit::parse_number(option + " i", text.substr(0, slash), true);
  const double n = kit::parse_number(option + " N", text.substr(slash + 1), true);
  const long long max_n = std::min(kMaxShards, cells);
  if (n < 1 || n > static_cast<double>(max_n))
    throw InvalidParameter(option, "1 <= N <= " + format_shortest(static_cast<double>(max_n)) + " (at most " +
                                       format_shortest(static_cast<double>(kMaxShards)) + " shards, and no more than the cells) (got '" + text +
                                       "')");
  if (i < 0 || i >= n) throw InvalidParameter(option, "0 <= i < N (got '" + text + "')");
  return Shard{static_cast<long long>(i), static_cast<long long>(n)};
}

}  // namespace dfchaos::sweep
