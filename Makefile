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

.PHONY: deps deps-windows build example test windows windows-test bench headers docs-image docs-panel docs-mc3b mc3b-demo clean fuzz vendor-record

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

# Regenerate the pictures of docs/mc3b.md, docs/mc3b-*.png, one per dialog of mc3b-app
# (commit them): the mc3b_app_browser test's run in headless Chromium, which otherwise
# checks them for drift.
docs-mc3b: build
	python3 c-tests/scripts/mc3b_app_browser.py $(BUILD)/cargo/release --screenshots docs

# mc3b-app against mc3b-emu on a pseudo-terminal: prints the page's address; lines typed
# here go to the emulator's control channel (`input 0 1`: limit input 0 at +5 V; see
# mc3b-emu --help). Ctrl-C ends both (the application first turns the motors off).
mc3b-demo: build
	@scripts/mc3b-demo.sh $(BUILD)/cargo/release

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

# Records the vendor differential scenarios again from the vendor's own 64-bit DLL under
# wine64 (docs/testing.md "Vendor traces"): make vendor-record VENDOR_DLL=/path/MCCLPCI_IMP3.dll
# [SCENARIOS="name ..."]. The DLL is read, never copied into the repository.
VENDOR_DLL ?=
SCENARIOS ?=
vendor-record:
	@test -n "$(VENDOR_DLL)" || { echo "make vendor-record VENDOR_DLL=/path/to/MCCLPCI_IMP3.dll" >&2; exit 2; }
	tools/vendor-record $(VENDOR_DLL) $(SCENARIOS)
