# The two commands of the README:
#   make example   run an unchanged vendor-style sample program on the virtual card
#   make test      build everything and run every test (Rust, C, C++, headers, bindings)
BUILD ?= build
EXAMPLE ?= InitSys

.PHONY: deps build example test headers clean

deps:
	@scripts/install-deps.sh

build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release
	cmake --build $(BUILD) -j2

example: build
	$(BUILD)/c-tests/$(EXAMPLE)

test: build
	ctest --test-dir $(BUILD) --output-on-failure

# Regenerate include/*.h from the Rust sources (commit the result).
headers:
	cargo run -q -p mccl-headers

clean:
	rm -rf $(BUILD)
