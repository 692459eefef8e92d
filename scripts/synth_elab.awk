# Blocks of the elaborated design (scripts/synth.sh). Reads the RTLIL that
# `hierarchy -check -top mcadsw_engine` wrote (after chparam DMAX) twice:
#   pass 1: modules, their source file, parameters, ports and cells;
#   pass 2: the same RTLIL with the top renamed mcadsw_engine and every block module
#           (each distinct module type the top instantiates) renamed
#           mcadsw_<instance name without u_>, written to stdout.
# Also writes (-v dir=DIR):
#   DIR/blocks.txt       label module instances base files weight (one line per block, top last;
#                        files: the block's source files, its sub-modules' included, comma-separated;
#                        weight: RTLIL lines of the block with its sub-modules, a size estimate)
#   DIR/<label>.sig      what the block's netlist depends on besides file contents and flow:
#                        its module names and parameters (and, for the top, the block ports)
function unq(s) { gsub(/^"|"$/, "", s); return s }
function base_of(m) { return (m in hdl) ? hdl[m] : substr(m, 2) }
function weight(m,   i, t, w) {                # RTLIL lines of m, sub-module instances included
  if (m in wmemo) return wmemo[m]
  w = nl[m]
  for (i = 1; i <= ncell[m]; i++) { t = ctype[m, i]; if ((t in ismod) && !(t in bb) && t != m) w += weight(t) }
  return wmemo[m] = w
}
function subtree(m, depth,   i, t) {          # files and parameters of m and its sub-modules
  if (depth > 50) { print "synth_elab: module hierarchy too deep at " m > "/dev/stderr"; exit 1 }
  st_files[src[m]] = 1
  st_sig = st_sig "module " m " (" base_of(m) ")" par[m] "\n"
  for (i = 1; i <= ncell[m]; i++) {
    t = ctype[m, i]
    if ((t in ismod) && !(t in bb) && !((m SUBSEP t) in seen_edge)) { seen_edge[m, t] = 1; subtree(t, depth + 1) }
  }
}
FNR == NR {
  if ($0 ~ /^attribute /) { pend[$2] = $3; next }
  if ($0 ~ /^module /) {
    mod = $2; ismod[mod] = 1; nmod++
    if ("\\src" in pend) { s = unq(pend["\\src"]); sub(/:.*$/, "", s); src[mod] = s }
    if ("\\hdlname" in pend) { h = unq(pend["\\hdlname"]); sub(/^\\\\/, "", h); hdl[mod] = h }
    if ("\\blackbox" in pend) bb[mod] = 1
    if ("\\top" in pend) top = mod
    delete pend; next
  }
  if ($0 ~ /^  parameter /) { par[mod] = par[mod] " " $2 "=" $3; next }
  if ($0 ~ /^  cell /) { ncell[mod]++; ctype[mod, ncell[mod]] = $2; cname[mod, ncell[mod]] = $3; next }
  if ($0 ~ /^  wire / && $0 ~ / (input|output|inout) /) { ports[mod] = ports[mod] $0 "\n"; next }
  if ($0 ~ /^end$/) mod = ""
  if (mod != "") nl[mod]++
  next
}
FNR == 1 {
  # End of pass 1: name the blocks.
  if (top == "") { print "synth_elab: no top module in the elaborated design" > "/dev/stderr"; exit 1 }
  newname[top] = "\\mcadsw_engine"
  nb = 0
  for (i = 1; i <= ncell[top]; i++) {
    t = ctype[top, i]
    if (!(t in ismod) || (t in bb)) continue
    if (t in label) { inst[t]++; continue }
    l = cname[top, i]; sub(/^\\/, "", l); sub(/^u_/, "", l); gsub(/[^A-Za-z0-9_]/, "_", l)
    if (l == "top" || l in used) { k = 2; while ((l "_" k) in used) k++; l = l "_" k }
    used[l] = 1; label[t] = l; inst[t] = 1; order[++nb] = t
    n = "\\mcadsw_" l
    # A name already taken by another module of the design gets a suffix.
    while ((n in ismod) && n != t) n = n "_blk"
    newname[t] = n
  }
  for (j = 1; j <= nb + 1; j++) {
    t = (j <= nb) ? order[j] : top
    l = (j <= nb) ? label[t] : "top"
    delete st_files; delete seen_edge; st_sig = ""
    if (j <= nb) subtree(t, 0)
    else {                                      # the top alone; the blocks are black boxes
      st_files[src[t]] = 1
      st_sig = "module " t " (" base_of(t) ")" par[t] "\n"
      for (k = 1; k <= nb; k++) st_sig = st_sig "ports of " substr(newname[order[k]], 2) ":\n" ports[order[k]]
    }
    files = ""
    for (f in st_files) if (f != "") files = files (files == "" ? "" : ",") f
    if (files == "") files = "-"
    print "renamed " substr(newname[t], 2) "\n" st_sig > (dir "/" l ".sig")
    close(dir "/" l ".sig")
    printf "%s %s %d %s %s %d\n", l, substr(newname[t], 2), (j <= nb) ? inst[t] : 1, base_of(t), files,
           (j <= nb) ? weight(t) : nl[t] > (dir "/blocks.txt")
  }
  close(dir "/blocks.txt")
}
{
  if ($0 ~ /^module / && ($2 in newname)) { print "module " newname[$2]; next }
  if ($0 ~ /^  cell / && ($2 in newname)) { print "  cell " newname[$2] " " $3; next }
  print
}
