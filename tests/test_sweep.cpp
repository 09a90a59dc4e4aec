// SPDX-License-Identifier: GPL-3.0-or-later
// Unit tests of the sweep engine (src/sweep): range, observable and shard parsing with their
// bounds; the cell's observables against direct calls of the library (as thm1_parameter_plane
// makes them) and the period against its definition; chunk planning; the header read back; the
// checkpoint of --resume (stale temporaries, damaged chunks, another spec, a second run); and the
// count of T evaluations used by `make bench`. Byte identity of whole runs (serial, threads,
// shards, resume, MPI) is checked by tests/sweep_identity.sh.
#include <gtest/gtest.h>
#include <omp.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>

#include "dfchaos/certified/covering.hpp"
#include "dfchaos/covering.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/map_derivative.hpp"
#include "dfchaos/next_hit.hpp"
#include "dfchaos/orbit.hpp"
#include "dfchaos/phase.hpp"
#include "dfchaos/superstable.hpp"
#include "kit/digest.hpp"
#include "kit/grid.hpp"
#include "kit/output.hpp"
#include "sweep/cell.hpp"
#include "sweep/checkpoint.hpp"
#include "sweep/engine.hpp"
#include "sweep/header.hpp"
#include "sweep/run.hpp"
#include "sweep/seal.hpp"
#include "t_evaluations.hpp"

using namespace dfchaos;
using namespace dfchaos::sweep;
namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("dfchaos-test-sweep-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

/// The message of the InvalidParameter thrown by f ("" if none).
template <class F>
std::string rejection(F&& f) {
  try {
    f();
  } catch (const InvalidParameter& e) {
    return e.what();
  }
  return "";
}

Spec spec_of(const std::string& q, const std::string& b, const std::string& observables) {
  Spec s;
  s.q_over_a = Range::parse("q-range", q);
  s.b_over_a = Range::parse("b-range", b);
  s.observables = ObservableSet::parse("observables", observables);
  return s;
}

/// A cheap spec (short orbits, period only) for tests of runs and checkpoints: 4 x 3 cells.
Spec cheap_spec() {
  Spec s = spec_of("0.7:0.95:4", "0.01:0.2:3:log", "period");
  s.orbit.transient = 20;
  s.orbit.steps = 10;
  return s;
}

void run_to_file(RunOptions o) {
  sweep::Run run(std::move(o));
  EXPECT_EQ(run_on_threads(run), 0);
}

}  // namespace

// ---- ranges ---------------------------------------------------------------------------------------

TEST(Range, ValuesAreThoseOfTheKitAxes) {
  const Range lin = Range::parse("q-range", "0.5:1:5");
  const Range log = Range::parse("b-range", "1e-4:0.1:4:log");
  const Range mid = Range::parse("q-range", "0.7:1:6:mid");
  const auto al = kit::Axis::linear(0.5, 1, 5), ag = kit::Axis::log_ratio(1e-4, 1000.0, 4), am = kit::Axis::centres(0.7, 1, 6);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(lin[i], al[i]);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(log[i], ag[i]);  // as thm1_parameter_plane's b/a axis
  for (int i = 0; i < 6; ++i) EXPECT_EQ(mid[i], am[i]);  // as its q/a axis
  EXPECT_EQ(Range::parse("b-range", "0.25:0.25:1")[0], 0.25);
  EXPECT_EQ(Range::parse("q-range", "0.85").canonical(), Range::parse("q-range", "0.85:0.85:1").canonical());  // one value
  EXPECT_EQ(Range::parse("q-range", "0.85").size(), 1);
  EXPECT_EQ(Range::parse("b-range", "0.2:0.3:1:mid")[0], 0.25);
  EXPECT_EQ(lin.canonical(), "0.5:1:5:lin");
  EXPECT_EQ(Range::parse("q-range", "0.50:1.0:5:lin").canonical(), lin.canonical());  // one spec, one header
  EXPECT_EQ(log.canonical(), "1e-4:0.1:4:log");                                       // shortest decimals, as in the header
}

TEST(Range, RejectsMalformedOrEmptyRanges) {
  for (const char* bad : {"",       "x",     "nan",   "0:1",   "0:1:3:log:x",   "x:1:3",       "0:nan:3",   "0:inf:3",    "0:1:0",   "0:1:2.5",
                          "0:1:-3", "1:0:3", "1:1:3", "0:1:1", "0.5:0.5:1:mid", "0:1:3:cubic", "0:1:3:log", "-1:1:3:log", "0:1:1e9", "0::3"}) {
    const std::string msg = rejection([&] { Range::parse("q-range", bad); });
    EXPECT_NE(msg.find("q-range"), std::string::npos) << "'" << bad << "' -> " << msg;
  }
}

TEST(Spec, RejectsInadmissibleAxesAndTooMuchWork) {
  auto expect_rejected = [](Spec s, const std::string& option) {
    const std::string msg = rejection([&] { s.validate(); });
    EXPECT_EQ(msg.rfind(option + ":", 0), 0u) << msg;
  };
  expect_rejected(spec_of("0.5:1:3", "0.1:0.5:3", "covering"), "b-range");  // b/a = 1/2: no t2, t3
  expect_rejected(spec_of("0.5:1:3", "0.1:0.6:3", "covering"), "b-range");
  expect_rejected(spec_of("-0.5:1:3", "0.1:0.2:3", "covering"), "q-range");
  expect_rejected(spec_of("0:1:3", "0.1:0.2:3", "covering"), "q-range");
  expect_rejected(spec_of("0.5:1:100000", "0.01:0.2:10000", "covering"), "q-range");  // 10^9 cells
  Spec s = spec_of("0.5:1:1000", "0.01:0.2:1000", "rate");
  s.orbit.steps = kMaxSteps;
  expect_rejected(s, "steps");  // 10^6 cells * 10^7 steps
  s = spec_of("0.5:1:3", "0.01:0.2:3", "rate");
  s.orbit.theta0_fraction = 1;
  expect_rejected(s, "theta0-fraction");
  s.orbit.theta0_fraction = 0.5;
  s.period.tol = 0;
  expect_rejected(s, "period-tol");                                             // every option is checked, used or not
  EXPECT_NO_THROW(spec_of("0:1:3:mid", "0:0.5:3:mid", "covering").validate());  // centres lie inside the open bounds
}

TEST(Observables, ParsedInAnyOrderWrittenInColumnOrder) {
  const auto s = ObservableSet::parse("observables", "period,covering,superstable");
  EXPECT_EQ(s.canonical(), "covering,superstable,period");
  EXPECT_EQ(s.columns(), (std::vector<std::string>{"covering", "superstable", "epsilon", "period"}));
  EXPECT_TRUE(s.needs_orbit());
  EXPECT_FALSE(ObservableSet::parse("observables", "covering").needs_orbit());
}

TEST(Observables, CertifiedIsLastAndNotInTheDefaultSet) {
  const auto s = ObservableSet::parse("observables", "certified,period,covering");
  EXPECT_EQ(s.canonical(), "covering,period,certified");
  EXPECT_EQ(s.columns(), (std::vector<std::string>{"covering", "period", "certified", "certified_step"}));
  const auto d = ObservableSet::parse("observables", kDefaultObservables);
  EXPECT_FALSE(d.has(Observable::Certified));
  for (Observable o : kAllObservables)
    EXPECT_EQ(d.has(o), o != Observable::Certified && o != Observable::Region && o != Observable::Entropy) << observable_name(o);
  EXPECT_EQ(spec_of("0.8:0.9:2", "0.01:0.02:2", "certified,lyapunov").columns(),
            (std::vector<std::string>{"index", "q_over_a", "b_over_a", "status", "lyapunov", "certified", "certified_step", "error"}));
}

TEST(Observables, EntropyHasThreeColumnsLast) {
  const auto s = ObservableSet::parse("observables", "entropy,region,covering");
  EXPECT_EQ(s.canonical(), "covering,region,entropy");
  EXPECT_EQ(s.columns(), (std::vector<std::string>{"covering", "region", "region_uniform", "region_boxes", "region_stop", "entropy_lower",
                                                   "entropy_upper", "entropy_laps"}));
}

TEST(Observables, RegionHasFourColumnsAfterCertified) {
  const auto s = ObservableSet::parse("observables", "region,covering,certified");
  EXPECT_EQ(s.canonical(), "covering,certified,region");
  EXPECT_EQ(s.columns(),
            (std::vector<std::string>{"covering", "certified", "certified_step", "region", "region_uniform", "region_boxes", "region_stop"}));
  // A cell's rectangle reaches the next point: a b/a axis of one point has none.
  const std::string msg = rejection([] { spec_of("0.8:0.9:2", "0.002", "region").validate(); });
  EXPECT_NE(msg.find("b-range"), std::string::npos) << msg;
  EXPECT_NO_THROW(spec_of("0.85", "0.002:0.003:1:mid", "region").validate());
  auto s2 = spec_of("0.8:0.9:2", "0.01:0.02:2", "region");
  s2.region_max_boxes = 0;
  EXPECT_NE(rejection([&] { s2.validate(); }).find("region-max-boxes"), std::string::npos);
}

TEST(Range, ExtentsTileTheAxis) {
  const Range lin = Range::parse("q-range", "0.5:1:5");
  const Range log = Range::parse("b-range", "1e-4:0.1:4:log");
  const Range mid = Range::parse("q-range", "0.76:0.99:23:mid");
  for (const Range* r : {&lin, &log, &mid})
    for (long long i = 0; i + 1 < r->size(); ++i) {
      EXPECT_EQ(r->extent(i).second, r->extent(i + 1).first) << r->canonical() << " " << i;  // adjacent, no gap, no overlap
      EXPECT_LE(r->extent(i).first, (*r)[i]);
      EXPECT_GE(r->extent(i).second, (*r)[i]);
    }
  EXPECT_EQ(lin.extent(0), std::make_pair(0.5, lin[1]));
  EXPECT_DOUBLE_EQ(lin.extent(4).second, 1.125);  // the last reaches one step beyond hi
  EXPECT_DOUBLE_EQ(log.extent(3).second, 1.0);    // one log step beyond 0.1
  EXPECT_EQ(mid.extent(0).first, 0.76);           // mid: exactly the range
  EXPECT_EQ(mid.extent(22).second, 0.99);
  EXPECT_NEAR(mid.extent(9).second - mid.extent(9).first, 0.01, 1e-15);
  EXPECT_EQ(Range::parse("q-range", "0.85").extent(0), std::make_pair(0.85, 0.85));  // a single point
}

TEST(Observables, RejectsUnknownEmptyAndRepeatedNames) {
  for (const char* bad : {"", ",", "covering,", ",covering", "covering,,rate", "chaos", "Covering", "rate,rate", "certified,certified",
                          "certified_step", "Certified"}) {
    const std::string msg = rejection([&] { ObservableSet::parse("observables", bad); });
    EXPECT_EQ(msg.rfind("observables:", 0), 0u) << "'" << bad << "' -> " << msg;
  }
}

// ---- shards and chunks ----------------------------------------------------------------------------

TEST(Shard, EveryCellInExactlyOneShard) {
  for (long long cells : {1LL, 7LL, 30LL, 1001LL})
    for (long long n : {1LL, 2LL, 3LL, 7LL}) {
      if (n > cells) continue;
      std::vector<int> seen(static_cast<std::size_t>(cells), 0);
      for (long long i = 0; i < n; ++i) {
        const Shard s = Shard::parse("shard", std::to_string(i) + "/" + std::to_string(n), cells);
        long long last = -1;
        for (long long p = 0; p < s.size(cells); ++p) {
          ASSERT_LT(s.cell(p), cells);
          ASSERT_GT(s.cell(p), last);  // increasing
          last = s.cell(p);
          ++seen[static_cast<std::size_t>(s.cell(p))];
        }
      }
      for (int c : seen) EXPECT_EQ(c, 1) << cells << " cells, " << n << " shards";
    }
}

TEST(Shard, RejectsMalformedShards) {
  for (const char* bad : {"", "1", "1/", "/2", "2/2", "3/2", "-1/2", "0/0", "1/0", "0.5/2", "a/b", "1/2/3", "0/31"}) {
    const std::string msg = rejection([&] { Shard::parse("shard", bad, 30); });
    EXPECT_EQ(msg.rfind("shard", 0), 0u) << "'" << bad << "' -> " << msg;
  }
}

TEST(Plan, ChunksAreTheComplementOfWhatIsDone) {
  std::mt19937 rng(20261123);
  for (int trial = 0; trial < 200; ++trial) {
    const long long positions = 1 + static_cast<long long>(rng() % 200), chunk = 1 + static_cast<long long>(rng() % 17);
    std::vector<Interval> done;
    for (long long at = 0; at < positions;) {  // random disjoint done intervals
      const long long gap = static_cast<long long>(rng() % 9), len = 1 + static_cast<long long>(rng() % 9);
      if (at + gap + len > positions) break;
      if (rng() % 2) done.push_back(Interval{at + gap, at + gap + len});
      at += gap + len;
    }
    std::vector<int> covered(static_cast<std::size_t>(positions), 0);
    for (const auto& d : done)
      for (long long p = d.begin; p < d.end; ++p) ++covered[static_cast<std::size_t>(p)];
    long long last_end = 0;
    for (const auto& c : plan_chunks(positions, done, chunk)) {
      ASSERT_GE(c.begin, last_end);
      ASSERT_LE(c.size(), chunk);
      ASSERT_GT(c.size(), 0);
      last_end = c.end;
      for (long long p = c.begin; p < c.end; ++p) ++covered[static_cast<std::size_t>(p)];
    }
    for (int c : covered) ASSERT_EQ(c, 1);
  }
}

// ---- the header -----------------------------------------------------------------------------------

TEST(Header, ReadBackWithTheShardLineApart) {
  const Spec s = spec_of("0.7:1:6:mid", "1e-4:0.1:5:log", "covering,superstable,lyapunov,rate,period");
  const std::string whole = header_text(s, std::nullopt), shard = header_text(s, Shard{2, 3});
  // The column line first (numpy.genfromtxt(names=True) reads its names from line 1), then the title.
  EXPECT_EQ(whole.rfind("index\tq_over_a\tb_over_a\tstatus\t", 0), 0u);
  EXPECT_NE(whole.find("\n" + std::string(kTitleLine) + "\n"), std::string::npos);
  EXPECT_EQ(shard.substr(shard.rfind('\n', shard.size() - 2) + 1, 10), "# shard = ") << "the shard line is the last";
  std::istringstream in(shard);
  const ParsedHeader h = read_header("sweep-merge", "x", in);
  EXPECT_EQ(h.common, whole);  // the merge writes exactly the unsharded header
  ASSERT_TRUE(h.shard.has_value());
  EXPECT_EQ(h.shard->canonical(), "2/3");
  EXPECT_EQ(h.cells, 30);
  EXPECT_EQ(h.fields, s.columns().size());
  EXPECT_EQ(whole.find("shard"), std::string::npos);
  EXPECT_EQ(h.columns, s.columns());
}

TEST(Header, RowProblemChecksEveryField) {
  const std::vector<std::string> cols = {"index", "q_over_a", "b_over_a", "status", "covering", "period", "error"};
  const std::string good = "12\t0.80000000000000004\t0.001\tok\t1\t3\t-";
  EXPECT_EQ(row_problem(good, 12, cols), "");
  EXPECT_EQ(row_problem("12\t0.80000000000000004\t0.001\tinadmissible\tnan\tnan\t-", 12, cols), "");
  EXPECT_EQ(row_problem("12\t0.80000000000000004\t0.001\terror\tnan\tnan\tcovering: gave up", 12, cols), "");
  // One change in each field is refused.
  for (const std::string& bad :
       std::vector<std::string>{"13\t0.80000000000000004\t0.001\tok\t1\t3\t-",                            // another index
                                "12\t0.8000000000000000x\t0.001\tok\t1\t3\t-",                            // q/a not a number
                                "12\t0.800000000000000040\t0.001\tok\t1\t3\t-",                           // q/a not as the sweep writes it
                                "12\t0.80000000000000004\t-0.001\tok\t1\t3\t-",                           // negative b/a
                                "12\t0.80000000000000004\t0.001\tXX\t1\t3\t-",                            // status
                                "12\t0.80000000000000004\t0.001\tok\t7\t3\t-",                            // covering 7
                                "12\t0.80000000000000004\t0.001\tok\t1\t3.5\t-",                          // period not a count
                                "12\t0.80000000000000004\t0.001\tok\t1\t3\tboom",                         // a message in an ok cell
                                "12\t0.80000000000000004\t0.001\terror\tnan\tnan\t-",                     // an error without message
                                "12\t0.80000000000000004\t0.001\tinadmissible\t1\tnan\t-",                // a value in an inadmissible cell
                                "12\t0.80000000000000004\t0.001\tok\t1\t3",                               // a field missing
                                "12\t0.80000000000000004\t0.001\tok\t1\t3\t-\t-",                         // a field too many
                                std::string("12\t0.80000000000000004\t0.0") + '\0' + "01\tok\t1\t3\t-"})  // a NUL byte
    EXPECT_NE(row_problem(bad, 12, cols), "") << bad;
}

TEST(Header, RowProblemChecksTheCertifiedColumns) {
  const std::vector<std::string> cols = {"index", "q_over_a", "b_over_a", "status", "certified", "certified_step", "error"};
  EXPECT_EQ(row_problem("3\t0.84999999999999998\t0.01\tok\t0\t2\t-", 3, cols), "");
  EXPECT_EQ(row_problem("3\t0.84999999999999998\t0.01\tok\t1\t0\t-", 3, cols), "");
  EXPECT_EQ(row_problem("3\t0.84999999999999998\t0.01\terror\tnan\tnan\tcertified: x", 3, cols), "");
  for (const std::string& bad : std::vector<std::string>{"3\t0.84999999999999998\t0.01\tok\t2\t0\t-",    // certified 2
                                                         "3\t0.84999999999999998\t0.01\tok\t0\t7\t-",    // no step 7
                                                         "3\t0.84999999999999998\t0.01\tok\t0\t-1\t-",   // nor -1
                                                         "3\t0.84999999999999998\t0.01\tok\t0\t2.5\t-",  // a code is an integer
                                                         "3\t0.84999999999999998\t0.01\tinadmissible\tnan\t0\t-"})
    EXPECT_NE(row_problem(bad, 3, cols), "") << bad;
}

TEST(Seal, ParsesExactlyWhatItWrites) {
  const std::string digest = kit::sha256_hex("abc");
  EXPECT_EQ(digest, "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");  // FIPS 180-2, Appendix B.1
  const std::string line = seal_line(42, digest);
  const auto s = parse_seal_line(line.substr(0, line.size() - 1));
  ASSERT_TRUE(s.has_value());
  EXPECT_EQ(s->rows, 42);
  EXPECT_EQ(s->sha256, digest);
  for (std::size_t k = 0; k + 1 < line.size(); ++k) {  // any changed character makes it something else
    std::string bad = line.substr(0, line.size() - 1);
    bad[k] = bad[k] == '7' ? '8' : '7';
    const auto t = parse_seal_line(bad);
    EXPECT_TRUE(!t || t->rows != 42 || t->sha256 != digest) << bad;
  }
  Seal seal;
  const std::string text = "1\tx\n" + seal_line(1, kit::sha256_hex("1\tx\n"));
  EXPECT_EQ(check_text_seal("resume", "chunk", text, seal), "1\tx\n");
  EXPECT_NE(rejection([&] { check_text_seal("resume", "chunk", "1\ty\n" + text.substr(4), seal); }).find("damaged"), std::string::npos);
  EXPECT_NE(rejection([&] { check_text_seal("resume", "chunk", "1\tx\n", seal); }).find("no seal"), std::string::npos);
}

TEST(Header, RejectsATruncatedOrForeignHeader) {
  const std::string whole = header_text(cheap_spec(), std::nullopt);
  for (const std::string& bad :
       {whole.substr(0, whole.size() - 1), whole.substr(0, whole.size() / 2), std::string("index\tx\n"), "# something else\n" + whole}) {
    std::istringstream in(bad);
    EXPECT_NE(rejection([&] { read_header("sweep-merge", "f", in); }).find("sweep-merge"), std::string::npos);
  }
}

// ---- cells ------------------------------------------------------------------------------------------

TEST(Cell, CoveringAndSuperstableAreThoseOfThm1ParameterPlane) {
  // The same calls as experiments/thm1_parameter_plane.cpp makes, at a few of its cells.
  const Spec s = spec_of("0.7246113537767086:1:6:mid", "1e-4:0.1:5:log", "covering,superstable");
  for (long long index : {0LL, 7LL, 14LL, 23LL, 29LL}) {
    const CellValues v = evaluate_cell(s, index);
    ASSERT_EQ(v.status, CellStatus::Ok) << v.error;
    const Parameters p(1.0, s.b_at(index), s.q_at(index));
    EXPECT_EQ(v.covering, lemma4_covering(p).holds ? 1 : 0);
    const SuperstableCheck c = superstable_check(p, 400);
    EXPECT_EQ(v.superstable, c.fixed && c.epsilon > 0 ? 1 : 0);
    EXPECT_EQ(v.epsilon, c.epsilon);
    EXPECT_TRUE(std::isnan(v.lyapunov) && std::isnan(v.rate) && std::isnan(v.period));  // not asked for
  }
}

TEST(Cell, OrbitObservablesAreThoseOfOrbitStatistics) {
  Spec s = spec_of("0.75:0.95:3", "1e-3:0.1:3:log", "lyapunov,rate");
  s.orbit.theta0_fraction = 0.25;
  s.orbit.transient = 300;
  s.orbit.steps = 200;
  for (long long index = 0; index < s.cells(); ++index) {
    const CellValues v = evaluate_cell(s, index);
    const Parameters p(1.0, s.b_at(index), s.q_at(index));
    const OrbitStatistics st = orbit_statistics(p, *p.t2() + 0.25 * (*p.t3() - *p.t2()), 300, 200);
    EXPECT_EQ(v.lyapunov, st.lyapunov);
    EXPECT_EQ(v.rate, st.penetration_rate);
  }
}

TEST(Cell, PeriodFollowsItsDefinition) {
  // period = the smallest k <= period_max with |T^k(e) - e| <= tol, e = T^(transient+steps)(theta0),
  // recomputed here from return_map_step; and the same whether or not lyapunov/rate are computed
  // along (two code paths to e).
  Spec s = spec_of("0.6:0.98:5", "1e-3:0.3:5:log", "period");
  s.orbit.transient = 150;
  s.orbit.steps = 100;
  Spec with_orbit = s;
  with_orbit.observables = ObservableSet::parse("observables", "lyapunov,period");
  int periodic = 0, aperiodic = 0;
  for (long long index = 0; index < s.cells(); ++index) {
    const CellValues v = evaluate_cell(s, index);
    if (v.status != CellStatus::Ok) continue;
    EXPECT_EQ(evaluate_cell(with_orbit, index).period, v.period) << "cell " << index;
    const Parameters p(1.0, s.b_at(index), s.q_at(index));
    double e = *p.t2() + 0.5 * (*p.t3() - *p.t2());
    for (int n = 0; n < 250; ++n) e = return_map_step(p, e).T;
    long long expected = 0;
    double th = e;
    for (long long k = 1; k <= 64 && expected == 0; ++k) {
      th = return_map_step(p, th).T;
      if (circle_distance(th, e) <= 1e-9) expected = k;
    }
    EXPECT_EQ(v.period, static_cast<double>(expected)) << "cell " << index;
    (expected > 0 ? periodic : aperiodic)++;
  }
  EXPECT_GT(periodic, 0);  // the grid meets both kinds, so both branches are exercised
  EXPECT_GT(aperiodic, 0);
}

TEST(Cell, InadmissibleAndFailingCellsAreRecordedNotThrown) {
  const Spec s = spec_of("0.6:0.98:2", "0.45:0.45:1", "covering,superstable,period");
  const CellValues inadmissible = evaluate_cell(s, 0);  // q/a = 0.6 <= 2 b/a = 0.9
  EXPECT_EQ(inadmissible.status, CellStatus::Inadmissible);
  EXPECT_TRUE(std::isnan(inadmissible.covering));
  // b/a = 0.45, q/a = 0.98: the progression from t0 repeats for ever (eternal stick-slip), T gives up.
  const CellValues failed = evaluate_cell(s, 1);
  EXPECT_EQ(failed.status, CellStatus::Error);
  EXPECT_NE(failed.error.find("covering: "), std::string::npos);
  EXPECT_NE(failed.error.find("orbit: "), std::string::npos);
  const std::string row = format_row(s, failed);
  EXPECT_EQ(row_problem(row.substr(0, row.size() - 1), 1, s.columns()), "") << row;  // one line, all fields well-formed
  EXPECT_NE(row.find("\terror\tnan\tnan\tnan\tnan\tcovering: "), std::string::npos) << row;
}

TEST(Cell, CertifiedStepCodesAreProveCoveringsStepNames) {
  std::set<std::string> names;
  for (std::size_t k = 0; k < std::size(kAllCertifiedSteps); ++k) {
    const CertifiedStep c = kAllCertifiedSteps[k];
    const int code = static_cast<int>(c);
    EXPECT_EQ(code, static_cast<int>(k)) << "codes in order";
    names.insert(certified_step_name(c));
    if (c != CertifiedStep::Proved) {
      EXPECT_EQ(certified_step_of(certified_step_name(c)), c);
    }
    EXPECT_NE(certified_step_legend().find(std::to_string(code) + " " + certified_step_name(c)), std::string::npos);
  }
  EXPECT_EQ(names.size(), std::size(kAllCertifiedSteps));  // one name per code
  EXPECT_FALSE(certified_step_of("proved").has_value());   // not a step of a failed proof
  EXPECT_FALSE(certified_step_of("covering: candidate").has_value());
  EXPECT_FALSE(certified_step_of("").has_value());
}

TEST(Cell, CertifiedIsProvedWhereProveCoveringProvesIt) {
  // a = 1, q = 0.85, b = 1e-4 and b = 2e-3 (q from 0.78 to 0.99): proved in a few ms each.
  const Spec s = spec_of("0.85:0.85:1", "1e-4:2e-3:2:log", "covering,certified");
  for (long long index = 0; index < s.cells(); ++index) {
    const CellValues v = evaluate_cell(s, index);
    ASSERT_EQ(v.status, CellStatus::Ok) << v.error;
    EXPECT_EQ(v.certified, 1) << "b/a = " << s.b_at(index);
    EXPECT_EQ(v.certified_step, 0);
    EXPECT_EQ(v.covering, 1);  // the sampled search finds what is proved
    EXPECT_TRUE(std::isnan(v.superstable) && std::isnan(v.lyapunov));
    const std::string row = format_row(s, v);
    EXPECT_NE(row.find("\tok\t1\t1\t0\t-\n"), std::string::npos) << row;
    EXPECT_EQ(row_problem(row.substr(0, row.size() - 1), index, s.columns()), "") << row;
  }
  for (double q : {0.78, 0.9, 0.99}) {
    const PlaneCertified c = plane_certified(Parameters(1.0, 2e-3, q));
    EXPECT_TRUE(c.proved) << "q = " << q;
    EXPECT_EQ(c.step, CertifiedStep::Proved);
  }
}

TEST(Cell, CertifiedNotProvedGivesZeroAndTheStep) {
  // q/a = 0.85, b/a = 1e-2: the floating search proposes fewer than two disjoint candidates
  // ("covering: candidates"); q/a = 1.2 > 1 + 2 b/a: T is defined (q > 2b) but the certified layer
  // requires q - 2b < a ("admissibility").
  const Spec s = spec_of("0.85:1.2:2", "1e-2:1e-2:1", "certified");
  const CellValues candidates = evaluate_cell(s, 0), admissibility = evaluate_cell(s, 1);
  ASSERT_EQ(candidates.status, CellStatus::Ok) << candidates.error;
  EXPECT_EQ(candidates.certified, 0);
  EXPECT_EQ(candidates.certified_step, static_cast<int>(CertifiedStep::Candidates));
  ASSERT_EQ(admissibility.status, CellStatus::Ok) << admissibility.error;
  EXPECT_EQ(admissibility.certified, 0);
  EXPECT_EQ(admissibility.certified_step, static_cast<int>(CertifiedStep::Admissibility));
  // The same verdicts from the certified layer called directly.
  for (long long index : {0LL, 1LL}) {
    const certified::CoveringProof p = certified::prove_covering(certified::ParameterBox::point(1.0, s.b_at(index), s.q_at(index)));
    EXPECT_FALSE(p.verdict.proved);
    EXPECT_EQ(p.verdict.step, certified_step_name(index == 0 ? CertifiedStep::Candidates : CertifiedStep::Admissibility));
  }
  const std::string row = format_row(s, candidates);
  EXPECT_NE(row.find("\tok\t0\t2\t-\n"), std::string::npos) << row;
}

TEST(Cell, CertifiedFailuresAreRecordedNotThrown) {
  // Inadmissible: nan. A branch budget too small for two candidates: not proved at the step
  // "covering: candidates" (a count, not an error), the other observables kept.
  Spec s = spec_of("0.6:0.85:2", "0.4:0.4:1", "superstable,certified");
  const CellValues inadmissible = evaluate_cell(s, 0);  // q/a = 0.6 <= 2 b/a = 0.8
  EXPECT_EQ(inadmissible.status, CellStatus::Inadmissible);
  EXPECT_TRUE(std::isnan(inadmissible.certified) && std::isnan(inadmissible.certified_step));
  s = spec_of("0.85:0.85:1", "1e-3:1e-3:1", "superstable,certified");
  s.covering_max_branches = kDenseCostFactor;  // the candidate window: one branch of T1 above t2
  const CellValues over = evaluate_cell(s, 0);
  EXPECT_EQ(over.status, CellStatus::Ok) << over.error;
  EXPECT_EQ(over.certified, 0);
  EXPECT_EQ(over.certified_step, static_cast<int>(CertifiedStep::Candidates));
  EXPECT_FALSE(std::isnan(over.superstable));
  const std::string row = format_row(s, over);
  EXPECT_EQ(row_problem(row.substr(0, row.size() - 1), 0, s.columns()), "") << row;
  // The budget is max_branches / kDenseCostFactor branches (the proof's candidate search is a
  // Dense one); with all the branches of [t2, 3pi/2] the covering is proved.
  const Parameters p(1.0, 1e-3, 0.85);
  const long long branches = symmetric_tangency_count(p, *p.t2(), 1.5 * pi) + 1;
  ASSERT_GT(branches, 100);
  s.covering_max_branches = branches * kDenseCostFactor;
  const CellValues at = evaluate_cell(s, 0);
  EXPECT_EQ(at.status, CellStatus::Ok) << at.error;
  EXPECT_EQ(at.certified, 1);
}

/// The rows of every cell of `s`: on 1 thread, on 3 threads in reverse order (put back in cell
/// order), and on 3 threads again in order.
struct RowsOnThreads {
  std::vector<std::string> one, three, again;
};
RowsOnThreads rows_on_threads(const Spec& s) {
  std::vector<long long> cells;
  for (long long i = 0; i < s.cells(); ++i) cells.push_back(i);
  const int before = omp_get_max_threads();
  RowsOnThreads r;
  omp_set_num_threads(1);
  r.one = compute_rows(s, cells, nullptr);
  omp_set_num_threads(3);
  const std::vector<long long> reversed(cells.rbegin(), cells.rend());
  r.three = compute_rows(s, reversed, nullptr);
  std::reverse(r.three.begin(), r.three.end());
  r.again = compute_rows(s, cells, nullptr);
  omp_set_num_threads(before);
  return r;
}

TEST(Cell, CertifiedRowsDoNotDependOnTheThreadCount) {
  // prove_covering's work is bounded by counts, not time: the same rows on 1 and 3 threads, in
  // either order, and again on a second run.
  const Spec s = spec_of("0.8:1.1:3", "1e-3:0.2:4:log", "covering,certified");
  const RowsOnThreads r = rows_on_threads(s);
  int proved = 0, not_proved = 0;
  for (std::size_t k = 0; k < r.one.size(); ++k) {
    EXPECT_EQ(r.one[k], r.three[k]);
    EXPECT_EQ(r.one[k], r.again[k]);
    const std::vector<std::string>& one = r.one;
    const std::string tail = one[k].substr(one[k].rfind('\t', one[k].rfind('\t', one[k].rfind('\t') - 1) - 1));
    if (tail == "\t1\t0\t-\n") ++proved;
    if (tail.rfind("\t0\t", 0) == 0) ++not_proved;
  }
  EXPECT_GT(proved, 0);  // the grid holds both answers
  EXPECT_GT(not_proved, 0);
}

TEST(Cell, RowsDoNotDependOnTheThreadCount) {
  const RowsOnThreads r = rows_on_threads(spec_of("0.7:0.95:4", "0.01:0.2:3:log", "superstable,lyapunov,period"));
  for (std::size_t k = 0; k < r.one.size(); ++k) EXPECT_EQ(r.one[k], r.three[k]);
}

// ---- runs and the checkpoint of --resume -----------------------------------------------------------

TEST(Resume, StoppedAndResumedEqualsOneRun) {
  const fs::path d = fresh_dir("resume");
  RunOptions whole;
  whole.spec = cheap_spec();
  whole.out = (d / "whole.tsv").string();
  run_to_file(whole);
  RunOptions part;
  part.spec = cheap_spec();
  part.resume = (d / "part.tsv").string();
  part.chunk = 5;
  part.max_chunks = 1;
  {
    sweep::Run run(part);
    EXPECT_EQ(run_on_threads(run), kExitIncomplete);
  }
  EXPECT_FALSE(fs::exists(d / "part.tsv"));
  // A writer killed mid-chunk leaves a temporary: ignored and removed.
  std::ofstream(Checkpoint::directory(d / "part.tsv") / "chunk-000000000005-000000000010.tsv.tmp.1.2.3") << "1\tpartial";
  part.max_chunks = 0;
  part.chunk = 2;
  run_to_file(part);
  EXPECT_EQ(slurp(d / "part.tsv"), slurp(d / "whole.tsv"));
  EXPECT_FALSE(fs::exists(Checkpoint::directory(d / "part.tsv")));
  run_to_file(part);  // complete already: accepted as is
  EXPECT_EQ(slurp(d / "part.tsv"), slurp(d / "whole.tsv"));
  fs::remove_all(d);
}

TEST(Resume, RejectsAnotherSpecADamagedChunkAndASecondRun) {
  const fs::path d = fresh_dir("reject");
  RunOptions o;
  o.spec = cheap_spec();
  o.resume = (d / "r.tsv").string();
  o.chunk = 4;
  o.max_chunks = 2;
  {
    sweep::Run run(o);
    EXPECT_EQ(run_on_threads(run), kExitIncomplete);
  }
  RunOptions other = o;
  other.spec.orbit.steps = 11;
  EXPECT_EQ(rejection([&] { sweep::Run r(other); }).rfind("resume:", 0), 0u);
  RunOptions sharded = o;
  sharded.shard = Shard{0, 2};
  EXPECT_EQ(rejection([&] { sweep::Run r(sharded); }).rfind("resume:", 0), 0u);
  {
    sweep::Run first(o);  // holds the lock
    EXPECT_NE(rejection([&] { sweep::Run second(o); }).find("in use"), std::string::npos);
  }
  const fs::path chunk = Checkpoint::directory(d / "r.tsv") / "chunk-000000000004-000000000008.tsv";
  ASSERT_TRUE(fs::exists(chunk));
  const std::string rows = slurp(chunk);
  std::ofstream(chunk, std::ios::trunc) << rows.substr(0, rows.size() - 3);  // the seal cut short
  EXPECT_NE(rejection([&] { sweep::Run r(o); }).find("no seal"), std::string::npos);
  std::string changed = rows;
  changed[rows.find("\tok\t")] = ' ';  // one byte of a row: the digest no longer matches
  std::ofstream(chunk, std::ios::trunc) << changed;
  EXPECT_NE(rejection([&] { sweep::Run r(o); }).find("damaged"), std::string::npos);
  std::ofstream(chunk, std::ios::trunc) << rows;
  std::ofstream(Checkpoint::directory(d / "r.tsv") / "chunk-000000000006-000000000009.tsv") << rows;
  EXPECT_NE(rejection([&] { sweep::Run r(o); }).find("resume"), std::string::npos);  // overlapping (and wrong rows)
  fs::remove_all(d);
}

TEST(Run, RejectsBadOptionCombinations) {
  RunOptions o;
  o.spec = cheap_spec();
  o.max_chunks = 2;  // without --resume the chunks done would be lost
  EXPECT_EQ(rejection([&] { sweep::Run r(o); }).rfind("max-chunks:", 0), 0u);
  o.max_chunks = 0;
  o.chunk = 0;
  EXPECT_EQ(rejection([&] { sweep::Run r(o); }).rfind("chunk:", 0), 0u);
  o.chunk = 1;
  o.out = "x";
  o.resume = "y";
  EXPECT_EQ(rejection([&] { sweep::Run r(o); }).rfind("resume:", 0), 0u);
}

// ---- the count of T evaluations (make bench) -------------------------------------------------------

TEST(TEvaluations, CountsEveryEvaluation) {
  const Parameters p(1.0, 0.01, 0.85);
  const long long before = T_evaluations();
  orbit_statistics(p, 4.0, 10, 20);  // exactly transient + steps evaluations (map_derivative.hpp)
  EXPECT_EQ(T_evaluations() - before, 30);
  const long long mid = T_evaluations();
  T(p, 4.0);
  return_map_step(p, 4.0);
  EXPECT_EQ(T_evaluations() - mid, 2);
  const long long walk = T_evaluations();
  for (const MapStep& s : Orbit(p, 4.0, 7)) (void)s;  // one evaluation per step, none past the last
  EXPECT_EQ(T_evaluations() - walk, 7);
  const long long power = T_evaluations();
  T_power(p, 4.0, 5);
  EXPECT_EQ(T_evaluations() - power, 5);
}
