/// @file io.hpp
/// @brief Experiment outputs: TSV tables with a provenance header, claims as JSON, LaTeX table
/// fragments and macros; all written atomically (temporary file, then rename) only at the end, so
/// that a failed run leaves no partial file.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace dfchaos {

/// Writes `content` to `path` through `path.tmp` and an atomic rename; creates parent folders.
void write_atomically(const std::filesystem::path& path, const std::string& content);

/// A minimal JSON value (null, bool, number, string, array, object with ordered keys).
class Json {
 public:
  Json() = default;
  Json(bool b) : v_(b) {}                                  ///< a boolean
  Json(double d) : v_(d) {}                                ///< a number (non-finite: null)
  Json(int i) : v_(static_cast<long long>(i)) {}           ///< an integer
  Json(long i) : v_(static_cast<long long>(i)) {}          ///< an integer
  Json(long long i) : v_(i) {}                             ///< an integer
  Json(const char* s) : v_(std::string(s)) {}              ///< a string
  Json(std::string s) : v_(std::move(s)) {}                ///< a string
  static Json array();                                     ///< an empty array
  static Json object();                                    ///< an empty object
  /// Sets a key of an object (insertion order is kept).
  Json& set(const std::string& key, Json value);
  /// Appends to an array.
  Json& push(Json value);
  /// Serialises; non-finite numbers become null; doubles in %.17g.
  std::string dump(int indent = 2) const;

 private:
  using Array = std::vector<Json>;
  using Object = std::vector<std::pair<std::string, Json>>;
  std::variant<std::nullptr_t, bool, double, long long, std::string, std::shared_ptr<Array>, std::shared_ptr<Object>> v_ =
      nullptr;
  void dump_to(std::string& out, int indent, int depth) const;
};

/// A table cell: number, integer or text.
using Cell = std::variant<double, long long, std::string>;

/// A tab-separated table: one header line of column names, then rows; doubles in %.17g.
class Table {
 public:
  explicit Table(std::vector<std::string> columns);  ///< a table with these column names
  /// Appends a row. @throws std::logic_error if the number of cells differs from the columns.
  Table& row(std::vector<Cell> cells);
  std::size_t rows() const { return rows_.size(); }  ///< number of rows so far
  std::string render() const;                        ///< header line and rows, tab-separated

 private:
  std::vector<std::string> columns_;
  std::vector<std::vector<Cell>> rows_;
};

/// One claim of the paper as checked by an experiment.
struct Claim {
  std::string id;          ///< short stable identifier, e.g. "eq1.unique"
  std::string reference;   ///< where in the paper, e.g. "Eq. (1)", "Lemma 2"
  std::string statement;   ///< the claim, in our words
  Json parameters = Json::object();  ///< the parameters it was checked at
  Json evidence = Json::object();    ///< the numbers the verdict rests on
  bool holds = false;      ///< the computed verdict
  bool expected = true;    ///< whether the experiment asserts that it holds (a failure is then an error)
  /// How the verdict was reached (DESIGN.md §2): "analytic", "sampled", "certified" (ball arithmetic
  /// over the whole claim) or "precision-limited". Written to the claims JSON as "evidence_kind"
  /// ("unspecified" when left empty).
  std::string evidence_kind{};
};

/// Collects everything an experiment produces and writes it under an output root:
/// `data/NAME[-PART].tsv`, `tables/FILE.tex`, `tables/NAME-macros.tex`, `claims/NAME.json`,
/// and for the report `tables/NAME-claims.tex` (claim ids are letters, digits, '.' and '_'; one `\\dfcclaimrow{id}{reference}{statement}{verdict}`
/// per claim, plus `\\dfcsetverdict{id}{holds|fails}`) and `tables/NAME-params.tex` (one
/// `\\dfcparamrow{key}{value}` per run parameter).
class ExperimentOutput {
 public:
  /// Outputs of experiment `name`, to be written below the folder `root` (usually build/).
  ExperimentOutput(std::string name, std::filesystem::path root);

  /// Records a run parameter (goes into every header and the claims file).
  void parameter(const std::string& key, const std::string& value);
  void parameter(const std::string& key, double value);  ///< the same, a number in %.17g

  /// Adds a data table, written to `data/NAME.tsv` (part empty) or `data/NAME-PART.tsv`.
  void table(const std::string& part, const Table& t, const std::string& description);
  /// Adds a LaTeX fragment, written to `tables/FILE.tex`.
  void latex(const std::string& file, const std::string& tex);
  /// Adds a macro `\\dfcNAME{value}` (NAME: letters only), written to `tables/EXPERIMENT-macros.tex`.
  void macro(const std::string& name, const std::string& value);
  void macro(const std::string& name, double value, int significant_digits);  ///< the same, a number rounded to digits
  /// Adds a claim.
  void claim(Claim c);

  /// Writes all files; prints one line per claim to stderr. @return 0 when every claim marked
  /// `expected` holds, 1 otherwise (after saying which failed, in one line each).
  int finish() const;

  const std::string& name() const { return name_; }  ///< the experiment's name

 private:
  std::string name_;
  std::filesystem::path root_;
  std::vector<std::pair<std::string, std::string>> parameters_;
  std::vector<std::pair<std::filesystem::path, std::string>> files_;
  std::vector<std::pair<std::string, std::string>> macros_;
  std::vector<Claim> claims_;
  std::string header() const;
};

/// Formats a number with the given count of significant digits (for macros and tables).
std::string format_significant(double x, int digits);

/// The compiler that built dfchaos (for provenance).
std::string compiler_id();

/// Versions of everything that went into the build (dfchaos, git hash, compiler, Eigen, GSL,
/// CLI11), as (name, version) pairs, for the report's provenance appendix.
std::vector<std::pair<std::string, std::string>> build_info();

/// A number in exponent notation ("1.4e-13") as LaTeX (\\f$1.4\\times10^{-13}\\f$); any other
/// text unchanged. Applied to every macro value, so that the report typesets numbers properly.
std::string latex_number(const std::string& text);

/// Escapes text for LaTeX (the ten special characters), so that claim statements and parameter
/// values can be typeset verbatim.
std::string latex_escape(const std::string& text);

}  // namespace dfchaos
