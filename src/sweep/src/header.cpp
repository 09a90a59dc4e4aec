// SPDX-License-Identifier: GPL-3.0-or-later
#include "sweep/header.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iterator>

#include "dfchaos/errors.hpp"
#include "kit/provenance.hpp"
#include "sweep/cell.hpp"
#include "sweep/seal.hpp"

namespace dfchaos::sweep {

namespace {
/// Most header lines accepted when reading one back (ours have about 20).
constexpr int kMaxHeaderLines = 1000;

std::string join_tabs(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : "\t") + x;
  return s;
}
bool starts_with(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }
}  // namespace

std::string header_text(const Spec& spec, const std::optional<Shard>& shard) {
  std::string h = join_tabs(spec.columns()) + "\n" + std::string(kTitleLine);
  h += "\n# dfchaos " + std::string(kit::version()) + " (" + kit::git_hash() + "), " + kit::compiler_id() + "\n";
  for (const auto& line : spec.header_lines()) h += "# " + line + "\n";
  if (shard) {
    h += std::string(kShardPrefix) + shard->canonical() + "  (the cells with index mod " + std::to_string(shard->count) + " = " +
         std::to_string(shard->index) + ": " + std::to_string(shard->size(spec.cells())) + " of " + std::to_string(spec.cells()) +
         "; dfchaos sweep-merge joins the shards)\n";
  }
  return h;
}

ParsedHeader read_header(const std::string& option, const std::string& file, std::istream& in) {
  ParsedHeader h;
  std::string line;
  // The column line comes first (so that numpy.genfromtxt(names=True) takes its names from it).
  if (!std::getline(in, line) || in.eof())  // every header line ends in '\n'
    throw InvalidParameter(option, file + " ends inside its header (not a complete sweep output)");
  if (!starts_with(line, "index\t"))
    throw InvalidParameter(option, file + " is not a sweep output (its first line is not the column line 'index<TAB>q_over_a<TAB>...')");
  for (std::size_t at = 0;;) {
    const std::size_t tab = line.find('\t', at);
    h.columns.push_back(line.substr(at, tab == std::string::npos ? std::string::npos : tab - at));
    if (tab == std::string::npos) break;
    at = tab + 1;
  }
  h.fields = h.columns.size();
  if (h.columns.size() < 5 || h.columns[1] != "q_over_a" || h.columns[2] != "b_over_a" || h.columns[3] != "status" || h.columns.back() != "error")
    throw InvalidParameter(option, file + ": malformed column line (index, q_over_a, b_over_a, status, ..., error expected)");
  h.common += line + "\n";
  // Then the '#' lines: the title, the build, the spec (with the cell count) and, last, the shard line.
  bool has_cells = false;
  for (int n = 0; n < kMaxHeaderLines; ++n) {
    if (in.peek() != '#') {
      if (!has_cells) throw InvalidParameter(option, file + ": malformed sweep header (no cell count line)");
      if (h.shard && h.shard->count > h.cells) throw InvalidParameter(option, file + ": more shards than cells");
      return h;
    }
    if (!std::getline(in, line) || in.eof()) throw InvalidParameter(option, file + " ends inside its header (not a complete sweep output)");
    if (n == 0 && line != kTitleLine)
      throw InvalidParameter(option, file + " is not a sweep output (its second line is not '" + std::string(kTitleLine) + "')");
    if (starts_with(line, "# end:")) throw InvalidParameter(option, file + " has no rows after its header (not a complete sweep output)");
    if (h.shard) throw InvalidParameter(option, file + ": a header line after the shard line");
    if (starts_with(line, kShardPrefix)) {
      const std::string text = line.substr(kShardPrefix.size(), line.find(' ', kShardPrefix.size()) - kShardPrefix.size());
      h.shard = Shard::parse(option + " (" + file + ")", text, kMaxShards);  // checked against the cells below
      continue;
    }
    if (starts_with(line, kCellsPrefix)) {
      char* end = nullptr;
      h.cells = std::strtoll(line.c_str() + kCellsPrefix.size(), &end, 10);
      has_cells = end != line.c_str() + kCellsPrefix.size() && h.cells >= 1 && h.cells <= kMaxCells;
    }
    h.common += line + "\n";
  }
  throw InvalidParameter(option, file + ": header longer than " + std::to_string(kMaxHeaderLines) + " lines");
}

namespace {
/// Whether `text` is a number exactly as format_double writes it (%.17g: nan, inf and -inf too).
bool canonical_number(std::string_view text, double& x) {
  if (text.empty() || text.size() > 32) return false;
  const std::string s(text);
  char* end = nullptr;
  x = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && format_double(x) == s;
}
}  // namespace

std::string row_problem(std::string_view row, long long index, const std::vector<std::string>& columns) {
  for (char c : row)
    if ((static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7f) return "a control character";
  std::vector<std::string_view> f;
  for (std::size_t at = 0;;) {
    const std::size_t tab = row.find('\t', at);
    f.push_back(row.substr(at, tab == std::string_view::npos ? std::string_view::npos : tab - at));
    if (tab == std::string_view::npos) break;
    at = tab + 1;
  }
  if (f.size() != columns.size()) return std::to_string(f.size()) + " fields instead of " + std::to_string(columns.size());
  if (f[0] != std::to_string(index)) return "index " + std::string(f[0].substr(0, 24)) + " instead of " + std::to_string(index);
  double x = 0;
  for (std::size_t k : {std::size_t{1}, std::size_t{2}})
    if (!canonical_number(f[k], x) || !(x > 0 && std::isfinite(x))) return columns[k] + " is not a positive number as the sweep writes it";
  const std::string_view status = f[3];
  if (status != "ok" && status != "inadmissible" && status != "error") return "unknown status";
  for (std::size_t k = 4; k + 1 < f.size(); ++k) {
    if (!canonical_number(f[k], x)) return columns[k] + " is not a number as the sweep writes it";
    const std::string& c = columns[k];
    if ((c == "covering" || c == "superstable" || c == "certified") && !(x == 0 || x == 1 || std::isnan(x))) return c + " is not 0, 1 or nan";
    if (c == "certified_step" && !std::isnan(x) && !(x >= 0 && x == std::floor(x) && x <= static_cast<int>(std::size(kAllCertifiedSteps)) - 1))
      return "certified_step is not a step code";
    if (c == "region" && !std::isnan(x) && !(x >= 0 && x <= 1)) return "region is not a fraction in [0, 1]";
    if (c == "region_uniform" && !std::isnan(x) && !(x >= 0 && x < 0.5)) return "region_uniform is not a b/a bound";
    if (c == "region_boxes" && !std::isnan(x) && !(x >= 0 && x == std::floor(x) && x <= 1e18)) return "region_boxes is not a count";
    if (c == "region_stop" && !std::isnan(x) && !(x == 0 || x == 1 || x == 2)) return "region_stop is not a stop code";
    if (c == "period" && !std::isnan(x) && !(x >= 0 && x == std::floor(x) && x <= 1e18)) return "period is not a count";
    if (status == "inadmissible" && !std::isnan(x)) return c + " is not nan in an inadmissible cell";
  }
  const std::string_view error = f.back();
  if ((status == "error") == (error == "-" || error.empty()))
    return status == "error" ? "an error cell without its message" : "an error message in a cell that is not in error";
  return "";
}

void check_rows(const std::string& option, const std::string& what, std::istream& in, const Shard& shard, long long first, long long count,
                const std::vector<std::string>& columns, Sealer* rows_seen) {
  std::string row;
  for (long long p = first; p < first + count; ++p) {
    if (!std::getline(in, row) || in.eof())  // every row ends in '\n'
      throw InvalidParameter(option, what + " has " + std::to_string(p - first) + " of its " + std::to_string(count) + " rows (incomplete)");
    const std::string problem = row_problem(row, shard.cell(p), columns);
    if (!problem.empty())
      throw InvalidParameter(option, what + ": row " + std::to_string(p - first + 1) + " is not a valid row of cell " +
                                         std::to_string(shard.cell(p)) + " (" + problem + ")");
    if (rows_seen) {
      row += '\n';
      rows_seen->add(row, 1);
    }
  }
}

CheckedFile check_sweep_file(const std::string& option, const std::string& file, std::istream& in) {
  const SealedFile sealed = check_file_seal(option, file, in);
  CheckedFile c;
  c.header = read_header(option, file, in);
  c.first_row = in.tellg();
  c.seal = sealed.seal;
  const Shard shard = c.header.shard.value_or(Shard{});
  const long long rows = shard.size(c.header.cells);
  if (sealed.seal.rows != rows)
    throw InvalidParameter(option, file + " is damaged (its seal counts " + std::to_string(sealed.seal.rows) + " rows, shard " + shard.canonical() +
                                       " of " + std::to_string(c.header.cells) + " cells has " + std::to_string(rows) + ")");
  check_rows(option, file, in, shard, 0, rows, c.header.columns);
  if (static_cast<std::uintmax_t>(in.tellg()) != sealed.body_bytes)
    throw InvalidParameter(option, file + " has more rows than the " + std::to_string(rows) + " of shard " + shard.canonical());
  in.clear();
  in.seekg(c.first_row);
  return c;
}

}  // namespace dfchaos::sweep
