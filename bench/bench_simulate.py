"""Benchmark of the synthetic drive generator: seconds and MB per 100 pairs, peak RSS.

    .venv/bin/python -m bench.bench_simulate [--pairs 100] [--width 1920 --height 1080] [--depth] [--keep DIR]
"""

from __future__ import annotations

import argparse
import resource
import shutil
import sys
import tempfile
import time
from pathlib import Path

from signmapper_core.simulate import SimulationConfig, generate_drive


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--pairs", type=int, default=100)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--width", type=int, default=1920)
    p.add_argument("--height", type=int, default=1080)
    p.add_argument("--depth", action="store_true", help="also write true depth maps")
    p.add_argument("--keep", help="write the drive here and keep it (default: a temporary folder)")
    args = p.parse_args(argv)
    cfg = SimulationConfig(pairs=args.pairs, seed=args.seed, width=args.width, height=args.height,
                           fx=1750.0 * args.width / 1920, write_depth=args.depth)
    tmp = None
    if args.keep:
        out = Path(args.keep)
    else:
        tmp = Path(tempfile.mkdtemp(prefix="bench_simulate_"))
        out = tmp / "drive"
    try:
        started = time.perf_counter()
        summary = generate_drive(out, cfg)
        seconds = time.perf_counter() - started
    finally:
        if tmp is not None:
            shutil.rmtree(tmp, ignore_errors=True)
    per100 = 100.0 / args.pairs
    peak_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    print(f"{args.pairs} pairs {args.width}x{args.height}{' + depth' if args.depth else ''}, "
          f"{len(summary.signs)} signs in truth")
    print(f"seconds per 100 pairs: {seconds * per100:.1f}")
    print(f"MB on disk per 100 pairs: {summary.bytes_written / 1e6 * per100:.1f}")
    print(f"peak RSS: {peak_mb:.0f} MB")
    return 0


if __name__ == "__main__":
    sys.exit(main())
