// SPDX-License-Identifier: GPL-3.0-or-later
// `dfchaos simulate` once held every event (72 B) and sample (40 B) in memory before printing
// them, so `--t-end 1e12 --max-events 1e8` needed about 8 GB and died of std::bad_alloc under
// `ulimit -v 1500000`, and `--sample 1 --t-end 4.9e6` the same under 300 MB. The library now has a
// streaming form of simulate() (a SimulationSink receives each event and sample as it is found) and
// the tool streams the events to stdout and spools the sample rows to an unnamed temporary file.
//
// The regression tests run the tool in a forked child (dfchaos::cli::run, in-process) under an
// address-space limit kHeadroom above what the test process maps, on two long commands
// reduced to 1e6 events and 1e6 samples (the old code needed more than 75 MB for either), and check
// the exit status, the shape of the output and that the child's peak resident memory exceeds that
// of a 10-time-unit run by less than kFlatGrowth. The other tests check that the streaming and the
// vector forms give the same simulation, in the documented order of calls.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>
#endif

#include "cli.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/simulator.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define DFCHAOS_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define DFCHAOS_TEST_ASAN 1
#endif
#endif

namespace {

using namespace dfchaos;

// ---- the streaming form against the vector form ------------------------------------------------

/// One call of a sink, in the order received.
struct Call {
  enum Kind { Start, Event, Sample } kind;
  std::size_t index;  ///< into Recorder::events or Recorder::samples
};

/// A sink that records every call.
struct Recorder final : SimulationSink {
  bool started = false;
  Regime initial = Regime::Free;
  std::vector<SimulationEvent> events;
  std::vector<dfchaos::Sample> samples;
  std::vector<Call> calls;
  void start(Regime r) override {
    started = true;
    initial = r;
    calls.push_back({Call::Start, 0});
  }
  void event(const SimulationEvent& e) override {
    calls.push_back({Call::Event, events.size()});
    events.push_back(e);
  }
  void sample(const dfchaos::Sample& s) override {
    calls.push_back({Call::Sample, samples.size()});
    samples.push_back(s);
  }
};

bool same(double x, double y) { return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y); }

void expect_same_event(const SimulationEvent& a, const SimulationEvent& b, std::size_t k) {
  EXPECT_TRUE(same(a.t, b.t) && a.when.turn == b.when.turn && same(a.when.phase, b.when.phase) && a.before == b.before && a.after == b.after &&
              a.kind == b.kind && same(a.x, b.x) && same(a.y, b.y) && same(a.v_before, b.v_before) && same(a.v_after, b.v_after))
      << "event " << k << " at t=" << a.t << " / " << b.t;
}

struct Case {
  Parameters p;
  double x0, y0, v0, t0, t_end, dt;
};

// Inside and outside the paper's assumptions (b >= a/2, q <= 2b, q >= a + 2b), with and without
// samples, a sample step that is a multiple of nothing in particular.
const Case kCases[] = {
    {Parameters(1.0, 0.01, 0.85), 0.0, 0.0, 0.0, 4.0, 300.0, 0.1}, {Parameters(1.0, 0.3, 0.85), 0.0, 0.0, 0.0, 0.0, 1000.0, 0.37},
    {Parameters(1.0, 0.3, 0.5), -1.0, 0.0, 2.0, -3.0, 500.0, 1.0}, {Parameters(2.0, 1.5, 0.5), -1.0, 0.0, 2.0, -3.0, 500.0, 2.0},
    {Parameters(1.0, 0.6, 1.5), -1.0, 0.0, 0.0, 0.0, 200.0, 0.0},  {Parameters(1.0, 0.1, 2.5), -0.5, 0.0, 0.3, 0.0, 300.0, 0.25},
};

TEST(SimulateStreaming, SinkReceivesTheVectorFormsSimulationInTimeOrder) {
  for (const Case& c : kCases) {
    SCOPED_TRACE(testing::Message() << "a=" << c.p.a() << " b=" << c.p.b() << " q=" << c.p.q() << " dt=" << c.dt);
    SimulationOptions o;
    o.sample_dt = c.dt;
    const Simulation v = simulate(c.p, c.x0, c.y0, c.v0, c.t0, c.t_end, o);
    Recorder r;
    const MechanicalState final_state = simulate(c.p, c.x0, c.y0, c.v0, c.t0, c.t_end, o, r);

    ASSERT_FALSE(v.events.empty());
    ASSERT_EQ(r.events.size(), v.events.size());
    for (std::size_t k = 0; k < v.events.size(); ++k) expect_same_event(r.events[k], v.events[k], k);
    ASSERT_EQ(r.samples.size(), v.samples.size());
    if (c.dt > 0) {
      EXPECT_EQ(r.samples.size(), static_cast<std::size_t>((c.t_end - c.t0) / c.dt) + 1);
    }
    for (std::size_t k = 0; k < v.samples.size(); ++k) {
      const auto &a = r.samples[k], &b = v.samples[k];
      EXPECT_TRUE(same(a.t, b.t) && same(a.x, b.x) && same(a.y, b.y) && same(a.v, b.v) && a.regime == b.regime) << "sample " << k;
    }
    EXPECT_EQ(r.initial, v.initial_regime);
    EXPECT_TRUE(final_state.t == v.final_state.t && same(final_state.x, v.final_state.x) && same(final_state.y, v.final_state.y) &&
                same(final_state.v, v.final_state.v) && final_state.regime == v.final_state.regime);

    // The order of the calls: start first and once; a sample before an event exactly when its
    // instant is earlier (the documented contract of SimulationSink).
    ASSERT_EQ(r.calls.front().kind, Call::Start);
    std::size_t next_event = 0;
    for (std::size_t k = 1; k < r.calls.size(); ++k) {
      ASSERT_NE(r.calls[k].kind, Call::Start);
      if (r.calls[k].kind == Call::Event) {
        ++next_event;
        continue;
      }
      const Instant ts = Instant::from_time(r.samples[r.calls[k].index].t);
      if (next_event < r.events.size()) {
        EXPECT_TRUE(before(ts, r.events[next_event].when)) << "sample " << r.calls[k].index;
      }
      if (next_event > 0) {
        EXPECT_FALSE(before(ts, r.events[next_event - 1].when)) << "sample " << r.calls[k].index;
      }
    }
  }
}

TEST(SimulateStreaming, GivingUpLeavesTheEventsBeforeTheLimitWithTheSink) {
  const Parameters p(1.0, 0.3, 0.85);
  SimulationOptions o;
  o.sample_dt = 0.5;
  const Simulation all = simulate(p, 0.0, 0.0, 0.0, 0.0, 2000.0, o);
  ASSERT_GT(all.events.size(), 100u);
  o.max_events = 100;
  Recorder r;
  EXPECT_THROW(simulate(p, 0.0, 0.0, 0.0, 0.0, 2000.0, o, r), GaveUp);
  EXPECT_TRUE(r.started);
  ASSERT_EQ(r.events.size(), 100u);
  for (std::size_t k = 0; k < r.events.size(); ++k) expect_same_event(r.events[k], all.events[k], k);
  // Every sample before the 101st event, and none after it.
  const Instant limit = all.events[100].when;
  std::size_t expected = 0;
  while (expected < all.samples.size() && before(Instant::from_time(all.samples[expected].t), limit)) ++expected;
  EXPECT_EQ(r.samples.size(), expected);
}

TEST(SimulateStreaming, RejectsBadInputBeforeAnyCallOfTheSink) {
  const Parameters p(1.0, 0.3, 0.85);
  SimulationOptions o;
  Recorder r;
  EXPECT_THROW(simulate(p, 1.0, 0.0, 0.0, 0.0, 10.0, o, r), InvalidParameter);  // x0 > y0
  EXPECT_THROW(simulate(p, 0.0, 0.0, 0.0, 10.0, 0.0, o, r), InvalidParameter);  // t_end < t0
  o.sample_dt = 1e-9;
  EXPECT_THROW(simulate(p, 0.0, 0.0, 0.0, 0.0, 1e3, o, r), InvalidParameter);  // too many samples
  EXPECT_TRUE(r.calls.empty());
}

// ---- the tool in bounded memory ------------------------------------------------------------------

#if defined(__linux__) && !defined(DFCHAOS_TEST_ASAN)

/// Address space granted to the child above what the test process maps when it forks: the old code
/// needed more than 75 MB on each of the reduced commands below.
constexpr long kHeadroom = 48L << 20;
/// Largest growth of the child's peak resident memory (KiB) over a run of 10 time units: flat.
constexpr long kFlatGrowthKiB = 16L << 10;

/// What a run of the tool in a child printed: lines of stdout (and where the sample table starts),
/// stderr, exit status, peak resident memory.
struct ChildRun {
  int status = -1;  ///< the exit status, or 128 + the signal
  long lines = 0;
  std::string first, last;  ///< first and last line of stdout
  long blank_lines = 0;
  long sample_header = -1;  ///< index of the line "t x y v regime", -1 if none
  std::string err;
  long maxrss_kib = 0;
};

long mapped_bytes() {
  long pages = 0;
  if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(f, "%ld", &pages) != 1) pages = 0;
    std::fclose(f);
  }
  return pages * ::sysconf(_SC_PAGESIZE);
}

/// Runs `dfchaos simulate ARGS` through dfchaos::cli::run in a forked child whose address space is
/// limited to kHeadroom above the current one; reads its stdout line by line as it streams.
ChildRun run_simulate(const std::vector<std::string>& args) {
  ChildRun r;
  int out[2], err[2];
  if (::pipe(out) != 0 || ::pipe(err) != 0) {
    ADD_FAILURE() << "pipe: " << std::strerror(errno);
    return r;
  }
  const long limit = mapped_bytes() + kHeadroom;
  std::cout.flush();
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(out[1], 1);
    ::dup2(err[1], 2);
    for (int fd : {out[0], out[1], err[0], err[1]}) ::close(fd);
    const rlimit rl{static_cast<rlim_t>(limit), static_cast<rlim_t>(limit)};
    if (::setrlimit(RLIMIT_AS, &rl) != 0) ::_exit(99);
    std::vector<std::string> words{"dfchaos", "simulate"};
    words.insert(words.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    const int status = dfchaos::cli::run(static_cast<int>(words.size()), argv.data());
    std::fflush(nullptr);
    ::_exit(status);
  }
  ::close(out[1]);
  ::close(err[1]);
  std::vector<char> chunk(1 << 16);
  std::string line;
  ssize_t n;
  while ((n = ::read(out[0], chunk.data(), chunk.size())) > 0)
    for (ssize_t k = 0; k < n; ++k) {
      if (chunk[k] != '\n') {
        line += chunk[k];
        continue;
      }
      if (r.lines == 0) r.first = line;
      if (line.empty()) ++r.blank_lines;
      if (line == "t\tx\ty\tv\tregime") r.sample_header = r.lines;
      r.last = line;
      ++r.lines;
      line.clear();
    }
  while ((n = ::read(err[0], chunk.data(), chunk.size())) > 0) r.err.append(chunk.data(), static_cast<std::size_t>(n));
  ::close(out[0]);
  ::close(err[0]);
  int status = 0;
  rusage ru{};
  if (::wait4(pid, &status, 0, &ru) != pid) {
    ADD_FAILURE() << "wait4: " << std::strerror(errno);
    return r;
  }
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.maxrss_kib = ru.ru_maxrss;
  EXPECT_TRUE(line.empty()) << "stdout does not end with a newline";
  return r;
}

const std::vector<std::string> kModel = {"--a", "1", "--b", "0.3", "--q", "0.85", "--x0", "0", "--y0", "0", "--v0", "0", "--t0", "0"};

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

/// A text file's lines (the samples file of --samples-out).
std::vector<std::string> file_lines(const std::string& path) {
  std::vector<std::string> lines;
  if (std::FILE* f = std::fopen(path.c_str(), "r")) {
    std::string line;
    for (int c; (c = std::fgetc(f)) != EOF;) {
      if (c != '\n') {
        line += static_cast<char>(c);
        continue;
      }
      lines.push_back(line);
      line.clear();
    }
    std::fclose(f);
  }
  return lines;
}

/// A file name for the samples of one test, removed first.
std::string samples_path(const char* name) {
  const std::string path = ::testing::TempDir() + "dfchaos-samples-" + name + ".tsv";
  std::remove(path.c_str());
  return path;
}

/// The provenance lines after the column line (cli.hpp, provenance_text): the title, the build, then
/// a, b, q, x0, y0, v0, t0, t-end, max-events, and sample when samples are taken.
constexpr std::size_t kProvenanceLines = 2 + 9;

/// A short run under the same limit: the reference for the peak memory (and a check of the limit).
ChildRun reference_run() {
  const std::string samples = samples_path("reference");
  const ChildRun r = run_simulate(with(kModel, {"--t-end", "10", "--sample", "1", "--samples-out", samples}));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.lines, 1 + (kProvenanceLines + 1) + 1 + 3 + 1) << "column line, provenance, initial regime, 3 events, final state";
  EXPECT_EQ(file_lines(samples).size(), 1 + (kProvenanceLines + 1) + 11U) << "column line, provenance, 11 samples";
  return r;
}

TEST(SimulateStreaming, Regression_28_7_EventsStreamInFlatMemory) {
  // The command `--t-end 1e12 --max-events 1e8` with 1e6 events: the give-up after them leaves the
  // rows already streamed on stdout, one line on stderr, exit status 1, and no out-of-memory.
  const ChildRun ref = reference_run();
  const ChildRun r = run_simulate(with(kModel, {"--t-end", "1e12", "--max-events", "1e6"}));
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "dfchaos: gave up: simulate: more than 1000000 events before t-end=1e12; raise the event limit or shorten the time span\n");
  EXPECT_EQ(r.first, "t\tphase\tbefore\tafter\tkind\tx\ty\tv_before\tv_after");
  EXPECT_EQ(r.lines, 1 + kProvenanceLines + 1 + 1'000'000) << "column line, provenance, initial regime, the first 1e6 events (no final state)";
  EXPECT_EQ(r.sample_header, -1);
  EXPECT_EQ(r.blank_lines, 0);
  EXPECT_LT(r.maxrss_kib - ref.maxrss_kib, kFlatGrowthKiB)
      << "peak resident memory " << r.maxrss_kib << " KiB against " << ref.maxrss_kib << " KiB for 10 time units";
}

TEST(SimulateStreaming, Regression_28_7_SamplesSpoolInFlatMemory) {
  // The command `--sample 1 --t-end 4.9e6` with 1e6 samples (and about 3.2e5 events): complete, the
  // events on stdout, the sample table in its own file (streamed into a temporary beside it), exit
  // status 0.
  const ChildRun ref = reference_run();
  const std::string samples = samples_path("million");
  const ChildRun r = run_simulate(with(kModel, {"--t-end", "1e6", "--sample", "1", "--max-events", "1e8", "--samples-out", samples}));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(r.first, "t\tphase\tbefore\tafter\tkind\tx\ty\tv_before\tv_after");
  EXPECT_GT(r.lines, 100'000) << "the events";
  EXPECT_EQ(r.sample_header, -1) << "no sample table on stdout";
  EXPECT_EQ(r.blank_lines, 0);
  EXPECT_EQ(r.last.substr(0, 20), "# final state: t = 1");
  const std::vector<std::string> rows = file_lines(samples);
  ASSERT_EQ(rows.size(), 1 + (kProvenanceLines + 1) + 1'000'001U) << "column line, provenance, samples at t = 0, 1, ..., 1e6";
  EXPECT_EQ(rows[0], "t\tx\ty\tv\tregime");
  EXPECT_EQ(rows.back().substr(0, 8), "1000000\t");
  std::remove(samples.c_str());
  EXPECT_LT(r.maxrss_kib - ref.maxrss_kib, kFlatGrowthKiB)
      << "peak resident memory " << r.maxrss_kib << " KiB against " << ref.maxrss_kib << " KiB for 10 time units";
}

#endif

}  // namespace
