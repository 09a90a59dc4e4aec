# dfchaos — thin front door over CMake. `make help` lists the targets.
# On a fresh Debian 12 machine `make test` and `make reproduce` each do the whole set-up:
# they first install the missing Debian packages (scripts/install-deps.sh).

BUILD   ?= build
JOBS    ?= $(shell nproc 2>/dev/null || echo 2)
BTYPE   ?= RelWithDebInfo
CMAKE   ?= cmake

.PHONY: help deps deps-report configure build test reproduce experiments clean

help:
	@echo "dfchaos make targets:"
	@echo "  make test        install missing packages, build, run every test through CTest"
	@echo "  make reproduce   install missing packages (with LaTeX, gnuplot), build, run every experiment"
	@echo "  make build       configure and build into $(BUILD)/ (binaries in $(BUILD)/bin)"
	@echo "  make deps        install the packages needed to build and test"
	@echo "  make clean       remove $(BUILD)/"
	@echo "Variables: BUILD=$(BUILD) JOBS=$(JOBS) BTYPE=$(BTYPE)"

deps:
	@bash scripts/install-deps.sh build

deps-report:
	@bash scripts/install-deps.sh report

configure:
	@$(CMAKE) -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=$(BTYPE) > $(BUILD).configure.log 2>&1 || { cat $(BUILD).configure.log; exit 1; }
	@rm -f $(BUILD).configure.log

build: deps configure
	@$(CMAKE) --build $(BUILD) -j $(JOBS)

test: build
	@ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

experiments: build
	@bash scripts/run-experiments.sh $(BUILD)

reproduce: deps-report
	@echo "== [1/3] build"
	@$(MAKE) --no-print-directory build
	@echo "== [2/3] experiments"
	@bash scripts/run-experiments.sh $(BUILD)
	@echo "== [3/3] report: not yet part of the pipeline (issue 5)"

clean:
	rm -rf $(BUILD)
