#!/usr/bin/env bash
# The netlist and macro models OpenSTA reads (called by scripts/synth.sh).
#   scripts/sta_netlist.sh NETLIST OUT_DIR LIBERTY
# NETLIST is the gate-level netlist of `make synth` (also the one gate-level
# simulation uses): the block netlists assembled by scripts/synth.sh (mcadsw_engine
# instantiating one module per block). Every instantiated module must be defined in it, a cell or a macro, with
# matching port widths (hierarchy -check; a resized port stops here). OpenSTA's
# Verilog reader takes neither instance parameters nor concatenations on the left
# of an assign, so this writes
#   OUT_DIR/mcadsw_engine_sta.v  flattened by Yosys, nets split to bits, remaining
#                             wire-to-wire assigns replaced by BUFX2, every MCADSW_RAM instance renamed to a
#                             parameter-free cell per shape (MCADSW_RAM_S<words>_W<bits>_A<addr bits>_<SYNC|ASYNC>,
#                             _WE when all bit write enables are one net: a word write enable)
#   OUT_DIR/mcadsw_ram.lib    a liberty cell per shape, timing from constraints/mcadsw_ram_timing.cfg
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
netlist=$1; out=$2; lib=$3
cfg=$root/constraints/mcadsw_ram_timing.cfg

cat > "$out/sta_netlist.ys" <<YS
read_verilog -lib $root/sim/gls/mcadsw_ram_model.v
read_liberty -lib $lib
read_verilog $netlist
hierarchy -check -top mcadsw_engine
flatten
# Single-bit nets, so that bits of one wire that alias another bit merge
# instead of becoming buffers (a write enable fanned out to 384 aliases did).
splitnets
opt_clean -purge
insbuf -buf BUFX2 A Y
write_verilog -noattr -noexpr -nohex -nodec $out/mcadsw_engine_flat.v
YS
yosys -q -l "$out/sta_netlist.log" "$out/sta_netlist.ys" > /dev/null || {
  tail -20 "$out/sta_netlist.log"; echo "sta_netlist: yosys failed" >&2; exit 1; }
if grep -q "Resizing cell port" "$out/sta_netlist.log"; then
  grep "Resizing cell port" "$out/sta_netlist.log" | awk 'NR <= 5' >&2
  echo "sta_netlist: port widths of an instance and its module differ in $netlist" >&2; exit 1
fi

# Parameterised macro instances -> one cell name per shape.
awk -v shapes="$out/mcadsw_ram_shapes.txt" '
  function val(s,   v, i, b) {           # 32'"'"'b0101 / 1'"'"'b1 / decimal -> integer
    sub(/^.*\(/, "", s); sub(/\).*$/, "", s)
    if (s ~ /'"'"'b/) { b = s; sub(/^.*'"'"'b/, "", b); v = 0; for (i = 1; i <= length(b); i++) v = v * 2 + substr(b, i, 1); return v }
    if (s ~ /'"'"'d/) sub(/^.*'"'"'d/, "", s)
    return s + 0
  }
  /^ *MCADSW_RAM #\($/ { inmac = 1; delete p; next }
  inmac && /^ *\./ { name = $1; sub(/^\./, "", name); sub(/\(.*$/, "", name); p[name] = val($0); next }
  inmac && /^ *\) / {
    if (p["RD_PORTS"] != 1 || p["WR_PORTS"] != 1) { print "sta_netlist: multi-port macro" > "/dev/stderr"; exit 1 }
    cell = sprintf("MCADSW_RAM_S%d_W%d_A%d_%s", p["SIZE"], p["WIDTH"], p["ABITS"], p["RD_CLK_ENABLE"] ? "SYNC" : "ASYNC")
    if (!(cell in seen)) { seen[cell] = 1; printf "%s %d %d %d %d\n", cell, p["SIZE"], p["WIDTH"], p["ABITS"], p["RD_CLK_ENABLE"] > shapes }
    line = $0; sub(/^ *\)/, "  " cell, line); print line; inmac = 0; next
  }
  inmac { print "sta_netlist: unexpected line in a macro instance: " $0 > "/dev/stderr"; exit 1 }
  { print }
' "$out/mcadsw_engine_flat.v" > "$out/mcadsw_engine_renamed.v"
rm -f "$out/mcadsw_engine_flat.v"

# A macro whose bit write enables are all one net is a macro with a word write
# enable (WR_WE): that is how it would be built, and it keeps a single enable
# from appearing to drive thousands of macro pins (the cell becomes <shape>_WE).
awk '
  function flush(   i) { for (i = 1; i <= nbuf; i++) print buf[i]; nbuf = 0 }
  /^ *MCADSW_RAM_[A-Z0-9_]+ .*\($/ { inst = 1; nbuf = 0; buf[++nbuf] = $0; next }
  inst && /^ *\.WR_EN\(\{ .* \}\),?$/ {
    body = $0; sub(/^ *\.WR_EN\(\{ /, "", body); comma = (body ~ /,$/); sub(/ \}\),?$/, "", body)
    n = split(body, items, ", "); same = 1
    for (i = 2; i <= n; i++) if (items[i] != items[1]) { same = 0; break }
    if (same) { sub(/^ *MCADSW_RAM_[A-Z0-9_]+/, "&_WE", buf[1])
      buf[++nbuf] = "    .WR_WE(" items[1] ")" (comma ? "," : ""); next }
  }
  inst { buf[++nbuf] = $0; if ($0 ~ /^ *\);$/) { inst = 0; flush() } next }
  { print }
' "$out/mcadsw_engine_renamed.v" > "$out/mcadsw_engine_sta.v"
rm -f "$out/mcadsw_engine_renamed.v"
if grep -q "#(" "$out/mcadsw_engine_sta.v"; then
  echo "sta_netlist: parameterised instances left in $out/mcadsw_engine_sta.v" >&2; exit 1
fi

# Liberty: bus types and one cell per shape.
cfgv() { awk -v k="$1" '$1 == k {print $2}' "$cfg"; }
clk_to_q=$(cfgv clk_to_q); access=$(cfgv async_access); setup=$(cfgv setup); hold=$(cfgv hold)
slew=$(cfgv out_transition); cap=$(cfgv pin_cap)
awk -v clk_to_q="$clk_to_q" -v access="$access" -v setup="$setup" -v hold="$hold" -v slew="$slew" -v cap="$cap" '
  function arc(rel, type, d) {
    printf "      timing () { related_pin : \"%s\"; timing_type : %s;\n", rel, type
    if (type ~ /setup|hold/)
      printf "        rise_constraint (scalar) { values (\"%s\"); } fall_constraint (scalar) { values (\"%s\"); } }\n", d, d
    else
      printf "        cell_rise (scalar) { values (\"%s\"); } cell_fall (scalar) { values (\"%s\"); }\n        rise_transition (scalar) { values (\"%s\"); } fall_transition (scalar) { values (\"%s\"); } }\n", d, d, slew, slew
  }
  function input_bus(name, w, clk) {
    printf "    bus (%s) { bus_type : bus%d; direction : input; capacitance : %s;\n", name, w, cap
    arc(clk, "setup_rising", setup); arc(clk, "hold_rising", hold); print "    }"
  }
  function input_pin(name, clk) {
    printf "    pin (%s) { direction : input; capacitance : %s;\n", name, cap
    arc(clk, "setup_rising", setup); arc(clk, "hold_rising", hold); print "    }"
  }
  { cell[NR] = $1; size[NR] = $2; width[NR] = $3; abits[NR] = $4; sync[NR] = $5; w[$3] = 1; w[$4] = 1 }
  END {
    print "/* Generated by scripts/sta_netlist.sh from constraints/mcadsw_ram_timing.cfg: timing models"
    print "   of the MCADSW_RAM memory macros (one cell per shape). Not a characterised library. */"
    print "library (mcadsw_ram) {"
    print "  delay_model : table_lookup;"
    print "  time_unit : \"1ns\"; voltage_unit : \"1V\"; current_unit : \"1uA\";"
    print "  pulling_resistance_unit : \"1kohm\"; leakage_power_unit : \"1nW\"; capacitive_load_unit (1,pf);"
    print "  slew_upper_threshold_pct_rise : 80; slew_lower_threshold_pct_rise : 20;"
    print "  slew_upper_threshold_pct_fall : 80; slew_lower_threshold_pct_fall : 20;"
    print "  input_threshold_pct_rise : 50; input_threshold_pct_fall : 50;"
    print "  output_threshold_pct_rise : 50; output_threshold_pct_fall : 50;"
    print "  nom_process : 1; nom_voltage : 1.8; nom_temperature : 25;"
    for (n in w)
      printf "  type (bus%d) { base_type : array; data_type : bit; bit_width : %d; bit_from : %d; bit_to : 0; downto : true; }\n", n, n, n - 1
    for (v = 0; v < 2 * NR; v++) {
      i = int(v / 2) + 1; we = v % 2
      printf "  cell (%s%s) {\n    area : 0; dont_touch : true; dont_use : true;\n", cell[i], we ? "_WE" : ""
      printf "    pin (RD_CLK) { direction : input; capacitance : %s; clock : true; }\n", cap
      printf "    pin (WR_CLK) { direction : input; capacitance : %s; clock : true; }\n", cap
      printf "    pin (RD_ARST) { direction : input; capacitance : %s; }\n", cap
      if (sync[i]) { input_pin("RD_EN", "RD_CLK"); input_bus("RD_ADDR", abits[i], "RD_CLK") }
      else {
        printf "    pin (RD_EN) { direction : input; capacitance : %s; }\n", cap
        printf "    bus (RD_ADDR) { bus_type : bus%d; direction : input; capacitance : %s; }\n", abits[i], cap
      }
      if (we) input_pin("WR_WE", "WR_CLK"); else input_bus("WR_EN", width[i], "WR_CLK")
      input_bus("WR_ADDR", abits[i], "WR_CLK"); input_bus("WR_DATA", width[i], "WR_CLK")
      printf "    bus (RD_DATA) { bus_type : bus%d; direction : output;\n", width[i]
      if (sync[i]) arc("RD_CLK", "rising_edge", clk_to_q)
      else {
        printf "      timing () { related_bus_pins : \"RD_ADDR\"; timing_type : combinational; timing_sense : non_unate;\n"
        printf "        cell_rise (scalar) { values (\"%s\"); } cell_fall (scalar) { values (\"%s\"); }\n        rise_transition (scalar) { values (\"%s\"); } fall_transition (scalar) { values (\"%s\"); } }\n", access, access, slew, slew
        arc("WR_CLK", "rising_edge", access)
      }
      print "    }\n  }"
    }
    print "}"
  }' "$out/mcadsw_ram_shapes.txt" > "$out/mcadsw_ram.lib"
echo "sta_netlist: $(wc -l < "$out/mcadsw_ram_shapes.txt") macro shapes -> $out/mcadsw_ram.lib, netlist $out/mcadsw_engine_sta.v"
