# SPDX-License-Identifier: GPL-3.0-or-later
# dfchaos — thin front door over CMake. `make help` lists the targets.
# On a fresh Debian 12 machine `make test` and `make reproduce` each do the whole set-up:
# they first install the missing Debian packages (scripts/install-deps.sh).
#
# The reproduce pipeline is ordinary make dependencies, so a second run redoes only what changed:
#   build/bin/experiments/X  -> build/stamps/X.ok   (experiment X ran: data/, tables/, claims/)
#   figures/fig_Y.gp + stamps -> build/figures/fig_Y.tex/.pdf   (gnuplot, cairolatex)
#   paper/report.tex + figures + tables -> build/paper/report.pdf   (latexmk tracks its own inputs)

BUILD   ?= build
JOBS    ?= $(shell nproc 2>/dev/null || echo 2)
BTYPE   ?= RelWithDebInfo
CMAKE   ?= cmake
PLANE_N ?= 2000
PLANE_RANKS ?= 2
# Extra ctest arguments of test-sanitize and test-clang (CI passes -LE "slow|crossval": those tiers run in
# `make test`, and three times slower under the sanitizers).
CHECK_CTEST_ARGS ?=
# Extra arguments of the configure step of $(BUILD) (e.g. -DDFCHAOS_DEBUG_INFO=OFF, as .ci/run sets it);
# CMake keeps them in its cache for the later runs.
CMAKE_ARGS ?=
ABS     := $(abspath $(BUILD))

EXPERIMENTS := $(sort $(basename $(notdir $(wildcard experiments/*.cpp))))
FIGURES     := $(sort $(basename $(notdir $(wildcard figures/fig_*.gp))))
STAMPS      := $(EXPERIMENTS:%=$(BUILD)/stamps/%.ok)
FIGS        := $(FIGURES:%=$(BUILD)/figures/%.tex)

.PHONY: help deps deps-report configure build build-tools test reproduce experiments figures report manifest claims-map \
        docs bench bench-snapshot plane-hires clean test-sanitize test-clang check-determinism check-report-extension certify-region certify-region-snapshot certify-band dist format format-check test-tidy

help:
	@echo "dfchaos make targets:"
	@echo "  make reproduce   install missing packages (with LaTeX, gnuplot), build, run every experiment,"
	@echo "                   draw every figure, build $(BUILD)/paper/report.pdf (reruns only what changed)"
	@echo "  make test        install missing packages, build, run every test through CTest"
	@echo "  make build       configure and build into $(BUILD)/ (binaries in $(BUILD)/bin, the Python module in $(BUILD)/python)"
	@echo "  make experiments run the experiments whose executables changed (data, tables, claims)"
	@echo "  make figures     draw the figures from $(BUILD)/data into $(BUILD)/figures"
	@echo "  make report      typeset $(BUILD)/paper/report.pdf from what is already computed"
	@echo "  make claims-map  the claims map (paper item -> experiment -> claims -> figures -> tests): $(BUILD)/claims-map.md"
	@echo "  make manifest    write $(BUILD)/MANIFEST.sha256 over data and tables"
	@echo "  make docs        Doxygen HTML of the library and experiments in $(BUILD)/docs"
	@echo "  make bench       T per second vs the GSL odeiv2 baseline, the plane's cost, 1- vs 2-rank sweep:"
	@echo "                   $(BUILD)/bench/bench.json, bench.tex; time per certified proof: bench_certified.json, .tex"
	@echo "  make bench-snapshot  make bench, then copy its table with its date into paper/bench-snapshot.tex"
	@echo "  make certify-region  Theorem 1 proved over area across the plane (b/a 1e-6..0.02), through the sweep"
	@echo "                   engine (MPI, resumable): $(BUILD)/region/ (measured time: docs/cluster.md)"
	@echo "  make certify-region-snapshot  copy the summary of make certify-region into paper/certify-region-snapshot.tex"
	@echo "  make certify-band  Lemma 4 over parameter boxes with certificates on a band (CERT_BAND=...)"
	@echo "  make plane-hires the (q/a, b/a) plane at $(PLANE_N) x $(PLANE_N), every observable, MPI on $(PLANE_RANKS) ranks"
	@echo "                   when built: $(BUILD)/plane/ (hours: docs/cluster.md; rerun to resume)"
	@echo "  make test-sanitize  build with ASan+UBSan in $(BUILD)-sanitize and run every test"
	@echo "  make test-clang  build warning-free with clang++ in $(BUILD)-clang and run every test"
	@echo "  make format      reformat every tracked C++ file with .clang-format (clang-format 14)"
	@echo "  make format-check  fail, naming the files, when clang-format would change a tracked C++ file"
	@echo "  make test-tidy   clang-tidy 14 with .clang-tidy on the library and the dfchaos tool (compile commands"
	@echo "                   of $(BUILD)-tidy, configured only): fail on any warning"
	@echo "  make check-determinism  rerun every experiment on 1 thread (and on 2 unless make reproduce ran on 2+):"
	@echo "                   manifests must match each other and the last make reproduce"
	@echo "  make dist        $(BUILD)/dist/dfchaos-<version>.tar.gz, a git archive of HEAD (refused while tracked files"
	@echo "                   have uncommitted changes), and dfchaos-<version>-report.pdf if make reproduce built the"
	@echo "                   report from HEAD (dist does not run it: run make reproduce first)"
	@echo "  make deps        install the packages needed to build and test"
	@echo "  make clean       remove $(BUILD)/"
	@echo "Variables: BUILD=$(BUILD) JOBS=$(JOBS) BTYPE=$(BTYPE) PLANE_N=$(PLANE_N) PLANE_RANKS=$(PLANE_RANKS)"

deps:
	@bash scripts/install-deps.sh build

deps-report:
	@bash scripts/install-deps.sh report

# A build directory copied from another clone (or left by a moved one) names other sources in its
# CMakeCache.txt, and CMake's own error does not say what to do: say it.
configure:
	@mkdir -p $(BUILD)
	@home=$$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' $(BUILD)/CMakeCache.txt 2>/dev/null); \
	if [ -n "$$home" ] && [ "$$(cd "$$home" 2>/dev/null && pwd -P)" != "$$(pwd -P)" ]; then \
	  echo "configure: $(BUILD)/ was configured for the sources in $$home, not these ($$(pwd -P)): remove it (rm -rf $(BUILD)) and run make again, or choose another directory (make BUILD=dir ...)" >&2; \
	  exit 2; fi
	@$(CMAKE) -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=$(BTYPE) $(CMAKE_ARGS) > $(BUILD)/configure.log 2>&1 || { cat $(BUILD)/configure.log; exit 1; }

build: deps configure
	@$(CMAKE) --build $(BUILD) -j $(JOBS)

# Only what the reproduction needs: the library, the dfchaos tool and the experiments.
build-tools: deps configure
	@$(CMAKE) --build $(BUILD) -j $(JOBS) --target reproduce_tools

test: build
	@ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

# ---- the reproduce pipeline -------------------------------------------------------------

# The report states how long this run took up to its typesetting (scripts/build-report.sh reads the
# start time; the file goes when the run ends, so that a later `make report` claims no time).
reproduce: deps-report
	@mkdir -p $(BUILD)/stamps && date +%s > $(BUILD)/stamps/reproduce-started
	@echo "== [1/5] build (library, dfchaos tool, experiments)"
	@$(MAKE) --no-print-directory build-tools
	@echo "== [2/5] experiments ($(words $(EXPERIMENTS)); only those whose executable changed)"
	@$(MAKE) --no-print-directory -j 2 --output-sync=target experiments
	@echo "== [3/5] figures ($(words $(FIGURES)))"
	@$(MAKE) --no-print-directory figures
	@echo "== [4/5] report"
	@$(MAKE) --no-print-directory report
	@echo "== [5/5] manifest"
	@$(MAKE) --no-print-directory manifest
	@rm -f $(BUILD)/stamps/reproduce-started
	@echo "reproduce: done; read $(BUILD)/paper/report.pdf"

experiments: $(STAMPS)

$(BUILD)/stamps/%.ok: $(BUILD)/bin/experiments/%
	@mkdir -p $(@D)
	@echo "-- experiment $*"
	@$< --out $(BUILD)
	@touch $@

figures: $(FIGS)

$(BUILD)/figures/%.tex: figures/%.gp figures/style.gp $(STAMPS)
	@mkdir -p $(@D)
	@echo "-- figure $*"
	@cd $(@D) && gnuplot -e "data='$(ABS)/data'; figdir='$(CURDIR)/figures'" $(CURDIR)/$< 2> $*.log \
	  || { cat $*.log; rm -f $*.tex $*.pdf; exit 1; }
	@if [ -s $(@D)/$*.log ]; then echo "figure $*: gnuplot warned:"; cat $(@D)/$*.log; rm -f $@; exit 1; fi

$(BUILD)/tables/build-info.tex: $(BUILD)/bin/dfchaos
	@mkdir -p $(@D)
	@$< provenance --latex > $@.tmp && mv $@.tmp $@

# Every certificate the experiments wrote, re-checked by the independent checker (a rejection fails
# the reproduction); the report's table of certified claims with their certificates' SHA-256.
$(BUILD)/tables/certificates.tex: $(STAMPS) $(BUILD)/bin/dfchaos-recheck scripts/recheck_certificates.py
	@python3 scripts/recheck_certificates.py $(BUILD) $(BUILD)/bin/dfchaos-recheck

# REPORT_LIMITS=warn: the report's page limits warn instead of failing (an extension of the report,
# docs/adding-an-experiment.md); strict, the default, is what CI checks.
REPORT_LIMITS ?= strict
report: $(FIGS) $(BUILD)/tables/build-info.tex $(BUILD)/tables/certificates.tex $(wildcard $(BUILD)/bench/bench.tex)
	@DFCHAOS_REPORT_LIMITS=$(REPORT_LIMITS) bash scripts/build-report.sh $(BUILD)

claims-map: $(STAMPS)
	@python3 scripts/claims_map.py $(BUILD) .

manifest:
	@cd $(BUILD) && find data tables $$(test -d certificates && echo certificates) -type f ! -name '*.tmp*' | LC_ALL=C sort | xargs sha256sum > MANIFEST.sha256
	@echo "manifest: $(BUILD)/MANIFEST.sha256 ($$(wc -l < $(BUILD)/MANIFEST.sha256) files)"

docs: deps-report configure
	@bash scripts/build-docs.sh $(BUILD)

bench: deps configure
	@$(CMAKE) --build $(BUILD) -j $(JOBS) --target bench_return_map bench_certified
	@$(BUILD)/bin/bench_return_map --out=$(BUILD)
	@$(BUILD)/bin/bench_certified --out=$(BUILD)
	@printf '\\def\\dfcBenchWhen{%s, %s cores, %s}\n' "$$(date -u +%F)" "$$(nproc)" \
	  "$$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1 | sed 's/[\\&%$$#_{}~^]/ /g')" > $(BUILD)/bench/bench-when.tex

# The report's Performance section shows build/bench/bench.tex when `make bench` ran in this build,
# else the last committed measurement, paper/bench-snapshot.tex (with its date); this refreshes it.
bench-snapshot: bench
	@{ echo "% SPDX-License-Identifier: GPL-3.0-or-later"; \
	   echo "% written by make bench-snapshot from $(BUILD)/bench; do not edit"; \
	   sed 's/dfcBenchWhen/dfcBenchSnapshotWhen/' $(BUILD)/bench/bench-when.tex; \
	   grep -v '^%' $(BUILD)/bench/bench.tex; } > paper/bench-snapshot.tex.tmp && mv paper/bench-snapshot.tex.tmp paper/bench-snapshot.tex
	@echo "bench-snapshot: paper/bench-snapshot.tex (commit it)"

# Theorem 1's covering proved over area across the plane (q/a in [0.76, 0.99], b/a from 1e-6 to
# 0.02), through the sweep engine (`--observables covering,region`, MPI when built, resumable):
# $(BUILD)/region/region.tsv and its summary $(BUILD)/region/certify-region.tex, which the report
# reads (else the committed paper/certify-region-snapshot.tex). Measured time: docs/cluster.md.
# REGION_Q and REGION_B override the axes; REGION_RANKS the MPI ranks.
REGION_RANKS ?= 2
certify-region: deps configure
	@$(CMAKE) --build $(BUILD) -j $(JOBS) --target dfchaos_cli $$(grep -q '^DFCHAOS_MPI:BOOL=ON' $(BUILD)/CMakeCache.txt && echo dfchaos_sweep_mpi)
	@bash scripts/certify-region.sh $(BUILD) $(REGION_RANKS)

certify-region-snapshot:
	@test -f $(BUILD)/region/certify-region.tex || { echo "certify-region-snapshot: no $(BUILD)/region/certify-region.tex: run make certify-region first" >&2; exit 2; }
	@{ echo "% SPDX-License-Identifier: GPL-3.0-or-later"; \
	   echo "% written by make certify-region-snapshot from $(BUILD)/region; do not edit"; \
	   grep -v '^%' $(BUILD)/region/certify-region.tex; } > paper/certify-region-snapshot.tex.tmp && \
	  mv paper/certify-region-snapshot.tex.tmp paper/certify-region-snapshot.tex
	@echo "certify-region-snapshot: paper/certify-region-snapshot.tex (commit it)"

# Lemma 4 over boxes of (b/a, q/a) with a certificate per column, on a band larger than `make
# reproduce` certifies (the experiment certified_region; its default is a thin strip that fits the
# reproduce budget). Rewrites $(BUILD)/data/certified_region*.tsv; `make report` then shows this band.
# Measured time: docs/certified.md. Override the band with CERT_BAND="--b-lo ... --b-hi ... --max-boxes ...".
CERT_BAND ?= --b-lo 1.5e-3 --b-hi 2e-3 --q-lo 0.76 --q-hi 0.99 --columns 23 --max-boxes 200000
certify-band: build-tools
	@mkdir -p $(BUILD)/stamps
	@$(BUILD)/bin/experiments/certified_region --out $(BUILD) $(CERT_BAND)
	@touch $(BUILD)/stamps/certified_region.ok

# The high-resolution plane: resumable, so a second `make plane-hires` continues.
plane-hires: deps configure
	@$(CMAKE) --build $(BUILD) -j $(JOBS) --target dfchaos_cli $$(grep -q '^DFCHAOS_MPI:BOOL=ON' $(BUILD)/CMakeCache.txt && echo dfchaos_sweep_mpi)
	@bash scripts/plane-hires.sh $(BUILD) $(PLANE_N) $(PLANE_RANKS)

# ---- reliability checks ----------------------------------------------------------------------

# The sanitizer build leaves out the benchmarks (timings, not behaviour; `make bench` runs them and
# test-clang compiles them) and compiles at -O1 -g1 (the optimisation AddressSanitizer's authors
# advise; line tables for its reports): on 2 cores 590 s instead of about 1300 s at -O2 -g, with the
# same 264 tests in the same 380 s (measured). SANITIZE_CXX chooses the compiler (empty: CMake's
# default, g++): CI builds it with clang++ (warnings are errors there too), so that one build checks
# both the sanitizers and clang's diagnostics, and `make test-clang` is left to developers.
SANITIZE_CXX ?=
SANITIZE_BUILD = $(BUILD)-sanitize$(if $(SANITIZE_CXX),-$(notdir $(SANITIZE_CXX)))
test-sanitize: deps
	@$(if $(SANITIZE_CXX),bash scripts/install-deps.sh check)
	@$(if $(SANITIZE_CXX),CXX=$(SANITIZE_CXX)) $(CMAKE) -S . -B $(SANITIZE_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
	  "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" -DDFCHAOS_SANITIZE=ON -DDFCHAOS_BUILD_BENCH=OFF > /dev/null
	@$(CMAKE) --build $(SANITIZE_BUILD) -j $(JOBS)
	@ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  ctest --test-dir $(SANITIZE_BUILD) --output-on-failure -j $(JOBS) $(CHECK_CTEST_ARGS)

test-clang:
	@bash scripts/install-deps.sh check
	@CXX=clang++ $(CMAKE) -S . -B $(BUILD)-clang -DCMAKE_BUILD_TYPE=RelWithDebInfo > /dev/null
	@$(CMAKE) --build $(BUILD)-clang -j $(JOBS)
	@ctest --test-dir $(BUILD)-clang --output-on-failure -j $(JOBS) $(CHECK_CTEST_ARGS)

# The tracked C++ sources, formatted by .clang-format (format) or checked against it (format-check).
CXX_SOURCES = $(shell git ls-files '*.cpp' '*.hpp' '*.h' 2>/dev/null)

format:
	@bash scripts/install-deps.sh check
	@clang-format -i $(CXX_SOURCES)

format-check:
	@bash scripts/install-deps.sh check
	@bad=$$(for f in $(CXX_SOURCES); do clang-format --dry-run --Werror "$$f" > /dev/null 2>&1 || echo "$$f"; done); \
	if [ -n "$$bad" ]; then echo "format-check: clang-format would change these files (make format):"; echo "$$bad"; exit 1; fi; \
	echo "format-check: $(words $(CXX_SOURCES)) C++ files are as .clang-format writes them"

# Static analysis: clang-tidy 14 with .clang-tidy on the sources of TIDY_DIRS, the library and the
# dfchaos tool (the experiments, tests, benchmarks and Python bindings are not analysed: they add
# time to CI and none of them is used by another program). The compile commands come from
# $(BUILD)-tidy, which is configured and not built: no file the analysis reads is generated. Every
# warning is an error (.clang-tidy); the log is $(BUILD)-tidy/tidy.log.
TIDY_DIRS  = src/dfchaos src/certify src/kit src/sweep src/recheck src/mpi src/cli
TIDY_REGEX = $(CURDIR)/($(subst $(eval) ,|,$(TIDY_DIRS)))/

test-tidy:
	@bash scripts/install-deps.sh check
	@mkdir -p $(BUILD)-tidy
	@$(CMAKE) -S . -B $(BUILD)-tidy -DCMAKE_BUILD_TYPE=$(BTYPE) -DCMAKE_EXPORT_COMPILE_COMMANDS=ON -DDFCHAOS_UNITY_BUILD=OFF > $(BUILD)-tidy/configure.log 2>&1 \
	  || { cat $(BUILD)-tidy/configure.log; exit 1; }
	@start=$$(date +%s); \
	files=$$(grep -cE '"file": "$(TIDY_REGEX)' $(BUILD)-tidy/compile_commands.json); \
	run-clang-tidy -p $(BUILD)-tidy -j $(JOBS) -quiet '$(TIDY_REGEX)' > $(BUILD)-tidy/tidy.log 2>&1; status=$$?; \
	sed -i 's/\x1b\[[0-9;]*m//g' $(BUILD)-tidy/tidy.log; \
	found=$$(grep -E '^/.*: (warning|error): ' $(BUILD)-tidy/tidy.log | sort -u | wc -l); \
	if [ $$status -ne 0 ] || [ $$found -ne 0 ]; then \
	  grep -v -e '^clang-tidy' -e 'warnings\? generated\.$$' $(BUILD)-tidy/tidy.log; \
	  echo "test-tidy: $$found warning(s) in $$files files (CONTRIBUTING.md says what to do with one)"; exit 1; fi; \
	echo "test-tidy: $$files files of the library and the dfchaos tool, no warning, in $$(( $$(date +%s) - start )) s"

# After make reproduce: an extension of the report (a throwaway section and figure, three pages more)
# fails the page limits by default and passes with REPORT_LIMITS=warn (scripts/check-report-extension.sh).
check-report-extension:
	@bash scripts/check-report-extension.sh $(BUILD)

check-determinism: build-tools
	@bash scripts/check-determinism.sh $(BUILD)

# ---- release ----------------------------------------------------------------------------------

# A source archive of HEAD named with the version of CMakeLists.txt's project(), and the report when it
# was built from HEAD (scripts/dist.sh). Cheap: it builds nothing and does not run make reproduce.
dist:
	@bash scripts/dist.sh $(BUILD)

clean:
	rm -rf $(BUILD) $(BUILD)-sanitize $(BUILD)-sanitize-clang++ $(BUILD)-clang $(BUILD)-tidy
