# sunglint: `make demo` and `make test` set everything up on a fresh Debian 12 machine
# (packages through scripts/install-deps.sh, as root or through sudo), build in Release
# and run. Other targets: build, bench, pictures, sanitize, format, format-check, clean, ocean-scenes.
BUILD ?= build
JOBS ?= $(shell nproc)
CMAKE_FLAGS ?=

.PHONY: all deps configure build test demo pictures bench sanitize format format-check clean ocean-scenes

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

format:
	clang-format -i $$(git ls-files '*.cpp' '*.h' '*.glsl')

format-check:
	clang-format --dry-run --Werror $$(git ls-files '*.cpp' '*.h' '*.glsl')

clean:
	rm -rf $(BUILD) build-asan
