"""Map drives once and say whether the σ each fused sign reports is honest, with the one-feature-per-sign figures.

    python -m scripts.precision_check DRIVE [DRIVE ...] [--workers 1] [--radius 0.75]

Per drive and over all: reference signs in view (the mapped range, as ``evaluate_mapping``), detected, reference
signs with more than one feature (duplicates), features whose views lie within the radius of two reference signs,
one of which has no feature of its own (two signs merged into one), and the RMS of the error along the sign's
mean line of sight (the mean of the unit rays from its views' cameras) divided by ``sigma_along_m`` and of the error
across it, per axis, divided by ``sigma_across_m``: near 1 when the σ are honest. Plates are left out, as in
Table 2.
"""

from __future__ import annotations

import argparse
import sys
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from scripts.evaluate_mapping import positions_ids
from signmapper_core.catalogue import load_catalogue
from signmapper_core.drive.reader import open_drive
from signmapper_core.evaluation.accuracy import evaluate, match_to_reference
from signmapper_core.evaluation.visibility import mappable_signs
from signmapper_core.pipeline import PipelineConfig
from signmapper_core.run.mapping import map_drive

RADIUS_M = 0.75  # the matching radius of evaluate_mapping's Table 2


def mean_sight(position, camera_centres) -> np.ndarray:
    """The unit mean of the rays from ``camera_centres`` to ``position``: the line of sight σ along refers to."""
    rays = np.asarray(position, float) - np.asarray(camera_centres, float).reshape(-1, 3)
    rays /= np.maximum(np.linalg.norm(rays, axis=1, keepdims=True), 1e-9)
    total = rays.sum(axis=0)
    return total / max(float(np.linalg.norm(total)), 1e-9)


def error_ratios(error, sight, sigma_along: float, sigma_across: float) -> tuple[float, float]:
    """(error along ``sight`` / σ along, error across it per axis / σ across): the across error is the length of
    the part across divided by √2, as σ across is per axis of the plane across."""
    error, sight = np.asarray(error, float), np.asarray(sight, float)
    along = float(error @ sight)
    across = float(np.linalg.norm(error - along * sight)) / np.sqrt(2.0)
    return along / sigma_along, across / sigma_across


def merged_features(view_positions, reference_xyz, match, radius_m: float) -> int:
    """Features whose views (``view_positions``: per feature, the positions its views measured) lie within
    ``radius_m`` of two or more reference signs, one of which no feature matched: two signs fused into one."""
    reference_xyz = np.asarray(reference_xyz, float).reshape(-1, 3)
    unmatched = set(range(len(reference_xyz))) - set(int(m) for m in match if m >= 0)
    merged = 0
    for views in view_positions:
        seen = set(int(r) for r in match_to_reference(np.asarray(views, float), reference_xyz, radius_m) if r >= 0)
        merged += len(seen) >= 2 and bool(seen & unmatched)
    return merged


def rms(values) -> float:
    return float(np.sqrt(np.mean(np.square(values)))) if len(values) else float("nan")


@dataclass
class Figures:
    """What one or more drives came to."""

    in_view: int = 0
    detected: int = 0
    duplicates: int = 0
    merged: int = 0
    features: int = 0
    false_positives: int = 0
    along: list = field(default_factory=list)
    across: list = field(default_factory=list)
    errors_3d: list = field(default_factory=list)

    def __add__(self, other: Figures) -> Figures:
        return Figures(self.in_view + other.in_view, self.detected + other.detected,
                       self.duplicates + other.duplicates, self.merged + other.merged, self.features + other.features,
                       self.false_positives + other.false_positives, self.along + other.along,
                       self.across + other.across, self.errors_3d + other.errors_3d)

    def line(self, name: str) -> str:
        share = 100.0 * self.detected / self.in_view if self.in_view else float("nan")
        return (f"{name}: in view {self.in_view}, detected {self.detected} ({share:.1f} %), >1 feature "
                f"{self.duplicates}, merged {self.merged}, features {self.features} of which false positives "
                f"{self.false_positives}; {len(self.along)} matched: RMS along/σ "
                f"{rms(self.along):.2f}, across/σ {rms(self.across):.2f}, 3D RMS {100 * rms(self.errors_3d):.1f} cm")


def drive_figures(signs, reference, radius_m: float, trajectory_xy) -> Figures:
    """The figures of fused ``signs`` (plates left out) against the ``reference`` signs in view."""
    ref_xyz = np.array([s.position for s in reference], float).reshape(-1, 3)
    mapped_xyz, mapped_ids = positions_ids(signs)
    report = evaluate(mapped_xyz, mapped_ids, ref_xyz, [s.template_id for s in reference], trajectory_xy, radius_m)
    figures = Figures(len(reference), report.table1.detected_signs, report.table1.duplicates,
                      merged_features([[o.position for o in s.observations] for s in signs], ref_xyz, report.match,
                                      radius_m), len(signs),
                      report.table1.false_positive_detections)
    for sign, ref in zip(signs, report.match):
        if ref < 0 or not sign.sigma_along_m or not sign.sigma_across_m:
            continue
        error = np.asarray(sign.position, float) - ref_xyz[ref]
        sight = mean_sight(sign.position, [o.camera_centre for o in sign.observations])
        along, across = error_ratios(error, sight, sign.sigma_along_m, sign.sigma_across_m)
        figures.along.append(along)
        figures.across.append(across)
        figures.errors_3d.append(float(np.linalg.norm(error)))
    return figures


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("drives", nargs="+", type=Path, help="drive folders with truth.csv")
    parser.add_argument("--radius", type=float, default=RADIUS_M, help="matching radius in metres")
    parser.add_argument("--workers", type=int, default=0, help="worker processes (0 = all cores)")
    args = parser.parse_args(argv)
    catalogue = load_catalogue(None)
    config = PipelineConfig()
    total = Figures()
    for folder in args.drives:
        drive = open_drive(folder, require_truth=True)
        result = map_drive(drive, catalogue, config, warn=lambda message: print(message, file=sys.stderr),
                           workers=args.workers)
        reference = mappable_signs(drive, result.config.depth)
        traj = np.array([[r.pose.easting, r.pose.northing] for r in drive.pairs])
        figures = drive_figures([s for s in result.signs if s.plate_of is None], reference, args.radius, traj)
        print(figures.line(str(folder)), flush=True)
        total = total + figures
    print(total.line("all"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
