#include "sweep/header.hpp"

#include <algorithm>
#include <cstdlib>

#include "dfchaos/errors.hpp"
#include "kit/provenance.hpp"

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
  std::string h(kTitleLine);
  h += "\n# dfchaos " + std::string(kit::version()) + " (" + kit::git_hash() + "), " + kit::compiler_id() + "\n";
  for (const auto& line : spec.header_lines()) h += "# " + line + "\n";
  if (shard) {
    h += std::string(kShardPrefix) + shard->canonical() + "  (the cells with index mod " + std::to_string(shard->count) + " = " +
         std::to_string(shard->index) + ": " + std::to_string(shard->size(spec.cells())) + " of " +
         std::to_string(spec.cells()) + "; dfchaos sweep-merge joins the shards)\n";
  }
  h += join_tabs(spec.columns()) + "\n";
  return h;
}

ParsedHeader read_header(const std::string& option, const std::string& file, std::istream& in) {
  ParsedHeader h;
  std::string line;
  bool titled = false, has_cells = false;
  for (int n = 0; n < kMaxHeaderLines; ++n) {
    if (!std::getline(in, line) || in.eof())  // the column line must end in '\n' too
      throw InvalidParameter(option, file + " ends inside its header (not a complete sweep output)");
    if (n == 0) {
      if (line != kTitleLine) throw InvalidParameter(option, file + " is not a sweep output (its first line is not '" + std::string(kTitleLine) + "')");
      titled = true;
    }
    if (starts_with(line, kShardPrefix)) {
      if (h.shard) throw InvalidParameter(option, file + " has two shard lines");
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
    if (line.empty() || line[0] != '#') {  // the column line
      if (!titled || !has_cells || !starts_with(line, "index\t"))
        throw InvalidParameter(option, file + ": malformed sweep header (no cell count or column line)");
      h.fields = static_cast<std::size_t>(std::count(line.begin(), line.end(), '\t')) + 1;
      if (h.shard && h.shard->count > h.cells) throw InvalidParameter(option, file + ": more shards than cells");
      return h;
    }
  }
  throw InvalidParameter(option, file + ": header longer than " + std::to_string(kMaxHeaderLines) + " lines");
}

bool row_matches(std::string_view row, long long index, std::size_t fields) {
  const std::string key = std::to_string(index);
  if (row.size() <= key.size() || row.substr(0, key.size()) != key || row[key.size()] != '\t') return false;
  return static_cast<std::size_t>(std::count(row.begin(), row.end(), '\t')) + 1 == fields;
}

}  // namespace dfchaos::sweep
