# Thin wrapper over CMake. `make run` and `make test` also install what is missing.
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
SCENE ?= scenes/showcase.scene

.PHONY: all build deps bench-deps configure run test bench clean

all: build

deps:
	@tools/install_deps.sh

configure:
	@cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release > /dev/null

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

# Set-up, build, then show the default scene (a window if there is a display,
# otherwise a PNG whose path is printed).
run: deps build
	@tools/run_default.sh $(BUILD_DIR)/Raytracer $(SCENE)

# Set-up, build, then the whole test suite on lavapipe with validation on.
test: deps build
	@cd $(BUILD_DIR) && ctest --output-on-failure -j 2 --timeout 900

# Set-up with the benchmark's extras (Embree, matplotlib), build (embree_peer is built
# once Embree is there), then Raytracer against its CPU peers: tables on stdout, CSV and
# chart under $(BUILD_DIR)/bench/. BENCH_ARGS=--quick for a fast check.
bench: bench-deps build
	@VK_ICD_FILENAMES=$${VK_ICD_FILENAMES:-} tools/bench $(BUILD_DIR)/Raytracer $(BENCH_ARGS)

bench-deps:
	@tools/install_deps.sh --bench

clean:
	@rm -rf $(BUILD_DIR)
