#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# Negative control of scripts/doc_check.py (ctest docs_check_fails): on a scratch doc
# naming a file the tree does not have and a make target the Makefile does not define, the
# check fails naming both; on one naming a file and a target that exist, it passes.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
check=$root/scripts/doc_check.py
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "docs_check_fails: $*" >&2; exit 1; }

printf '%s\n' '# Bad' '' 'The top is `rtl/no_such_file.sv`; run' '`make no-such-target`.' > "$tmp/bad.md"
if python3 "$check" "$tmp/bad.md" > "$tmp/out1.txt" 2>&1; then cat "$tmp/out1.txt"; fail "passed on bad.md"; fi
grep -q "bad.md:3: path rtl/no_such_file.sv" "$tmp/out1.txt" || { cat "$tmp/out1.txt"; fail "the missing file not named"; }
grep -q "bad.md:4: make target no-such-target" "$tmp/out1.txt" || { cat "$tmp/out1.txt"; fail "the missing target not named"; }

printf '%s\n' '# Good' '' 'The top is `rtl/mcadsw_top.sv`; run `make sim`.' > "$tmp/good.md"
python3 "$check" "$tmp/good.md" > "$tmp/out0.txt" 2>&1 || { cat "$tmp/out0.txt"; fail "failed on good.md"; }

echo "docs_check_fails: the check fails on a missing file and a missing make target, and passes on existing ones"
