"""Pairs per second of mapping a drive end to end with two checkouts' defaults, runs interleaved.

    python -m bench.ab_mapping BASE_CHECKOUT [--pairs 200] [--seed 2001] [--rounds 3] [--workers 2]

Each round maps the drive of ``bench.bench_mapping`` (generated once, cached under build/drives/) once with
the checkout BASE_CHECKOUT and once with this one, the order swapped every round, each run in its own
process with its own checkout's ``bench.bench_mapping --mode pipeline-all`` (``map_drive`` with its default
``PipelineConfig``, a worker process per core, start-up, decoding, SGBM, detection, fusion and OCR
included). On a machine shared with other work the speed drifts over minutes, so only runs close in time
are compared: each round prints both rates and their ratio (this checkout / base), then the median ratio
over the rounds. BASE_CHECKOUT: a copy of another commit, e.g. ``git archive main | tar -x -C DIR``.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
from pathlib import Path

from bench.bench_mapping import drive_folder

REPO = Path(__file__).resolve().parents[1]


def run(checkout: Path, folder: Path) -> dict:
    """One end-to-end mapping of ``folder`` by ``checkout``'s bench_mapping, in its own process: run as a module,
    or as a file in a checkout from before bench/ was a package."""
    module = ["-m", "bench.bench_mapping"] if (checkout / "bench" / "__init__.py").is_file() else \
        [str(checkout / "bench" / "bench_mapping.py")]
    out = subprocess.run([sys.executable, *module, "--mode", "pipeline-all", "--drive", str(folder)],
                         capture_output=True, text=True, check=True, cwd=checkout)
    return json.loads(out.stdout.strip().splitlines()[-1])


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("base", type=Path, help="the other checkout (its defaults are the baseline)")
    parser.add_argument("--pairs", type=int, default=200)
    parser.add_argument("--seed", type=int, default=2001)
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()
    folder = drive_folder(args.seed, args.pairs)
    print(f"drive {folder}: {args.pairs} Full-HD JPEG pairs, no depth maps; base {args.base.resolve()}, "
          f"new {REPO}; {os.cpu_count()} cores")
    ratios = []
    for k in range(1, args.rounds + 1):
        order = (("base", args.base), ("new", REPO)) if k % 2 else (("new", REPO), ("base", args.base))
        results = {name: run(checkout, folder) for name, checkout in order}
        rates = {name: r["pairs"] / r["seconds"] for name, r in results.items()}
        ratios.append(rates["new"] / rates["base"])
        print(f"round {k}: " + "; ".join(
            f"{name} {rates[name]:.2f} pairs/s, {1000 * r['cpu_seconds'] / r['pairs']:.0f} ms CPU/pair, "
            f"{r['detections']} detections, {r['signs']} signs, load {r['load'][0]:.1f}-{r['load'][1]:.1f}"
            for name, r in results.items()) + f"; new / base {ratios[-1]:.2f}", flush=True)
    print(f"{args.rounds} rounds: new / base pairs/s {min(ratios):.2f}-{max(ratios):.2f}, "
          f"median {statistics.median(ratios):.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
