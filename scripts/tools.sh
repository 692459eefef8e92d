# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0
#
# Sourced by the scripts that run the tool environment's programs (Verilator,
# verilator_coverage): puts .venv/bin (scripts/bootstrap.sh) first on PATH, so that they
# run the pinned versions however they are started (make, ctest, by hand), and stops with a clear error when it is not installed.
mcadsw_venv=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/.venv
if [ ! -x "$mcadsw_venv/bin/verilator" ]; then
  echo "$(basename "$0"): no tool environment at $mcadsw_venv (run scripts/bootstrap.sh)" >&2
  exit 2
fi
PATH=$mcadsw_venv/bin:$PATH
export PATH
