# User entry points. CMake (CMakeLists.txt) is the source of truth; this file
# only wraps its targets. Every target installs missing Debian packages first.
#
#   make test    build everything and run the test suite (what CI runs)
#   make sim     engine regression on the bundled pairs, bit-exact against the reference
#                (CASE=<name> one case, WAVES=1 an FST; make wave CASE=<name> opens it)
#   make sim-random N=<cases> SEED=<s>  random pairs, sizes, D, tables and memory timing
#                against the reference (default 200 cases, seed 1)
#   make sim-build DMAX=<n> PAR=<p>  the reference, RTL and harness built for DMAX (1..128)
#                disparities, PAR (1, 2, 4) a step, in build/dmax<n>_par<p> (bin/mcadsw_sim);
#                make sim and make sim-random with DMAX= or PAR= use that build
#   make ref-sim the reference model alone: Middlebury error table
#   make synth   Yosys -> OSU 0.18 um gates block by block, memories as macros, OpenSTA timing
#                (flow/synth.py and the Yosys/OpenSTA scripts in flow/; build/synth/report.md;
#                DMAX=16 for the reduced configuration; DMAX=128 PAR=4 another configuration in
#                build/synth_dmax<n>[_par<p>]; SYNTH_JOBS=2 Yosys processes at a time whose
#                expected peaks stay within SYNTH_MEM_MB=7500)
#   make synth-check  make synth, then gates, slack and memory against constraints/budget.json (CI)
#   make fpga    FPGA estimate: Yosys synth_xilinx (7-series) LUT / FF / BRAM / DSP of mcadsw_top,
#                whether it fits an XC7Z020 and an XC7A100T (build/fpga/summary.json; flow/synth.py fpga)
#   make gls     gate-level simulation of the synthesised netlist against the RTL
#                (FRAME=1 also a whole Tsukuba frame against the reference)
#   make coverage  Verilator line and toggle coverage of the RTL under the regression stimulus
#                (build/cov/coverage/summary.txt; N=<random cases>, default 40); fails below
#                90 % toggle or on an untoggled point tests/coverage/untoggled.txt does not list
#   make formal  bounded proofs (Yosys SAT) of the memory controller, AXI4 master, depth FIFO
#                and ping-pong ownership properties in formal/ (build/formal/summary.json); SELFTEST=1: each against a
#                mutant that must fail (scripts/formal.sh)
#   make mutate  mutation score: N=200 Yosys mutants (SEED=1) of the flattened design, each
#                against the kill suite (engine and AXI tests, random frames); survivors must
#                be listed in tests/mutate/survivors.txt (build/mutate/summary.json;
#                SAMPLE=20 a seeded sample of them, as CI runs; scripts/mutate.sh)
#   make lint    verilator --lint-only -Wall on every RTL module
#   make rtl-pkg regenerate rtl/mcadsw_pkg.sv from params.hpp (build/bin/gen_rtl_pkg --dmax <n>
#                --par <p> writes another configuration's package, and is the one check of DMAX/PAR)
#   make bench   Google Benchmark of the reference and OpenCV's matchers (MDE/s)
#   make report  build/report/report.md: Middlebury errors and figures next to the paper and
#                OpenCV SGBM/BM, software and simulation speed, hardware figures
#   make sweep   weight-table gamma sweep on the Middlebury pairs (docs/algorithm.md)
#   make clean   remove build/ (every build tree, synthesis and report of these targets)

BUILD_DIR ?= build
JOBS      ?= $(shell nproc)

.PHONY: all bootstrap configure build test sim sim-build wave sim-random ref-sim coverage gen-rtl-pkg synth synth-check gls fpga formal mutate lint rtl-pkg bench report sweep clean

all: build

bootstrap:
	@scripts/bootstrap.sh

configure: bootstrap
	@cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

test: build
	@cd $(BUILD_DIR) && ctest -j $(JOBS) --output-on-failure

# A configuration's build: DMAX= or PAR= on the command line select
# build/dmax<DMAX>_par<PAR> (defaults 64 and 1); otherwise the default build.
CFG_SET := $(strip $(DMAX)$(PAR))
CFG_DIR := $(if $(CFG_SET),$(BUILD_DIR)/dmax$(or $(DMAX),64)_par$(or $(PAR),1),$(BUILD_DIR))
CFG_DEP := $(if $(CFG_SET),sim-build,build)

# make sim-build DMAX=<n> PAR=<p>: that configuration's mcadsw_sim and mcadsw_sim_random
sim-build: bootstrap
	@cmake -S . -B $(CFG_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release -DMCADSW_DMAX=$(or $(DMAX),64) \
	  -DMCADSW_PAR=$(or $(PAR),1) > /dev/null
	@cmake --build $(CFG_DIR) -j $(JOBS) --target mcadsw_sim mcadsw_sim_random
	@echo "sim-build: $(CFG_DIR)/bin/mcadsw_sim (DMAX=$(or $(DMAX),64), PAR=$(or $(PAR),1))"

# make sim [CASE=<name>] [WAVES=1] [DMAX=<n> PAR=<p>]: the engine regression (scripts/sim_regression.sh)
sim: $(CFG_DEP)
	@scripts/sim_regression.sh $(CFG_DIR) "$(CASE)" "$(WAVES)"

# make sim-random [N=200] [SEED=1] [DMAX=<n> PAR=<p>]: random differential regression
N    ?= 200
SEED ?= 1
sim-random: $(CFG_DEP)
	@$(CFG_DIR)/bin/mcadsw_sim_random --cases $(N) --seed $(SEED)

# make coverage [N=40]: instrumented model in build/cov (scripts/coverage.sh)
coverage: bootstrap
	@N=$(if $(filter command line,$(origin N)),$(N),40) scripts/coverage.sh $(abspath $(BUILD_DIR)/cov)

# make wave CASE=<name>: open the waves of `make sim CASE=<name> WAVES=1`
wave:
	@f=$(BUILD_DIR)/sim/$(CASE).fst; [ -n "$(CASE)" ] || { echo "usage: make wave CASE=<name>"; exit 2; }; \
	 [ -f $$f ] || { echo "no $$f: run make sim CASE=$(CASE) WAVES=1 first"; exit 1; }; \
	 if [ -n "$$DISPLAY" ] && command -v gtkwave >/dev/null; then gtkwave $$f $(BUILD_DIR)/sim/$(CASE).gtkw; \
	 else echo "no display: waves in $$f, save file $(BUILD_DIR)/sim/$(CASE).gtkw"; fi

# The reference model alone on the bundled pairs ('all' error table).
ref-sim: build
	@scripts/eval_pairs.sh -b $(BUILD_DIR) -s middlebury -o $(BUILD_DIR)/ref
	@scripts/eval_pairs.sh -b $(BUILD_DIR) -s cif -o $(BUILD_DIR)/ref

# The package generator of the default build: writes the RTL package of a
# configuration and is the one check of DMAX and PAR (make synth, synth-check, fpga).
GEN_RTL_PKG := $(abspath $(BUILD_DIR))/bin/gen_rtl_pkg
gen-rtl-pkg: configure
	@cmake --build $(BUILD_DIR) --target gen_rtl_pkg > /dev/null

# make synth [DMAX=<n>] [PAR=<p>] [SYNTH_JOBS=2] [SYNTH_MEM_MB=7500]: gate count, memory
# inventory and timing (flow/synth.py; block by block and incremental)
SYNTH_JOBS   ?= 2
SYNTH_MEM_MB ?= 7500
SYNTH_ARGS = $(if $(DMAX),--dmax $(DMAX)) $(if $(PAR),--par $(PAR)) --jobs $(SYNTH_JOBS) \
  --mem-mb $(SYNTH_MEM_MB) --build $(abspath $(BUILD_DIR)) --gen-rtl-pkg $(GEN_RTL_PKG)
synth: gen-rtl-pkg
	@python3 flow/synth.py synth $(SYNTH_ARGS)

# make synth-check: make synth (DMAX=64), then constraints/budget.json (flow/synth.py check)
synth-check: gen-rtl-pkg
	@python3 flow/synth.py check $(SYNTH_ARGS)

# make fpga [DMAX=<n>] [PAR=<p>] [TOP=<module>]: Yosys synth_xilinx estimate, build/fpga/summary.json
# (flow/synth.py fpga, flow/fpga.tcl; TOP=mcadsw_regs a quick check of the flow, in build/fpga_<module>)
fpga: gen-rtl-pkg
	@python3 flow/synth.py fpga $(if $(DMAX),--dmax $(DMAX)) $(if $(PAR),--par $(PAR)) \
	  $(if $(TOP),--top $(TOP) --out $(abspath $(BUILD_DIR))/fpga_$(TOP)) \
	  --build $(abspath $(BUILD_DIR)) --gen-rtl-pkg $(GEN_RTL_PKG)

# make gls [DMAX=64]: the netlist in the Verilator harness (scripts/gls.sh)
gls: gen-rtl-pkg
	@DMAX=$(DMAX) FRAME=$(FRAME) BUILD_DIR=$(abspath $(BUILD_DIR)) scripts/gls.sh

lint: bootstrap
	@scripts/rtl_check.sh lint

formal: bootstrap
	@scripts/formal.sh $(BUILD_DIR) $(if $(SELFTEST),--selftest)

# make mutate [N=200] [SEED=1] [SAMPLE=k] [MUTANTS="i j"]: mutation testing (scripts/mutate.sh)
mutate: bootstrap
	@N=$(N) SEED=$(SEED) SAMPLE=$(SAMPLE) MUTANTS="$(MUTANTS)" JOBS=$(JOBS) \
	  BUILD_DIR=$(abspath $(BUILD_DIR)) scripts/mutate.sh

rtl-pkg: configure
	@cmake --build $(BUILD_DIR) --target gen_rtl_pkg > /dev/null
	@$(BUILD_DIR)/bin/gen_rtl_pkg > rtl/mcadsw_pkg.sv
	@$(BUILD_DIR)/bin/gen_rtl_pkg regs-doc > docs/registers.md
	@echo "rtl/mcadsw_pkg.sv and docs/registers.md regenerated from sw_ref/include/mcadsw/params.hpp and regs.hpp"

bench: build
	@$(BUILD_DIR)/bin/bench_ref

report: build
	@scripts/report.sh $(abspath $(BUILD_DIR))

sweep: build
	@scripts/eval_pairs.sh -b $(BUILD_DIR) -g "6 8 10 12 14 16 18 20 21 22 23 24 28 32 40"

clean:
	rm -rf $(BUILD_DIR)
