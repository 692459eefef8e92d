// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// mcadsw_activity: switching activity of the synthesised engine netlist for
// `make power` (flow/power.py, docs/results.md "Power").
//
// OpenSTA 2.0.17 (Debian) has no read_vcd / read_saif, and an activity set on a
// pin does not propagate through the logic after it, so every net needs its own
// activity from a simulation. A gate-level VCD of the ~365k cells would be huge;
// instead this program simulates the OpenSTA netlist itself (the flat
// mcadsw_engine_sta.v of `make synth`, zero-delay, cycle by cycle, event-driven,
// the clock's two phases simulated so that the clock gates work as in silicon:
// INVX1 -> LATCH -> AND2 on clk_i as flow/clock_gate.py builds them, and the same on a
// gated clock, a gate behind a gate: a block's gates behind a gate of the whole block)
// on the input ports an RTL run recorded (mcadsw_sim_core --record-ports FILE),
// and counts every net's transitions and high cycles. The RTL run's output ports
// are compared every cycle: a mismatch stops the run (the netlist, this
// simulator or the recording is wrong), so the activity is that of the frame the
// RTL computed, bit for bit. Glitches are not modelled (zero delay).
//
//   mcadsw_activity NETLIST.v PORTS.txt OUT_PREFIX [--hold N]
//
// Writes OUT_PREFIX.frame.txt (the recorded cycles) and, with --hold N,
// OUT_PREFIX.idle.txt: N further cycles with the last configuration held and
// start_i, mem_gnt_i and mem_rvalid_i low (the engine configured, not started).
// Each file: "cycles N", then "net <name> <transitions> <high cycles>" for every
// net (high cycles in halves: a gated clock is high half a cycle)
// net, "macro <instance> <cell> <words> <bits> <reads> <writes>" for every memory
// macro (reads: RD_EN high at a clock edge; writes: any write enable high).
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace {

[[noreturn]] void fail(const std::string& msg) { throw std::runtime_error(msg); }

// ---- Cells: the OSU 0.18 um cells the flow maps to (sim/gls/osu018_cells.v) ------------
enum class Kind { kComb, kDff, kDffSr, kMacro };
struct CellType {
  Kind kind;
  std::vector<std::string> in, out;  // pin names, in evaluation order
};

const std::map<std::string, CellType>& cell_types() {
  static const std::map<std::string, CellType> t = [] {
    std::map<std::string, CellType> m;
    const auto comb = [&](const char* n, std::vector<std::string> in, std::vector<std::string> out) {
      m[n] = {Kind::kComb, std::move(in), std::move(out)};
    };
    for (const char* n : {"AND2X1", "AND2X2", "NAND2X1", "NOR2X1", "OR2X1", "OR2X2", "XOR2X1", "XNOR2X1"})
      comb(n, {"A", "B"}, {"Y"});
    for (const char* n : {"BUFX2", "BUFX4", "CLKBUF1", "CLKBUF2", "CLKBUF3", "INVX1", "INVX2", "INVX4", "INVX8"})
      comb(n, {"A"}, {"Y"});
    comb("AOI21X1", {"A", "B", "C"}, {"Y"});
    comb("OAI21X1", {"A", "B", "C"}, {"Y"});
    comb("NAND3X1", {"A", "B", "C"}, {"Y"});
    comb("NOR3X1", {"A", "B", "C"}, {"Y"});
    comb("AOI22X1", {"A", "B", "C", "D"}, {"Y"});
    comb("OAI22X1", {"A", "B", "C", "D"}, {"Y"});
    comb("MUX2X1", {"A", "B", "S"}, {"Y"});
    comb("FAX1", {"A", "B", "C"}, {"YC", "YS"});
    comb("LATCH", {"D", "CLK"}, {"Q"});  // transparent while CLK is high (a level-sensitive gate)
    comb("HAX1", {"A", "B"}, {"YC", "YS"});
    m["DFFPOSX1"] = {Kind::kDff, {"CLK", "D"}, {"Q"}};
    m["DFFSR"] = {Kind::kDffSr, {"CLK", "D", "R", "S"}, {"Q"}};
    return m;
  }();
  return t;
}

// ---- The netlist ----------------------------------------------------------------------------
struct Cell {
  std::string type, name;
  Kind kind;
  std::vector<int> in, out;
};
struct Macro {
  std::string name, type;
  int words = 0, bits = 0, abits = 0;
  bool word_we = false;
  int rd_en = -1, clk = -1;  // clk: RD_CLK = WR_CLK, clk_i or a gated clock
  std::vector<int> rd_addr, rd_data, wr_addr, wr_data, wr_en;  // LSB first
  std::vector<std::vector<uint8_t>> mem;
  long reads = 0, writes = 0;
};

struct Netlist {
  std::vector<std::string> net_name;
  std::unordered_map<std::string, int> net_id;
  std::map<std::string, std::pair<int, int>> bus;  // port -> (msb, lsb)
  std::vector<std::string> inputs, outputs;        // port names
  std::vector<Cell> cells;
  std::vector<Macro> macros;
  int c0 = -1, c1 = -1, clk = -1;  // constants, the clock port

  int net(const std::string& n) {
    auto it = net_id.find(n);
    if (it != net_id.end()) return it->second;
    const int id = int(net_name.size());
    net_name.push_back(n);
    net_id.emplace(n, id);
    return id;
  }
  // The bits of a port, LSB first.
  std::vector<int> port_bits(const std::string& p) {
    const auto it = bus.find(p);
    if (it == bus.end()) return {net(p)};
    std::vector<int> b;
    const auto [msb, lsb] = it->second;
    for (int i = lsb; msb >= lsb ? i <= msb : i >= msb; msb >= lsb ? ++i : --i)
      b.push_back(net(p + "[" + std::to_string(i) + "]"));
    return b;
  }
};

// Tokens of Yosys' write_verilog output: escaped identifiers (\name up to
// whitespace), identifiers, numbers with base, punctuation.
class Lexer {
 public:
  explicit Lexer(std::string text) : s_(std::move(text)) {}
  std::string next() {
    for (;;) {
      while (i_ < s_.size() && std::isspace(uint8_t(s_[i_]))) ++i_;
      if (i_ + 1 < s_.size() && s_[i_] == '/' && s_[i_ + 1] == '/') {
        while (i_ < s_.size() && s_[i_] != '\n') ++i_;
        continue;
      }
      if (i_ + 1 < s_.size() && s_[i_] == '/' && s_[i_ + 1] == '*') {
        const size_t e = s_.find("*/", i_ + 2);
        i_ = e == std::string::npos ? s_.size() : e + 2;
        continue;
      }
      break;
    }
    if (i_ >= s_.size()) return "";
    const size_t b = i_;
    if (s_[i_] == '\\') {
      while (i_ < s_.size() && !std::isspace(uint8_t(s_[i_]))) ++i_;
      return s_.substr(b + 1, i_ - b - 1);  // the name without the backslash
    }
    if (std::isalnum(uint8_t(s_[i_])) || s_[i_] == '_' || s_[i_] == '$') {
      while (i_ < s_.size() && (std::isalnum(uint8_t(s_[i_])) || s_[i_] == '_' || s_[i_] == '$' || s_[i_] == '\''))
        ++i_;
      return s_.substr(b, i_ - b);
    }
    ++i_;
    return s_.substr(b, 1);
  }
  std::string peek() {
    const size_t save = i_;
    std::string t = next();
    i_ = save;
    return t;
  }
  void expect(const std::string& t) {
    const std::string g = next();
    if (g != t) fail("netlist: expected '" + t + "', found '" + g + "'");
  }

 private:
  std::string s_;
  size_t i_ = 0;
};

// A constant such as 1'b0 or 32'b0101...: its bits, LSB first.
std::vector<int> constant_bits(Netlist& nl, const std::string& tok) {
  const size_t q = tok.find('\'');
  const int width = std::stoi(tok.substr(0, q));
  if (tok[q + 1] != 'b') fail("netlist: constant not in binary: " + tok);
  const std::string digits = tok.substr(q + 2);
  std::vector<int> bits(size_t(width), nl.c0);
  for (int i = 0; i < width && i < int(digits.size()); ++i)
    bits[size_t(i)] = digits[digits.size() - 1 - size_t(i)] == '1' ? nl.c1 : nl.c0;
  return bits;
}

// An expression: a net, a bit of a port, a whole port, a constant or a
// concatenation of these. Its bits, LSB first.
std::vector<int> expression(Netlist& nl, Lexer& lx) {
  std::string t = lx.next();
  if (t == "{") {
    std::vector<std::vector<int>> parts;
    for (;;) {
      parts.push_back(expression(nl, lx));
      const std::string sep = lx.next();
      if (sep == "}") break;
      if (sep != ",") fail("netlist: bad concatenation near '" + sep + "'");
    }
    std::vector<int> bits;
    for (auto it = parts.rbegin(); it != parts.rend(); ++it) bits.insert(bits.end(), it->begin(), it->end());
    return bits;
  }
  if (!t.empty() && std::isdigit(uint8_t(t[0]))) return constant_bits(nl, t);
  if (lx.peek() == "[") {
    lx.next();
    const std::string idx = lx.next();
    if (lx.peek() == ":") fail("netlist: part-select of " + t + " not supported");
    lx.expect("]");
    return {nl.net(t + "[" + idx + "]")};
  }
  return nl.port_bits(t);
}

// Memory macro cell names: MCADSW_RAM_S<words>_W<bits>_A<abits>_SYNC[_WE] (flow/sta.py).
bool parse_macro_type(const std::string& type, Macro& m) {
  if (type.rfind("MCADSW_RAM_S", 0) != 0) return false;
  if (std::sscanf(type.c_str(), "MCADSW_RAM_S%d_W%d_A%d", &m.words, &m.bits, &m.abits) != 3)
    fail("netlist: cannot read the shape of macro cell " + type);
  if (type.find("_ASYNC") != std::string::npos) fail("netlist: asynchronous-read macro " + type + " not modelled");
  m.word_we = type.size() > 3 && type.compare(type.size() - 3, 3, "_WE") == 0;
  return true;
}

Netlist read_netlist(const std::string& path) {
  std::ifstream f(path);
  if (!f) fail("cannot read the netlist " + path);
  std::stringstream ss;
  ss << f.rdbuf();
  Lexer lx(ss.str());
  Netlist nl;
  nl.c0 = nl.net("1'b0");
  nl.c1 = nl.net("1'b1");
  std::string t;
  while ((t = lx.next()) != "module")
    if (t.empty()) fail("netlist: no module in " + path);
  lx.next();  // module name
  while (lx.next() != ";") {
  }
  for (;;) {
    t = lx.next();
    if (t.empty()) fail("netlist: no endmodule");
    if (t == "endmodule") break;
    if (t == "input" || t == "output" || t == "wire") {
      int msb = -1, lsb = -1;
      if (lx.peek() == "[") {
        lx.next();
        msb = std::stoi(lx.next());
        lx.expect(":");
        lsb = std::stoi(lx.next());
        lx.expect("]");
      }
      const std::string name = lx.next();
      lx.expect(";");
      if (msb >= 0) nl.bus[name] = {msb, lsb};
      if (t == "input") nl.inputs.push_back(name);
      if (t == "output") nl.outputs.push_back(name);
      continue;
    }
    if (t == "assign") {  // lhs = rhs: a buffer
      const std::vector<int> lhs = expression(nl, lx);
      lx.expect("=");
      const std::vector<int> rhs = expression(nl, lx);
      lx.expect(";");
      if (lhs.size() != rhs.size()) fail("netlist: assign of different widths");
      for (size_t i = 0; i < lhs.size(); ++i) nl.cells.push_back({"BUFX2", "assign", Kind::kComb, {rhs[i]}, {lhs[i]}});
      continue;
    }
    // An instance: TYPE NAME ( .PIN(expr), ... );
    const std::string type = t, name = lx.next();
    lx.expect("(");
    std::map<std::string, std::vector<int>> pins;
    while (lx.peek() != ")") {
      lx.expect(".");
      const std::string pin = lx.next();
      lx.expect("(");
      pins[pin] = lx.peek() == ")" ? std::vector<int>{} : expression(nl, lx);
      lx.expect(")");
      if (lx.peek() == ",") lx.next();
    }
    lx.expect(")");
    lx.expect(";");
    const auto pin = [&](const std::string& p) -> std::vector<int>& {
      auto it = pins.find(p);
      if (it == pins.end()) fail("netlist: " + type + " " + name + " has no pin " + p);
      return it->second;
    };
    Macro m;
    if (parse_macro_type(type, m)) {
      m.name = name;
      m.type = type;
      if (pin("RD_CLK").size() != 1 || pin("RD_CLK") != pin("WR_CLK"))
        fail("netlist: macro " + name + " has two clocks");
      m.clk = pin("RD_CLK")[0];  // clk_i or a gated clock: check_clocks
      m.rd_addr = pin("RD_ADDR");
      m.rd_data = pin("RD_DATA");
      m.rd_en = pin("RD_EN").at(0);
      m.wr_addr = pin("WR_ADDR");
      m.wr_data = pin("WR_DATA");
      m.wr_en = m.word_we ? pin("WR_WE") : pin("WR_EN");
      if (int(m.rd_data.size()) != m.bits || int(m.wr_data.size()) != m.bits || int(m.rd_addr.size()) != m.abits)
        fail("netlist: macro " + name + " ports do not match its cell " + type);
      const auto& arst = pin("RD_ARST");
      if (arst.size() != 1 || arst[0] != nl.c0) fail("netlist: macro " + name + " uses RD_ARST (not modelled)");
      m.mem.assign(size_t(m.words), std::vector<uint8_t>(size_t(m.bits), 0));
      nl.macros.push_back(std::move(m));
      continue;
    }
    const auto ct = cell_types().find(type);
    if (ct == cell_types().end()) fail("netlist: no model of cell type " + type + " (instance " + name + ")");
    Cell c{type, name, ct->second.kind, {}, {}};
    for (const auto& p : ct->second.in) c.in.push_back(pin(p).at(0));
    for (const auto& p : ct->second.out) {
      auto it = pins.find(p);
      c.out.push_back(it == pins.end() || it->second.empty() ? -1 : it->second.at(0));
    }
    nl.cells.push_back(std::move(c));
  }
  const auto ck = nl.net_id.find("clk_i");
  if (ck == nl.net_id.end()) fail("netlist: no clk_i");
  nl.clk = ck->second;
  return nl;
}



// ---- The recorded ports (sim/dut_core.cpp, --record-ports) ------------------------------
// Line 1: "ports" then name:width:in|out for each port; then one line a clock
// cycle: each port's value in hex, as it is just before the rising edge.
struct Recording {
  struct Port {
    std::string name;
    int width;
    bool input;
  };
  std::vector<Port> ports;
  std::ifstream f;
};

std::vector<uint8_t> hex_bits(const std::string& h, int width) {
  std::vector<uint8_t> b(size_t(width), 0);
  int bit = 0;
  for (auto it = h.rbegin(); it != h.rend() && bit < width; ++it) {
    const int d = std::isdigit(uint8_t(*it)) ? *it - '0' : std::tolower(*it) - 'a' + 10;
    if (d < 0 || d > 15) fail("recording: bad hex value " + h);
    for (int k = 0; k < 4 && bit < width; ++k, ++bit) b[size_t(bit)] = uint8_t(d >> k & 1);
  }
  return b;
}

// ---- Simulation ----------------------------------------------------------------------------
// Zero delay, cycle by cycle, event-driven: the gates sorted by level, a gate
// evaluated when an input changed (a bit set of pending gates, scanned once a
// cycle in order: a gate's fan-out lies at higher indices). A net's value is
// final when its one driver has been evaluated, so a transition is counted there.
enum Op : uint8_t { kAnd2, kNand2, kNand3, kOr2, kNor2, kNor3, kXor2, kXnor2, kBuf, kInv,
                    kAoi21, kAoi22, kOai21, kOai22, kMux2, kFaC, kFaS, kHaC, kHaS, kLatch };

Op op_of(const std::string& type, int out) {
  static const std::map<std::string, Op> ops = {
      {"AND2X1", kAnd2}, {"AND2X2", kAnd2}, {"NAND2X1", kNand2}, {"NAND3X1", kNand3}, {"OR2X1", kOr2},
      {"OR2X2", kOr2}, {"NOR2X1", kNor2}, {"NOR3X1", kNor3}, {"XOR2X1", kXor2}, {"XNOR2X1", kXnor2},
      {"BUFX2", kBuf}, {"BUFX4", kBuf}, {"CLKBUF1", kBuf}, {"CLKBUF2", kBuf}, {"CLKBUF3", kBuf},
      {"INVX1", kInv}, {"INVX2", kInv}, {"INVX4", kInv}, {"INVX8", kInv}, {"AOI21X1", kAoi21},
      {"AOI22X1", kAoi22}, {"OAI21X1", kOai21}, {"OAI22X1", kOai22}, {"MUX2X1", kMux2}, {"LATCH", kLatch}};
  if (type == "FAX1") return out == 0 ? kFaC : kFaS;
  if (type == "HAX1") return out == 0 ? kHaC : kHaS;
  const auto it = ops.find(type);
  if (it == ops.end()) fail("no model of cell " + type);
  return it->second;
}

// Every flip-flop and memory macro is clocked by clk_i or by a clock gate (AND2 of a
// clock and a LATCH's Q, the LATCH's CLK an inverter of that clock; buffers allowed
// between), where that clock is clk_i or itself a gated clock (a gate of
// flow/clock_gate.py inside a block whose clock is gated as a whole): the two-phase
// simulation is right for these only. Cells are told apart by their model (op_of),
// not by name.
void check_clocks(const Netlist& nl) {
  std::vector<int> driver(nl.net_name.size(), -1);
  for (size_t i = 0; i < nl.cells.size(); ++i)
    for (int o : nl.cells[i].out)
      if (o >= 0) driver[size_t(o)] = int(i);
  const auto op = [](const Cell* c) { return c && c->kind == Kind::kComb ? int(op_of(c->type, 0)) : -1; };
  // The net a net is buffered from, and its driver (null: a port or undriven).
  const auto source = [&](int net) {
    for (int hops = 0; hops < 64 && driver[size_t(net)] >= 0; ++hops) {
      const Cell& c = nl.cells[size_t(driver[size_t(net)])];
      if (op(&c) != kBuf) break;
      net = c.in[0];
    }
    return net;
  };
  const auto drv = [&](int net) -> const Cell* {
    const int d = driver[size_t(source(net))];
    return d < 0 ? nullptr : &nl.cells[size_t(d)];
  };
  // A clock: clk_i, or a gate's AND on a clock (at most 4 gates deep).
  const std::function<bool(int, int)> clock = [&](int net, int depth) {
    if (source(net) == nl.clk) return true;
    const Cell* a = drv(net);
    if (depth == 4 || op(a) != kAnd2) return false;
    for (int k = 0; k < 2; ++k) {
      const int c = source(a->in[size_t(k)]);
      const Cell* l = drv(a->in[size_t(1 - k)]);
      if (op(l) != kLatch) continue;
      const Cell* inv = drv(l->in[1]);
      if (op(inv) == kInv && source(inv->in[0]) == c && clock(c, depth + 1)) return true;
    }
    return false;
  };
  const auto check = [&](const std::string& what, int net) {
    if (source(net) == nl.clk) return 0;
    if (!clock(net, 0))
      fail("netlist: " + what + " is clocked by " + nl.net_name[size_t(net)] +
           ", neither clk_i nor a clock gate (INVX -> LATCH -> AND2 on a clock)");
    return 1;
  };
  long gated_flops = 0, gated_macros = 0;
  for (const Cell& c : nl.cells)
    if (c.kind == Kind::kDff || c.kind == Kind::kDffSr) gated_flops += check("flip-flop " + c.name, c.in[0]);
  for (const Macro& m : nl.macros) gated_macros += check("macro " + m.name, m.clk);
  std::cerr << "activity: " << gated_flops << " flip-flops and " << gated_macros << " memory macros on gated clocks\n";
}

struct Gate {  // one output of a combinational cell
  Op op;
  int in[4];
  int out;
};

class Sim {
 public:
  explicit Sim(Netlist& nl) : nl_(nl) {
    const size_t n = nl.net_name.size();
    val_.assign(n, 0);
    val_[size_t(nl.c1)] = 1;
    toggles_.assign(n, 0);
    high_.assign(n, 0);
    high_since_.assign(n, -1);
    // Gates (one a cell output) in level order: sources (ports, flip-flops,
    // macros, constants) are level 0, a gate one above its highest input.
    std::vector<int> driver(n, -1);
    std::vector<Gate> gates;
    for (const Cell& c : nl.cells) {
      if (c.kind == Kind::kDff || c.kind == Kind::kDffSr) {
        flops_.push_back({c.in[1], c.out[0], c.kind == Kind::kDffSr ? c.in[2] : nl.c1,
                          c.kind == Kind::kDffSr ? c.in[3] : nl.c1, c.in[0]});
        continue;
      }
      for (size_t o = 0; o < c.out.size(); ++o) {
        if (c.out[o] < 0) continue;
        Gate g{op_of(c.type, int(o)), {nl.c0, nl.c0, nl.c0, nl.c0}, c.out[o]};
        for (size_t j = 0; j < c.in.size(); ++j) g.in[j] = c.in[j];
        gates.push_back(g);
      }
    }
    for (size_t i = 0; i < gates.size(); ++i) {
      if (driver[size_t(gates[i].out)] >= 0) fail("netlist: net " + nl.net_name[size_t(gates[i].out)] + " has two drivers");
      driver[size_t(gates[i].out)] = int(i);
    }
    std::vector<int> level(gates.size(), -1);
    // Iterative depth-first levelling (the netlist is deep: no recursion).
    for (size_t i = 0; i < gates.size(); ++i) {
      if (level[i] >= 0) continue;
      std::vector<std::pair<int, int>> stack{{int(i), 0}};
      while (!stack.empty()) {
        auto& [g, k] = stack.back();
        if (level[size_t(g)] == -2 && k == 0) fail("netlist: combinational loop");
        if (k == 0) level[size_t(g)] = -2;  // on the stack
        if (k < 4) {
          const int d = driver[size_t(gates[size_t(g)].in[k])];
          ++k;
          if (d >= 0 && level[size_t(d)] == -1) stack.push_back({d, 0});
          else if (d >= 0 && level[size_t(d)] == -2) fail("netlist: combinational loop");
          continue;
        }
        int lv = 0;
        for (int j = 0; j < 4; ++j) {
          const int d = driver[size_t(gates[size_t(g)].in[j])];
          if (d >= 0) lv = std::max(lv, level[size_t(d)] + 1);
        }
        level[size_t(g)] = lv;
        stack.pop_back();
      }
    }
    std::vector<int> order(gates.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = int(i);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return level[size_t(a)] < level[size_t(b)]; });
    gates_.reserve(gates.size());
    for (int i : order) gates_.push_back(gates[size_t(i)]);
    // Fan-out of every net (gate indices, ascending), compressed rows.
    std::vector<int> count(n + 1, 0);
    for (const Gate& g : gates_)
      for (int j = 0; j < 4; ++j)
        if (j == 0 || g.in[j] != g.in[j - 1]) ++count[size_t(g.in[j]) + 1];
    for (size_t i = 0; i < n; ++i) count[i + 1] += count[i];
    fan_start_ = count;
    fan_.assign(size_t(count[n]), 0);
    for (size_t i = 0; i < gates_.size(); ++i)
      for (int j = 0; j < 4; ++j)
        if (j == 0 || gates_[i].in[j] != gates_[i].in[j - 1]) fan_[size_t(count[size_t(gates_[i].in[j])]++)] = int(i);
    pending_.assign((gates_.size() + 63) / 64, ~0ull);  // everything once
    for (const Flop& f : flops_)
      for (int x : {f.r, f.s})
        if (x != nl.c1 && x != nl.c0 && nl.net_name[size_t(x)] != "rst_ni")
          fail("netlist: a flip-flop's set or reset is not rst_ni or a constant");
  }

  void set(int net, uint8_t v) {
    uint8_t& x = val_[size_t(net)];
    if (x == v) return;
    x = v;
    ++toggles_[size_t(net)];
    if (v) high_since_[size_t(net)] = time_;
    else high_[size_t(net)] += time_ - high_since_[size_t(net)];
    for (int k = fan_start_[size_t(net)]; k < fan_start_[size_t(net) + 1]; ++k)
      pending_[size_t(fan_[size_t(k)]) >> 6] |= 1ull << (fan_[size_t(k)] & 63);
  }
  uint8_t get(int net) const { return val_[size_t(net)]; }

  // Settles the logic (the flip-flops' asynchronous reset and set first).
  void settle() {
    for (const Flop& f : flops_) {
      if (!val_[size_t(f.r)]) set(f.q, 0);
      else if (!val_[size_t(f.s)]) set(f.q, 1);
    }
    const uint8_t* v = val_.data();
    for (size_t w = 0; w < pending_.size(); ++w)
      while (pending_[w]) {
      const int bit = __builtin_ctzll(pending_[w]);
      pending_[w] &= pending_[w] - 1;
      if (w * 64 + size_t(bit) >= gates_.size()) continue;  // the last word's padding
      const Gate& g = gates_[w * 64 + size_t(bit)];
      const uint8_t a = v[g.in[0]], b = v[g.in[1]], c = v[g.in[2]], d = v[g.in[3]];
      uint8_t y;
      switch (g.op) {
        case kAnd2: y = a & b; break;
        case kNand2: y = !(a & b); break;
        case kNand3: y = !(a & b & c); break;
        case kOr2: y = a | b; break;
        case kNor2: y = !(a | b); break;
        case kNor3: y = !(a | b | c); break;
        case kXor2: y = a ^ b; break;
        case kXnor2: y = !(a ^ b); break;
        case kBuf: y = a; break;
        case kInv: y = !a; break;
        case kAoi21: y = !((a & b) | c); break;
        case kAoi22: y = !((a & b) | (c & d)); break;
        case kOai21: y = !((a | b) & c); break;
        case kOai22: y = !((a | b) & (c | d)); break;
        case kMux2: y = !(c ? a : b); break;
        case kFaC: y = (a & b) | (b & c) | (c & a); break;
        case kFaS: y = a ^ b ^ c; break;
        case kLatch: y = b ? a : v[g.out]; break;  // D, CLK: holds while CLK is low
        case kHaC: y = a & b; break;
        default: y = a ^ b; break;  // kHaS
      }
      set(g.out, y);
      }
  }

  // The rising clock edge, which begins the next cycle: clk_i rises and the clock
  // network settles (the gates' latches close, a gate whose latched enable is 1
  // passes the edge), then every flip-flop whose clock rose takes D and the
  // macros read and write (all with the values before the edge), and the logic
  // settles in the high phase (the latches hold). The caller then sets the
  // cycle's inputs, settles, and calls fall().
  void clock() {
    ++cycle_;
    time_ = 2 * cycle_;
    clk_before_.clear();
    for (const Flop& f : flops_) clk_before_.push_back(val_[size_t(f.c)]);
    for (const Macro& m : nl_.macros) clk_before_.push_back(val_[size_t(m.clk)]);
    set(nl_.clk, 1);
    settle();
    next_.clear();
    for (size_t i = 0; i < flops_.size(); ++i) {
      const Flop& f = flops_[i];
      if (clk_before_[i] || !val_[size_t(f.c)]) continue;
      next_.emplace_back(f.q, !val_[size_t(f.r)] ? 0 : !val_[size_t(f.s)] ? 1 : val_[size_t(f.d)]);
    }
    for (size_t i = 0; i < nl_.macros.size(); ++i) {
      Macro& m = nl_.macros[i];
      if (clk_before_[flops_.size() + i] || !val_[size_t(m.clk)]) continue;  // its clock did not rise
      const auto addr = [&](const std::vector<int>& a) {
        long x = 0;
        for (size_t k = 0; k < a.size(); ++k) x |= long(val_[size_t(a[k])]) << k;
        return x;
      };
      const long ra = addr(m.rd_addr), wa = addr(m.wr_addr);
      if (val_[size_t(m.rd_en)]) {
        ++m.reads;
        for (int k = 0; k < m.bits; ++k)
          next_.emplace_back(m.rd_data[size_t(k)], ra < m.words ? m.mem[size_t(ra)][size_t(k)] : 0);
      }
      bool wrote = false;
      for (int k = 0; k < m.bits; ++k) {
        const int en = m.word_we ? m.wr_en[0] : m.wr_en[size_t(k)];
        if (!val_[size_t(en)]) continue;
        wrote = true;
        if (wa < m.words) m.mem[size_t(wa)][size_t(k)] = val_[size_t(m.wr_data[size_t(k)])];
      }
      m.writes += wrote;
    }
    for (const auto& [net, v] : next_) set(net, v);
    settle();
  }
  // The falling edge, half a cycle after the rising one: the gates' latches
  // open and take the enables of the settled logic, the gated clocks fall.
  void fall() {
    time_ = 2 * cycle_ + 1;
    set(nl_.clk, 0);
    settle();
  }

  long cycle() const { return cycle_; }
  // Starts a new count window.
  void restart() {
    std::fill(toggles_.begin(), toggles_.end(), 0);
    std::fill(high_.begin(), high_.end(), 0);
    for (size_t n = 0; n < val_.size(); ++n) high_since_[n] = val_[n] ? time_ : -1;
    for (Macro& m : nl_.macros) m.reads = m.writes = 0;
    start_ = cycle_;
  }
  // The window so far: every net's transitions and high cycles.
  void write(const std::string& path) const {
    std::ofstream o(path);
    o << "cycles " << cycle_ - start_ << "\n";
    for (size_t n = 0; n < val_.size(); ++n) {
      if (int(n) == nl_.c0 || int(n) == nl_.c1) continue;
      const long high = high_[n] + (val_[n] ? time_ - high_since_[n] : 0);  // half cycles
      o << "net " << nl_.net_name[n] << " " << toggles_[n] << " " << high / 2 << (high % 2 ? ".5" : "") << "\n";
    }
    for (const Macro& m : nl_.macros)
      o << "macro " << m.name << " " << m.type << " " << m.words << " " << m.bits << " " << m.reads << " "
        << m.writes << "\n";
    if (!o) fail("cannot write " + path);
  }

 private:
  struct Flop {
    int d, q, r, s, c;
  };
  Netlist& nl_;
  std::vector<uint8_t> val_;
  std::vector<long> toggles_, high_, high_since_;
  std::vector<Gate> gates_;
  std::vector<int> fan_start_, fan_;
  std::vector<uint64_t> pending_;
  std::vector<Flop> flops_;
  std::vector<std::pair<int, uint8_t>> next_;
  std::vector<uint8_t> clk_before_;
  long cycle_ = 0, start_ = 0, time_ = 0;  // time_ in half cycles
};

int run(int argc, char** argv) {
  if (argc < 4) {
    std::cerr << "usage: mcadsw_activity NETLIST.v PORTS.txt OUT_PREFIX [--hold N]\n";
    return 2;
  }
  const std::string netlist = argv[1], ports = argv[2], prefix = argv[3];
  long hold = 0;
  for (int i = 4; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--hold" && i + 1 < argc) hold = std::stol(argv[++i]);
    else fail("unknown option " + a);
  }
  Netlist nl = read_netlist(netlist);
  check_clocks(nl);
  std::cerr << "activity: " << nl.cells.size() << " cells, " << nl.macros.size() << " macros, "
            << nl.net_name.size() << " nets\n";

  std::ifstream rec(ports);
  if (!rec) fail("cannot read the port recording " + ports);
  std::string line;
  std::getline(rec, line);
  std::istringstream hs(line);
  std::string word;
  hs >> word;
  if (word != "ports") fail("recording " + ports + ": no 'ports' header");
  struct P {
    std::vector<int> bits;
    bool input;
    std::string name;
  };
  std::vector<P> cols;
  while (hs >> word) {
    const size_t a = word.find(':'), b = word.rfind(':');
    const std::string name = word.substr(0, a);
    const int width = std::stoi(word.substr(a + 1, b - a - 1));
    const bool input = word.substr(b + 1) == "in";
    P p{nl.port_bits(name), input, name};
    if (int(p.bits.size()) != width)
      fail("recording: port " + name + " has " + std::to_string(width) + " bits, the netlist " +
           std::to_string(p.bits.size()));
    cols.push_back(std::move(p));
  }
  // The recording must give every port but the clock, as the netlist declares it.
  {
    std::vector<std::string> want, got;
    for (const auto& v : {nl.inputs, nl.outputs})
      for (const auto& p : v)
        if (p != "clk_i") want.push_back(p);
    for (const P& c : cols) got.push_back(c.name);
    std::sort(want.begin(), want.end());
    std::sort(got.begin(), got.end());
    if (want != got) {
      std::string miss;
      for (const auto& p : want)
        if (!std::binary_search(got.begin(), got.end(), p)) miss += " " + p;
      fail("recording " + ports + ": its ports are not the netlist's (missing:" + (miss.empty() ? " none" : miss) +
           "; or extra or repeated ones)");
    }
  }
  Sim sim(nl);
  sim.settle();
  sim.restart();
  long mismatches = 0;
  while (std::getline(rec, line)) {
    std::istringstream ls(line);
    std::vector<std::string> vals;
    while (ls >> word) vals.push_back(word);
    const long cycle = sim.cycle();
    if (vals.size() != cols.size()) fail("recording: line " + std::to_string(cycle + 2) + " has a wrong field count");
    for (size_t k = 0; k < cols.size(); ++k)
      if (cols[k].input) {
        const auto b = hex_bits(vals[k], int(cols[k].bits.size()));
        for (size_t j = 0; j < b.size(); ++j) sim.set(cols[k].bits[j], b[j]);
      }
    sim.settle();
    sim.fall();
    for (size_t k = 0; k < cols.size(); ++k)
      if (!cols[k].input) {
        const auto b = hex_bits(vals[k], int(cols[k].bits.size()));
        for (size_t j = 0; j < b.size(); ++j)
          if (sim.get(cols[k].bits[j]) != b[j]) {
            if (++mismatches <= 5)
              std::cerr << "activity: cycle " << cycle << ": output " << cols[k].name << " bit " << j
                        << ": netlist " << int(sim.get(cols[k].bits[j])) << ", RTL " << int(b[j]) << "\n";
            break;
          }
      }
    if (mismatches) fail("the netlist's outputs differ from the RTL's (" + std::to_string(mismatches) + ")");
    sim.clock();
    if (sim.cycle() % 100000 == 0) std::cerr << "activity: " << sim.cycle() << " cycles\n";
  }
  if (sim.cycle() == 0) fail("recording " + ports + " has no cycles");
  sim.settle();
  sim.write(prefix + ".frame.txt");
  std::cerr << "activity: " << sim.cycle() << " cycles, outputs equal to the RTL's in every cycle\n";
  if (hold > 0) {
    // Idle: the configuration held, no start, the memory port quiet.
    for (size_t k = 0; k < cols.size(); ++k)
      if (cols[k].input && (cols[k].name == "start_i" || cols[k].name == "mem_gnt_i" || cols[k].name == "mem_rvalid_i"))
        for (int b : cols[k].bits) sim.set(b, 0);
    for (int i = 0; i < 4; ++i) {  // let the last responses drain
      sim.settle();
      sim.fall();
      sim.clock();
    }
    sim.settle();
    sim.restart();
    for (long i = 0; i < hold; ++i) {
      sim.settle();
      sim.fall();
      sim.clock();
    }
    sim.settle();
    sim.write(prefix + ".idle.txt");
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "mcadsw_activity: " << e.what() << "\n";
    return 1;
  }
}
