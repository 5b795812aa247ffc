"""Where the time of mapping one pair goes: cProfile over ``mapping.map_pair`` (decoding included), one process.

    python -m bench.profile_pair [--drive build/drives/seed2001-100-stereo] [--pairs 10] [--top 25] [--callees NAME]

Profiles the first ``--pairs`` pairs of a drive (JPEG pairs, depth by SGBM) after
one warm-up pair (classifier loaded, OpenCV initialised), with OpenCV on one
thread as in a worker process, and prints the functions with the most time spent
inside them and below them, in CPU milliseconds per pair (process time, so a
busy machine does not inflate them; OpenCV runs on one thread).
"""

from __future__ import annotations

import argparse
import cProfile
import pstats
import sys
import time
from pathlib import Path

from scripts.drives import DRIVES


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--drive", type=Path, default=DRIVES / "seed2001-100-stereo")
    parser.add_argument("--pairs", type=int, default=10)
    parser.add_argument("--top", type=int, default=25)
    parser.add_argument("--callees", metavar="NAME",
                        help="also print what the functions of this name spend their time in (e.g. read_face)")
    args = parser.parse_args()
    import cv2

    from signmapper_core.catalogue import load_catalogue
    from signmapper_core.drive.reader import open_drive
    from signmapper_core.pipeline import PipelineConfig
    from signmapper_core.run.pair import map_pair

    cv2.setNumThreads(1)
    drive, catalogue, config = open_drive(args.drive), load_catalogue(), PipelineConfig()
    map_pair(drive, drive.pairs[0], catalogue, config)  # warm-up
    records = drive.pairs[1: 1 + args.pairs]
    profiler = cProfile.Profile(time.process_time)  # CPU time: other processes on the machine do not count
    profiler.enable()
    for record in records:
        map_pair(drive, record, catalogue, config)
    profiler.disable()
    stats = pstats.Stats(profiler)
    total = stats.total_tt / len(records)
    print(f"{len(records)} pairs of {args.drive.name}, {total * 1000:.0f} ms CPU per pair (one thread)")
    rows = []
    for (path, line, name), (_, calls, own, cumulative, _) in stats.stats.items():
        where = f"{Path(path).name}:{name}" if line else name
        rows.append((cumulative, own, calls, where))
    print(f"{'ms/pair (with callees)':>22} {'ms/pair (own)':>14} {'calls/pair':>10}  function")
    for cumulative, own, calls, where in sorted(rows, reverse=True)[: args.top]:
        print(f"{cumulative * 1000 / len(records):22.1f} {own * 1000 / len(records):14.1f} "
              f"{calls / len(records):10.1f}  {where}")
    if args.callees:
        print(f"\nwithin {args.callees}:")
        stats.print_callees(f":[0-9]+\\({args.callees}\\)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
