# The two commands of the README:
#   make example   run a vendor-style sample program (GeneralMotion) on the virtual card
#   make test      build everything and run every test (Rust, C, C++, headers, bindings)
# and for Windows (README, "Windows"):
#   make windows        the Windows DLLs, x64 and x86, in $(BUILD)/windows/
#   make windows-test   those DLLs tested under Wine (C/C++ programs, Rust unit tests)
BUILD ?= build
EXAMPLE ?= GeneralMotion
# The example runs on the fast virtual clock unless told otherwise (MCCL_CLOCK=realtime).
MCCL_CLOCK ?= fast
export MCCL_CLOCK

.PHONY: deps deps-windows build example test windows windows-test bench headers docs-image docs-panel clean fuzz

deps:
	@scripts/install-deps.sh

deps-windows:
	@scripts/install-deps.sh --windows

build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release
	cmake --build $(BUILD) -j2

TRACE_TOOL = $(BUILD)/cargo/release/mccl-trace

example: build
	MCCL_TRACE=$(BUILD)/$(EXAMPLE).csv $(BUILD)/c-tests/$(EXAMPLE)
	$(TRACE_TOOL) plot $(BUILD)/$(EXAMPLE).csv -o $(BUILD)/$(EXAMPLE).svg
	$(TRACE_TOOL) report $(BUILD)/$(EXAMPLE).csv -o $(BUILD)/$(EXAMPLE).html
	@echo "every tick of every group: $(BUILD)/$(EXAMPLE).csv (events: $(BUILD)/$(EXAMPLE).events.csv)"
	@echo "plots: $(BUILD)/$(EXAMPLE).svg"
	@echo "report: $(BUILD)/$(EXAMPLE).html"

test: build
	ctest --test-dir $(BUILD) --output-on-failure

# The same from CMake: cmake --build $(BUILD) --target windows.
windows: deps-windows
	scripts/windows/build.sh $(BUILD)/windows

windows-test: windows
	scripts/windows/test.sh $(BUILD)/windows $(BUILD)/cargo

# Performance numbers of the engine (not a test).
bench:
	cargo bench --bench engine
	cargo bench --bench realtime
	cargo bench --bench tick_floor

# Regenerate include/*.h from the Rust sources (commit the result).
headers:
	cargo run -q -p mccl-headers

# Regenerate the picture docs/GeneralMotion.svg of docs/clocks-and-tracing.md (commit
# the result; the trace_tool test checks it).
docs-image: build
	MCCL_CLOCK=fast MCCL_TRACE=$(BUILD)/docs-GeneralMotion.csv $(BUILD)/c-tests/GeneralMotion >/dev/null
	$(TRACE_TOOL) plot $(BUILD)/docs-GeneralMotion.csv -o docs/GeneralMotion.svg

# Regenerate the README's screenshot of the browser panel docs/panel.png (commit it): the
# panel_browser test's run of panel_demo under the realtime clock in headless Chromium.
docs-panel: build
	python3 c-tests/scripts/panel_browser.py $(BUILD)/c-tests/panel_demo --screenshot docs/panel.png

clean:
	rm -rf $(BUILD)

# The random-call fuzzer, long run (docs/testing.md "Fuzzing"): FUZZ_CALLS calls over
# FUZZ_WORKERS seeds from FUZZ_SEED, calls/s printed; FUZZ_ARGS adds options (e.g.
# --routine-init safe).
FUZZ_SEED ?= 1
FUZZ_CALLS ?= 10000000
FUZZ_WORKERS ?= 100
FUZZ_ARGS ?=
fuzz: build
	$(BUILD)/c-tests/mccl_fuzz --seed $(FUZZ_SEED) --calls $(FUZZ_CALLS) --workers $(FUZZ_WORKERS) --require-routines --keep-going $(FUZZ_ARGS)
