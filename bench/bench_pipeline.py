"""Per-step time and per-pair detection quality of the pipeline on a synthetic drive.

    python -m bench.bench_pipeline [--pairs 20] [--seed 2001] [--mode given|sgbm|sgbm-full] [--verbose]

Generates (once, cached under build/drives/) a Full-HD drive with true depth
maps and truth.csv, runs detect_pair on every pair and reports:
  - seconds per pair and per step (depth, colour, segments, hough);
  - per pair, the truth signs expected to be seen (face centre 4-14 m ahead,
    inside the image, facing the camera within 45 deg) matched with detections
    by pixel distance: found, right template id, 3D position error;
  - detections matching no expected sign (false positives, or signs seen
    outside the expectation rule, e.g. at a steep angle).
given: depth/<id>.npy; sgbm: range-restricted SGBM on the row bands of colour
candidates (default config); sgbm-full: SGBM on the whole frame.
"""

from __future__ import annotations

import argparse
import sys
import time
from collections import defaultdict
from pathlib import Path

import numpy as np

from scripts.drives import DRIVES, cached_drive


def drive_folder(seed: int, pairs: int) -> Path:
    from signmapper_core.simulate import SimulationConfig

    return cached_drive(DRIVES / f"seed{seed}-{pairs}-depth",
                        SimulationConfig(pairs=pairs, seed=seed, write_depth=True))


def expected_signs(drive, record, config, max_angle_deg=45.0):
    """Truth signs whose face centre is in the search space, in the image and facing the camera."""
    from signmapper_core.geometry import world_to_pixel
    from signmapper_core.pipeline.search_range import edge_share, in_search_range

    out = []
    cam = drive.camera
    for sign in drive.truth or []:
        u, v, z = world_to_pixel(cam, record.pose, sign.position)
        if not (0 <= u < cam.width and 0 <= v < cam.height and in_search_range(z, edge_share(cam, u, v), config.depth)):
            continue
        facing = np.radians(sign.facing)
        normal = np.array([np.sin(facing), np.cos(facing), 0.0])
        to_camera = record.pose.centre - sign.position
        cos = normal @ to_camera / np.linalg.norm(to_camera)
        if cos < np.cos(np.radians(max_angle_deg)):
            continue
        out.append((sign, float(u), float(v), float(z)))
    return out


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--pairs", type=int, default=20)
    parser.add_argument("--seed", type=int, default=2001)
    parser.add_argument("--mode", choices=("given", "sgbm", "sgbm-full"), default="given")
    parser.add_argument("--drive", type=Path, help="an existing drive folder instead of a generated one")
    parser.add_argument("--verbose", action="store_true")
    args = parser.parse_args()

    from signmapper_core.catalogue import load_catalogue
    from signmapper_core.drive.reader import open_drive
    from signmapper_core.pipeline import PipelineConfig, detect_pair
    from signmapper_core.pipeline.config import with_settings
    from signmapper_core.pipeline.depth_range import config_for_camera

    folder = args.drive or drive_folder(args.seed, args.pairs)
    drive = open_drive(folder)
    catalogue = load_catalogue()
    config = config_for_camera(PipelineConfig(), drive.camera)  # the range map_drive would search
    if args.mode == "sgbm-full":
        config = with_settings(config, {"depth": {"sgbm_rows_only": False}})
    steps, total = defaultdict(float), 0.0
    n_expected = n_found = n_right = n_false = n_det = n_accepted_right = 0
    errors = []
    for record in drive.pairs:
        left = drive.load_left(record)
        depth = drive.load_depth(record) if args.mode == "given" else None
        right = drive.load_right(record) if depth is None else None
        timings = {}
        start = time.perf_counter()
        detections = detect_pair(left, depth, right, drive.camera, record.pose, catalogue, config, timings)
        total += time.perf_counter() - start
        for k, v in timings.items():
            steps[k] += v
        expected = expected_signs(drive, record, config)
        used = set()
        for sign, u, v, _z in expected:
            n_expected += 1
            best = None
            for i, det in enumerate(detections):
                x, y, w, h = det.bbox
                if i not in used and x - 5 <= u <= x + w + 5 and y - 5 <= v <= y + h + 5:
                    best = i
                    break
            if best is None:
                if args.verbose:
                    print(f"  {record.id}: missed {sign.template_id} at ({u:.0f}, {v:.0f}) Z={_z:.1f}")
                continue
            used.add(best)
            det = detections[best]
            n_found += 1
            n_right += det.template_id == sign.template_id
            n_accepted_right += det.template_id == sign.template_id and det.status == "accepted"
            errors.append(float(np.linalg.norm(det.position - sign.position)))
            if args.verbose:
                print(f"  {record.id}: {sign.template_id} -> {det.template_id} ({det.status}, "
                      f"det {det.detection_indicator:.2f}, cls {det.classification_indicator:.2f}, "
                      f"{det.format}, err {errors[-1]:.2f} m)")
        n_det += len(detections)
        for i, det in enumerate(detections):
            if i not in used:
                n_false += 1
                if args.verbose:
                    print(f"  {record.id}: unmatched {det.template_id} {det.status} at ({det.u:.0f}, {det.v:.0f}) "
                          f"Z={det.depth_m:.1f} det {det.detection_indicator:.2f} "
                          f"cls {det.classification_indicator:.2f} [{det.source}]")
    n = len(drive.pairs)
    print(f"drive {folder} ({n} pairs, {drive.camera.width}x{drive.camera.height}), mode {args.mode}")
    print(f"time per pair {total / n:.3f} s ({n / total:.1f} pairs/s); per step: "
          + ", ".join(f"{k} {v / n:.3f}" for k, v in steps.items()))
    print(f"expected sign views {n_expected}, found {n_found}, right id {n_right} "
          f"(accepted {n_accepted_right}), detections {n_det}, unmatched {n_false}")
    if errors:
        print(f"position error median {np.median(errors):.3f} m, 90% {np.percentile(errors, 90):.3f} m")
    return 0


if __name__ == "__main__":
    sys.exit(main())
