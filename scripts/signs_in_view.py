"""Signs in view per colour family (faces of the procedural designs apart), from truth and poses only: nothing mapped.

    python -m scripts.signs_in_view DRIVE [DRIVE ...]
    python -m scripts.signs_in_view --seeds 8000-8059 --pairs 100 [--plan | --generate]

For a held-out set, chosen before anything is mapped: every family should have enough signs in view over it.
A sign is in view as ``visibility.mappable_signs`` says (its centre inside the image, within the depth range,
its face turned to the camera, in one pair at least); its row is ``family_evaluation.sign_group``. ``--seeds``
counts the synthetic drives ``python -m scripts.evaluate_mapping --generate SEEDS --pairs N`` maps (the same folders
under build/drives/): ``--plan`` from their layout alone (no pixel rendered; the same truth and poses the drives
carry), ``--generate`` writes those not there yet, else the folders must exist.
"""

from __future__ import annotations

import argparse
import sys
from collections import Counter
from pathlib import Path

from scripts.evaluate_mapping import add_depth_range_arguments, depth_settings, drive_folder, generated_drive
from signmapper_core.catalogue import load_catalogue
from signmapper_core.drive.reader import open_drive
from signmapper_core.evaluation.families import GROUP_TITLES, GROUPS, catalogue_colour, sign_group
from signmapper_core.evaluation.visibility import pose_ranges, visible_in_pair
from signmapper_core.pipeline.config import DepthConfig, PipelineConfig
from signmapper_core.pipeline.depth_range import config_for_camera


def searched_range(camera, near, far) -> DepthConfig:
    """The range a mapping of ``camera``'s drive searches: the camera's, or ``near``..``far`` where either is given."""
    return config_for_camera(PipelineConfig(depth=depth_settings(near, far)), camera).depth


def in_view(truth, camera, poses, near, far) -> list:
    """The signs (not plates) of ``truth`` seen face-on within the searched range from one of ``poses`` at least."""
    ranges = pose_ranges(list(poses), searched_range(camera, near, far))
    return [t for t in truth if not t.is_plate
            and any(visible_in_pair(camera, p, t, pair_range) for p, pair_range in zip(poses, ranges))]


def planned(seed: int, pairs: int, near, far) -> list:
    """The signs in view of the drive ``evaluate_mapping --generate`` would write, from its layout alone."""
    from signmapper_core.simulate import SimulationConfig
    from signmapper_core.simulate.generator import make_scene, make_street, recorded_poses, true_poses

    config = SimulationConfig(pairs=pairs, seed=seed)
    street = make_street(config)
    poses = recorded_poses(config, true_poses(config, street))
    return in_view(make_scene(config, street).truth, config.camera(), poses, near, far)


def seed_range(text: str) -> list[int]:
    """'8000-8059' or '8000,8003' (or both, comma-separated)."""
    seeds = []
    for part in text.split(","):
        lo, _, hi = part.partition("-")
        seeds += list(range(int(lo), int(hi or lo) + 1))
    return seeds


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("drives", nargs="*", type=Path, help="drive folders with truth.csv")
    parser.add_argument("--seeds", type=seed_range, default=[], help="synthetic drives by seed: 8000-8059")
    parser.add_argument("--pairs", type=int, default=100, help="pairs of each synthetic drive")
    how = parser.add_mutually_exclusive_group()
    how.add_argument("--plan", action="store_true", help="count from the layout, write nothing")
    how.add_argument("--generate", action="store_true", help="write the synthetic drives not there yet")
    add_depth_range_arguments(parser)
    args = parser.parse_args(argv)
    if not args.drives and not args.seeds:
        parser.error("give drive folders or --seeds")
    colour_of = catalogue_colour(load_catalogue())
    totals = Counter()
    sources = [(str(d), d) for d in args.drives] + [(f"seed {s}", s) for s in args.seeds]
    for name, source in sources:
        if isinstance(source, int) and args.plan:
            seen = planned(source, args.pairs, args.near, args.far)
        else:
            folder = source if isinstance(source, Path) else \
                generated_drive(source, args.pairs, False) if args.generate else drive_folder(source, args.pairs, False)
            drive = open_drive(folder, require_truth=True)
            seen = in_view(drive.truth, drive.camera, [r.pose for r in drive.pairs], args.near, args.far)
        counts = Counter(sign_group(t, colour_of) for t in seen)
        totals += counts
        print(f"{name}: {len(seen)} signs in view; " + ", ".join(f"{g} {counts[g]}" for g in GROUPS if counts[g]),
              flush=True)
    print(f"== {len(sources)} drives, {sum(totals.values())} signs in view (near {args.near} m, far {args.far} m; "
          "None: the default and the camera's reach)")
    for group in GROUPS:
        print(f"  {GROUP_TITLES.get(group, group):<20} {totals[group]:>5}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
