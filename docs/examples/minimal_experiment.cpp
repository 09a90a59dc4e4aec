// SPDX-License-Identifier: GPL-3.0-or-later
/// @file minimal_experiment.cpp
/// @brief The worked example of docs/adding-an-experiment.md: a complete experiment in one file.
/// It checks a fact the paper uses without comment (Section 2): dividing x by a leaves the motion
/// unchanged, so T depends on b/a and q/a only. Built and run by the test package_downstream,
/// copied under another name.
#include <algorithm>
#include <cmath>

#include "dfchaos/phase.hpp"
#include "dfchaos/return_map.hpp"
#include "kit/experiment.hpp"

using namespace dfchaos;
using namespace dfchaos::kit;

// 1. The declaration: everything the build, --help, --describe, the bad-input tests and the claims
//    maps need to know. The name of the experiment is the name of this file.
const Experiment experiment{.title = "scale invariance: T depends on b/a and q/a only",
                            .paper = {"Section 2"},
                            .tests = {"test_parameters"},
                            .options = {count("n", 200, "phases of [t2, t3) checked per scale").range(1, 100000).fast_value(20),
                                        real("b", 0.01, "b/a").range(1e-6, 0.2), real("q", 0.85, "q/a").range(0.5, 0.99)},
                            .outputs = {data("", "T at a = 1 and at a = 1000 on a grid of phases")},
                            // 2. The body: compute, write a table, state a claim with its kind of evidence and its verdict.
                            .body = [](Run& run) {
                              const int n = run.count_int("n");
                              const double ba = run.real("b"), qa = run.real("q");
                              const Parameters unit(1.0, ba, qa), large(1000.0, 1000.0 * ba, 1000.0 * qa);
                              Table t({"theta", "T_a1", "T_a1000"});
                              double worst = 0;
                              for (int i = 0; i < n; ++i) {
                                const double th = *unit.t2() + (*unit.t3() - *unit.t2()) * (i + 0.5) / n;
                                const double x = T(unit, th), y = T(large, std::min(std::max(th, *large.t2()), std::nextafter(*large.t3(), 0.0)));
                                t.row({th, x, y});
                                worst = std::max(worst, circle_distance(x, y));
                              }
                              run.table("", t);
                              run.out
                                  .claim("example.scale_invariance", "Section 2", EvidenceKind::Sampled,
                                         "Multiplying a, b and q by 1000 changes T by at most {tol} on the grid.")
                                  .ours()
                                  .at_most("max_difference", worst, 1e-9);
                              run.out.macro("ExampleWorst", worst, 2);
                            }};

// 3. main(): parsing, checks, provenance and the all-or-nothing write come from the kit.
DFCHAOS_EXPERIMENT_MAIN(experiment)
