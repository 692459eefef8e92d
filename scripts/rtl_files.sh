#!/usr/bin/env bash
# Prints the RTL files of rtl/mcadsw.f, one a line, as paths under DIR.
#   scripts/rtl_files.sh [--no-pkg] [DIR]   DIR defaults to the repository's rtl/
# --no-pkg leaves out mcadsw_pkg.sv (a configuration's build supplies its own).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
nopkg=0
if [ "${1:-}" = --no-pkg ]; then nopkg=1; shift; fi
dir=${1:-$root/rtl}
sed -e 's://.*$::' -e 's/[[:space:]]*$//' "$root/rtl/mcadsw.f" | grep -v '^$' |
  { if [ $nopkg = 1 ]; then grep -vx 'mcadsw_pkg.sv'; else cat; fi; } | sed "s|^|$dir/|"
