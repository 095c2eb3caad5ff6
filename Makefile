# cyclecert — the only set-up a newcomer needs:
#   make run    bootstrap (as root: missing Debian packages), build, check + fuzz the built-in engines,
#               report in build/report/index.html
#   make test   bootstrap, build, run every test through CTest
#   make build  configure into build/ and build (the CLI lands at build/cyclecert)
#   make fuzz   libFuzzer on cyclecert's own readers (clang, ASan + UBSan; tests/fuzz/README.md),
#               FUZZ_SECONDS per target (default 60), new inputs merged into tests/fuzz/corpus/
BUILD      ?= build
BUILD_TYPE ?= RelWithDebInfo
JOBS       ?= $(shell nproc 2>/dev/null || echo 2)
DEB_PACKAGES := librapidcheck-dev libgtest-dev nlohmann-json3-dev libboost-dev libbenchmark-dev libgoogle-perftools-dev libssl-dev cmake g++ make git python3 python3-jsonschema libxml2-utils
# Only the tests need a browser (they open the HTML report in headless Chromium); `make run` does not.
TEST_DEB_PACKAGES := chromium
# The sanitizer build and the fuzz targets are clang's (libFuzzer is part of its runtime).
FUZZ_DEB_PACKAGES := clang libclang-rt-14-dev
FUZZ_BUILD   ?= $(BUILD)-fuzz
FUZZ_SECONDS ?= 60
SMOKE_SECONDS ?= 15
FUZZ_TARGETS := gcode-read siemens-read plan spec-case toolpath-json process-reply results linuxcnc-canon

.PHONY: all bootstrap bootstrap-test bootstrap-fuzz configure build rs274 test run bench sanitize fuzz fuzz-build fuzz-smoke clean

all: build

# Installs only what is missing, and only when we are root (otherwise explains what to install).
bootstrap:
	@missing=""; for p in $(DEB_PACKAGES); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = 0 ]; then \
	    echo "bootstrap: installing$$missing"; \
	    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing; \
	  else \
	    echo "bootstrap: missing Debian packages:$$missing (run as root, or: sudo apt-get install$$missing)"; exit 1; \
	  fi; \
	fi

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE)

configure: bootstrap $(BUILD)/CMakeCache.txt

build: configure
	cmake --build $(BUILD) -j $(JOBS)

# LinuxCNC's rs274 as an engine under test, taken from Debian's archive into $(BUILD)/linuxcnc
# (not installed: the full package pulls a real-time kernel). Optional: without it the linuxcnc
# engine reports every case as an engine failure and its end-to-end tests are skipped.
rs274: configure
	@harness/engines/linuxcnc/fetch-rs274.sh $(BUILD) || echo "note: LinuxCNC's rs274 is not available; the linuxcnc engine is off"

bootstrap-test: bootstrap
	@$(MAKE) --no-print-directory bootstrap DEB_PACKAGES="$(TEST_DEB_PACKAGES)"

bootstrap-fuzz: bootstrap
	@$(MAKE) --no-print-directory bootstrap DEB_PACKAGES="$(FUZZ_DEB_PACKAGES)"

test: build rs274 bootstrap-test
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# The main job (tools/main-job.sh): check + a 30-second fuzz against reference and linuxcnc, one
# report in $(BUILD)/report/. Findings in an engine are the product working: exit 0 when it completed.
run: build rs274
	@./tools/main-job.sh $(BUILD)

bench: build
	$(BUILD)/cyclecert-bench --benchmark_min_time=0.2

# Address + undefined-behaviour sanitizer build of the whole test suite, with clang (also run by
# .ci/run): the libraries carry libFuzzer's coverage (-fsanitize=fuzzer-no-link) so that the same
# build gives the fuzz targets, each then run for a short smoke from its checked-in corpus.
sanitize: bootstrap bootstrap-fuzz
	CC=clang CXX=clang++ cmake -S . -B $(BUILD)-asan -DCMAKE_BUILD_TYPE=Debug -DCYCLECERT_LIBFUZZER=ON -DCYCLECERT_BENCH=OFF
	cmake --build $(BUILD)-asan -j $(JOBS)
	cd $(BUILD)-asan && ctest --output-on-failure -j $(JOBS)
	@$(MAKE) --no-print-directory fuzz-smoke FUZZ_BUILD=$(BUILD)-asan

# Each fuzz target SMOKE_SECONDS from a copy of its corpus (nothing written back); fails on a finding.
fuzz-smoke:
	tools/fuzz-run.sh --smoke $(FUZZ_BUILD) $(SMOKE_SECONDS) $(FUZZ_TARGETS)

# The fuzz targets only, optimised (RelWithDebInfo) for a campaign.
fuzz-build: bootstrap-fuzz
	CC=clang CXX=clang++ cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCYCLECERT_LIBFUZZER=ON -DCYCLECERT_BENCH=OFF
	cmake --build $(FUZZ_BUILD) -j $(JOBS) --target cyclecert-fuzz

# A campaign: each target FUZZ_SECONDS, its new inputs merged back, minimised, into its corpus.
fuzz: fuzz-build
	tools/fuzz-run.sh --merge $(FUZZ_BUILD) $(FUZZ_SECONDS) $(FUZZ_TARGETS)

clean:
	rm -rf $(BUILD) $(BUILD)-asan $(FUZZ_BUILD)
