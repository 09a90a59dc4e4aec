// SPDX-License-Identifier: GPL-3.0-or-later
#include "sweep/options.hpp"

#include "dfchaos/errors.hpp"
#include "dfchaos/units.hpp"
#include "kit/format.hpp"
#include "kit/options.hpp"
#include "sweep/cell.hpp"
#include "sweep/header.hpp"
#include "sweep/observables.hpp"

namespace dfchaos::sweep {

namespace {
long long count(const std::string& name, const std::string& text, long long lo, long long hi) { return kit::parse_count(name, text, lo, hi); }
}  // namespace

void SweepArguments::add_to(CLI::App* app) {
  app->add_option("-a,--a", a,
                  "forcing amplitude, " + format_shortest(kMinA) + " <= a <= " + format_shortest(kMaxA) +
                      ", and a*(q/a), a*(b/a) in the same range at every cell (default 1; only q/a and b/a matter)")
      ->type_name("FLOAT");
  app->add_option("--physical", physical,
                  "instead of --a: a drilling model in physical units, MASS (kg), OMEGA the forcing's angular frequency (rad/s),\n"
                  "AMPLITUDE of the harmonic force (N); a = AMPLITUDE/(MASS OMEGA^2) m. The axes stay q/a = FRICTION/AMPLITUDE and\n"
                  "b/a = STATIC/(2 AMPLITUDE); rate becomes rate_m_per_s, and friction_N, static_N are added (docs/units.md)")
      ->expected(3)
      ->type_name("MASS OMEGA AMPLITUDE")
      ->excludes("--a");
  app->add_option("--q-range", q_range, "q/a axis lo:hi:n[:lin|log|mid] (every q/a > 0)")->required()->type_name("LO:HI:N[:KIND]");
  app->add_option("--b-range", b_range, "b/a axis lo:hi:n[:lin|log|mid] (every b/a in [" + format_shortest(kMinMapRatio) + ", 1/2))")
      ->required()
      ->type_name("LO:HI:N[:KIND]");
  app->add_option("--observables", observables,
                  "comma-separated: " + observable_names(",") +
                      "\n"
                      "(default " +
                      std::string(kDefaultObservables) + ": all but certified, region and entropy, proofs per cell)")
      ->type_name("LIST");
  app->add_option("--max-branches", max_branches,
                  "covering's work budget per cell: a cell whose [t2, 3pi/2] holds more branches of T1\n"
                  "(about 0.16 a/b) is an error cell naming it (certified: more than N/" +
                      std::to_string(kDenseCostFactor) + "), 1.." + std::to_string(kMaxCoveringBranches) + " (default " +
                      std::to_string(kDefaultMaxCoveringBranches) + ")")
      ->type_name("N");
  app->add_option("--superstable-scan", superstable_scan,
                  "scan of superstable_check, " + std::to_string(kMinSuperstableScan) + ".." + std::to_string(kMaxSuperstableScan) + " (default 400)")
      ->type_name("N");
  app->add_option("--theta0-fraction", theta0, "orbit start as a fraction f in [0, 1) of the arc: theta_0 = t2 + f (t3 - t2) (default 0.5)")
      ->type_name("F");
  // --theta0 is a phase everywhere else (orbit, Python): here it is refused with the option to use.
  app->add_option("--theta0", old_theta0)->group("");
  app->add_option("--transient", transient,
                  "orbit steps discarded, 0 <= N <= " + format_shortest(static_cast<double>(kMaxTransient)) + " (default 1000)")
      ->type_name("N");
  app->add_option("--steps", steps,
                  "orbit steps averaged, 1 <= N <= " + format_shortest(static_cast<double>(kMaxSteps)) + " (as orbit --steps; default 1000)")
      ->type_name("N");
  app->add_option("--period-max", period_max, "largest period searched, 1.." + std::to_string(kMaxPeriod) + " (default 64)")->type_name("K");
  app->add_option("--period-tol", period_tol, "closing tolerance of a cycle on the circle, 1e-15..1e-3 (default 1e-9)")->type_name("TOL");
  app->add_option("--region-max-boxes", region_max_boxes,
                  "region: box proofs per cell above the uniform bound, 1.." + format_shortest(static_cast<double>(kMaxRegionBoxes)) + " (default " +
                      std::to_string(kDefaultRegionBoxes) + ")")
      ->type_name("N");
  app->add_option("--max-proofs", max_proofs,
                  "certified and region: most proofs of the whole sweep, cells * (1 for certified + region-max-boxes for region),\n"
                  "refused above it before any work, 1.." +
                      format_shortest(static_cast<double>(kMaxMaxProofs)) + " (default " + format_shortest(static_cast<double>(kDefaultMaxProofs)) +
                      ")")
      ->type_name("N");
  app->add_option("--shard", shard, "compute only shard i of N: the cells with index mod N = i (0 <= i < N)")->type_name("i/N");
  auto* o = app->add_option("--out", out, "write to FILE (atomically) instead of stdout")->type_name("FILE");
  auto* r = app->add_option("--resume", resume, "write to FILE, keeping finished chunks in FILE.chunks/; rerun to continue an interrupted run")
                ->type_name("FILE");
  o->excludes(r);
  app->add_option("--chunk", chunk,
                  "cells per chunk (the unit of --resume), 1.." + std::to_string(kMaxChunk) + " (default " + std::to_string(kDefaultChunk) + ")")
      ->type_name("N");
  app->add_option("--max-chunks", max_chunks, "with --resume: stop after N new chunks, exit status 3 (0: no limit)")->type_name("N");
  app->add_flag("--progress", progress, "progress on stderr even when it is not a terminal");
  app->footer(
      "Output (TSV, stdout unless --out/--resume): the column names, then '#' header lines (title; dfchaos version, git hash,\n"
      "compiler; the spec as 'key = value'; shard files last '# shard = i/N'), then one row per cell in increasing index\n"
      "(index = i*n_b + j, i over q/a, j over b/a), numbers in %.17g. One call reads it with its names:\n" +
      std::string(kit::kLoadInPython) +
      ".\nThe columns:\n"
      "  index, q_over_a, b_over_a   the cell\n"
      "  status       ok | inadmissible (q/a <= 2 b/a) | error (an observable threw; its values nan)\n"
      "  covering     Lemma 4 / Theorem 1: two disjoint covering segments found (1) or not (0)\n"
      "  superstable  Theorem 2: T(t2) = t2 with superstable width epsilon > 0 (1) or not (0); then epsilon\n"
      "  lyapunov     mean ln|T'| over the averaged steps of the orbit (-inf when a step stops)\n"
      "  rate         mean drilling speed over those steps (delimiter advance / elapsed time); rate_m_per_s with --physical\n"
      "  friction_N, static_N   with --physical only: the cell's forces Q = (q/a) AMPLITUDE and P = 2 (b/a) AMPLITUDE\n"
      "  period       smallest k <= period-max with |T^k(e) - e| <= period-tol, e = T^(transient+steps)(theta_0); 0 if none\n"
      "  certified    Lemma 4 proved in ball arithmetic (Arb) at the cell's double parameters (1) or not proved (0):\n"
      "               a proof at that point, not over the cell (as 'dfchaos certify covering'); then certified_step,\n"
      "               the code of the step not proved: " +
      certified_step_legend() +
      "\n"
      "  region       Lemma 4 proved for every parameter of the cell's rectangle (from its point to the next one on each\n"
      "               axis; mid: its part of the range): the proved fraction of its b/a length; then region_uniform (the\n"
      "               b/a bound of Lemma 4 for every small b/a on its q/a range, 0 if none), region_boxes (parameter boxes\n"
      "               tried above it) and region_stop: " +
      region_stop_legend() +
      "\n"
      "  error        'observable: message' for each observable that threw, '-' if none\n"
      "The last line is the seal '# end: N rows, sha256 HEX (of every byte above this line)': sweep-merge and --resume\n"
      "refuse a file without it (cut short) or whose bytes or rows do not match it (damaged). --out follows a symlink and\n"
      "refuses a directory, device or FIFO; SIGINT/SIGTERM/SIGHUP leave no temporary (docs/reliability.md).\n"
      "Progress with an estimate of the time left goes to stderr (on a terminal, or with --progress).\n"
      "Exit status: 0 done, 1 writing failed, 2 bad input, 3 stopped by --max-chunks (rerun to continue).\n"
      "Threads: OMP_NUM_THREADS. The rows do not depend on the thread, shard or rank count.");
}

RunOptions SweepArguments::resolve() const {
  RunOptions r;
  Spec& s = r.spec;
  if (physical.empty()) {
    s.a = kit::parse_number("a", a, false);
  } else {
    s.physical = {.mass = kit::parse_number("mass", physical[0], false),
                  .omega = kit::parse_number("omega", physical[1], false),
                  .amplitude = kit::parse_number("amplitude", physical[2], false)};
    s.a = length_scale(s.physical.mass, s.physical.omega, s.physical.amplitude);
  }
  s.q_over_a = Range::parse("q-range", q_range);
  s.b_over_a = Range::parse("b-range", b_range);
  s.observables = ObservableSet::parse("observables", observables);
  s.superstable_scan = count("superstable-scan", superstable_scan, kMinSuperstableScan, kMaxSuperstableScan);
  s.covering_max_branches = count("max-branches", max_branches, 1, kMaxCoveringBranches);
  if (!old_theta0.empty())
    throw InvalidParameter("theta0", "a sweep starts each orbit at a fraction of [t2, t3): use --theta0-fraction F (--theta0 is a phase, in orbit)");
  s.orbit.theta0_fraction = kit::parse_number("theta0-fraction", theta0, false);
  s.orbit.transient = count("transient", transient, 0, kMaxTransient);
  s.orbit.steps = count("steps", steps, 1, kMaxSteps);
  s.period.max = count("period-max", period_max, 1, kMaxPeriod);
  s.period.tol = kit::parse_number("period-tol", period_tol, false);
  s.region_max_boxes = count("region-max-boxes", region_max_boxes, 1, kMaxRegionBoxes);
  s.max_proofs = count("max-proofs", max_proofs, 1, kMaxMaxProofs);
  s.validate();
  if (!shard.empty()) r.shard = Shard::parse("shard", shard, s.cells());
  r.out = out;
  r.resume = resume;
  r.chunk = count("chunk", chunk, 1, kMaxChunk);
  r.max_chunks = count("max-chunks", max_chunks, 0, kMaxChunks);
  r.progress = progress;
  return r;
}

}  // namespace dfchaos::sweep
