# sunglint: `make demo` and `make test` set everything up on a fresh Debian 12 machine
# (packages through scripts/install-deps.sh, as root or through sudo), build in Release
# and run. Other targets: build, bench, pictures, sanitize, fuzz, format, format-check, clean, ocean-scenes.
BUILD ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=

.PHONY: all deps configure build test demo pictures bench sanitize fuzz format format-check clean ocean-scenes

all: build

deps:
	@bash scripts/install-deps.sh

$(BUILD)/build.ninja: | deps
	cmake -S . -B $(BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)

configure: deps $(BUILD)/build.ninja

build: configure
	cmake --build $(BUILD) -j $(JOBS)

test: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS)

# FULL=1: the paper-sized study (640x360, 30 frames); DOCS=1: then regenerate docs/results.md
# and the README's demo section from its results.json.
demo: build
	bash scripts/demo.sh $(if $(FULL),--full) $(if $(DOCS),--docs) $(BUILD)/sunglint

# The README's pictures and videos of the three picture scenes (scripts/pictures.sh).
pictures: build
	bash scripts/pictures.sh $(BUILD)/sunglint

bench: build
	$(BUILD)/sunglint bench scenes/simple.json scenes/smooth.json scenes/medium.json scenes/high.json

# The spectrum-generated scenes (scenes/ocean-*.json) from `sunglint ocean` (docs/ocean.md).
ocean-scenes: build
	bash scripts/ocean-scenes.sh $(BUILD)/sunglint

# The test suite under AddressSanitizer and UndefinedBehaviorSanitizer (Debug build).
sanitize: deps
	cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DSUNGLINT_SANITIZE=ON \
	  -DSUNGLINT_BUILD_BENCH=OFF
	cmake --build build-asan -j $(JOBS)
	ctest --test-dir build-asan --output-on-failure -j $(JOBS) -LE slow

# The scene loader under libFuzzer (clang, fuzz/scene_fuzz.cpp) for FUZZ_SECONDS, from a seed
# corpus of the shipped, bad and edge scenes; new inputs go to build-fuzz/corpus, findings
# to build-fuzz/artifacts (the run fails on one).
FUZZ_SECONDS ?= 60
fuzz: deps
	cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_CXX_COMPILER=clang++ -DSUNGLINT_FUZZ=ON -DSUNGLINT_BUILD_TESTS=OFF \
	  -DSUNGLINT_BUILD_BENCH=OFF
	cmake --build build-fuzz -j $(JOBS) --target scene_fuzz
	mkdir -p build-fuzz/corpus build-fuzz/artifacts
	build-fuzz/fuzz/scene_fuzz -max_total_time=$(FUZZ_SECONDS) -timeout=10 -rss_limit_mb=4096 \
	  -max_len=16384 -dict=fuzz/scene.dict -artifact_prefix=build-fuzz/artifacts/ \
	  -print_final_stats=1 build-fuzz/corpus scenes tests/scenes/bad tests/scenes/edge \
	  tests/scenes/extreme

format:
	clang-format -i $$(git ls-files '*.cpp' '*.h' '*.glsl')

format-check:
	clang-format --dry-run --Werror $$(git ls-files '*.cpp' '*.h' '*.glsl')

clean:
	rm -rf $(BUILD) build-asan build-fuzz
