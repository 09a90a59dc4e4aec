// SPDX-License-Identifier: GPL-3.0-or-later
/// @file header.hpp
/// @brief The header of a sweep's TSV output, and its reading back (by sweep-merge and --resume).
///
/// The output is `#` comment lines, then one line of column names, then one row per cell in
/// increasing index:
///
///     # dfchaos sweep: observables over the (q/a, b/a) plane
///     # dfchaos VERSION (GIT HASH), COMPILER
///     # key = value                      (the spec: Spec::header_lines())
///     [# shard = i/N  (...)]             (shard files only)
///     index  q_over_a  b_over_a  status  <observable columns>  error
///     ... rows ...
///     # end: ROWS rows, sha256 HEX (of every byte above this line)      (seal.hpp)
///
/// Nothing in it differs between an unsharded, a merged, a resumed or an MPI run of the same spec
/// with the same build: no time, no thread, shard or rank count. Shard files carry one more line,
/// which the merge checks and drops.
#pragma once

#include <ios>
#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sweep/seal.hpp"
#include "sweep/shard.hpp"
#include "sweep/spec.hpp"

namespace dfchaos::sweep {

/// The second line of every sweep output (the first is the column line).
inline constexpr std::string_view kTitleLine = "# dfchaos sweep: observables over the (q/a, b/a) plane";
/// The prefix of the shard line.
inline constexpr std::string_view kShardPrefix = "# shard = ";
/// The prefix of the cell-count line.
inline constexpr std::string_view kCellsPrefix = "# cells = ";

/// The header of the output of `spec`, each line ending in '\n': the column line, then the comment
/// lines (the title kTitleLine, the build, the spec), and last the shard line when `shard` is given.
/// The column line comes first so that one standard call reads the file with its names
/// (docs/cluster.md, "Reading the output").
std::string header_text(const Spec& spec, const std::optional<Shard>& shard);

/// A header read back from a file.
struct ParsedHeader {
  std::string common;                ///< the column line and every header line but the shard line, as text
  std::optional<Shard> shard;        ///< from the shard line, if any
  long long cells = 0;               ///< from the cells line
  std::size_t fields = 0;            ///< the number of columns
  std::vector<std::string> columns;  ///< the column names
};

/// Reads the header at the start of `in`, leaving `in` at the first row. Errors name `option` and
/// `file`. @throws InvalidParameter when the text is not a sweep output.
ParsedHeader read_header(const std::string& option, const std::string& file, std::istream& in);

/// Why `row` (without its '\n') is not a well-formed row of cell `index` under `columns`, or ""
/// when it is one. Every field is checked: the index; q/a and b/a positive finite numbers; the
/// status one of ok, inadmissible, error; each observable a number in the form the sweep writes
/// (%.17g, nan, inf), covering, superstable and certified 0, 1 or nan, period nan or a count,
/// certified_step nan or a code of CertifiedStep; the error
/// field "-" exactly when the status is not error, and no control character anywhere.
std::string row_problem(std::string_view row, long long index, const std::vector<std::string>& columns);

/// Reads `count` rows from `in`, which must be the rows of positions first .. first + count - 1
/// of `shard` under `columns`, each ending in '\n' and well-formed (row_problem); adds each (with
/// its '\n') to `rows_seen` if given. @throws InvalidParameter naming `option` and `what` at the
/// first row that is missing or not well-formed.
void check_rows(const std::string& option, const std::string& what, std::istream& in, const Shard& shard, long long first, long long count,
                const std::vector<std::string>& columns, Sealer* rows_seen = nullptr);

/// A whole sweep file read back and checked.
struct CheckedFile {
  ParsedHeader header;       ///< its header
  std::streampos first_row;  ///< where its rows begin
  Seal seal;                 ///< its seal (checked against its bytes)
};

/// Checks the whole sweep file `file`, opened as `in`: its seal (seal.hpp: complete and undamaged),
/// its header, and every row (row_problem), which must be exactly the cells of its shard (0/1 when
/// it has no shard line), in order, as many as the seal states. Leaves `in` at the first row.
/// @throws InvalidParameter naming `option` and the file, saying what is wrong.
CheckedFile check_sweep_file(const std::string& option, const std::string& file, std::istream& in);

}  // namespace dfchaos::sweep
