# sunglint: `make demo` and `make test` set everything up on a fresh Debian 12 machine
# (packages through scripts/install-deps.sh, as root or through sudo), build in Release
# and run. Other targets: build, bench, pictures, sanitize, fuzz, ci-fast, format, format-check,
# clean, ocean-scenes. CI (.ci/run) and its budget: docs/ci.md.
BUILD ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=

.PHONY: all deps configure build test demo pictures bench sanitize sanitize-build sanitize-test \
  fuzz fuzz-build fuzz-run ci-fast format format-check clean ocean-scenes

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

# Every unit test (each test program; CTest labels unit, gl and slow) under AddressSanitizer and
# UndefinedBehaviorSanitizer: a build of the test programs alone (no CLI, viewer binary,
# tools or benchmarks), -O1 with line tables only (-g1: stack traces with lines, at a
# fraction of -g's compile time). Without -Werror: GCC 12 warns falsely (maybe-uninitialized
# inside libstdc++'s <regex>) at -O1 with the sanitizers; the Release build holds the code
# warning-free.
SANITIZE_BUILD ?= build-asan
sanitize: sanitize-build sanitize-test

sanitize-build: deps
	cmake -S . -B $(SANITIZE_BUILD) -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-g1 \
	  -DSUNGLINT_SANITIZE=ON -DSUNGLINT_BUILD_BENCH=OFF
	cmake --build $(SANITIZE_BUILD) -j $(JOBS) --target unit_tests

# The CLI's end-to-end tests (label cli, some also gl) need the sunglint binary, which this
# build leaves out: they run in the Release suite. `MovingCameraTargets` (staa's statistical
# targets under a moving camera: 173 s under the sanitizers, a third of the suite) runs in
# the Release suite only; the code it runs (the moving camera's staa, supersample, point and
# reference) runs under the sanitizers in `MovingCamera.*` and the GL engine's moving-camera
# test (docs/ci.md).
# `Staa.BeatsPointSamplingOnTheSharedScenes` (staa against point over ten frames of the
# four shared scenes: 75 s under the sanitizers) likewise: its code runs under them in
# `StaaFootprint.*` and the GL engine's shared-scenes test. `AliasingTargets` (staa and
# lean over thirty frames against a stored reference) too: its code runs under them in
# `Staa.*` and `Lean.*`. `RandomSeas` (staa, point, lean and the reference on eight
# generated seas, against bounds on their errors: 76 s) runs its code under them in
# `FiniteProperty` (random valid scenes), `Staa.*`, `Lean.*` and `ReferenceEstimator.*`.
# Of the GL engine's tests, `MatchesTheCpuEngineOnTheSharedScenes` (140 s) and
# `GlReferenceIsWithinTheNoiseOfTwoCpuSeeds` (65 s, a statistical check) leave too: the
# host code they run, the engine's and the CPU methods', runs under the sanitizers in
# `EngineAgreement` (random scenes), `GlReferenceMeanMatchesTheCpuOffTheSharedScenes` and
# the other `GlEngineTest` cases.
SANITIZE_EXCLUDE ?= ^(MovingCameraTargets\.|AliasingTargets\.|RandomSeas\.|Staa\.BeatsPointSamplingOnTheSharedScenes$$|GlEngineTest\.(MatchesTheCpuEngineOnTheSharedScenes|GlReferenceIsWithinTheNoiseOfTwoCpuSeeds)$$)
sanitize-test:
	ctest --test-dir $(SANITIZE_BUILD) --output-on-failure -j $(JOBS) -L '^(unit|gl|slow)$$' \
	  -LE '^cli$$' -E '$(SANITIZE_EXCLUDE)'

# The scene loader under libFuzzer (clang, fuzz/scene_fuzz.cpp; line tables only, -g1, as
# the sanitizer build) for FUZZ_SECONDS, from a seed corpus of the shipped, bad and edge
# scenes; new inputs go to build-fuzz/corpus, findings to build-fuzz/artifacts (the run
# fails on one).
FUZZ_SECONDS ?= 60
fuzz: fuzz-build fuzz-run

fuzz-build: deps
	cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
	  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO='-O2 -g1 -DNDEBUG' -DCMAKE_CXX_COMPILER=clang++ \
	  -DSUNGLINT_FUZZ=ON -DSUNGLINT_BUILD_TESTS=OFF -DSUNGLINT_BUILD_BENCH=OFF
	cmake --build build-fuzz -j $(JOBS) --target scene_fuzz

fuzz-run:
	mkdir -p build-fuzz/corpus build-fuzz/artifacts
	build-fuzz/fuzz/scene_fuzz -max_total_time=$(FUZZ_SECONDS) -timeout=10 -rss_limit_mb=4096 \
	  -max_len=16384 -dict=fuzz/scene.dict -artifact_prefix=build-fuzz/artifacts/ \
	  -print_final_stats=1 build-fuzz/corpus scenes tests/scenes/bad tests/scenes/edge \
	  tests/scenes/extreme

# The check before every merge (docs/ci.md): the Release build and its whole suite, and the
# formatting; at most 5 minutes from a built tree. CI (.ci/run) adds the sanitizers and the
# fuzzer.
ci-fast: test format-check

format:
	clang-format -i $$(git ls-files --cached --others --exclude-standard '*.cpp' '*.h' '*.glsl')

format-check:
	clang-format --dry-run --Werror $$(git ls-files --cached --others --exclude-standard '*.cpp' '*.h' '*.glsl')

clean:
	rm -rf $(BUILD) $(SANITIZE_BUILD) build-fuzz build-ci-logs
