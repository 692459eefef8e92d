#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# Prints the RTL files of rtl/mcadsw.f, one a line, as paths under DIR.
#   scripts/rtl_files.sh [--no-pkg] [--no-rect] [DIR]   DIR defaults to the repository's rtl/
# --no-pkg leaves out mcadsw_pkg.sv (a configuration's build supplies its own).
# --no-rect: the engine without the rectifier (a package with RECT = 0, gen_rtl_pkg
# --no-rect): rtl/rect/'s modules replaced by rect/mcadsw_rect_none.sv (its package stays:
# the engine reads its constants).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
nopkg=0
norect=0
while [ $# -gt 0 ]; do
  case $1 in
    --no-pkg) nopkg=1; shift ;;
    --no-rect) norect=1; shift ;;
    *) break ;;
  esac
done
dir=${1:-$root/rtl}
# Bash alone (no pipeline of sed and grep). (rtl_check's "not in rtl/mcadsw.f" failures
# of 2026-11-26 were not a short list but rtl_check's own `printf | grep -q` under
# pipefail failing on a match by SIGPIPE; rtl_check now tests membership in bash.)
while IFS= read -r line || [ -n "$line" ]; do
  line=${line%%//*}                                  # comment
  line=${line%"${line##*[![:space:]]}"}              # trailing white space
  [ -n "$line" ] || continue
  [ $nopkg = 1 ] && [ "$line" = mcadsw_pkg.sv ] && continue
  [ $norect = 1 ] && [ "${line#rect/}" != "$line" ] && [ "$line" != rect/mcadsw_rect_pkg.sv ] && continue
  printf '%s/%s\n' "$dir" "$line"
done < "$root/rtl/mcadsw.f"
if [ $norect = 1 ]; then printf '%s/%s\n' "$dir" rect/mcadsw_rect_none.sv; fi
