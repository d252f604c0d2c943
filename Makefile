# The two commands of the README:
#   make example   run a vendor-style sample program (GeneralMotion) on the virtual card
#   make test      build everything and run every test (Rust, C, C++, headers, bindings)
BUILD ?= build
EXAMPLE ?= GeneralMotion
# The example runs on the fast virtual clock unless told otherwise (MCCL_CLOCK=realtime).
MCCL_CLOCK ?= fast
export MCCL_CLOCK

.PHONY: deps build example test bench headers clean

deps:
	@scripts/install-deps.sh

build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release
	cmake --build $(BUILD) -j2

example: build
	MCCL_TRACE=$(BUILD)/$(EXAMPLE).csv $(BUILD)/c-tests/$(EXAMPLE)
	@echo "every tick of every group: $(BUILD)/$(EXAMPLE).csv"

test: build
	ctest --test-dir $(BUILD) --output-on-failure

# Performance numbers of the engine (not a test).
bench:
	cargo bench --bench engine
	cargo bench --bench realtime

# Regenerate include/*.h from the Rust sources (commit the result).
headers:
	cargo run -q -p mccl-headers

clean:
	rm -rf $(BUILD)
