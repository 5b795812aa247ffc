"""Time of opening (validating) a long drive: headers of every file, plausibility checks, first depth map.

    .venv/bin/python -m bench.bench_open_drive --pairs 10000 [--folder /tmp/drive10k]

Writes a drive of tiny 64x48 pairs (left, right, depth) once, then opens it three times and prints the
seconds; the cost is per file (headers), not per pixel.
"""

from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pairs", type=int, default=10000)
    parser.add_argument("--folder", type=Path, default=None, help="drive folder to write (kept for reruns)")
    args = parser.parse_args()
    from signmapper_core.drive.reader import open_drive
    from tests.drive_fixtures import make_drive

    folder = args.folder or Path(tempfile.mkdtemp()) / "drive"
    if not (folder / "poses.csv").exists():
        make_drive(folder, n_pairs=args.pairs, image_suffix=".jpg")
    for run in range(3):
        start = time.perf_counter()
        drive = open_drive(folder)
        seconds = time.perf_counter() - start
        print(f"open_drive, {len(drive.pairs)} pairs ({3 * len(drive.pairs)} files), run {run + 1}: {seconds:.2f} s "
              f"({1e3 * seconds / len(drive.pairs):.2f} ms/pair), {len(drive.warnings)} warnings")


if __name__ == "__main__":
    main()
