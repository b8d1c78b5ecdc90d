# Thin wrapper over CMake. `make run` and `make test` also install what is missing.
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
SCENE ?= scenes/showcase.scene
SANITIZE_DIR ?= build-sanitize
FUZZ_SECONDS ?= 60

.PHONY: all build deps bench-deps configure run test check-hardening bench bench-kernel bench-scale clean

all: build

deps:
	@tools/build/install_deps.sh

configure:
	@cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release > /dev/null

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

# Set-up, build the program alone (not the tests and tools, which `make test` builds),
# then show the default scene (a window if there is a display, otherwise a PNG whose path
# is printed).
run: deps configure
	@cmake --build $(BUILD_DIR) -j $(JOBS) --target Raytracer
	@tools/build/run_default.sh $(BUILD_DIR)/Raytracer $(SCENE)

# Set-up, build, then the whole test suite on lavapipe with validation on; in CI
# (CI=true, as .ci/run is run there) also the hardening checks below.
test: deps build
	@start=$$(date +%s); cd $(BUILD_DIR) && ctest --output-on-failure -j 2 --timeout 900; \
	    status=$$?; echo "test suite: $$(($$(date +%s) - start)) s"; exit $$status
	@if [ "$${CI:-}" = true ]; then $(MAKE) --no-print-directory check-hardening; fi

# The whole suite again, built by clang with AddressSanitizer and UndefinedBehaviorSanitizer
# in $(SANITIZE_DIR) (any report fails its test), then the scene parser fuzzed for
# FUZZ_SECONDS (any crash, leak, hang or out-of-memory fails). See docs/testing.md.
check-hardening: deps
	@start=$$(date +%s); \
	    cmake -S . -B $(SANITIZE_DIR) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRAYTRACER_SANITIZE=ON \
	        -DCMAKE_CXX_COMPILER=clang++ > /dev/null && \
	    cmake --build $(SANITIZE_DIR) -j $(JOBS) && \
	    echo "sanitizer build: $$(($$(date +%s) - start)) s" && start=$$(date +%s) && \
	    cd $(SANITIZE_DIR) && ctest --output-on-failure -j 2 --timeout 900; \
	    status=$$?; echo "sanitizer suite: $$(($$(date +%s) - start)) s"; exit $$status
	@start=$$(date +%s); tools/fuzz.sh $(FUZZ_SECONDS); \
	    status=$$?; echo "fuzzing: $$(($$(date +%s) - start)) s"; exit $$status

# Set-up with the benchmark's extras (Embree, matplotlib), build (embree_peer is built
# once Embree is there), then Raytracer against its CPU peers: tables on stdout, CSV and
# chart under $(BUILD_DIR)/bench/. BENCH_ARGS=--quick for a fast check. Then the kernel's
# costs (bench-kernel, about 4 minutes on 2 cores).
bench: bench-deps build
	@tools/bench $(BUILD_DIR)/Raytracer $(BENCH_ARGS)
	@echo
	@tools/kernel_costs $(BUILD_DIR)/Raytracer $(KERNEL_BENCH_ARGS)

# The robust methods against the naive ones, fp64, and the scene-specialised kernel against
# the general one: a table of CPU time per frame, CSV in $(BUILD_DIR)/bench/kernel_costs.csv.
# KERNEL_BENCH_ARGS="--rounds 12" for finer figures.
bench-kernel: build
	@tools/kernel_costs $(BUILD_DIR)/Raytracer $(KERNEL_BENCH_ARGS)

# From file to first frame at scale: torus knots of 1M, 4M, 10M and 30M triangles as OBJ,
# each with its start-up by phase, parse MB/s on 1 and all threads, peak memory, GPU bytes
# per triangle, frame time and Embree's build beside the hierarchy's (tools/bench_scale;
# SCALE_ARGS="--sizes 1e6 4e6" on a smaller machine). Tables on stdout, CSV under
# $(BUILD_DIR)/bench-scale/.
bench-scale: bench-deps build
	@tools/bench_scale $(BUILD_DIR)/Raytracer $(SCALE_ARGS)

bench-deps:
	@tools/build/install_deps.sh --bench

clean:
	@rm -rf $(BUILD_DIR)
