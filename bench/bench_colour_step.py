"""Seconds per Full-HD image of the colour step without depth (colour passes, merges, Hough, shape, candidates).

    python -m bench.bench_colour_step [--data DIR] [--split tune] [--images 40]

Photographs of a real-photograph set (scenes_images.csv, e.g. GTSDB's 1360x800 scenes) are
scaled to 1920 px wide (Full HD width) before timing, so the figure is per Full-HD frame;
without ``--data`` a synthetic Full-HD drive (generated once, cached under build/drives/) is used.
Also prints segments and face candidates per image, the cost side of the colour step.
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import time
from pathlib import Path

from scripts.drives import DRIVES, cached_drive


def real_images(data: Path, split: str, count: int):
    from signmapper_core.validation import load_scene_list, read_bgr

    scenes = [s for s in load_scene_list(data / "scenes_images.csv") if split == "all" or s.split == split]
    return [read_bgr(s.image) for s in scenes[:count]]


def synthetic_images(count: int):
    from signmapper_core.drive.reader import open_drive
    from signmapper_core.simulate import SimulationConfig

    drive = open_drive(cached_drive(DRIVES / f"seed2001-{count}", SimulationConfig(pairs=count, seed=2001)))
    return [drive.load_left(r) for r in drive.pairs]


def main() -> int:
    import cv2

    from signmapper_core.catalogue import load_catalogue
    from signmapper_core.pipeline import PipelineConfig
    from signmapper_core.pipeline.candidates import colour_step

    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--data", type=Path, default=os.environ.get("SIGNMAPPER_REAL_DATA"))
    parser.add_argument("--split", choices=("tune", "report", "all"), default="tune")
    parser.add_argument("--images", type=int, default=40)
    args = parser.parse_args()
    images = real_images(Path(args.data), args.split, args.images) if args.data else synthetic_images(args.images)
    images = [cv2.resize(im, (1920, int(round(im.shape[0] * 1920 / im.shape[1]))), interpolation=cv2.INTER_LINEAR)
              if im.shape[1] != 1920 else im for im in images]
    catalogue, config = load_catalogue(), PipelineConfig()
    colour_step(images[0], catalogue, config)  # templates rendered and cached once, as in a run
    seconds, segments, candidates = [], [], []
    for image in images:
        start = time.perf_counter()
        segs, cands = colour_step(image, catalogue, config)
        seconds.append(time.perf_counter() - start)
        segments.append(len(segs))
        candidates.append(len(cands))
    source = f"{args.data} ({args.split})" if args.data else "synthetic drive seed 2001"
    print(f"colour step without depth on {len(images)} images of {source}, scaled to "
          f"{images[0].shape[1]}x{images[0].shape[0]}:")
    print(f"  {statistics.mean(seconds):.3f} s/image mean, {statistics.median(seconds):.3f} median, "
          f"{max(seconds):.3f} max; {statistics.mean(segments):.1f} segments, "
          f"{statistics.mean(candidates):.1f} face candidates per image")
    return 0


if __name__ == "__main__":
    sys.exit(main())
