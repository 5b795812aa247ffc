"""Figures of an imported drive: rows of every pair, static points across pairs, and a mapping run.

    .venv/bin/python -m scripts.import_figures DRIVE [--span 4] [--step 1] [--map]

- rows: mean absolute vertical disparity of matched features (``epipolar.match_features``) in every
  ``--step``-th pair: what rectification left over (must stay below 0.5 px);
- static points: corners followed through ``--span`` consecutive pairs, each placed in the world by its
  pair's disparity and pose (``consistency.static_point_spread``); their spread shows whether poses,
  lever arm, boresight and convergence agree from pair to pair (moving objects are outliers: medians);
- ``--map``: the mapping every front end runs (``mapping.map_drive``, default settings, the Swiss
  catalogue): detections, signs, and for signs seen in several pairs the spread of their observations.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np


def observation_spread(sign) -> float:
    """RMS 3D distance of the positions of a fused sign's observations of its id from its position [m]: how well
    the imported poses place one sign from several pairs (``sigma_m`` is the position's estimated error instead)."""
    views = [o for o in sign.observations if o.template_id == sign.template_id] or sign.observations
    return float(np.sqrt(np.mean([np.sum((o.position - sign.position) ** 2) for o in views])))


def main(argv=None) -> int:
    from signmapper_core.pipeline.config import DepthConfig

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("drive", type=Path)
    parser.add_argument("--span", type=int, default=2, help="pairs a static point is followed through (2: each "
                        "pair with the next; more where pairs are close together)")
    parser.add_argument("--step", type=int, default=1, help="check the rows of every n-th pair")
    parser.add_argument("--near", type=float, default=DepthConfig.near_m, help="nearest point used for the spread, m")
    parser.add_argument("--far", type=float, default=20.0, help="farthest point used for the spread, m")
    parser.add_argument("--map", action="store_true", help="also map the drive's signs")
    args = parser.parse_args(argv)
    from signmapper_core.drive.reader import open_drive
    from signmapper_core.importdrive.consistency import static_point_spread
    from signmapper_core.importdrive.epipolar import match_features

    drive = open_drive(args.drive)
    print(f"{args.drive}: {len(drive.pairs)} pairs, {drive.camera}, CRS {drive.crs}")
    rows = []
    for record in drive.pairs[::args.step]:
        check = match_features(drive.load_left(record), drive.load_right(record))
        rows.append((check.mean_abs_dy, check.matches))
    dy, matches = np.array(rows).T
    print(f"rows, {len(rows)} pairs: mean |vertical disparity| min {dy.min():.3f} / median {np.median(dy):.3f} / "
          f"max {dy.max():.3f} px over a median of {np.median(matches):.0f} matches per pair")
    spreads, planimetric = [], []
    for start in range(0, len(drive.pairs) - args.span + 1, args.span):
        result = static_point_spread(drive, start, args.span, args.near, args.far)
        print("  " + result.text())
        spreads.append(result.spread_3d)
        planimetric.append(result.spread_plan)
    if spreads:
        s3, s2 = np.concatenate(spreads), np.concatenate(planimetric)
        print(f"static points, all windows: {len(s3)} points, spread median {100 * np.median(s3):.1f} cm 3D / "
              f"{100 * np.median(s2):.1f} cm planimetric, 68 % within {100 * np.percentile(s3, 68):.1f} cm, "
              f"90 % within {100 * np.percentile(s3, 90):.1f} cm")
    if args.map:
        from signmapper_core.catalogue import load_catalogue
        from signmapper_core.pipeline import PipelineConfig
        from signmapper_core.run.mapping import map_drive

        started = time.perf_counter()
        result = map_drive(drive, load_catalogue(), PipelineConfig())
        print(f"mapping: {len(result.detections)} detections, {len(result.signs)} signs, "
              f"{len(result.skipped)} pairs skipped, {time.perf_counter() - started:.1f} s")
        spreads = {sign.sign_id: observation_spread(sign) for sign in result.signs}
        for sign in result.signs:
            spread = f", spread of its observations {100 * spreads[sign.sign_id]:.1f} cm" if sign.n_obs > 1 else ""
            print(f"  sign {sign.sign_id}: {sign.template_id} seen in {sign.n_obs} pair(s){spread}, {sign.status}")
        several = [spreads[s.sign_id] for s in result.signs if s.n_obs > 1]
        if several:
            print(f"signs seen in several pairs: {len(several)}, spread of their observations median "
                  f"{100 * np.median(several):.1f} cm, max {100 * np.max(several):.1f} cm")
    return 0


if __name__ == "__main__":
    sys.exit(main())
