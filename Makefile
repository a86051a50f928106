# HSM Planner. Two commands matter (README): `make demo` runs the main job, `make test` runs every test.
# Each target installs the Debian packages it misses, rebuilds what is stale and links the workbench.
#
# Two FreeCADs from one checkout: FREECAD=1.1 (the default; Debian forky: Qt 6, Python 3.14, OCCT 7.9) and
# FREECAD=1.0 (Debian 13: Qt 5, Python 3.13, OCCT 7.8). Each target runs where that FreeCAD is: natively on that
# Debian, else in a root of it that scripts/freecad-env.sh makes and keeps (the repository and ../shared seen
# at the same paths). `make test` without FREECAD tests both, one after the other.
FREECAD_VERSIONS := 1.0 1.1
ifeq ($(origin FREECAD),undefined)
FREECAD := 1.1
FREECAD_CHOSEN :=
else
FREECAD_CHOSEN := yes
endif
ifeq ($(filter $(FREECAD),$(FREECAD_VERSIONS)),)
$(error FREECAD=$(FREECAD) is not supported: use FREECAD=1.1 (Debian forky) or FREECAD=1.0 (Debian 13))
endif

ifeq ($(FREECAD_CHOSEN)$(filter test,$(MAKECMDGOALS)),test)
# `make test`: every level on each FreeCAD (the other goals given with it on the default one)
.PHONY: test $(filter-out test,$(MAKECMDGOALS))
test:
	@scripts/test-versions.sh $(FREECAD_VERSIONS)
$(filter-out test,$(MAKECMDGOALS)):
	@$(MAKE) --no-print-directory FREECAD=$(FREECAD) $@
else ifeq ($(shell scripts/freecad-env.sh $(FREECAD) needed),yes)
.DEFAULT_GOAL := all
.PHONY: all $(MAKECMDGOALS)
all $(MAKECMDGOALS):
	@scripts/freecad-env.sh $(FREECAD) run $(MAKE) --no-print-directory $@ $(MAKEOVERRIDES) FREECAD=$(FREECAD)
else
BUILD_DIR ?= build/freecad-$(FREECAD)
# the tests and examples find hsm-feedsim and the other programs of this build there
export HSM_BUILD_DIR := $(abspath $(BUILD_DIR))
OUT ?= out
JOBS ?= $(shell nproc)
FREECADCMD ?= freecadcmd
# Debian's own Python (the one FreeCAD embeds) and cmake, whatever else comes first on the PATH.
PYTHON := /usr/bin/python3
CMAKE := /usr/bin/cmake
CTEST := /usr/bin/ctest

ASAN_DIR ?= build/asan-freecad-$(FREECAD)
FUZZ_SECONDS ?= 60
# `make deb`: a build of its own (installed layout, Debian's hardening flags), the package written here
PACKAGE_DIR ?= $(BUILD_DIR)/package

.PHONY: all deps asan-deps package-deps configure build link test test-cpp test-python test-gui test-asan test-oracle fuzz demo study-roughing bench deb test-package clean

all: build

deps:
	@scripts/install-deps.sh

$(BUILD_DIR)/CMakeCache.txt: | deps
	$(CMAKE) -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=$(PYTHON)

configure: $(BUILD_DIR)/CMakeCache.txt

build: deps configure
	$(CMAKE) --build $(BUILD_DIR) -j $(JOBS)
	@$(FREECADCMD) scripts/link_workbench.py $(CURDIR) > $(BUILD_DIR)/link.log 2>&1 || { cat $(BUILD_DIR)/link.log; exit 1; }
	@grep -h "linked" $(BUILD_DIR)/link.log || true

test: build
	scripts/run-tests.sh $(BUILD_DIR)

test-cpp: build
	scripts/run-tests.sh $(BUILD_DIR) cpp

test-python: build
	scripts/run-tests.sh $(BUILD_DIR) python

test-gui: build
	scripts/run-tests.sh $(BUILD_DIR) gui

# The core and its C++ tests under AddressSanitizer and UndefinedBehaviorSanitizer (clang, no Python module);
# also builds the libFuzzer harnesses that `make fuzz` runs.
asan-deps: deps
	@scripts/install-deps.sh scripts/debian-packages-asan.txt

$(ASAN_DIR)/CMakeCache.txt: | asan-deps
	$(CMAKE) -S . -B $(ASAN_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ -DHSM_FUZZ=ON \
	  -DHSM_BUILD_PYTHON=OFF -DHSM_BUILD_BENCHMARKS=OFF

test-asan: $(ASAN_DIR)/CMakeCache.txt
	$(CMAKE) --build $(ASAN_DIR) -j $(JOBS)
	ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  LSAN_OPTIONS=suppressions=$(CURDIR)/tests/cpp/lsan.supp \
	  $(CTEST) --test-dir $(ASAN_DIR) --output-on-failure -j $(JOBS)

# LinuxCNC 2.9 as an oracle for the feed-rate simulator (docs/oracle.md), not part of `make test`: runs each
# program of tests/oracle/programs*/ (3 and 5 axes) in a headless LinuxCNC simulation (installs
# linuxcnc-uspace if missing; real time, about 10 min) and in hsm-feedsim with the same limits; prints the
# table of times and writes it to $(BUILD_DIR)/oracle/ (oracle.md, oracle.csv). Fails when LinuxCNC or
# hsm-feedsim failed, or when a program's |error| exceeds 2 %.
test-oracle: build
	$(PYTHON) tests/oracle/run_oracle.py --out $(BUILD_DIR)/oracle --feedsim $(BUILD_DIR)/bin/hsm-feedsim --max-error 2

# Each harness for FUZZ_SECONDS (default 60) on its corpus; new inputs are added to tests/fuzz/corpus/.
fuzz: $(ASAN_DIR)/CMakeCache.txt
	$(CMAKE) --build $(ASAN_DIR) -j $(JOBS)
	scripts/run-fuzzers.sh $(ASAN_DIR) $(FUZZ_SECONDS)

demo: build
	scripts/run-freecadcmd.sh examples/guidance_study.py $(OUT)
	scripts/run-freecadcmd.sh examples/master_bottom_feature.py $(OUT)
	scripts/run-freecadcmd.sh examples/curve_nets.py $(OUT)
	scripts/run-freecadcmd.sh examples/feedrate_study.py $(OUT)
	scripts/run-freecadcmd.sh examples/machining_direction.py $(OUT)
	scripts/run-freecadcmd.sh examples/roughing_partition.py $(OUT)
	scripts/run-freecadcmd.sh examples/roughing_paths.py $(OUT)
	scripts/run-freecadcmd.sh examples/roughing_study.py $(OUT) channels=1
	scripts/run-freecadcmd.sh examples/strategy_study.py $(OUT)
	@echo "make demo: done; the roughing study of all 7 channels is \`make study-roughing\` (about 20 min)"

# The roughing paper's five-strategy study on every channel of the impeller (docs/roughing.md; about 20 min on
# two cores): `make demo` runs it on one channel.
study-roughing: build
	scripts/run-freecadcmd.sh examples/roughing_study.py $(OUT)

bench: build
	$(BUILD_DIR)/bin/bench_curvenet
	$(BUILD_DIR)/bin/bench_feedsim
	scripts/run-freecadcmd.sh tests/bench/bench_preview.py
	$(BUILD_DIR)/bin/bench_dropcutter
	$(BUILD_DIR)/bin/bench_direction
	$(BUILD_DIR)/bin/bench_roughing
	test ! -x $(BUILD_DIR)/bin/bench_removal_models || $(BUILD_DIR)/bin/bench_removal_models
	scripts/run-freecadcmd.sh tests/bench/bench_finishing.py
	scripts/run-freecadcmd.sh tests/bench/bench_partition.py
	scripts/run-freecadcmd.sh tests/bench/bench_study.py

# The Debian package (docs/packaging.md) for this FreeCAD's Debian: freecad-hsmplanner_<version>+<suite>_<arch>.deb
# in this folder (+forky for FreeCAD 1.1, +trixie for 1.0), for `apt install ./freecad-hsmplanner_*.deb`, checked
# by lintian (an error fails the target).
SUITE := $(shell scripts/freecad-env.sh $(FREECAD) suite)
package-deps: deps
	@scripts/install-deps.sh scripts/debian-packages-deb.txt

$(PACKAGE_DIR)/CMakeCache.txt: | package-deps
	export DEB_BUILD_MAINT_OPTIONS=hardening=+all; \
	CXXFLAGS="$$(dpkg-buildflags --get CXXFLAGS) $$(dpkg-buildflags --get CPPFLAGS)" \
	  LDFLAGS="$$(dpkg-buildflags --get LDFLAGS)" \
	  $(CMAKE) -S . -B $(PACKAGE_DIR) -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/usr -DHSM_PACKAGE=ON \
	  -DHSM_BUILD_TESTS=OFF -DPython3_EXECUTABLE=$(PYTHON)

deb: package-deps $(PACKAGE_DIR)/CMakeCache.txt
	$(CMAKE) --build $(PACKAGE_DIR) -j $(JOBS)
	rm -rf $(PACKAGE_DIR)/package
	cd $(PACKAGE_DIR) && cpack -G DEB > cpack.log 2>&1 || { cat cpack.log; exit 1; }
	rm -f freecad-hsmplanner_*+$(SUITE)_*.deb
	cp $(PACKAGE_DIR)/package/freecad-hsmplanner_*+$(SUITE)_*.deb .
	lintian --display-info freecad-hsmplanner_*+$(SUITE)_*.deb
	@ls -l freecad-hsmplanner_*+$(SUITE)_*.deb

# The package installed into a clean root of its Debian (debootstrap into $(BUILD_DIR)/package-test, FreeCAD from
# Debian's archive) and used there outside the source tree, then removed: nothing may be left (docs/packaging.md).
# Not part of `make test`: the first run makes the root (minutes of downloads), later runs reuse it.
test-package: deb
	tests/package/run.sh $$(ls freecad-hsmplanner_*+$(SUITE)_*.deb) $(SUITE) $(BUILD_DIR)/package-test

clean:
	rm -rf $(BUILD_DIR) $(ASAN_DIR) python/hsmplanner/_core.cpython-*.so freecad-hsmplanner_*+$(SUITE)_*.deb

endif
