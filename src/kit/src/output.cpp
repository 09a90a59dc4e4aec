// SPDX-License-Identifier: GPL-3.0-or-later
#include "kit/output.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <csignal>
#include <iostream>
#include <mutex>

#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <random>
#include <stdexcept>
#include <system_error>

#include "dfchaos/errors.hpp"
#include "kit/format.hpp"
#include "kit/provenance.hpp"

namespace dfchaos::kit {

namespace fs = std::filesystem;

fs::path unique_temporary(const fs::path& path) {
  static std::atomic<unsigned long> counter{0};
  static const unsigned long tag = std::random_device{}();
  char buf[96];
  std::snprintf(buf, sizeof buf, ".tmp.%ld.%lu.%lx", static_cast<long>(::getpid()), counter++, tag);
  // Within NAME_MAX (255) even for a target whose own name is close to it: its name is shortened.
  constexpr std::size_t kNameMax = 255;
  std::string name = path.filename().string();
  const std::size_t suffix = std::strlen(buf);
  if (name.size() + suffix > kNameMax) name.resize(kNameMax > suffix ? kNameMax - suffix : 0);
  return path.parent_path() / (name + buf);
}

namespace {

/// The guarded temporaries: a fixed table that the signal handler can read without allocating.
/// state: 0 free, 1 being filled, 2 guarded.
struct GuardSlot {
  std::atomic<int> state{0};
  char path[4096];
};
GuardSlot g_slots[kMaxGuardedTemporaries];

extern "C" void remove_guarded_and_reraise(int sig) {
  remove_guarded_temporaries();
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

}  // namespace

int stdout_failure() {
  errno = 0;
  std::cout.flush();  // synced with stdio: flushes stdout too
  const int stream_errno = errno;
  const bool stream_ok = static_cast<bool>(std::cout);
  errno = 0;
  const bool stdio_ok = std::fflush(stdout) == 0 && !std::ferror(stdout);
  if (stream_ok && stdio_ok) return 0;
  if (stream_errno != 0) return stream_errno;
  return errno != 0 ? errno : EIO;  // EIO: the error flag was set by an earlier write
}

std::string one_line(std::string msg) {
  for (auto& ch : msg)
    if (ch == '\n' || ch == '\r') ch = ' ';
  return msg;
}

bool is_bad_path_errno(int err) {
  return err == ENOTDIR || err == ENOENT || err == EACCES || err == EROFS || err == EISDIR || err == EPERM || err == ENAMETOOLONG || err == ELOOP;
}

void remove_guarded_temporaries() {
  for (auto& s : g_slots)
    if (s.state.load() == 2) ::unlink(s.path);  // async-signal-safe
}

void remove_temporaries_on_signals() {
  static std::once_flag once;
  std::call_once(once, [] {
    // Beyond a file-size limit (ulimit -f) a write then fails with EFBIG and takes the ordinary
    // error path (one line, exit 1, temporary removed) instead of killing the process.
    ::signal(SIGXFSZ, SIG_IGN);
    // SIGPIPE too: `dfchaos simulate ... --samples-out F | head` ends by it, as any tool writing
    // to a closed pipe does, but without leaving F's temporary behind.
    for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) {
      struct sigaction old {};
      if (::sigaction(sig, nullptr, &old) != 0 || old.sa_handler == SIG_IGN) continue;
      struct sigaction sa {};
      sa.sa_handler = remove_guarded_and_reraise;
      sigemptyset(&sa.sa_mask);
      ::sigaction(sig, &sa, nullptr);
    }
  });
}

TemporaryFileGuard::TemporaryFileGuard(const fs::path& path) {
  const std::string p = path.string();
  if (p.size() >= sizeof(g_slots[0].path)) return;
  for (int i = 0; i < kMaxGuardedTemporaries; ++i) {
    int expected = 0;
    if (g_slots[i].state.compare_exchange_strong(expected, 1)) {
      std::memcpy(g_slots[i].path, p.c_str(), p.size() + 1);
      g_slots[i].state.store(2);
      slot_ = i;
      return;
    }
  }
}

TemporaryFileGuard::~TemporaryFileGuard() { release(); }

void TemporaryFileGuard::release() {
  if (slot_ >= 0) g_slots[slot_].state.store(0);
  slot_ = -1;
}

namespace {
/// Refuses an output path that exists and is not a regular file, saying what it is.
[[noreturn]] void refuse_kind(const fs::path& path, const fs::file_status& st, const std::string& option) {
  const char* kind = fs::is_directory(st)                                 ? "a directory"
                     : fs::is_character_file(st) || fs::is_block_file(st) ? "a device"
                     : fs::is_fifo(st)                                    ? "a pipe or FIFO"
                     : fs::is_socket(st)                                  ? "a socket"
                                                                          : "not a regular file";
  throw OutputError(option + ": " + path.string() + " is " + kind + ", not a file; an output is a regular file (give a file name" +
                        (option == "out" ? ", or use stdout)" : ")"),
                    true);
}
}  // namespace

fs::path output_target(const fs::path& path, const std::string& option) {
  fs::path p = path;
  std::error_code ec;
  // The path as the kernel resolves it first: /dev/stdout on a pipe is a link to "pipe:[N]", which
  // is no path, so the links are followed by hand only once this says it is a file or nothing yet.
  if (const fs::file_status st = fs::status(path, ec); fs::exists(st) && !fs::is_regular_file(st)) refuse_kind(path, st, option);
  for (int links = 0; fs::is_symlink(fs::symlink_status(p, ec)); ++links) {
    if (links == 40) throw OutputError(option + ": " + path.string() + ": more than 40 symbolic links in a chain", true);
    const fs::path to = fs::read_symlink(p, ec);
    if (ec) throw OutputError(option + ": cannot read the symbolic link " + p.string() + " (" + ec.message() + ")", true);
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
  if (p.filename().string().size() > 255)  // NAME_MAX: the file could never be created
    throw OutputError(option + ": " + path.string().substr(0, 60) + "...: a file name longer than 255 bytes", true);
  const fs::file_status st = fs::status(p, ec);
  if (fs::exists(st) && !fs::is_regular_file(st)) refuse_kind(path, st, option);
  return p;
}

namespace {

/// Writes content to a new file `tmp`. @throws OutputError (after removing tmp).
void write_file(const fs::path& tmp, const std::string& content) {
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) {
    const int err = errno;
    throw OutputError("cannot create " + tmp.string() + (tmp.has_parent_path() ? "" : " in the current directory") + ": " + std::strerror(err),
                      is_bad_path_errno(err));
  }
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t w = ::write(fd, content.data() + done, content.size() - done);
    if (w < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      ::close(fd);
      ::unlink(tmp.c_str());
      throw OutputError("cannot write " + tmp.string() + ": " + std::strerror(err), false);
    }
    done += static_cast<std::size_t>(w);
  }
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    throw OutputError("cannot write " + tmp.string() + ": " + std::strerror(err), false);
  }
}

}  // namespace

void require_output_root(const fs::path& root) {
  std::error_code ec;
  if (fs::exists(root, ec) && !fs::is_directory(root, ec))
    throw OutputError("out: must be a directory (" + root.string() + " exists and is not one)", true);
  fs::create_directories(root, ec);
  if (ec) throw OutputError("out: cannot create the directory " + root.string() + " (" + ec.message() + ")", true);
}

void write_all_or_nothing(const std::vector<std::pair<fs::path, std::string>>& files) {
  std::vector<fs::path> temporaries, targets;
  std::vector<std::unique_ptr<TemporaryFileGuard>> guards;  // removed on SIGINT/SIGTERM/SIGHUP
  auto discard = [&] {
    for (const auto& t : temporaries) ::unlink(t.c_str());
  };
  try {
    for (const auto& [path, content] : files) {
      if (path.has_parent_path()) {
        std::error_code ec;
        if (fs::exists(path.parent_path(), ec) && !fs::is_directory(path.parent_path(), ec))
          throw OutputError("cannot write into " + path.parent_path().string() + ": not a directory", true);
        fs::create_directories(path.parent_path(), ec);
        if (ec) throw OutputError("cannot create the directory " + path.parent_path().string() + " (" + ec.message() + ")", true);
      }
      targets.push_back(output_target(path, "out"));
      const fs::path tmp = unique_temporary(targets.back());
      guards.push_back(std::make_unique<TemporaryFileGuard>(tmp));
      write_file(tmp, content);
      temporaries.push_back(tmp);
    }
  } catch (...) {
    discard();
    throw;
  }
  // Every file is complete: rename them into place (a rename within a directory does not fail for
  // lack of space; should one fail anyway, the rest are not renamed and their temporaries removed).
  for (std::size_t k = 0; k < files.size(); ++k) {
    if (std::rename(temporaries[k].c_str(), targets[k].c_str()) != 0) {
      const int err = errno;
      for (std::size_t r = k; r < files.size(); ++r) ::unlink(temporaries[r].c_str());
      throw OutputError("cannot rename into " + files[k].first.string() + ": " + std::strerror(err), false);
    }
  }
}

void write_atomically(const fs::path& path, const std::string& content) { write_all_or_nothing({{path, content}}); }

Output::Output(std::string name, fs::path root) : name_(std::move(name)), root_(std::move(root)) {}

void Output::parameter(const std::string& key, const std::string& value) { parameters_.emplace_back(key, value); }
void Output::parameter(const std::string& key, double value) { parameters_.emplace_back(key, format_shortest(value)); }

std::string Output::header() const {
  std::string h = "# experiment: " + name_ + "\n# dfchaos " + version() + " (" + git_hash() + "), " + compiler_id() + "\n";
  for (const auto& [k, v] : parameters_) h += "# " + k + " = " + v + "\n";
  return h;
}

void Output::table(const std::string& part, const Table& t, const std::string& description) {
  const std::string file = part.empty() ? name_ : name_ + "-" + part;
  files_.emplace_back(root_ / "data" / (file + ".tsv"), t.render(header() + "# " + description + "\n"));
  written_.emplace_back("data", part);
}

void Output::retire(const fs::path& path) { retired_.push_back(path); }

void Output::certificate(const std::string& file, const std::string& json) {
  files_.emplace_back(root_ / "certificates" / (file + ".json"), json);
  written_.emplace_back("certificate", file);
}

void Output::latex(const std::string& file, const std::string& tex) {
  files_.emplace_back(root_ / "tables" / (file + ".tex"), "% generated by experiment " + name_ + "; do not edit\n" + tex);
  written_.emplace_back("latex", file);
}

void Output::macro(const std::string& name, const std::string& value) {
  if (name.empty()) throw std::logic_error("macro name must not be empty");
  for (char ch : name)
    if (!std::isalpha(static_cast<unsigned char>(ch))) throw std::logic_error("macro name must be letters only: " + name);
  for (const auto& [k, v] : macros_)
    if (k == name) throw std::logic_error("macro defined twice: " + name);
  macros_.emplace_back(name, value);
}
void Output::macro(const std::string& name, double value, int digits) { macro(name, format_significant(value, digits)); }

Claim& Output::claim(std::string id, std::string reference, EvidenceKind kind, std::string statement) {
  for (const auto& c : claims_)
    if (c.id() == id) throw std::logic_error("claim defined twice: " + id);
  claims_.emplace_back(std::move(id), std::move(reference), kind, std::move(statement));
  return claims_.back();
}

int Output::finish() const {
  for (const auto& c : claims_)
    if (c.verdict() == Verdict::Undecided) throw std::logic_error("claim " + c.id() + " has no verdict (a bug in the experiment)");
  auto files = files_;
  if (!macros_.empty()) {
    std::string tex = "% generated by experiment " + name_ + "; do not edit\n";
    for (const auto& [k, v] : macros_) tex += "\\newcommand{\\dfc" + k + "}{" + latex_number(v) + "}\n";
    files.emplace_back(root_ / "tables" / (name_ + "-macros.tex"), tex);
  }
  Json doc = Json::object();
  doc.set("experiment", name_);
  doc.set("version", std::string(version()));
  doc.set("git", std::string(git_hash()));
  doc.set("compiler", compiler_id());
  Json params = Json::object();
  for (const auto& [k, v] : parameters_) params.set(k, v);
  doc.set("run_parameters", params);
  Json list = Json::array();
  int failed_expected = 0;
  for (const auto& c : claims_) {
    list.push(c.to_json());
    if (c.expected() && c.verdict() == Verdict::Fails) ++failed_expected;
  }
  doc.set("claims", list);
  files.emplace_back(root_ / "claims" / (name_ + ".json"), doc.dump());

  std::string rows = "% generated by experiment " + name_ + "; do not edit\n";
  for (const auto& c : claims_) {
    const char* verdict = c.report_verdict();
    rows += "\\dfcsetverdict{" + c.id() + "}{" + verdict + "}{" + evidence_kind_name(c.kind()) + "}{" + origin_name(c.origin()) + "}\n";
    rows += "\\dfcclaimrow{" + c.id() + "}{" + latex_escape(c.reference()) + "}{" + latex_escape(c.statement()) + "}{" + verdict + "}{" +
            evidence_kind_name(c.kind()) + "}{" + origin_name(c.origin()) + "}\n";
  }
  files.emplace_back(root_ / "tables" / (name_ + "-claims.tex"), rows);
  std::string prow = "% generated by experiment " + name_ + "; do not edit\n";
  for (const auto& [k, v] : parameters_) prow += "\\dfcparamrow{" + latex_escape(k) + "}{" + latex_escape(v) + "}\n";
  files.emplace_back(root_ / "tables" / (name_ + "-params.tex"), prow);
  write_all_or_nothing(files);
  for (const auto& path : retired_) {
    std::error_code ec;
    fs::remove(path, ec);
    if (ec) std::fprintf(stderr, "%s: warning: cannot remove the stale %s (%s)\n", name_.c_str(), path.string().c_str(), ec.message().c_str());
  }
  for (const auto& c : claims_) {
    const char* v = c.verdict() == Verdict::Holds ? "holds" : c.verdict() == Verdict::Fails ? "FAILS" : "incon.";
    std::fprintf(stderr, "  %-6s %-30s %-18s %s\n", v, c.id().c_str(), evidence_kind_name(c.kind()), c.reference().c_str());
  }
  for (const auto& c : claims_)
    if (c.expected() && c.verdict() == Verdict::Fails)
      std::fprintf(stderr, "%s: claim %s (%s) expected to hold but fails\n", name_.c_str(), c.id().c_str(), c.reference().c_str());
  return failed_expected ? 1 : 0;
}

}  // namespace dfchaos::kit
