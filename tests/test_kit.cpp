// SPDX-License-Identifier: GPL-3.0-or-later
// Unit tests of the experiment kit (src/kit): option parsing and ranges, claims and their
// tolerances, the all-or-nothing output writer, grids, and dfchaos::bisect.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "dfchaos/bisect.hpp"
#include "dfchaos/errors.hpp"
#include "kit/claim.hpp"
#include "kit/format.hpp"
#include "kit/grid.hpp"
#include "kit/json.hpp"
#include "kit/options.hpp"
#include "kit/output.hpp"
#include "kit/table.hpp"

using namespace dfchaos;
using namespace dfchaos::kit;
namespace fs = std::filesystem;

namespace {
fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("dfchaos-test-kit-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(d);
  return d;
}
std::string read(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}
}  // namespace

TEST(Json, DumpWritesKeysInOrderDoublesWith17DigitsAndNonFiniteAsNull) {
  Json j = Json::object();
  j.set("z", 0.1).set("a", 1.0).set("n", 3).set("inf", std::numeric_limits<double>::infinity());
  j.set("s", std::string("q\"\\\n\t\x01")).set("list", Json::array().push(true).push(Json())).set("e", Json::object());
  j.set("z", 1e-5);  // an existing key keeps its place
  const std::string want =
      "{\n"
      "  \"z\": " +
      format_double(1e-5) +
      ",\n"
      "  \"a\": 1,\n"
      "  \"n\": 3,\n"
      "  \"inf\": null,\n"
      "  \"s\": \"q\\\"\\\\\\n\\t\\u0001\",\n"
      "  \"list\": [\n"
      "    true,\n"
      "    null\n"
      "  ],\n"
      "  \"e\": {}\n"
      "}\n";
  EXPECT_EQ(j.dump(), want);
  EXPECT_EQ(format_double(1e-5), "1.0000000000000001e-05");
  EXPECT_EQ(Json::array().dump(0), "[]\n");
  EXPECT_THROW(Json::array().set("k", 1), std::logic_error);
  EXPECT_THROW(Json::object().push(1), std::logic_error);
}

TEST(Options, ParseNumberAcceptsNumbersAndRejectsTheRest) {
  EXPECT_EQ(parse_number("n", "400", true), 400);
  EXPECT_EQ(parse_number("n", "1e8", true), 1e8);  // a count may be written in exponent form
  EXPECT_DOUBLE_EQ(parse_number("b", "2.5e-3", false), 2.5e-3);
  for (const char* bad : {"", "x", "nan", "inf", "-inf", "1e999", "3x", " "}) EXPECT_THROW(parse_number("b", bad, false), InvalidParameter) << bad;
  EXPECT_THROW(parse_number("n", "1.5", true), InvalidParameter);
}

TEST(Options, RangeViolationsNameTheOptionAndTheCondition) {
  const std::vector<OptionSpec> specs = {count("nq", 400, "grid").range(2, 100000).fast_value(20), real("ba-min", 1e-5, "smallest").range(1e-9, 0.1)};
  OptionValues v;
  v.set_defaults(specs, false);
  EXPECT_EQ(v.count("nq"), 400);
  v.set_defaults(specs, true);
  EXPECT_EQ(v.count("nq"), 20);       // the fast default
  EXPECT_EQ(v.real("ba-min"), 1e-5);  // no fast value declared: the default
  try {
    v.set(specs[0], {"1"});
    FAIL() << "out of range accepted";
  } catch (const InvalidParameter& e) {
    EXPECT_EQ(std::string(e.what()), "nq: must satisfy 2 <= nq <= 100000 (got 1)");
    EXPECT_EQ(e.parameter(), "nq");
  }
  EXPECT_THROW(v.set(specs[1], {"0.2"}), InvalidParameter);
  v.set(specs[0], {"1e5"});
  EXPECT_EQ(v.count("nq"), 100000);
  EXPECT_TRUE(v.given("nq"));
  EXPECT_FALSE(v.given("ba-min"));
  EXPECT_THROW(v.real("nq"), std::logic_error);  // wrong type
  EXPECT_THROW(v.count("undeclared"), std::logic_error);
  EXPECT_EQ(specs[1].record_key(), "ba_min");
}

TEST(Claims, ToleranceIsWrittenIntoTheStatementAsChecked) {
  EXPECT_EQ(format_tolerance(1e-8), "1e-8");
  EXPECT_EQ(format_tolerance(1e-10), "1e-10");
  EXPECT_EQ(format_tolerance(0.05), "0.05");
  EXPECT_EQ(format_tolerance(1e-4), "1e-4");
  EXPECT_EQ(format_tolerance(2.5e-7), "2.5e-7");
  EXPECT_EQ(format_tolerance(1e3), "1000");
  Claim c("x.y", "Eq. (1)", EvidenceKind::Sampled, "agrees to {tol}");
  c.at_most("error", 2e-9, 1e-8);
  EXPECT_EQ(c.statement(), "agrees to 1e-8");
  EXPECT_EQ(c.verdict(), Verdict::Holds);
  Claim d("x.z", "Eq. (1)", EvidenceKind::Sampled, "agrees to {tol}");
  d.at_most("error", 2e-8, 1e-8);
  EXPECT_EQ(d.verdict(), Verdict::Fails);
  Claim e("x.w", "Eq. (1)", EvidenceKind::Sampled, "no placeholder");
  e.tolerance(1e-3);
  EXPECT_THROW(e.statement(), std::logic_error);  // a tolerance that the statement does not show
}

TEST(Claims, PrecisionLimitedIsInconclusiveNeverFails) {
  Claim c("x.p", "Section 7", EvidenceKind::Sampled, "all words");
  c.inconclusive("orbit points closer than double precision").holds(false);
  EXPECT_EQ(c.verdict(), Verdict::Inconclusive);
  EXPECT_EQ(c.kind(), EvidenceKind::PrecisionLimited);
  EXPECT_NE(c.to_json().dump().find("\"evidence_kind\": \"precision-limited\""), std::string::npos);
}

// A statement that follows from certified inequalities by a written argument has
// its own kind, written as such, never as "certified".
TEST(Claims, CertifiedInequalitiesWithAWrittenArgumentHaveTheirOwnKind) {
  Claim c("x.u", "Lemma 4", EvidenceKind::CertifiedArgument, "for every small b/a");
  c.holds(true);
  const std::string j = c.to_json().dump();
  EXPECT_NE(j.find("\"evidence_kind\": \"certified+argument\""), std::string::npos) << j;
  EXPECT_STREQ(evidence_kind_name(EvidenceKind::CertifiedArgument), "certified+argument");
  EXPECT_STRNE(evidence_kind_name(EvidenceKind::CertifiedArgument), evidence_kind_name(EvidenceKind::Certified));
}

TEST(Claims, CasesLostToPrecisionMakeAClaimInconclusiveNeverFailing) {
  Claim lost("x.lost", "Section 6", EvidenceKind::Sampled, "every case");
  lost.cases(20, 0, 11).holds(false);  // a later holds(false) cannot turn it into a failure
  EXPECT_EQ(lost.verdict(), Verdict::Inconclusive);
  EXPECT_EQ(lost.kind(), EvidenceKind::PrecisionLimited);
  const std::string j = lost.to_json().dump();
  EXPECT_NE(j.find("\"precision_undecided\": 11"), std::string::npos);
  EXPECT_NE(j.find("\"checked\": 20"), std::string::npos);
  Claim counter("x.counter", "Section 6", EvidenceKind::Sampled, "every case");
  counter.cases(20, 1, 11);  // one decided counterexample refutes it whatever the rest
  EXPECT_EQ(counter.verdict(), Verdict::Fails);
  EXPECT_EQ(counter.kind(), EvidenceKind::Sampled);
  Claim all("x.all", "Section 6", EvidenceKind::Sampled, "every case");
  all.cases(20, 0, 0);
  EXPECT_EQ(all.verdict(), Verdict::Holds);
  // Order does not hide a failure: a counterexample survives a later holds(true), and an earlier
  // failure survives cases() with undecided cases.
  Claim later("x.later", "Section 6", EvidenceKind::Sampled, "every case");
  later.cases(20, 2, 5).holds(true);
  EXPECT_EQ(later.verdict(), Verdict::Fails);
  Claim earlier("x.earlier", "Section 6", EvidenceKind::Sampled, "every case");
  earlier.holds(false).cases(20, 0, 5);
  EXPECT_EQ(earlier.verdict(), Verdict::Fails);
  Claim added("x.added", "Section 6", EvidenceKind::Sampled, "every case");
  added.cases(20, 0, 0).holds(false);  // a condition of its own that fails
  EXPECT_EQ(added.verdict(), Verdict::Fails);
  Claim bad("x.bad", "Section 6", EvidenceKind::Sampled, "every case");
  EXPECT_THROW(bad.cases(5, 3, 3), std::logic_error);
  EXPECT_THROW(bad.cases(5, -1, 0), std::logic_error);
}

TEST(Claims, AnErratumThatHoldsIsShownAsARefutationNeverAsHolds) {
  Claim c("x.err", "Theorem 2", EvidenceKind::Certified, "the paper's statement fails here");
  c.erratum().holds(true);
  EXPECT_EQ(c.verdict(), Verdict::Holds);
  EXPECT_STREQ(c.report_verdict(), "refutes");
  const std::string j = c.to_json().dump();
  EXPECT_NE(j.find("\"origin\": \"erratum\""), std::string::npos);
  EXPECT_NE(j.find("\"report_verdict\": \"refutes\""), std::string::npos);
  Claim d("x.err2", "Theorem 2", EvidenceKind::Certified, "not shown");
  d.erratum().holds(false);
  EXPECT_STREQ(d.report_verdict(), "fails");
}

TEST(Claims, RejectsMalformedIds) {
  EXPECT_THROW(Claim("bad id", "", EvidenceKind::Sampled, "s"), std::logic_error);
  EXPECT_THROW(Claim("", "", EvidenceKind::Sampled, "s"), std::logic_error);
}

TEST(Output, WritesEverythingWithKindsAndVerdicts) {
  const fs::path root = fresh_dir("ok");
  Output out("demo", root);
  out.parameter("n", "3");
  Table t({"x", "y"});
  t.row({1.0, 2LL}).row({0.1, std::string("text")});
  out.table("", t, "a table");
  out.latex("demo_table", LatexTable("rr", {"a", "b"}).row({"1", "2"}).render());
  out.macro("DemoValue", 0.123456789, 3);
  out.claim("demo.one", "Lemma 1", EvidenceKind::Analytic, "one holds").holds(true);
  out.claim("demo.two", "Lemma 2", EvidenceKind::Sampled, "two fails").ours().not_expected().holds(false);
  EXPECT_EQ(out.finish(), 0);  // the failing claim is not asserted
  const std::string tsv = read(root / "data" / "demo.tsv");
  EXPECT_NE(tsv.find("# n = 3\n"), std::string::npos);
  // The column line first (numpy.genfromtxt(names=True) takes its names from line 1), then the
  // '#' lines, then the rows.
  EXPECT_EQ(tsv.rfind("x\ty\n# experiment: demo\n", 0), 0U);
  EXPECT_EQ(tsv.size() - tsv.rfind("# a table\n1\t2\n0.10000000000000001\ttext\n"),
            std::string("# a table\n1\t2\n0.10000000000000001\ttext\n").size());
  EXPECT_EQ(read(root / "tables" / "demo_table.tex"),
            "% generated by experiment demo; do not edit\n\\begin{tabular}{rr}\n\\toprule\na & b\\\\\n\\midrule\n1 & 2\\\\\n"
            "\\bottomrule\n\\end{tabular}\n");
  EXPECT_NE(read(root / "tables" / "demo-macros.tex").find("\\newcommand{\\dfcDemoValue}{0.123}"), std::string::npos);
  const std::string claims = read(root / "claims" / "demo.json");
  EXPECT_NE(claims.find("\"evidence_kind\": \"analytic\""), std::string::npos);
  EXPECT_NE(claims.find("\"origin\": \"ours\""), std::string::npos);
  EXPECT_NE(read(root / "tables" / "demo-claims.tex").find("\\dfcsetverdict{demo.two}{fails}{sampled}{ours}"), std::string::npos);
  for (const auto& e : fs::recursive_directory_iterator(root)) EXPECT_EQ(e.path().string().find(".tmp."), std::string::npos);
  fs::remove_all(root);
}

TEST(LatexTable, TypesetsCellsInExponentNotationAndLeavesOtherCells) {
  const std::string t = LatexTable("rrrr", {"a", "b", "c", "d"}).row({"8.68e-05", "1e-12", "0.85", "---"}).render();
  EXPECT_NE(t.find("\\ensuremath{8.68\\times 10^{-5}} & \\ensuremath{10^{-12}} & 0.85 & ---\\\\\n"), std::string::npos) << t;
  EXPECT_EQ(t.find("e-05"), std::string::npos) << t;
}

TEST(Format, SignificantDownNeverRoundsABoundUp) {
  EXPECT_EQ(format_significant_down(7.8246700263127835e-5, 3), "7.82e-5");
  EXPECT_EQ(format_significant_down(0.047054156659257156, 3), "0.047");
  EXPECT_EQ(format_significant_down(0.04789, 3), "0.0478");  // to nearest it would be 0.0479, above the bound
  EXPECT_EQ(format_significant_down(2.0, 2), "2");
  EXPECT_EQ(format_significant_down(0.0, 3), "0");  // an unproved bound
  for (double x = 1e-9; x < 1e9; x *= 1.37) {       // never above x, and within one unit of the last digit
    const double d = std::strtod(format_significant_down(x, 3).c_str(), nullptr);
    EXPECT_LE(d, x) << x;
    EXPECT_GT(d, x * (1 - 1.01e-2)) << x;
  }
}

TEST(Output, CertificatesGoWithTheOtherOutputsOrNotAtAll) {
  const fs::path root = fresh_dir("cert");
  Output out("demo", root);
  out.certificate("demo.one", "{\"format\": \"x\"}\n");
  out.claim("demo.one", "Lemma 1", EvidenceKind::Certified, "one holds").holds(true);
  EXPECT_EQ(out.finish(), 0);
  EXPECT_EQ(read(root / "certificates" / "demo.one.json"), "{\"format\": \"x\"}\n");
  fs::remove_all(root);
  // A failure elsewhere in the set leaves no certificate either.
  fs::create_directories(root);
  std::ofstream(root / "data") << "a regular file where the data folder should be";
  Output bad("demo", root);
  bad.certificate("demo.one", "{}\n");
  bad.table("", Table({"x"}), "t");
  bad.claim("demo.one", "Lemma 1", EvidenceKind::Certified, "s").holds(true);
  EXPECT_THROW(bad.finish(), OutputError);
  EXPECT_FALSE(fs::exists(root / "certificates" / "demo.one.json"));
  fs::remove_all(root);
}

TEST(Output, ARetiredFileIsRemovedOnlyOnceTheNewOutputsAreInPlace) {
  const fs::path root = fresh_dir("retire");
  fs::create_directories(root / "certificates");
  std::ofstream(root / "certificates" / "demo.old.json") << "{}\n";
  // A failing set keeps the old file: nothing of the run is written, nothing removed.
  std::ofstream(root / "data") << "a regular file where the data folder should be";
  Output bad("demo", root);
  bad.retire(root / "certificates" / "demo.old.json");
  bad.table("", Table({"x"}), "t");
  EXPECT_THROW(bad.finish(), OutputError);
  EXPECT_TRUE(fs::exists(root / "certificates" / "demo.old.json"));
  fs::remove(root / "data");
  Output out("demo", root);
  out.retire(root / "certificates" / "demo.old.json");
  out.certificate("demo.new", "{}\n");
  EXPECT_EQ(out.finish(), 0);
  EXPECT_FALSE(fs::exists(root / "certificates" / "demo.old.json"));
  EXPECT_TRUE(fs::exists(root / "certificates" / "demo.new.json"));
  fs::remove_all(root);
}

TEST(Output, AnExpectedFailureGivesExitStatusOne) {
  const fs::path root = fresh_dir("fail");
  Output out("demo", root);
  out.claim("demo.one", "Lemma 1", EvidenceKind::Sampled, "fails").holds(false);
  EXPECT_EQ(out.finish(), 1);
  fs::remove_all(root);
}

TEST(Output, RejectsAClaimWithoutVerdictBeforeWritingAnything) {
  const fs::path root = fresh_dir("undecided");
  Output out("demo", root);
  out.table("", Table({"x"}), "t");
  out.claim("demo.one", "Lemma 1", EvidenceKind::Sampled, "no verdict");
  EXPECT_THROW(out.finish(), std::logic_error);
  EXPECT_FALSE(fs::exists(root));
}

TEST(Output, RejectsABadPathAndLeavesNothingBehind) {
  const fs::path root = fresh_dir("badpath");
  fs::create_directories(root);
  std::ofstream(root / "data") << "a regular file where the data folder should be";
  Output out("demo", root);
  out.latex("first", "x\n");         // tables/ can be written ...
  out.table("", Table({"x"}), "t");  // ... data/ cannot
  out.claim("demo.one", "Lemma 1", EvidenceKind::Sampled, "s").holds(true);
  try {
    out.finish();
    FAIL() << "no error";
  } catch (const OutputError& e) {
    EXPECT_TRUE(e.bad_path());
  }
  // Nothing was renamed into place and no temporary is left.
  EXPECT_FALSE(fs::exists(root / "tables" / "first.tex"));
  if (fs::exists(root / "tables"))
    for (const auto& e : fs::directory_iterator(root / "tables")) ADD_FAILURE() << "left behind: " << e.path();
  EXPECT_THROW(require_output_root(root / "data"), OutputError);
  fs::remove_all(root);
}

TEST(Output, AFailedWriteLeavesNoPartialOutputSet) {
  // A full disk, simulated by a file-size limit (writes beyond it fail with EFBIG), in a child
  // process: the first file fits, the second does not. Nothing may appear, and no temporary remain.
  const fs::path root = fresh_dir("full");
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    ::signal(SIGXFSZ, SIG_IGN);
    const struct rlimit limit { 4096, 4096 };
    ::setrlimit(RLIMIT_FSIZE, &limit);
    Output out("demo", root);
    out.latex("small", "fits\n");
    out.latex("large", std::string(100000, 'x') + "\n");
    out.claim("demo.one", "Lemma 1", EvidenceKind::Sampled, "s").holds(true);
    try {
      out.finish();
    } catch (const OutputError& e) {
      ::_exit(e.bad_path() ? 3 : 0);  // 0: a failed write, as expected
    }
    ::_exit(4);  // no error at all
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  std::size_t files = 0;
  if (fs::exists(root))
    for (const auto& e : fs::recursive_directory_iterator(root)) files += e.is_regular_file();
  EXPECT_EQ(files, 0u);
  fs::remove_all(root);
}

TEST(Output, ConcurrentRunsUseDistinctTemporaries) {
  const fs::path root = fresh_dir("concurrent");
  // Two writers of the same file: both succeed, the file holds one of the two contents whole.
  Output a("demo", root), b("demo", root);
  a.latex("same", std::string(100000, 'a') + "\n");
  b.latex("same", std::string(100000, 'b') + "\n");
  a.claim("demo.x", "", EvidenceKind::Sampled, "s").holds(true);
  b.claim("demo.x", "", EvidenceKind::Sampled, "s").holds(true);
  int ra = -1, rb = -1;
#pragma omp parallel sections
  {
#pragma omp section
    ra = a.finish();
#pragma omp section
    rb = b.finish();
  }
  EXPECT_EQ(ra, 0);
  EXPECT_EQ(rb, 0);
  const std::string s = read(root / "tables" / "same.tex");
  EXPECT_TRUE(s.find(std::string(100000, 'a')) != std::string::npos || s.find(std::string(100000, 'b')) != std::string::npos);
  fs::remove_all(root);
}

TEST(Grid, AxesGiveTheDocumentedValues) {
  const Axis c = Axis::centres(0, 1, 4);
  EXPECT_EQ(c.values(), (std::vector<double>{0.125, 0.375, 0.625, 0.875}));
  const Axis l = Axis::linear(1, 2, 3);
  EXPECT_EQ(l.values(), (std::vector<double>{1, 1.5, 2}));
  const Axis g = Axis::log(1e-4, 1e-1, 4);
  EXPECT_EQ(g[0], 1e-4);
  EXPECT_NEAR(g[1], 1e-3, 1e-18);
  EXPECT_NEAR(g[3], 1e-1, 1e-16);
  EXPECT_THROW(Axis::linear(0, 1, 1), std::logic_error);
  EXPECT_THROW(Axis::log(0, 1, 3), std::logic_error);
}

TEST(Grid, SweepKeepsTheOrderAndRecordsFailuresPerCell) {
  const auto r = sweep<double>(Axis::linear(0, 1, 5), Axis::linear(0, 2, 3), [](const Cell2& c) {
    if (c.i == 2 && c.j == 1) throw InvalidParameter("x", "a failing cell");
    return 10.0 * c.i + c.j;
  });
  ASSERT_EQ(r.size(), 15u);
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 3; ++j) {
      const auto& cell = r[static_cast<std::size_t>(i * 3 + j)];
      if (i == 2 && j == 1) {
        EXPECT_TRUE(cell.failed);
        EXPECT_NE(cell.error.find("a failing cell"), std::string::npos);
      } else {
        EXPECT_FALSE(cell.failed);
        EXPECT_EQ(cell.value, 10.0 * i + j);
      }
    }
}

TEST(Bisect, FindsTheBoundaryFromEitherSide) {
  const double root = std::sqrt(2.0);
  auto [lo, hi] = bisect([&](double x) { return x * x < 2; }, 0.0, 2.0);
  EXPECT_LT(lo * lo, 2);
  EXPECT_GE(hi * hi, 2);
  EXPECT_LE(hi - lo, 4.5e-16);
  EXPECT_NEAR(lo, root, 4.5e-16);
  // lo on the right of hi: the boundary of "x > sqrt 2"
  auto [lo2, hi2] = bisect([&](double x) { return x * x > 2; }, 2.0, 0.0, BisectStop{200, 1e-6, 0});
  EXPECT_GT(lo2, hi2);
  EXPECT_LE(lo2 - hi2, 1e-6);
  EXPECT_NEAR(lo2, root, 1e-6);
  // the iteration bound: 10 halvings of [0, 2] leave a bracket of 2/1024
  auto [lo3, hi3] = bisect([&](double x) { return x * x < 2; }, 0.0, 2.0, BisectStop{10, 0, 0});
  EXPECT_DOUBLE_EQ(hi3 - lo3, 2.0 / 1024);
  // a predicate without an answer at a point (std::nullopt) ends the search with the bracket so far
  int calls = 0;
  auto [lo4, hi4] = bisect(
      [&](double x) -> std::optional<bool> {
        ++calls;
        if (x > 1.2 && x < 1.3) return std::nullopt;
        return x * x < 2;
      },
      0.0, 2.0);
  EXPECT_EQ(calls, 3);  // midpoints 1 (holds), 1.5 (does not), 1.25 (no answer: the end)
  EXPECT_EQ(lo4, 1.0);
  EXPECT_EQ(hi4, 1.5);
}
