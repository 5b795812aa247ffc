"""Change detection: a mapping run compared with the sign inventory a road owner already has.

Cavegn (2011) names the point of mapping signs from stereo imagery: keeping an
inventory up to date by automated change analysis. For every inventory sign the
drive could have seen, a verdict:

- ``confirmed``: a mapped sign of the same type within the tolerance;
- ``moved``: the same type, farther than the tolerance but within the move radius;
- ``changed``: another type at the same place (within the tolerance, and at the
  same height where both heights are known, so a stacked neighbour is not taken);
- ``missing``: the drive should have shown it and nothing was mapped there;
- ``not covered``: the drive never had it in view (or its type cannot be mapped
  with this catalogue): no verdict is possible.

Mapped signs left over are ``new``. Whether the drive could have seen a sign is
decided from the drive's poses and camera as for the evaluation
(:mod:`visibility`): in some pair the whole face projects inside the image at a
depth within the mapping run's search range, and its face is turned towards the
camera within the angle a sign is readable at. Distances are planimetric: an
inventory often has no heights (Signalo stores the support's 2D position).
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from typing import Optional, Sequence

import numpy as np

from ..evaluation.visibility import READABLE_FACE_ANGLE_DEG, facing_vector
from ..pipeline.config import DepthConfig

CONFIRMED, MOVED, CHANGED, MISSING, NOT_COVERED, NEW = "confirmed", "moved", "changed", "missing", "not covered", "new"
VERDICTS = (CONFIRMED, MOVED, CHANGED, MISSING, NOT_COVERED, NEW)
VERDICT_COLOURS = {CONFIRMED: "#2e7d32", MOVED: "#1565c0", CHANGED: "#8e24aa", MISSING: "#d52b1e",
                   NOT_COVERED: "#9e9e9e", NEW: "#f57c00"}
DEFAULT_FACE_M = 0.6  # face size assumed for a sign whose size the inventory does not give


@dataclass(frozen=True)
class InventorySign:
    """One sign of the existing inventory, in the drive's CRS.

    ``position`` is (E, N, H); H is NaN where the inventory has no height, then
    ``height_above_road_m`` (the face centre above the road) may stand in for it.
    ``facing``: azimuth the face looks towards, None where unknown (then any
    direction counts as readable).
    """

    key: str  # the inventory's own id: feature id, Signalo sign uuid
    template_id: str  # in the mapping catalogue's ids where it has the type, else the inventory's own code
    position: np.ndarray
    facing: Optional[float] = None
    width_m: Optional[float] = None
    height_m: Optional[float] = None
    height_above_road_m: Optional[float] = None
    label: str = ""  # how the inventory names it, for messages

    @property
    def has_height(self) -> bool:
        return bool(np.isfinite(self.position[2]))


@dataclass(frozen=True)
class MappedSign:
    """One sign of the mapping run (a feature of its ``signs`` layer)."""

    sign_id: int
    template_id: str
    position: np.ndarray
    status: str = ""
    azimuth: Optional[float] = None
    best_pair_id: str = ""
    u: Optional[float] = None
    v: Optional[float] = None
    bbox: Optional[tuple] = None  # (x, y, w, h) in the left image of best_pair_id
    key: str = ""  # the layer's feature id


@dataclass(frozen=True)
class ChangeConfig:
    """Tolerances of the verdicts and the visibility test (the mapping run's search range)."""

    tolerance_m: float = 0.5  # the same sign: planimetrically closer than this
    move_radius_m: float = 5.0  # the same type farther than the tolerance but within this: moved
    height_gate_m: float = 0.35  # same place only within this vertically, where both heights are known
    near_m: float = DepthConfig.near_m
    far_m: float = DepthConfig.far_m
    max_face_angle_deg: float = READABLE_FACE_ANGLE_DEG
    camera_height_m: Optional[float] = None  # above the road, for inventory heights given above the road

    def validate(self) -> ChangeConfig:
        if not 0 < self.tolerance_m < self.move_radius_m:
            raise ValueError(f"tolerance {self.tolerance_m} m must be positive and below the move radius "
                             f"{self.move_radius_m} m")
        if not 0 < self.near_m < self.far_m:
            raise ValueError(f"near limit {self.near_m} m must be positive and below the far limit {self.far_m} m")
        if not 0 < self.max_face_angle_deg <= 90:
            raise ValueError(f"readable face angle {self.max_face_angle_deg}° must be in (0, 90]")
        return self


@dataclass(frozen=True)
class PairView:
    """Where a sign should appear in one pair: its centre, its face box in the left image, its depth."""

    pair_id: str
    time: float
    u: float
    v: float
    bbox: tuple  # (x, y, w, h), integers
    depth_m: float


@dataclass
class Change:
    """The verdict on one inventory sign or one new mapped sign, and what it rests on."""

    verdict: str
    inventory: Optional[InventorySign]
    mapped: Optional[MappedSign]
    distance_m: Optional[float] = None  # planimetric, inventory to mapped
    height_difference_m: Optional[float] = None  # mapped minus inventory, where both are known
    views: list = field(default_factory=list)  # PairView of every pair that should have shown the inventory sign
    reason: str = ""

    @property
    def visible_pair_ids(self) -> list[str]:
        return [view.pair_id for view in self.views]

    @property
    def best_view(self) -> Optional[PairView]:
        """The pair showing the inventory sign largest (nearest) with its whole face in the image."""
        return min(self.views, key=lambda view: view.depth_m) if self.views else None

    @property
    def position(self) -> np.ndarray:
        """Where the feature goes: the inventory sign, or for a new sign the mapped one."""
        return self.inventory.position if self.inventory is not None else self.mapped.position


@dataclass
class ChangeReport:
    changes: list[Change]
    config: ChangeConfig

    def counts(self) -> dict:
        counted = Counter(c.verdict for c in self.changes)
        return {verdict: counted.get(verdict, 0) for verdict in VERDICTS}

    def of(self, verdict: str) -> list[Change]:
        return [c for c in self.changes if c.verdict == verdict]

    def summary(self) -> str:
        counts = self.counts()
        inventory = sum(n for v, n in counts.items() if v != NEW)
        return (f"{inventory} inventory signs: " + ", ".join(f"{counts[v]} {v}" for v in VERDICTS if v != NEW)
                + f"; {counts[NEW]} new mapped signs")


def pose_arrays(records) -> tuple[np.ndarray, np.ndarray]:
    """Rotations (n, 3, 3) and centres (n, 3) of the pairs' poses, for projecting many signs at once."""
    rotations = np.array([r.pose.rotation for r in records]).reshape(-1, 3, 3)
    centres = np.array([r.pose.centre for r in records]).reshape(-1, 3)
    return rotations, centres


def sign_views(camera, records, poses, position, facing: Optional[float], width_m: float, height_m: float,
               config: ChangeConfig) -> list[PairView]:
    """Every pair in which the sign's whole face is in the image, within the depth range and turned readably
    towards the camera (``facing`` None: any direction)."""
    rotations, centres = poses
    if len(records) == 0:
        return []
    rel = np.asarray(position, float)[None, :] - centres
    xc = np.einsum("ni,nij->nj", rel, rotations)  # world_to_camera of every pose at once
    u, v, z = camera.camera_to_pixel(xc)
    with np.errstate(divide="ignore", invalid="ignore"):
        half_w = camera.fx * width_m / 2.0 / z
        half_h = camera.fy * height_m / 2.0 / z
    ok = (z >= config.near_m) & (z <= config.far_m)
    ok &= (u - half_w >= 0) & (u + half_w <= camera.width - 1) & (v - half_h >= 0) & (v + half_h <= camera.height - 1)
    if facing is not None:
        to_camera = -rel[:, :2]
        norm = np.hypot(to_camera[:, 0], to_camera[:, 1])
        with np.errstate(divide="ignore", invalid="ignore"):
            cos_angle = (to_camera @ facing_vector(facing)[:2]) / norm
        ok &= (norm > 0) & (cos_angle >= np.cos(np.radians(config.max_face_angle_deg)))
    views = []
    for i in np.flatnonzero(ok):
        x0, y0 = int(round(u[i] - half_w[i])), int(round(v[i] - half_h[i]))
        box = (x0, y0, max(1, int(round(2 * half_w[i]))), max(1, int(round(2 * half_h[i]))))
        views.append(PairView(records[i].id, records[i].time, float(u[i]), float(v[i]), box, float(z[i])))
    return views


def with_height(sign: InventorySign, centres: np.ndarray, config: ChangeConfig) -> np.ndarray:
    """The sign's position with a height to project: its own, else the road beside it plus its height above
    the road (where the drive states its camera height), else the nearest camera's height (signs are mounted
    about as high as a vehicle's cameras)."""
    position = np.asarray(sign.position, float).copy()
    if np.isfinite(position[2]) or len(centres) == 0:
        return position
    nearest = centres[np.argmin(np.hypot(centres[:, 0] - position[0], centres[:, 1] - position[1]))]
    if sign.height_above_road_m is not None and config.camera_height_m is not None:
        position[2] = nearest[2] - config.camera_height_m + sign.height_above_road_m
    else:
        position[2] = nearest[2]
    return position


def _planimetric(a: np.ndarray, b: np.ndarray) -> float:
    return float(np.hypot(a[0] - b[0], a[1] - b[1]))


def _assign(pairs, taken_inventory: set, taken_mapped: set):
    """Greedy one-to-one assignment of (distance, i, m) candidates, nearest first."""
    for distance, i, m in sorted(pairs):
        if i in taken_inventory or m in taken_mapped:
            continue
        taken_inventory.add(i)
        taken_mapped.add(m)
        yield distance, i, m


def compare(inventory: Sequence[InventorySign], mapped: Sequence[MappedSign], camera, records,
            config: Optional[ChangeConfig] = None, mappable_types=None) -> ChangeReport:
    """Verdicts on every inventory sign and the mapped signs no inventory sign accounts for.

    ``records``: the drive's pairs (PairRecord, with poses). ``mappable_types``:
    the template ids the run could assign (its catalogue minus exclusions); an
    inventory sign of another type gets ``not covered``. Assignment is one to
    one, in three rounds, each nearest first: same type at the same place
    (confirmed), another type at the same place (changed), the same type within
    the move radius (moved).
    """
    config = (config or ChangeConfig()).validate()
    poses = pose_arrays(records)
    heights = [with_height(sign, poses[1], config) for sign in inventory]
    same_type, same_place, in_radius = [], [], []
    for i, sign in enumerate(inventory):
        for m, found in enumerate(mapped):
            distance = _planimetric(sign.position, found.position)
            if distance > config.move_radius_m:
                continue
            level = not sign.has_height or abs(found.position[2] - sign.position[2]) <= config.height_gate_m
            if found.template_id == sign.template_id:
                (same_type if distance <= config.tolerance_m and level else in_radius).append((distance, i, m))
            elif distance <= config.tolerance_m and level:
                same_place.append((distance, i, m))
    taken_i, taken_m, matched = set(), set(), {}
    for verdict, candidates in ((CONFIRMED, same_type), (CHANGED, same_place), (MOVED, in_radius)):
        for distance, i, m in _assign(candidates, taken_i, taken_m):
            matched[i] = (verdict, m, distance)

    changes = []
    for i, sign in enumerate(inventory):
        size = (sign.width_m or DEFAULT_FACE_M, sign.height_m or DEFAULT_FACE_M)
        views = sign_views(camera, records, poses, heights[i], sign.facing, *size, config)
        if i in matched:
            verdict, m, distance = matched[i]
            found = mapped[m]
            dz = float(found.position[2] - sign.position[2]) if sign.has_height else None
            reason = {CONFIRMED: f"mapped sign {found.sign_id} of the same type {distance:.2f} m away",
                      CHANGED: f"mapped sign {found.sign_id} at the same place is a {found.template_id}",
                      MOVED: f"mapped sign {found.sign_id} of the same type {distance:.2f} m away"}[verdict]
            changes.append(Change(verdict, sign, found, distance, dz, views, reason))
        elif mappable_types is not None and sign.template_id not in mappable_types:
            changes.append(Change(NOT_COVERED, sign, None, views=views,
                                  reason=f"type {sign.label or sign.template_id} cannot be mapped with the run's "
                                         "catalogue"))
        elif views:
            changes.append(Change(MISSING, sign, None, views=views,
                                  reason=f"in view in {len(views)} pairs, nothing mapped within "
                                         f"{config.tolerance_m:g} m"))
        else:
            changes.append(Change(NOT_COVERED, sign, None,
                                  reason=f"never in view {config.near_m:g}-{config.far_m:g} m ahead with its face "
                                         "readable"))
    for m, found in enumerate(mapped):
        if m not in taken_m:
            changes.append(Change(NEW, None, found, reason="no inventory sign of its type within "
                                                            f"{config.move_radius_m:g} m"))
    return ChangeReport(changes, config)
