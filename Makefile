# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# User entry points. CMake (CMakeLists.txt) is the source of truth; this file
# only wraps its targets. Every target first installs what is missing: Debian packages
# and the pinned Python tool environment .venv/ (scripts/bootstrap.sh, requirements.txt).
# `make help` lists the targets: each is described once, by the `##` lines above it.

BUILD_DIR ?= build
JOBS      ?= $(shell nproc)

.PHONY: all help bootstrap tools configure build test sim sim-build wave sim-random ref-sim coverage gen-rtl-pkg synth synth-check gls power fpga formal mutate lint rtl-pkg docs docs-figures docs-waves bench report sweep clean distclean

all: build

## help: this list
help:
	@awk '/^## / { sub(/^## /, ""); if ($$0 ~ /^[a-z-]+:/) { t = $$0; sub(/:.*/, "", t); d = $$0; sub(/^[^:]*: */, "", d); printf "  make %-12s %s\n", t, d } else printf "  %-17s %s\n", "", $$0 }' $(MAKEFILE_LIST)

bootstrap:
	@scripts/bootstrap.sh

## tools: every tool the project uses, with its version and path (Debian packages and the
##   pinned tool environment .venv/ of requirements.txt; the yowasp tools compile on first call)
tools: bootstrap
	@python3 scripts/tools.py

configure: bootstrap
	@cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null

## build: the reference, the CLI, the Verilated models and the tests (build/)
build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

## test: build everything and run the test suite (what CI runs); ctest -L unit|rtl|engine|flow|slow
##   in build/ runs a part (unit: about a minute)
test: build
	@cd $(BUILD_DIR) && ctest -j $(JOBS) --output-on-failure

# A configuration's build: DMAX=, PAR=, FPGA=1 or RECT=0 on the command line select
# build/dmax<DMAX>_par<PAR>[_fpga][_norect] (defaults 64, 1, the ASIC target, the
# rectifier built in); otherwise the default build.
ifneq ($(filter-out 0 1,$(or $(FPGA),0)),)
$(error FPGA=$(FPGA): 1 builds the FPGA target, 0 or nothing the ASIC's)
endif
ifneq ($(filter-out 0 1,$(or $(RECT),1)),)
$(error RECT=$(RECT): 0 builds the engine without the rectifier, 1 or nothing with it)
endif
comma   := ,
FPGA_ON := $(filter 1,$(FPGA))
NORECT  := $(filter 0,$(RECT))
CFG_SET := $(strip $(DMAX)$(PAR)$(FPGA_ON)$(NORECT))
CFG_DIR := $(if $(CFG_SET),$(BUILD_DIR)/dmax$(or $(DMAX),64)_par$(or $(PAR),1)$(if $(FPGA_ON),_fpga)$(if $(NORECT),_norect),$(BUILD_DIR))
CFG_DEP := $(if $(CFG_SET),sim-build,build)
# A configuration's build verilates only the SoC model, and on the FPGA target with the
# rectifier the benches of the blocks it reshapes: the options tests/dmax/run.sh gives the
# same directory (CMakeLists.txt, MCADSW_BLOCK_BENCHES).
CFG_BENCHES := $(if $(and $(FPGA_ON),$(if $(NORECT),,1)),census;weight_gen;cost_agg,none)

## sim-build: DMAX=<n> PAR=<p> FPGA=1 RECT=0: the reference, RTL and harness for DMAX (1..128)
##   disparities, PAR (1, 2, 4) a step, the FPGA target's memory shapes, without the rectifier, in
##   build/dmax<n>_par<p>[_fpga][_norect]; make sim and sim-random with DMAX=, PAR=, FPGA=1 or RECT=0 use it
sim-build: bootstrap
	@cmake -S . -B $(CFG_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release -DMCADSW_DMAX=$(or $(DMAX),64) \
	  -DMCADSW_PAR=$(or $(PAR),1) -DMCADSW_FPGA=$(if $(FPGA_ON),ON,OFF) -DMCADSW_RECT=$(if $(NORECT),OFF,ON) \
	  -DMCADSW_BLOCK_BENCHES="$(CFG_BENCHES)" -DMCADSW_CORE_MODEL=OFF > /dev/null
	@cmake --build $(CFG_DIR) -j $(JOBS) --target mcadsw_sim mcadsw_sim_random
	@echo "sim-build: $(CFG_DIR)/bin/mcadsw_sim (DMAX=$(or $(DMAX),64), PAR=$(or $(PAR),1), $(if $(FPGA_ON),FPGA,ASIC) target$(if $(NORECT),$(comma) without the rectifier))"

## sim: the engine regression on the bundled pairs, every pixel against the reference
##   (build/sim/summary.json; CASE=<name> one case, WAVES=1 an FST, DMAX= PAR= FPGA=1 RECT=0 a configuration)
sim: $(CFG_DEP)
	@python3 flow/sim_regression.py --build $(CFG_DIR) --case "$(CASE)" --waves "$(WAVES)"

## sim-random: N=200 SEED=1: random pairs, sizes, D, tables and memory timing against the reference
N    ?= 200
SEED ?= 1
sim-random: $(CFG_DEP)
	@$(CFG_DIR)/bin/mcadsw_sim_random --cases $(N) --seed $(SEED)

## coverage: Verilator line and toggle coverage under the regression stimulus (build/cov;
##   N=40 random cases); fails below 90 % toggle or on a point tests/coverage/untoggled.txt lacks
coverage: bootstrap
	@python3 flow/coverage.py --build $(abspath $(BUILD_DIR)/cov) --n $(if $(filter command line,$(origin N)),$(N),40) \
	  $(if $(MIN_TOGGLE),--min-toggle $(MIN_TOGGLE))

## wave: CASE=<name>: open the waves of `make sim CASE=<name> WAVES=1` in gtkwave
wave:
	@f=$(BUILD_DIR)/sim/$(CASE).fst; [ -n "$(CASE)" ] || { echo "usage: make wave CASE=<name>"; exit 2; }; \
	 [ -f $$f ] || { echo "no $$f: run make sim CASE=$(CASE) WAVES=1 first"; exit 1; }; \
	 if [ -n "$$DISPLAY" ] && command -v gtkwave >/dev/null; then gtkwave $$f $(BUILD_DIR)/sim/$(CASE).gtkw; \
	 else echo "no display: waves in $$f, save file $(BUILD_DIR)/sim/$(CASE).gtkw"; fi

## ref-sim: the reference model alone on the bundled pairs ("all" error table)
ref-sim: build
	@scripts/eval_pairs.sh -b $(BUILD_DIR) -s middlebury -o $(BUILD_DIR)/ref
	@scripts/eval_pairs.sh -b $(BUILD_DIR) -s cif -o $(BUILD_DIR)/ref

# The package generator of the default build: writes the RTL package of a
# configuration and is the one check of DMAX and PAR (make synth, synth-check, fpga).
GEN_RTL_PKG := $(abspath $(BUILD_DIR))/bin/gen_rtl_pkg
gen-rtl-pkg: configure
	@cmake --build $(BUILD_DIR) --target gen_rtl_pkg > /dev/null

SYNTH_JOBS   ?= 2
SYNTH_MEM_MB ?= 7500
SYNTH_ARGS = $(if $(DMAX),--dmax $(DMAX)) $(if $(PAR),--par $(PAR)) --jobs $(SYNTH_JOBS) \
  $(if $(CLOCK_GATE_MIN),--clock-gate-min $(CLOCK_GATE_MIN)) \
  --mem-mb $(SYNTH_MEM_MB) --build $(abspath $(BUILD_DIR)) --gen-rtl-pkg $(GEN_RTL_PKG)
## synth: Yosys to OSU 0.18 um gates block by block, memories as macros, OpenSTA timing
##   (build/synth/report.md; flow/; DMAX= PAR= another configuration, SYNTH_JOBS=2, SYNTH_MEM_MB=7500,
##   CLOCK_GATE_MIN=4: clock-gate groups of 4+ flip-flops sharing an enable, 0: none, in build/synth_ungated)
synth: gen-rtl-pkg
	@python3 flow/synth.py synth $(SYNTH_ARGS)

## synth-check: make synth, then gates, slack and memory against constraints/budget.json (CI)
synth-check: gen-rtl-pkg
	@python3 flow/synth.py check $(SYNTH_ARGS)

## power: mW at 95 MHz from the activity of real frames (raw, LR) on the netlist of make synth, by
##   block, energy per CIF frame (build/power/report.md; make synth first; DMAX= PAR= as make synth)
power: gen-rtl-pkg
	@cmake --build $(BUILD_DIR) --target mcadsw_sim_core mcadsw_activity > /dev/null
	@python3 flow/power.py $(if $(DMAX),--dmax $(DMAX)) $(if $(PAR),--par $(PAR)) --build $(abspath $(BUILD_DIR)) \
	  --gen-rtl-pkg $(GEN_RTL_PKG)

## fpga: the FPGA target of the SoC: ECP5 synth_ecp5 in the ULX3S shell, cells by block, place and route
##   and bitstream (nextpnr-ecp5, ecppack) when it fits, and the fit without the rectifier beside it
##   (build/fpga/ecp5_norect, packed only); XC7Z020 estimate (Yosys synth_xilinx); bars and
##   frames a second from make sim FPGA=1 (build/fpga/summary.json, report.md; DMAX= PAR= as make synth;
##   TOP=mcadsw_regs a quick 7-series check, in build/fpga_<module>)
FPGA_ROOT := $(abspath $(BUILD_DIR))/$(if $(filter-out 64_1,$(or $(DMAX),64)_$(or $(PAR),1)),fpga_dmax$(or $(DMAX),64)_par$(or $(PAR),1),fpga)
FPGA_SIM  := $(abspath $(BUILD_DIR))/dmax$(or $(DMAX),64)_par$(or $(PAR),1)_fpga/sim/summary.json
fpga: gen-rtl-pkg
ifneq ($(TOP),)
	@python3 flow/synth.py fpga $(if $(DMAX),--dmax $(DMAX)) $(if $(PAR),--par $(PAR)) \
	  --top $(TOP) --out $(abspath $(BUILD_DIR))/fpga_$(TOP) --build $(abspath $(BUILD_DIR)) --gen-rtl-pkg $(GEN_RTL_PKG)
else
	@rc=0; python3 flow/ecp5.py soc --dmax $(or $(DMAX),64) --par $(or $(PAR),1) --out $(FPGA_ROOT)/ecp5 \
	  --gen-rtl-pkg $(GEN_RTL_PKG) || rc=$$?; [ $$rc -le 1 ] || exit $$rc; \
	 rc=0; python3 flow/ecp5.py soc --no-rect --no-pnr --dmax $(or $(DMAX),64) --par $(or $(PAR),1) --out $(FPGA_ROOT)/ecp5_norect \
	  --gen-rtl-pkg $(GEN_RTL_PKG) || rc=$$?; [ $$rc -le 1 ] || exit $$rc; \
	 python3 flow/synth.py fpga $(if $(DMAX),--dmax $(DMAX)) $(if $(PAR),--par $(PAR)) --out $(FPGA_ROOT)/xc7 \
	  --build $(abspath $(BUILD_DIR)) --gen-rtl-pkg $(GEN_RTL_PKG) || exit $$?; \
	 [ -f $(FPGA_SIM) ] || echo "fpga: no $(FPGA_SIM): frames a second need make sim FPGA=1 $(if $(DMAX),DMAX=$(DMAX)) $(if $(PAR),PAR=$(PAR))"; \
	 python3 flow/fpga.py report --root $(FPGA_ROOT) --sim $(FPGA_SIM)
endif

## gls: the synthesised netlist in the Verilator harness against the RTL (FRAME=1 also a Tsukuba frame)
gls: gen-rtl-pkg
	@DMAX=$(DMAX) FRAME=$(FRAME) BUILD_DIR=$(abspath $(BUILD_DIR)) scripts/gls.sh

## lint: verilator --lint-only -Wall on every RTL module, with the ASIC and the FPGA target's package,
##   on the board shell of make fpga around the SoC, and on the vendor-tool wrapper rtl/mcadsw_axi.v
lint: configure
	@python3 flow/rtl_check.py lint
	@python3 flow/rtl_check.py lint $(BUILD_DIR)/rtl/fpga/mcadsw_pkg.sv
	@python3 flow/rtl_check.py board $(BUILD_DIR)/rtl/fpga/mcadsw_pkg.sv
	@python3 flow/rtl_check.py wrapper

## formal: SymbiYosys proofs of formal/*.sby (the blocks' MCADSW_ASSERTs and formal/*_props.sv)
##   and their covers (build/formal/summary.json); SELFTEST=1: each against a mutant that must fail
formal: bootstrap
	@python3 flow/formal.py --build $(BUILD_DIR) $(if $(SELFTEST),--selftest)

## mutate: N=200 SEED=1 Yosys mutants of the flattened design against the kill suite; survivors
##   must be listed in tests/mutate/survivors.txt (SAMPLE=12 a seeded sample, as CI runs; JOBS=,
##   MUTANTS="3 17" again, REPORT_ONLY=1, NO_RECT=1, TIMEOUT=300 a stage, REKEY=1 the list's keys
##   carried over to an RTL change that kept the draw: flow/mutate.py)
mutate: bootstrap
	@python3 flow/mutate.py $(if $(N),--n "$(N)") $(if $(SEED),--seed "$(SEED)") $(if $(SAMPLE),--sample "$(SAMPLE)") \
	  $(if $(strip $(MUTANTS)),--mutants "$(MUTANTS)") $(if $(JOBS),--jobs "$(JOBS)") \
	  $(if $(filter 1,$(REPORT_ONLY)),--report-only) $(if $(filter 1,$(REKEY)),--rekey) \
	  $(if $(NO_RECT),--no-rect "$(NO_RECT)") \
	  $(if $(TIMEOUT),--timeout "$(TIMEOUT)") --build $(abspath $(BUILD_DIR))

## rtl-pkg: regenerate rtl/mcadsw_pkg.sv, rtl/rect/mcadsw_rect_pkg.sv, docs/registers.md, the C header,
##   the FuseSoC core mcadsw.core, the IP-XACT component component.xml and docs/datasheet.md from their sources
rtl-pkg: configure
	@cmake --build $(BUILD_DIR) --target gen_rtl_pkg > /dev/null
	@$(BUILD_DIR)/bin/gen_rtl_pkg > rtl/mcadsw_pkg.sv
	@$(BUILD_DIR)/bin/gen_rtl_pkg regs-doc > docs/registers.md
	@$(BUILD_DIR)/bin/gen_rtl_pkg rect-pkg > rtl/rect/mcadsw_rect_pkg.sv
	@$(BUILD_DIR)/bin/gen_rtl_pkg c-header > driver/include/mcadsw/mcadsw_regs.h
	@python3 flow/fusesoc_core.py
	@python3 flow/ipxact.py --gen-rtl-pkg $(BUILD_DIR)/bin/gen_rtl_pkg
	@.venv/bin/python flow/datasheet.py render --gen-rtl-pkg $(BUILD_DIR)/bin/gen_rtl_pkg
	@echo "rtl/mcadsw_pkg.sv, rtl/rect/mcadsw_rect_pkg.sv, docs/registers.md and driver/include/mcadsw/mcadsw_regs.h regenerated from sw_ref/include/mcadsw/params.hpp and regs.hpp;"
	@echo "mcadsw.core from rtl/mcadsw.f, component.xml from rtl/mcadsw_axi.v, regs.hpp and the package, docs/datasheet.md"

## docs: the datasheet docs/datasheet.md (figures from docs/datasheet/figures.json, ports, registers,
##   timing diagrams rendered by wavedrom) and its HTML build/docs/datasheet.html (flow/datasheet.py)
docs: gen-rtl-pkg
	@.venv/bin/python flow/datasheet.py render --gen-rtl-pkg $(GEN_RTL_PKG) --html $(abspath $(BUILD_DIR))/docs/datasheet.html

## docs-figures: gather the datasheet's figures from the summaries of make synth-check, sim, sim FPGA=1,
##   power and fpga in build/ into docs/datasheet/figures.json (then make docs)
docs-figures: bootstrap
	@.venv/bin/python flow/datasheet.py collect --build $(abspath $(BUILD_DIR))

## docs-waves: record the datasheet's timing diagrams from a simulation (tests/cocotb/waves.py, Icarus)
docs-waves: build
	@.venv/bin/python tests/cocotb/run.py $(abspath $(BUILD_DIR)) --waves docs/datasheet/waves

## bench: Google Benchmark of the reference and OpenCV's matchers (MDE/s)
bench: build
	@$(BUILD_DIR)/bin/bench_ref

## bench-sim: RUNS=5 BASELINE=<commit|exe>: the model's speed on CIF Teddy D=64 raw, LR and rectified
##   (medians, kcycles/s; with BASELINE, runs alternating with that model and the ratio)
bench-sim: build
	@python3 flow/bench_sim.py --build $(abspath $(BUILD_DIR)) --runs $(or $(RUNS),5) \
	  $(if $(FRAMES),--frames "$(FRAMES)") $(if $(BASELINE),--baseline "$(BASELINE)")

## profile-sim: where a CIF D=64 frame's simulated time goes, per Verilog module and in the harness
##   (perf and Verilator's --prof-cfuncs; build/prof/profile/summary.txt); CALLGRIND=1: make sim's
##   model on a crop under callgrind, instructions by RTL instance (build/profile_callgrind/summary.txt)
ifeq ($(CALLGRIND),1)
profile-sim: build
	@python3 flow/profile_sim.py --callgrind --build $(abspath $(BUILD_DIR))
else
profile-sim: bootstrap
	@python3 flow/profile_sim.py --build $(abspath $(BUILD_DIR)/prof)
endif

## report: build/report/report.md: Middlebury errors next to the paper and OpenCV, speed, hardware
report: build
	@python3 flow/report.py --build $(abspath $(BUILD_DIR))

## sweep: the weight table's gamma swept on the Middlebury pairs (docs/algorithm.md)
sweep: build
	@scripts/eval_pairs.sh -b $(BUILD_DIR) -g "6 8 10 12 14 16 18 20 21 22 23 24 28 32 40"

## clean: remove build/ (every build tree of these targets)
clean:
	rm -rf $(BUILD_DIR)

## distclean: make clean, and remove the tool environment .venv/ (the next make installs it again)
distclean: clean
	rm -rf .venv .venv.lock
