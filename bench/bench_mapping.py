"""Pairs per second and peak memory of the mapping pipeline on a Full-HD drive.

    python bench/bench_mapping.py [--pairs 20] [--seed 2001]

Runs three ways over the same synthetic drive (generated once with true depth
maps, cached under build/drives/), each in its own process so peak RSS is its own:
  given-depth   depth/<id>.npy from the drive, no stereo matching
  sgbm          depth by SGBM with the disparity range from the 4-14 m search space
  baseline      full-frame, full-resolution SGBM over disparities 0..256 (the naive
                approach), then the same pipeline on that depth
The vehicle records 5 pairs/s; faster than that keeps up with the drive.
"""

from __future__ import annotations

import argparse
import json
import resource
import subprocess
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

MODES = ("given-depth", "sgbm", "baseline")


def baseline_depth(left, right, camera):
    """Full-frame SGBM over 0..256 disparities at full resolution: what the range restriction saves."""
    import cv2
    import numpy as np

    block = 5
    matcher = cv2.StereoSGBM_create(minDisparity=0, numDisparities=256, blockSize=block, P1=8 * block * block,
                                    P2=32 * block * block, disp12MaxDiff=2, uniquenessRatio=5,
                                    speckleWindowSize=60, speckleRange=2, preFilterCap=31,
                                    mode=cv2.STEREO_SGBM_MODE_SGBM_3WAY)
    grey_l = cv2.cvtColor(left, cv2.COLOR_BGR2GRAY)
    grey_r = cv2.cvtColor(right, cv2.COLOR_BGR2GRAY)
    disp = matcher.compute(grey_l, grey_r).astype(np.float32) / 16.0
    return camera.depth_from_disparity(np.where(disp > 0, disp, np.nan)).astype(np.float32)


def run_mode(mode: str, folder: Path) -> dict:
    from dataclasses import replace

    from signmapper_core.catalogue import load_catalogue
    from signmapper_core.drive import open_drive
    from signmapper_core.mapping import load_pair, map_drive
    from signmapper_core.pipeline import PipelineConfig, detect_pair

    drive = open_drive(folder)
    catalogue = load_catalogue()
    config = PipelineConfig()
    if mode != "given-depth":  # as with real data: depth from the stereo pair
        drive = replace(drive, pairs=[replace(r, depth_path=None) for r in drive.pairs])
    if mode != "baseline":
        result = map_drive(drive, catalogue, config)
        # decoding the JPEGs is not the pipeline's time; fusing the whole drive takes milliseconds
        detections, seconds = len(result.detections), result.seconds - result.load_seconds
    else:
        detections, seconds = 0, 0.0
        for record in drive.pairs:
            left, _, right = load_pair(drive, record)
            start = time.perf_counter()
            depth = baseline_depth(left, right, drive.camera)
            detections += len(detect_pair(left, depth, right, drive.camera, record.pose, catalogue, config))
            seconds += time.perf_counter() - start
    peak_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    return {"mode": mode, "pairs": len(drive.pairs), "seconds": seconds, "detections": detections,
            "peak_rss_mb": peak_mb}


def drive_folder(seed: int, pairs: int) -> Path:
    from signmapper_core.simulate import SimulationConfig, generate_drive

    out = REPO / "build" / "drives" / f"seed{seed}-{pairs}-depth"
    if not (out / "poses.csv").exists():
        print(f"generating {out} ...", flush=True)
        generate_drive(out, SimulationConfig(pairs=pairs, seed=seed, write_depth=True))
    return out


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--pairs", type=int, default=20)
    parser.add_argument("--seed", type=int, default=2001)
    parser.add_argument("--mode", choices=MODES, help=argparse.SUPPRESS)  # child process
    parser.add_argument("--drive", type=Path, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.mode:
        print(json.dumps(run_mode(args.mode, args.drive)))
        return 0
    folder = drive_folder(args.seed, args.pairs)
    print(f"drive {folder}: 1920x1080, {args.pairs} pairs; 2 cores; vehicle records 5 pairs/s")
    print(f"{'mode':<12} {'pairs/s':>8} {'s/pair':>8} {'detections':>10} {'peak RSS MB':>12}")
    for mode in MODES:
        out = subprocess.run([sys.executable, __file__, "--mode", mode, "--drive", str(folder)],
                             capture_output=True, text=True, check=True)
        r = json.loads(out.stdout.strip().splitlines()[-1])
        print(f"{mode:<12} {r['pairs'] / r['seconds']:8.2f} {r['seconds'] / r['pairs']:8.3f} "
              f"{r['detections']:10d} {r['peak_rss_mb']:12.0f}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
