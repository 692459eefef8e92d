#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# Negative control of ctest ipxact_component: tests/ipxact/check_component.py must reject a
# component.xml with one port map left out, with a register's access changed, with a field
# moved, and a wrapper with a port the component does not have.
#   tests/ipxact/check_fails.sh PYTHON
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
py=${1:-$root/.venv/bin/python}
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
check() { "$py" "$root/tests/ipxact/check_component.py" "$@" > "$work/out" 2>&1; }
fails=0
expect_fail() {
  local what=$1; shift
  if check "$@"; then echo "check_fails: accepted $what"; cat "$work/out"; fails=1
  else echo "check_fails: rejected $what: $(head -1 "$work/out")"; fi
}
check || { cat "$work/out"; echo "check_fails: the unchanged component is rejected" >&2; exit 1; }
# A port map left out (s_axi_wstrb's).
python3 - "$root/component.xml" "$work/nomap.xml" <<'PY'
import re, sys
s = open(sys.argv[1]).read()
s2 = re.sub(r"\s*<ipxact:portMap>\s*<ipxact:logicalPort><ipxact:name>WSTRB</ipxact:name></ipxact:logicalPort>\s*"
            r"<ipxact:physicalPort><ipxact:name>s_axi_wstrb</ipxact:name></ipxact:physicalPort>\s*</ipxact:portMap>", "", s, count=1)
assert s2 != s
open(sys.argv[2], "w").write(s2)
PY
expect_fail "a port in no bus interface" "$work/nomap.xml"
# CTRL read-only.
sed '0,/<ipxact:name>CTRL<\/ipxact:name>/!b; :a; n; s|<ipxact:access>read-write</ipxact:access>|<ipxact:access>read-only</ipxact:access>|; Ta' \
  "$root/component.xml" > "$work/access.xml"
cmp -s "$root/component.xml" "$work/access.xml" && { echo "check_fails: sed changed nothing" >&2; exit 1; }
expect_fail "a register's access changed" "$work/access.xml"
# STATUS.ERROR_CODE one bit up.
sed '/<ipxact:name>ERROR_CODE<\/ipxact:name>/,/bitOffset/ s|<ipxact:bitOffset>4</ipxact:bitOffset>|<ipxact:bitOffset>5</ipxact:bitOffset>|' \
  "$root/component.xml" > "$work/field.xml"
cmp -s "$root/component.xml" "$work/field.xml" && { echo "check_fails: sed changed nothing" >&2; exit 1; }
expect_fail "a field moved" "$work/field.xml"
# The wrapper with one more port.
sed 's|^  output wire        interrupt$|  output wire        interrupt,\n  output wire        extra_o|' "$root/rtl/mcadsw_axi.v" > "$work/wrapper.v"
cmp -s "$root/rtl/mcadsw_axi.v" "$work/wrapper.v" && { echo "check_fails: sed changed nothing" >&2; exit 1; }
expect_fail "a wrapper port the component lacks" "$root/component.xml" "$work/wrapper.v"
exit $fails
