#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

# Negative control of scripts/license_check.py (ctest license_check_fails): in a scratch
# repository with the project's licence files, it passes on headed files, then fails
# naming the file (1) with no licence at all, (2) of a commentable kind licensed only
# through REUSE.toml, (3) naming a licence whose text is missing under LICENSES/.
# The scratch files below carry licence tags as text (REUSE: not this file's own).
# REUSE-IgnoreStart
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
check=$root/scripts/license_check.py
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "license_check_fails: $*" >&2; exit 1; }

git -C "$tmp" init -q
cp "$root/LICENSE" "$tmp/"
mkdir "$tmp/LICENSES"; ln -s ../LICENSE "$tmp/LICENSES/Apache-2.0.txt"
printf '%s\n' '// SPDX-FileCopyrightText: 2026 The mcadsw authors' \
  '// SPDX-License-Identifier: Apache-2.0' 'module good; endmodule' > "$tmp/good.sv"
git -C "$tmp" add -A
python3 "$check" --root "$tmp" > "$tmp/out0.txt" || { cat "$tmp/out0.txt"; fail "a headed tree failed"; }

# (1) a module without a header
printf 'module bad; endmodule\n' > "$tmp/bad.sv"
git -C "$tmp" add -A
if python3 "$check" --root "$tmp" > "$tmp/out1.txt"; then fail "passed with bad.sv unlicensed"; fi
grep -q "bad.sv" "$tmp/out1.txt" || { cat "$tmp/out1.txt"; fail "bad.sv not named"; }
grep -q "good.sv" "$tmp/out1.txt" && fail "good.sv named"
rm "$tmp/bad.sv"

# (2) a C++ file licensed only by REUSE.toml
printf 'int x;\n' > "$tmp/side.cpp"
printf '%s\n' 'version = 1' '[[annotations]]' 'path = "side.cpp"' \
  'SPDX-FileCopyrightText = "2026 The mcadsw authors"' 'SPDX-License-Identifier = "Apache-2.0"' > "$tmp/REUSE.toml"
printf '%s\n' '# SPDX-FileCopyrightText: 2026 The mcadsw authors' '# SPDX-License-Identifier: Apache-2.0' \
  | cat - "$tmp/REUSE.toml" > "$tmp/r" && mv "$tmp/r" "$tmp/REUSE.toml"
git -C "$tmp" add -A
if python3 "$check" --root "$tmp" > "$tmp/out2.txt"; then fail "passed with side.cpp licensed by REUSE.toml only"; fi
grep -q "side.cpp: no SPDX-License-Identifier line of its own" "$tmp/out2.txt" || { cat "$tmp/out2.txt"; fail "side.cpp not named"; }
rm "$tmp/side.cpp" "$tmp/REUSE.toml"

# (3) a licence without its text
printf '%s\n' '# SPDX-FileCopyrightText: 2026 The mcadsw authors' '# SPDX-License-Identifier: MIT' > "$tmp/mit.py"
git -C "$tmp" add -A
if python3 "$check" --root "$tmp" > "$tmp/out3.txt"; then fail "passed with MIT's text missing"; fi
grep -q "MIT" "$tmp/out3.txt" || { cat "$tmp/out3.txt"; fail "the missing MIT text not named"; }

echo "license_check_fails: the check fails on an unlicensed file, a source licensed only by REUSE.toml and a missing licence text"
# REUSE-IgnoreEnd
