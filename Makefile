# The two commands a newcomer needs: `make run` and `make test`. Each installs what is missing,
# configures and builds Release, then does its job.
PRESET ?= release
BUILD_DIR := build/$(PRESET)
MARSOKHOD := $(BUILD_DIR)/apps/marsokhod
OUT ?= out

.PHONY: all setup configure build run test bench sanitize format format-check clean

all: build

setup:
	@sh scripts/setup.sh

configure: setup
	@cmake --preset $(PRESET) >/dev/null

build: configure
	@cmake --build --preset $(PRESET)

run: build
	@sh scripts/run-default.sh $(MARSOKHOD) $(OUT)

test: build
	@ctest --preset $(PRESET)

bench: build
	@cmake --build --preset $(PRESET) --target benches
	@sh scripts/run-benches.sh $(BUILD_DIR) $(OUT)/bench

# AddressSanitizer + UBSan build (build/sanitize) of the io, imaging, emulator, occam,
# navigation-program and overswitch layers' tests and the reader mutation test
# (scripts/sanitize.sh); `make sanitize SANITIZE_SCOPE=all` runs the whole suite.
SANITIZE_SCOPE ?= layers
sanitize: setup
	@sh scripts/sanitize.sh $(SANITIZE_SCOPE)

format: setup
	@git ls-files '*.cpp' '*.hpp' | xargs clang-format -i

format-check: setup
	@sh scripts/check-format.sh

clean:
	@rm -rf build
