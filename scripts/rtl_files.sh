#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# Prints the RTL files of rtl/mcadsw.f, one a line, as paths under DIR.
#   scripts/rtl_files.sh [--no-pkg] [DIR]   DIR defaults to the repository's rtl/
# --no-pkg leaves out mcadsw_pkg.sv (a configuration's build supplies its own).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
nopkg=0
if [ "${1:-}" = --no-pkg ]; then nopkg=1; shift; fi
dir=${1:-$root/rtl}
# Bash alone (no pipeline of sed and grep). (rtl_check's "not in rtl/mcadsw.f" failures
# of 2026-11-26 were not a short list but rtl_check's own `printf | grep -q` under
# pipefail failing on a match by SIGPIPE; rtl_check now tests membership in bash.)
while IFS= read -r line || [ -n "$line" ]; do
  line=${line%%//*}                                  # comment
  line=${line%"${line##*[![:space:]]}"}              # trailing white space
  [ -n "$line" ] || continue
  [ $nopkg = 1 ] && [ "$line" = mcadsw_pkg.sv ] && continue
  printf '%s/%s\n' "$dir" "$line"
done < "$root/rtl/mcadsw.f"
