# Two entry points for a fresh Debian 12 machine: `make run` and `make test`.
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
SCENE ?= scenes/default.toml
CTEST_ARGS ?=

.PHONY: run test deps configure build validate asan clean valve-quick

deps:
	scripts/install-deps

configure: deps
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=Release

build: configure
	cmake --build $(BUILD_DIR) -j$(JOBS)

run: build
	$(BUILD_DIR)/bin/valsalva run $(SCENE) --overwrite

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j$(JOBS) $(CTEST_ARGS)

# The valve at the coarse level: its meshes (once) and one cardiac cycle (scenes/valve_quick.toml).
valve-quick: build
	scripts/make-valve-quick $(BUILD_DIR)/bin/valsalva runs/valve_quick
	$(BUILD_DIR)/bin/valsalva run scenes/valve_quick.toml --overwrite

asan: deps
	cmake --preset asan && cmake --build --preset asan -j$(JOBS) && ctest --preset asan -L quick

clean:
	rm -rf $(BUILD_DIR)
