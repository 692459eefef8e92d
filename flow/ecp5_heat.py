# SPDX-FileCopyrightText: 2026 The mcadsw authors
# SPDX-License-Identifier: Apache-2.0

"""Which blocks sit where router2 is congested: a heat map of `flow/ecp5.py route --heatmap`
(router2's overused wires by tile after one iteration, heat_congestion_by_coordinate_<I>.csv)
laid over the placement it routed (placed.json, each cell's NEXTPNR_BEL tile).

    python3 flow/ecp5_heat.py --placed PLACED.json --heat ROUTE_DIR [--iteration I] [--top N]

A tile's overuse is shared among the blocks of the cells placed in it, in proportion to their
cells; a block's figure is then its share of all overuse, and its overuse per thousand of its
cells (a block that is large but calm against one that is small and congested). The block of
a cell: its instance path (u_soc.u_engine.u_weight_gen, the cost aggregator's, fetch's and
post stage's instances one level deeper, generate indices folded: g_horz[]), or for a cell
Yosys named itself, the first RTL file of its source attribute; "(unnamed)" if neither.
Overuse in tiles without a placed cell (routing-only tiles) is counted apart. Two placements
are compared at the same iteration. Exit 0; 2 on a missing or unreadable input.
"""
import argparse
import csv
import re
import sys
from collections import Counter, defaultdict
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from ecp5_paths import top_module  # noqa: E402

DEEPER = ("u_cost_agg", "u_fetch", "u_post", "u_rectifier")


def block_of(name, src=""):
    """The block a cell of the SoC's netlist belongs to (module docstring)."""
    if name.startswith("u_soc."):
        p = [re.sub(r"\[\d+\]", "[]", x) for x in name.split(".")[1:-1]]
        if len(p) >= 2 and p[0] == "u_engine":
            return ".".join(p[:3] if p[1] in DEEPER and len(p) > 2 else p[:2])
        if p:
            return p[0]
    m = re.search(r"rtl/([\w/]+)\.sv", src or "")
    return m.group(1) if m else "(unnamed)"


def tiles_of(placed):
    """{(x, y): Counter of blocks}, Counter of cells by block, from a placed design."""
    tiles, count = defaultdict(Counter), Counter()
    for name, c in top_module(placed)["cells"].items():
        attrs = c.get("attributes", {})
        bel = attrs.get("NEXTPNR_BEL")
        m = re.match(r"X(\d+)/Y(\d+)/", bel or "")
        if not m:
            continue
        b = block_of(name, attrs.get("src", ""))
        tiles[(int(m.group(1)), int(m.group(2)))][b] += 1
        count[b] += 1
    return tiles, count


def heat(tiles, csv_path):
    """(total overuse, overuse by block, overuse of tiles without cells, hottest tiles)."""
    total, by_block, empty, hot = 0, Counter(), 0, []
    with open(csv_path) as f:
        for y, row in enumerate(csv.reader(f)):
            for x, v in enumerate(row):
                v = int(v) if v.strip() else 0
                if v <= 0:
                    continue
                total += v
                hot.append((v, x, y))
                here = tiles.get((x, y))
                if not here:
                    empty += v
                    continue
                n = sum(here.values())
                for b, k in here.items():
                    by_block[b] += v * k / n
    hot.sort(key=lambda t: (-t[0], t[1], t[2]))
    return total, by_block, empty, hot


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--placed", required=True, help="placed.json of flow/ecp5.py place")
    ap.add_argument("--heat", required=True, help="the directory of a route --heatmap run")
    ap.add_argument("--iteration", type=int, default=10, help="router2's iteration (default 10)")
    ap.add_argument("--top", type=int, default=12, help="blocks listed (default 12)")
    a = ap.parse_args(argv)
    csv_path = Path(a.heat) / f"heat_congestion_by_coordinate_{a.iteration}.csv"
    try:
        tiles, count = tiles_of(a.placed)
        total, by_block, empty, hot = heat(tiles, csv_path)
    except (OSError, ValueError, KeyError) as e:
        print(f"ecp5_heat: {e}", file=sys.stderr)
        return 2
    print(f"ecp5_heat: {csv_path}: {total} overused wire uses at iteration {a.iteration}, "
          f"{empty} of them in tiles without a placed cell")
    print(f"{'share':>7} {'overuse':>8} {'cells':>7} {'per 1k cells':>12}  block")
    for b, v in by_block.most_common(a.top):
        print(f"{100 * v / max(total, 1):6.1f}% {v:8.0f} {count[b]:7d} {1000 * v / max(count[b], 1):12.1f}  {b}")
    print("hottest tiles: " + ", ".join(
        f"X{x}/Y{y} {v} ({tiles[(x, y)].most_common(1)[0][0] if (x, y) in tiles else 'no cell'})"
        for v, x, y in hot[:6]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
