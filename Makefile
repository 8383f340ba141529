# blockdem: the two commands a new user needs are `make demo` and `make test`.
# Both install missing Debian packages first (apt-get, with sudo when not root).

BUILD_DIR ?= build
BUILD_TYPE ?= Release
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
DEMO_OUT ?= out/demo

# Packages the build and the tests need (Debian 12 names).
CORE_PACKAGES := g++ cmake make pkg-config libtomlplusplus-dev libcli11-dev libfmt-dev \
                 nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev \
                 libopenmpi-dev openmpi-bin
# Packages for figures and the report (not needed by the library or the core tests).
# python3-vtk9 reads the VTK output back in the tests; chromium and nodejs run the report test
# (npm packages: tests/cli/report_browser/package.json); libjs-dygraphs is inlined in the report
# for its zoomable plots; ffmpeg writes the MP4 animation (GIF without it).
VIEW_PACKAGES := python3-matplotlib python3-numpy python3-vtk9 libjs-dygraphs ffmpeg chromium nodejs

.PHONY: all deps deps-view build test demo bench clean

all: build

deps:
	@scripts/install-deps.sh $(CORE_PACKAGES)

deps-view:
	@scripts/install-deps.sh $(VIEW_PACKAGES)

build: deps
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE)
	cmake --build $(BUILD_DIR) -j $(JOBS)

test: build deps-view
	ctest --test-dir $(BUILD_DIR) --output-on-failure -j $(JOBS)

demo: build deps-view
	@scripts/demo.sh $(BUILD_DIR) $(DEMO_OUT)

bench: build
	$(BUILD_DIR)/blockdem_bench --benchmark_counters_tabular=true

clean:
	rm -rf $(BUILD_DIR) out
