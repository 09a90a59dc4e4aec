// SPDX-License-Identifier: GPL-3.0-or-later
// dfchaos-recheck: re-verifies the certificates that `dfchaos certify ... --certificate FILE` writes,
// in MPFI interval arithmetic, with its own formulas taken from the paper. It shares no code with the
// prover (no header or library of the rest of src/): only MPFI, MPFR, GMP, nlohmann-json and the
// C++ standard library. It only checks, it never searches. What it trusts and what it checks:
// README.md beside this file; the format: docs/certificates.md.
//
//   dfchaos-recheck [--] FILE...      dfchaos-recheck --help | --version
//
// Exit status: 0 every step of every file re-verified (one line per file: OK, the statement, the
// number of steps); 1 a step failed (named); 2 a malformed certificate (not a regular file,
// unreadable, larger than kMaxBytes, not JSON, a duplicate key, a missing field, another format or
// version, embedded or not, a number that is not an exact hexadecimal float). Each file gets its
// line, written out as soon as it is decided; the status is the worst of them.
#include <fcntl.h>
#include <gmp.h>
#include <mpfi.h>
#include <mpfr.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "reading.hpp"
#include "statements.hpp"

#ifndef DFCHAOS_VERSION
#define DFCHAOS_VERSION "unknown"
#endif

namespace recheck {

/// A file name as the verdict line shows it: as it is when every byte is printable ASCII other than
/// space, '"' and '\\'; otherwise in double quotes with C escapes (\\n, \\t, \\", \\\\, \\xHH), so
/// that every verdict stays on one line and a name can be told from the text after it.
std::string shown(const std::string& path) {
  bool plain = !path.empty();
  for (unsigned char ch : path) plain = plain && ch > 0x20 && ch < 0x7f && ch != '"' && ch != '\\';
  if (plain) return path;
  std::string q = "\"";
  for (unsigned char ch : path) {
    if (ch == '"' || ch == '\\') {
      q += '\\';
      q += static_cast<char>(ch);
    } else if (ch == '\n') {
      q += "\\n";
    } else if (ch == '\t') {
      q += "\\t";
    } else if (ch < 0x20 || ch >= 0x7f) {
      char buf[5];
      std::snprintf(buf, sizeof buf, "\\x%02x", ch);
      q += buf;
    } else {
      q += static_cast<char>(ch);
    }
  }
  return q + "\"";
}

/// A message on one line: control bytes (a line break in a file's text) as C escapes.
std::string one_line(const std::string& text) {
  std::string r;
  for (unsigned char ch : text) {
    if (ch < 0x20 || ch == 0x7f) {
      char buf[5];
      std::snprintf(buf, sizeof buf, "\\x%02x", ch);
      r += buf;
    } else {
      r += static_cast<char>(ch);
    }
  }
  return r;
}

/// What a file that is not a regular file is, for the refusal.
const char* kind_of(mode_t m) {
  if (S_ISDIR(m)) return "a directory";
  if (S_ISFIFO(m)) return "a FIFO or pipe";
  if (S_ISSOCK(m)) return "a socket";
  if (S_ISCHR(m) || S_ISBLK(m)) return "a device";
  return "not a regular file";
}

/// The whole text of a certificate file. Anything but a regular file (a directory, a FIFO, a
/// device) is refused before it is read, so that nothing blocks; so is a file over kMaxBytes.
std::string read_certificate(const std::string& path) {
  struct stat sb {};
  if (::stat(path.c_str(), &sb) != 0) throw Malformed(std::string("cannot be opened: ") + std::strerror(errno));
  if (!S_ISREG(sb.st_mode)) throw Malformed(std::string("is ") + kind_of(sb.st_mode) + ", not a regular file: not read");
  // O_NONBLOCK: should the name be replaced by a FIFO after stat, open does not wait for a writer
  // (fstat below then refuses it).
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw Malformed(std::string("cannot be opened: ") + std::strerror(errno));
  std::string text;
  try {
    if (::fstat(fd, &sb) != 0 || !S_ISREG(sb.st_mode)) throw Malformed(std::string("is ") + kind_of(sb.st_mode) + ", not a regular file: not read");
    if (sb.st_size > kMaxBytes) throw Malformed("is larger than " + std::to_string(kMaxBytes >> 20) + " MiB (the checker's limit): not read");
    char buf[1 << 16];
    for (;;) {
      const ssize_t n = ::read(fd, buf, sizeof buf);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) throw Malformed(std::string("cannot be read: ") + std::strerror(errno));
      if (n == 0) break;
      if (static_cast<long long>(text.size()) + n > kMaxBytes)
        throw Malformed("is larger than " + std::to_string(kMaxBytes >> 20) + " MiB (the checker's limit): not read");
      text.append(buf, static_cast<std::size_t>(n));
    }
  } catch (...) {
    ::close(fd);
    throw;
  }
  ::close(fd);
  return text;
}

/// The JSON of a certificate; a key twice in one object is refused (which one a reader keeps is
/// not defined by JSON: a certificate must not depend on it).
json parse_certificate(const std::string& text) {
  std::vector<std::set<std::string>> keys;  // the keys seen in each open object
  std::string duplicate;
  const json::parser_callback_t cb = [&](int /*depth*/, json::parse_event_t event, json& parsed) {
    if (event == json::parse_event_t::object_start) {
      keys.emplace_back();
    } else if (event == json::parse_event_t::object_end) {
      if (!keys.empty()) keys.pop_back();
    } else if (event == json::parse_event_t::key && !keys.empty() && duplicate.empty()) {
      const std::string k = parsed.get<std::string>();
      if (!keys.back().insert(k).second) duplicate = k;
    }
    return true;
  };
  json c;
  try {
    c = json::parse(text, cb);
  } catch (const json::exception& e) {
    throw Malformed(std::string("not JSON: ") + e.what());
  }
  if (!duplicate.empty()) throw Malformed("the key '" + duplicate + "' appears twice in one object (JSON leaves its value undefined)");
  return c;
}

/// Checks one file; returns its exit status after printing its line (flushed at once).
int check_file(const std::string& path) {
  std::string statement = "?", what;
  const std::string name = shown(path);
  try {
    const json c = parse_certificate(read_certificate(path));
    const json& format = field(c, "format", "");
    if (format != kFormat) throw Malformed("format is not \"" + std::string(kFormat) + "\"");
    const json& version = field(c, "version", "");
    if (!version.is_number_integer() || version.get<long long>() != kVersion)
      throw Malformed("version " + version.dump() + " (this checker reads version " + std::to_string(kVersion) + ")");
    const json& st = field(c, "statement", "");
    if (!st.is_string()) throw Malformed("'statement' is not a string");
    statement = st.get<std::string>();
    long steps = 0;
    const Statement* found = nullptr;
    for (const Statement& t : statements())
      if (statement == t.name) found = &t;
    if (found == nullptr) throw Malformed("unknown statement '" + statement + "' (this checker reads " + statement_names() + ")");
    steps = found->check(c, what);
    std::printf("OK %s: %s, %ld steps re-verified%s\n", name.c_str(), statement.c_str(), steps, what.empty() ? "" : one_line("; " + what).c_str());
    std::fflush(stdout);
    return 0;
  } catch (const Failed& e) {
    std::printf("FAIL %s: %s: step not verified: %s\n", name.c_str(), shown(statement).c_str(), one_line(e.what()).c_str());
  } catch (const Malformed& e) {
    std::printf("MALFORMED %s: %s\n", name.c_str(), one_line(e.what()).c_str());
    std::fflush(stdout);
    return 2;
  } catch (const std::bad_alloc&) {
    std::printf("MALFORMED %s: the checker ran out of memory reading it\n", name.c_str());
    std::fflush(stdout);
    return 2;
  } catch (const std::exception& e) {  // a defect of the checker: never taken for a verdict of OK
    std::printf("MALFORMED %s: could not be checked: %s\n", name.c_str(), one_line(e.what()).c_str());
    std::fflush(stdout);
    return 2;
  }
  std::fflush(stdout);
  return 1;
}

constexpr const char* kUsage =
    "usage: dfchaos-recheck [--] FILE...\n"
    "       dfchaos-recheck --help | --version\n"
    "Re-verifies certificates written by `dfchaos certify ... --certificate FILE`, in MPFI interval\n"
    "arithmetic, with its own formulas from the paper (docs/certificates.md, src/recheck/README.md).\n"
    "One line per file, printed as soon as it is decided:\n"
    "  OK NAME: STATEMENT, N steps re-verified[; what was proved]\n"
    "  FAIL NAME: STATEMENT: step not verified: STEP\n"
    "  MALFORMED NAME: WHY   (not a regular file, unreadable, over 256 MiB, not JSON, a duplicate key,\n"
    "                        a missing field, another format or version, an inexact number)\n"
    "NAME is the file name as given, in double quotes with C escapes if it holds a space, a quote, a\n"
    "backslash or a byte that is not printable ASCII. A file whose name starts with '-' follows '--'.\n"
    "Exit status: 0 every file verified; 1 a step failed in some file; 2 some file malformed, or bad\n"
    "usage. Every file is checked whatever the others give.\n";

}  // namespace recheck

int main(int argc, char** argv) {
  std::vector<std::string> files;
  bool options = true;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (options && arg == "--") {
      options = false;
    } else if (options && (arg == "--help" || arg == "-h" || arg == "--version")) {
      // Only alone: exit 0 is the verdict "every file verified", which a file named --help that a
      // glob picked up among bad certificates must not earn.
      if (argc != 2) {
        std::fprintf(stderr, "dfchaos-recheck: %s takes no other argument (a file named so follows --)\n", arg.c_str());
        return 2;
      }
      if (arg == "--version")
        std::printf("dfchaos-recheck %s (MPFI %s, MPFR %s, GMP %s)\n", DFCHAOS_VERSION, mpfi_get_version(), mpfr_get_version(), gmp_version);
      else
        std::fputs(recheck::kUsage, stdout);
      return std::fflush(stdout) == 0 ? 0 : 2;
    } else if (options && arg.size() > 1 && arg[0] == '-') {
      std::fprintf(stderr, "dfchaos-recheck: unknown option %s (a file named so follows --; see --help)\n", recheck::shown(arg).c_str());
      return 2;
    } else {
      files.push_back(arg);
    }
  }
  if (files.empty()) {
    std::fputs("dfchaos-recheck: no FILE given (usage: dfchaos-recheck [--] FILE...; see --help)\n", stderr);
    return 2;
  }
  int status = 0;
  for (const std::string& f : files) status = std::max(status, recheck::check_file(f));
  mpfr_free_cache();
  return std::fflush(stdout) == 0 ? status : 2;
}
