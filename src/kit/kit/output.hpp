// SPDX-License-Identifier: GPL-3.0-or-later
/// @file output.hpp
/// @brief Everything an experiment writes, collected in memory and written at the end as a whole:
/// data tables (build/data), LaTeX tables and macros (build/tables), claims (build/claims).
///
/// **All or nothing.** Every file is first written to a uniquely named temporary file beside its
/// target (so that concurrent runs never collide); only when all of them are complete are they
/// renamed into place. A failure on the way (a bad path, a full disk) removes the temporaries and
/// leaves the previous outputs untouched.
#pragma once

#include <deque>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "kit/claim.hpp"
#include "kit/table.hpp"

namespace dfchaos::kit {

/// A temporary name beside `path` that no other process or call uses (pid, a counter and a random
/// tag): where a file is written before it is renamed onto `path`, so that readers never see it
/// half written. Used by the experiment outputs and by the sweep's output files.
std::filesystem::path unique_temporary(const std::filesystem::path& path);

/// Makes SIGINT, SIGTERM, SIGHUP and SIGPIPE remove every temporary file registered (TemporaryFileGuard)
/// before the process ends by the signal as it would have (the same status), and ignores SIGXFSZ
/// (a write beyond a file-size limit then fails with EFBIG: one line, exit 1). A signal that is
/// ignored when this is called (e.g. SIGHUP under nohup) stays ignored. Idempotent. SIGKILL
/// cannot be caught: what it leaves (a `.tmp.*` beside the target) is never taken for an output
/// and is removed by the next run that uses the same place (sweep checkpoints), or by hand.
void remove_temporaries_on_signals();

/// Removes every guarded temporary now (async-signal-safe: for handlers that end the process).
void remove_guarded_temporaries();

/// While it lives, a temporary file that the signal handlers of remove_temporaries_on_signals()
/// remove. At most kMaxGuardedTemporaries at once (more are simply not guarded).
class TemporaryFileGuard {
 public:
  explicit TemporaryFileGuard(const std::filesystem::path& path);
  ~TemporaryFileGuard();
  TemporaryFileGuard(const TemporaryFileGuard&) = delete;
  TemporaryFileGuard& operator=(const TemporaryFileGuard&) = delete;
  /// Stops guarding (the file was renamed into place or removed).
  void release();

 private:
  int slot_ = -1;
};

/// Most temporaries guarded at once.
inline constexpr int kMaxGuardedTemporaries = 256;

/// The file an output to `path` must write: `path` itself, or the file its chain of symbolic links
/// ends at (a symlink is written through, never replaced). @throws OutputError (bad_path() true)
/// when that is an existing directory, device, FIFO or socket (an output is a regular file: it is
/// written beside and renamed into place, which would replace a device by a file), or when the
/// chain of links is longer than 40.
std::filesystem::path output_target(const std::filesystem::path& path, const std::string& option);

/// Flushes everything written to standard output (C stdio and iostreams) and returns 0 when it all
/// reached its destination, else the errno of the failure (a full disk, a closed descriptor or pipe).
/// Every program of the project calls it before exiting: a failed write is never a success.
int stdout_failure();

/// The message with every line break made a space: an error is printed on one line.
std::string one_line(std::string msg);

/// Whether a failure with this errno, when creating an output, means the path itself is unusable
/// (bad input, exit 2: no such directory, no permission, a read-only file system, a name too long,
/// a loop of links) rather than a failed write (exit 1).
bool is_bad_path_errno(int err);

/// A file-system failure while writing outputs. `bad_path()` is true when the output location
/// itself is unusable (not a directory, not creatable: bad input, exit 2) and false when writing
/// failed (disk full, I/O error: exit 1).
class OutputError : public std::runtime_error {
 public:
  OutputError(const std::string& what, bool bad_path) : std::runtime_error(what), bad_path_(bad_path) {}
  bool bad_path() const { return bad_path_; }  ///< the path is unusable (as opposed to a failed write)

 private:
  bool bad_path_;
};

/// Writes a set of files as a whole: each through a unique temporary name, renamed only when all
/// are written. @throws OutputError (temporaries removed) on any failure.
void write_all_or_nothing(const std::vector<std::pair<std::filesystem::path, std::string>>& files);

/// Writes one file atomically (write_all_or_nothing of one file).
void write_atomically(const std::filesystem::path& path, const std::string& content);

/// Checks that `root` can hold outputs: it is a directory or can be created as one.
/// @throws OutputError with bad_path() true otherwise.
void require_output_root(const std::filesystem::path& root);

/// The outputs of one experiment run, written below an output root (usually build/):
/// `data/NAME[-PART].tsv`, `tables/FILE.tex`, `tables/NAME-macros.tex`, `claims/NAME.json`, and
/// for the report `tables/NAME-claims.tex` (one `\dfcsetverdict{id}{verdict}{kind}{origin}` and one
/// `\dfcclaimrow{id}{reference}{statement}{verdict}{kind}{origin}` per claim, read by
/// scripts/claims_map.py) and `tables/NAME-params.tex` (one `\dfcparamrow{key}{value}` per run
/// parameter; the report no longer prints them: the same values are in claims/NAME.json).
class Output {
 public:
  /// Outputs of experiment `name` below `root`.
  Output(std::string name, std::filesystem::path root);

  /// Records a run parameter (goes into every header and the claims file).
  void parameter(const std::string& key, const std::string& value);
  void parameter(const std::string& key, double value);  ///< the same, a number in %.17g

  /// Adds a data table, written to `data/NAME.tsv` (part empty) or `data/NAME-PART.tsv`.
  void table(const std::string& part, const Table& t, const std::string& description);
  /// Adds a LaTeX fragment, written to `tables/FILE.tex`.
  void latex(const std::string& file, const std::string& tex);
  /// Adds a proof certificate (a JSON document, written as given), to `certificates/FILE.json`.
  void certificate(const std::string& file, const std::string& json);
  /// A file of an earlier run that this run replaces by nothing (a certificate of a proof that no
  /// longer succeeds): removed by finish() once the new outputs are in place.
  void retire(const std::filesystem::path& path);
  /// Adds a macro `\dfcNAME{value}` (NAME: letters only), written to `tables/EXPERIMENT-macros.tex`.
  void macro(const std::string& name, const std::string& value);
  /// The same, a number rounded to the given significant digits.
  void macro(const std::string& name, double value, int significant_digits);
  /// Adds a claim and returns it for the chained calls that give its evidence and verdict. The
  /// reference stays valid for the life of the Output.
  Claim& claim(std::string id, std::string reference, EvidenceKind kind, std::string statement);

  /// Files written so far as (path below the root, kind), for the declared-output check.
  const std::vector<std::pair<std::string, std::string>>& written() const { return written_; }

  /// Writes all files (all or nothing); prints one line per claim to stderr.
  /// @return 0 when every claim marked expected holds (or is inconclusive), 1 otherwise (after
  ///         saying which failed, one line each).
  /// @throws std::logic_error if a claim has no verdict; OutputError on a file-system failure.
  int finish() const;

  const std::string& name() const { return name_; }  ///< the experiment's name
  /// The output root (for side files outside the experiment's outputs, e.g. timings under bench/).
  const std::filesystem::path& root() const { return root_; }

 private:
  std::string name_;
  std::filesystem::path root_;
  std::vector<std::pair<std::string, std::string>> parameters_;
  std::vector<std::pair<std::filesystem::path, std::string>> files_;
  std::vector<std::pair<std::string, std::string>> written_;
  std::vector<std::filesystem::path> retired_;  ///< files of an earlier run to remove after writing
  std::vector<std::pair<std::string, std::string>> macros_;
  std::deque<Claim> claims_;
  std::string header() const;
};

}  // namespace dfchaos::kit
