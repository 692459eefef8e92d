# User entry points. CMake (CMakeLists.txt) is the source of truth; this file
# only wraps its targets. Every target installs missing Debian packages first.
#
#   make test    build everything and run the test suite (what CI runs)
#   make sim     regression on the bundled pairs (reference only until the RTL engine exists)
#   make lint    verilator --lint-only -Wall on every RTL module
#   make rtl-pkg regenerate rtl/mcadsw_pkg.sv from params.hpp
#   make bench   Google Benchmark of the reference (MDE/s)
#   make sweep   weight-table gamma sweep on the Middlebury pairs (docs/algorithm.md)

BUILD_DIR ?= build
JOBS      ?= $(shell nproc)

.PHONY: all bootstrap configure build test sim lint rtl-pkg bench sweep clean

all: build

bootstrap:
	@scripts/bootstrap.sh

configure: bootstrap
	@cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

test: build
	@cd $(BUILD_DIR) && ctest -j $(JOBS) --output-on-failure

sim: build
	@echo "== make sim: reference model on the bundled pairs ('all' error %, threshold 1) =="
	@scripts/eval_pairs.sh -b $(BUILD_DIR) -s middlebury -o $(BUILD_DIR)/sim
	@scripts/eval_pairs.sh -b $(BUILD_DIR) -s cif -o $(BUILD_DIR)/sim
	@echo "Disparity maps: $(BUILD_DIR)/sim/*.png"
	@echo "NOTE: the RTL engine is not built yet (issue 4); this run exercised the C++ reference only."

lint: bootstrap
	@scripts/rtl_check.sh lint

rtl-pkg: configure
	@cmake --build $(BUILD_DIR) --target gen_rtl_pkg > /dev/null
	@$(BUILD_DIR)/bin/gen_rtl_pkg > rtl/mcadsw_pkg.sv
	@echo "rtl/mcadsw_pkg.sv regenerated from sw_ref/include/mcadsw/params.hpp"

bench: build
	@$(BUILD_DIR)/bin/bench_ref

sweep: build
	@scripts/eval_pairs.sh -b $(BUILD_DIR) -g "6 8 10 12 14 16 18 20 21 22 23 24 28 32 40"

clean:
	rm -rf $(BUILD_DIR)
