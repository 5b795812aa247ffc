"""Every detection of mapping drives, one line each, and the CPU time it took: to show a speed change keeps the output.

    python -m bench.dump_detections DRIVE [DRIVE ...] [--pairs 30] [--workers 1] --out before.txt
    diff before.txt after.txt

Each line: drive, pair id, template id, box, detection and classification
indicators (6 decimals), status, source and the position to the millimetre;
then the fused signs (id, template, position to the millimetre). The pairs/s and
CPU seconds per pair (this process and its worker processes, user + system) go
to stderr, with the load average, so a diff of two dumps is empty when nothing changed.
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from dataclasses import replace
from pathlib import Path

from bench.bench_mapping import cpu_seconds


def detection_line(drive_name: str, observation) -> str:
    x, y, w, h = observation.bbox
    e, n, z = observation.position
    return (f"{drive_name} {observation.record.id} {observation.template_id} box {x},{y},{w},{h} "
            f"det {observation.detection_indicator:.6f} cls {observation.classification_indicator:.6f} "
            f"{observation.status} {observation.source} pos {e:.3f},{n:.3f},{z:.3f}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("drives", nargs="+", type=Path)
    parser.add_argument("--pairs", type=int, default=0, help="only the first N pairs of each drive (0 = all)")
    parser.add_argument("--workers", type=int, default=1)
    parser.add_argument("--out", type=Path, required=True)
    args = parser.parse_args()
    from signmapper_core.catalogue import load_catalogue
    from signmapper_core.drive.reader import open_drive
    from signmapper_core.pipeline import PipelineConfig
    from signmapper_core.run.mapping import map_drive

    catalogue, config = load_catalogue(), PipelineConfig()
    lines, pairs = [], 0
    load_before = os.getloadavg()
    cpu_start, start = cpu_seconds(), time.perf_counter()
    for folder in args.drives:
        drive = open_drive(folder)
        if args.pairs:
            drive = replace(drive, pairs=drive.pairs[: args.pairs])
        pairs += len(drive.pairs)
        result = map_drive(drive, catalogue, config, workers=args.workers)
        lines += [detection_line(folder.name, o) for o in result.detections]
        lines += [f"{folder.name} sign {s.sign_id} {s.template_id} {s.status} pos "
                  f"{s.position[0]:.3f},{s.position[1]:.3f},{s.position[2]:.3f}" for s in result.signs]
    seconds, cpu = time.perf_counter() - start, cpu_seconds() - cpu_start
    args.out.write_text("\n".join(lines) + "\n")
    print(f"{pairs} pairs, {args.workers} worker(s): {pairs / seconds:.2f} pairs/s, "
          f"{1000 * cpu / pairs:.0f} ms CPU per pair (process + workers), {len(lines)} lines; "
          f"load average {load_before[0]:.2f} before, {os.getloadavg()[0]:.2f} after", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
