"""Accuracy of mapped signs against a reference, as in Cavegn (2011), Tables 1 and 2.

Table 1: number of reference signs, detection rate, correct-classification rate,
false positives. Table 2: per component (across track, along track, height,
planimetric, 3D) the maximum difference and the empirical standard deviation.
Components are taken in the frame of the trajectory at each reference sign, so
a lever-arm or timing error shows up where a surveyor expects it (along track).
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field

import numpy as np

COMPONENTS = ("across", "along", "height", "planimetric", "3d")


@dataclass
class Table1:
    reference_signs: int
    detected_signs: int
    correctly_classified_signs: int
    detections: int
    false_positive_detections: int
    duplicates: int  # reference signs matched by more than one mapped feature

    @property
    def detection_rate(self) -> float:
        return self.detected_signs / self.reference_signs if self.reference_signs else float("nan")

    @property
    def classification_rate(self) -> float:
        return self.correctly_classified_signs / self.detected_signs if self.detected_signs else float("nan")


@dataclass
class ComponentStats:
    n: int
    mean: float
    std: float  # empirical standard deviation (about the mean, n - 1)
    rms: float
    max_abs: float  # maximum absolute difference


@dataclass
class EvaluationReport:
    table1: Table1
    table2: dict[str, ComponentStats]
    match: np.ndarray  # per mapped feature: index of the reference sign, -1 = false positive
    differences: np.ndarray  # (n_matched, 5) across, along, height, planimetric, 3d
    reference_ids: list = field(default_factory=list)
    confusions: list = field(default_factory=list)  # (reference id, assigned id) of misclassified signs


def share_text(n: int, of: int) -> str:
    """'3 of 4 (75.0 %)', or '3 (none to count)' when there is nothing to count: the rows' one way of saying it."""
    return f"{n} of {of} ({100.0 * n / of:.1f} %)" if of else f"{n} (none to count)"


def majority_id(ids) -> str:
    """The id most of the features matched to one reference sign carry (the first of equals)."""
    return Counter(ids).most_common(1)[0][0]


def match_to_reference(mapped_xyz: np.ndarray, reference_xyz: np.ndarray, radius_m: float) -> np.ndarray:
    """Index of the nearest reference sign within ``radius_m`` (3D) of each mapped feature, else -1."""
    mapped_xyz = np.asarray(mapped_xyz, float).reshape(-1, 3)
    reference_xyz = np.asarray(reference_xyz, float).reshape(-1, 3)
    if len(mapped_xyz) == 0 or len(reference_xyz) == 0:
        return np.full(len(mapped_xyz), -1, int)
    dist = np.linalg.norm(mapped_xyz[:, None, :] - reference_xyz[None, :, :], axis=2)
    nearest = dist.argmin(axis=1)
    return np.where(dist[np.arange(len(mapped_xyz)), nearest] <= radius_m, nearest, -1)


def track_directions(points_xy: np.ndarray, trajectory_xy: np.ndarray) -> np.ndarray:
    """Unit along-track direction (E, N) at each point, from the nearest trajectory segment."""
    points_xy = np.asarray(points_xy, float).reshape(-1, 2)
    traj = np.asarray(trajectory_xy, float).reshape(-1, 2)
    if len(traj) < 2:
        raise ValueError("a trajectory needs at least two positions to define along track")
    seg = np.diff(traj, axis=0)
    keep = np.linalg.norm(seg, axis=1) > 1e-6
    starts, seg = traj[:-1][keep], seg[keep]
    if len(seg) == 0:
        raise ValueError("the trajectory does not move")
    rel = points_xy[:, None, :] - starts[None, :, :]
    t = np.clip((rel * seg[None]).sum(-1) / (seg * seg).sum(-1)[None], 0.0, 1.0)
    dist = np.linalg.norm(rel - t[..., None] * seg[None], axis=2)
    nearest = seg[dist.argmin(axis=1)]
    return nearest / np.linalg.norm(nearest, axis=1, keepdims=True)


def decompose(diff_xyz: np.ndarray, along_en: np.ndarray) -> np.ndarray:
    """(n, 5) across, along, height, planimetric, 3D components of differences (mapped - reference).

    Across track is positive to the right of the driving direction.
    """
    diff_xyz = np.asarray(diff_xyz, float).reshape(-1, 3)
    along = (diff_xyz[:, :2] * along_en).sum(axis=1)
    right = np.stack([along_en[:, 1], -along_en[:, 0]], axis=1)
    across = (diff_xyz[:, :2] * right).sum(axis=1)
    planimetric = np.hypot(diff_xyz[:, 0], diff_xyz[:, 1])
    return np.stack([across, along, diff_xyz[:, 2], planimetric, np.linalg.norm(diff_xyz, axis=1)], axis=1)


def component_stats(values: np.ndarray) -> ComponentStats:
    values = np.asarray(values, float)
    n = len(values)
    if n == 0:
        nan = float("nan")
        return ComponentStats(0, nan, nan, nan, nan)
    return ComponentStats(
        n=n,
        mean=float(values.mean()),
        std=float(values.std(ddof=1)) if n > 1 else 0.0,
        rms=float(np.sqrt(np.mean(values**2))),
        max_abs=float(np.abs(values).max()),
    )


def evaluate(mapped_xyz, mapped_ids, reference_xyz, reference_ids, trajectory_xy, radius_m: float = 1.0,
             ) -> EvaluationReport:
    """Compare mapped features with reference signs.

    Works for fused signs (one feature per sign) and for per-pair detections
    (several features per sign): a reference sign counts as detected when at
    least one feature matches it, and as correctly classified when the majority
    of its matched features carry its template id. ``duplicates`` counts reference
    signs with more than one matched feature, meaningful for fused output.
    """
    mapped_xyz = np.asarray(mapped_xyz, float).reshape(-1, 3)
    reference_xyz = np.asarray(reference_xyz, float).reshape(-1, 3)
    mapped_ids, reference_ids = list(mapped_ids), list(reference_ids)
    match = match_to_reference(mapped_xyz, reference_xyz, radius_m)
    detected = correct = duplicates = 0
    confusions = []
    for ref in range(len(reference_xyz)):
        ids = [mapped_ids[i] for i in np.flatnonzero(match == ref)]
        if not ids:
            continue
        detected += 1
        duplicates += len(ids) > 1
        majority = majority_id(ids)
        if majority == reference_ids[ref]:
            correct += 1
        else:
            confusions.append((reference_ids[ref], majority))
    matched = np.flatnonzero(match >= 0)
    diffs = mapped_xyz[matched] - reference_xyz[match[matched]]
    if len(matched):
        along = track_directions(reference_xyz[match[matched], :2], trajectory_xy)
        components = decompose(diffs, along)
    else:
        components = np.zeros((0, 5))
    table1 = Table1(
        reference_signs=len(reference_xyz),
        detected_signs=detected,
        correctly_classified_signs=correct,
        detections=len(mapped_xyz),
        false_positive_detections=int((match < 0).sum()),
        duplicates=duplicates,
    )
    table2 = {name: component_stats(components[:, k]) for k, name in enumerate(COMPONENTS)}
    return EvaluationReport(table1, table2, match, components, reference_ids, confusions)


def percent(share: float) -> str:
    return f"{100 * share:.1f} %"


def table1_texts(t1: Table1) -> dict[str, str]:
    """Table 1 as the reader should see it: counts "of" their base, never a "nan %" where the base is 0."""
    detected = (f"{t1.detected_signs} of {t1.reference_signs} ({percent(t1.detection_rate)})"
                if t1.reference_signs else "0 (no reference signs)")
    if t1.detected_signs:
        classified = (f"{t1.correctly_classified_signs} of {t1.detected_signs} detected "
                      f"({percent(t1.classification_rate)})")
    else:
        classified = "0 (no sign detected)"
    return {
        "reference signs": f"{t1.reference_signs}",
        "detected signs": detected,
        "correctly classified signs": classified,
        "mapped features": f"{t1.detections}" if t1.detections else "0 (no mapped signs)",
        "false positive features": f"{t1.false_positive_detections}",
        "reference signs with >1 feature": f"{t1.duplicates}",
    }


NO_DIFFERENCES = "no mapped sign matches a reference sign: no coordinate differences"


def format_report(report: EvaluationReport, title: str = "", aligned: bool = True) -> str:
    """Plain-text Tables 1 and 2, laid out like the paper's; ``aligned=False`` labels every figure instead of
    lining up columns (for logs shown in a proportional font, like QGIS's Processing log)."""
    lines = [title] if title else []
    if report.table1.detections == 0:
        lines.append("No mapped signs: every reference sign counts as missed.")
    lines.append("Table 1: detection and classification")
    lines += [f"  {name:<32}{text}" for name, text in table1_texts(report.table1).items()]
    lines.append("Table 2: coordinate differences (mapped - reference) [m]")
    if report.table2[COMPONENTS[0]].n == 0:
        lines.append(f"  {NO_DIFFERENCES}")
    elif not aligned:
        for name in COMPONENTS:
            s = report.table2[name]
            lines.append(f"  {name}: n {s.n}, mean {s.mean:.3f}, empirical σ {s.std:.3f}, RMS {s.rms:.3f}, "
                         f"max |d| {s.max_abs:.3f}")
    else:
        lines.append("  component       n     mean      std      rms  max|d|")
        for name in COMPONENTS:
            s = report.table2[name]
            lines.append(f"  {name:<12} {s.n:4d} {s.mean:8.3f} {s.std:8.3f} {s.rms:8.3f} {s.max_abs:7.3f}")
    if report.confusions:
        lines.append("Misclassified (reference -> assigned): " + ", ".join(f"{a}->{b}" for a, b in report.confusions))
    return "\n".join(lines)


def combine_reports(reports: list[EvaluationReport]) -> EvaluationReport:
    """Pool the reports of several drives: counts add up, Table 2 is over all differences."""
    counts = {name: sum(getattr(r.table1, name) for r in reports) for name in (
        "reference_signs", "detected_signs", "correctly_classified_signs", "detections",
        "false_positive_detections", "duplicates")}
    differences = np.vstack([r.differences for r in reports]) if reports else np.zeros((0, 5))
    table2 = {name: component_stats(differences[:, k]) for k, name in enumerate(COMPONENTS)}
    return EvaluationReport(
        Table1(**counts), table2, np.concatenate([r.match for r in reports]) if reports else np.zeros(0, int),
        differences, [i for r in reports for i in r.reference_ids], [c for r in reports for c in r.confusions],
    )
