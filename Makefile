# blockdem: the two commands a new user needs are `make demo` and `make test`.
# Both install missing Debian packages first (apt-get, with sudo when not root).

BUILD_DIR ?= build
BUILD_TYPE ?= Release
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
DEMO_OUT ?= out/demo

# Packages the build and the tests need (Debian 12 names).
CORE_PACKAGES := g++ cmake make pkg-config libtomlplusplus-dev libcli11-dev libfmt-dev \
                 nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev \
                 libopenmpi-dev openmpi-bin libhdf5-dev libglpk-dev libdxflib-dev
# Packages for the Python module and its tests (docs/python.md): pybind11 builds it, numpy is its
# arrays, pytest runs tests/python, setuptools and wheel serve `pip install --no-build-isolation .`.
PYTHON_PACKAGES := pybind11-dev python3-dev python3-numpy python3-pytest python3-setuptools python3-wheel
# Packages for the checks (docs/checks.md): clang 14 with its sanitizer and libFuzzer runtimes
# (libclang-rt-14-dev, only recommended by clang-14), its OpenMP runtime for the sanitized build,
# and llvm-symbolizer (llvm-14) for readable sanitizer reports. `make test` runs the fuzz smoke.
CHECK_PACKAGES := clang-14 libclang-rt-14-dev libomp-14-dev llvm-14
# Packages for figures and the report (not needed by the library or the core tests).
# python3-vtk9 reads the VTK output back in the tests; chromium and nodejs run the report test
# (npm packages: tests/cli/report_browser/package.json); libjs-dygraphs is inlined in the report
# for its zoomable plots; ffmpeg writes the MP4 animation (GIF without it).
VIEW_PACKAGES := python3-matplotlib python3-numpy python3-h5py python3-vtk9 libjs-dygraphs ffmpeg chromium nodejs

SANITIZE_DIR ?= build-sanitize
FUZZ_DIR ?= $(BUILD_DIR)/fuzz
FUZZ_SECONDS ?= 300

.PHONY: all deps deps-view deps-check build test demo bench fuzz sanitize clean python

all: build

deps:
	@scripts/install-deps.sh $(CORE_PACKAGES) $(PYTHON_PACKAGES)

deps-view:
	@scripts/install-deps.sh $(VIEW_PACKAGES)

deps-check:
	@scripts/install-deps.sh $(CHECK_PACKAGES)

build: deps
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE)
	cmake --build $(BUILD_DIR) -j $(JOBS)

# The module blockdem for this user (python3 -m site --user-site); without it, use
# PYTHONPATH=$(BUILD_DIR)/python.
python: build
	cmake --install $(BUILD_DIR) --component python --prefix "$$(/usr/bin/python3 -m site --user-site)"

test: build deps-view deps-check
	ctest --test-dir $(BUILD_DIR) --output-on-failure -j $(JOBS)

demo: build deps-view
	@scripts/demo.sh $(BUILD_DIR) $(DEMO_OUT)

bench: build
	$(BUILD_DIR)/blockdem_bench --benchmark_counters_tabular=true

# Each libFuzzer harness in turn for FUZZ_SECONDS (CPU at the lowest priority); the corpus grows
# in $(FUZZ_DIR)/corpus, findings land in $(FUZZ_DIR)/findings. Exit status 1 on any finding.
fuzz: deps deps-check
	scripts/fuzz.sh --build-dir $(FUZZ_DIR) --seconds $(FUZZ_SECONDS)

# The whole test suite built with AddressSanitizer and UndefinedBehaviorSanitizer (clang).
sanitize: deps deps-view deps-check
	scripts/sanitize.sh $(SANITIZE_DIR)

clean:
	rm -rf $(BUILD_DIR) $(SANITIZE_DIR) out
