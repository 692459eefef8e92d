# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# Checks the untoggled toggle points of a merged Verilator coverage file against
# tests/coverage/untoggled.txt (its header says the format), for flow/coverage.py:
#   awk -f scripts/untoggled_check.awk tests/coverage/untoggled.txt merged.dat
# Prints the counts by kind, every untoggled point no line lists, and every line
# that lists no untoggled point (stale); exit 1 if there is either. With
# -v verbose=1, also the points each line lists.
function bit_in(spec, b,    n, i, item, a, r) {
  if (spec == "*") return 1
  if (spec == "-") return b == "-"
  if (b == "-") return 0
  n = split(spec, item, ",")
  for (i = 1; i <= n; i++) {
    if (item[i] ~ /^[0-9]+$/ && b + 0 == item[i] + 0) return 1
    if (item[i] ~ /^[0-9]+:[0-9]+$/) { split(item[i], a, ":"); if (b + 0 >= a[1] + 0 && b + 0 <= a[2] + 0) return 1 }
    if (item[i] ~ /^[0-9]+%[0-9]+$/) { split(item[i], r, "%"); if ((b % r[2]) == r[1] + 0) return 1 }
  }
  return 0
}
FNR == NR {
  if ($0 ~ /^[ \t]*(#|$)/) next
  if (NF < 4 || $3 !~ /^(const|limit|unreached)$/ || $2 !~ /^(\*|-|([0-9]+(:[0-9]+|%[0-9]+)?)(,[0-9]+(:[0-9]+|%[0-9]+)?)*)$/) {
    printf "untoggled.txt:%d: malformed line (PATTERN BITS KIND REASON)\n", FNR; bad = 1; next
  }
  nl++; pat[nl] = "^(" $1 ")$"; bits[nl] = $2; kind[nl] = $3; lineno[nl] = FNR; text[nl] = $0
  next
}
/^C / && /\001page\002v_toggle\// {
  total++
  if ($NF + 0 > 0) next
  o = $0; sub(/.*\001o\002/, "", o); sub(/\001.*/, "", o)
  h = $0; sub(/.*\001h\002/, "", h); sub(/\001.*/, "", h); sub(/'[^']*$/, "", h)
  sub(/^TOP\.mcadsw_top\.?/, "", h); if (h == "") h = "top"
  b = "-"
  if (match(o, /\[[0-9]+\]$/)) { b = substr(o, RSTART + 1, RLENGTH - 2); o = substr(o, 1, RSTART - 1) }
  name = h "/" o
  for (i = 1; i <= nl; i++)
    if (name ~ pat[i] && bit_in(bits[i], b)) { used[i]++; by[kind[i]]++; pts[i] = pts[i] " " name "[" b "]"; break }
  if (i > nl) { unlisted++; if (unlisted <= 40 || ENVIRON["ALL"] != "") printf "  unlisted: %s[%s]\n", name, b }
}
END {
  if (verbose)
    for (i = 1; i <= nl; i++) printf "untoggled.txt:%d (%s, %d):%s\n", lineno[i], kind[i], used[i], pts[i]
  for (i = 1; i <= nl; i++)
    if (!used[i]) { stale++; printf "  stale (lists no untoggled point): untoggled.txt:%d: %s\n", lineno[i], substr(text[i], 1, 100) }
  un = by["const"] + by["limit"] + by["unreached"] + unlisted
  printf "untoggled: %d of %d toggle points: %d const, %d limit, %d unreached (listed), %d unlisted; %d stale line(s)\n", \
    un, total, by["const"], by["limit"], by["unreached"], unlisted, stale
  if (total > by["const"] + by["limit"])
    printf "toggle coverage of the points that can toggle (not const or limit): %.1f %%\n", \
      100 * (total - un) / (total - by["const"] - by["limit"])
  exit (bad || unlisted || stale) ? 1 : 0
}
