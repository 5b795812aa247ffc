"""Fusing per-pair detections into one feature per physical sign.

At 5 pairs/s a sign is seen in about five pairs within 4-14 m. Observations are
chained in driving order into tracks (3D proximity, compatible colour and shape,
a consistent face direction, at most one observation per pair, and no long gap),
then tracks of the same sign from separate passes are merged. Each sign gets a
position from all its views weighted by their precision (:mod:`.precision`: stereo
places a far face poorly along its line of sight), that position's σ along and
across the line of sight, a class by weighted vote, its standard size and its face azimuth.

The gates keep apart what must stay apart: two signs stacked on one pole are
~0.7 m apart vertically (vertical gate 0.3 m), back-to-back signs face opposite
ways (face gate 60°), and two identical signs a few metres apart exceed the 3D gate.
Each gate reaches ``gate_sigmas`` σ of the difference it tests where that is wider:
along the line of sight of far views, whose depth is uncertain by a metre at 25 m.
"""

from __future__ import annotations

from collections import defaultdict
from dataclasses import dataclass, field
from operator import attrgetter
from typing import Mapping, Optional, Sequence

import numpy as np

from ..catalogue.model import UNKNOWN_ID
from ..geometry import Camera
from ..output.review_reasons import DOUBTFUL_READINGS, sign_reason
from ..pipeline.config import DepthConfig
from ..plates.zone_panels import may_be_disc_of
from ..statuses import ACCEPTED, REVIEW
from .precision import Estimate, StereoPrecision, along_across, combined, gate_distance, inliers, variance_factor


def _reads(path: str, doc: str) -> property:
    """A read-only attribute that reads ``path`` (dotted) of its object: an observation shows its detection's and
    its pair's values, a fused sign its best observation's, without a copy that could go stale."""
    return property(attrgetter(path), doc=doc)


def _of_detection(name: str, doc: str) -> property:
    return _reads(f"detection.{name}", doc)


@dataclass(eq=False)
class Observation:
    """One detection of a sign in one pair: the pipeline's :class:`Detection` with its pair, not a copy of it.

    ``id`` numbers the detections of a run from 1 in driving order (their feature
    ids in the ``detections`` layer); ``sign_id`` is the fused sign the detection
    belongs to, set by :func:`fuse_observations`.
    """

    detection: object  # pipeline.Detection
    record: object  # drive.PairRecord
    id: Optional[int] = None
    sign_id: Optional[int] = None

    template_id = _of_detection("template_id", "catalogue id assigned in this pair")
    name = _of_detection("name", "template name")
    colour = _of_detection("colour", "segmented colour")
    shape = _of_detection("shape", "shape of the segment")
    width_m = _of_detection("width_m", "standard width of the format")
    height_m = _of_detection("height_m", "standard height of the format")
    format = _of_detection("format", "standard format name")
    detection_indicator = _of_detection("detection_indicator", "planar share, 0..1")
    classification_indicator = _of_detection("classification_indicator", "template score, 0..1")
    status = _of_detection("status", "accepted, review or manual")
    review_reason = _of_detection("review_reason", "the rule that held it for review, if one did")
    source = _of_detection("source", "colour segmentation or hough fallback")
    u = _of_detection("u", "column of the face centre in the left image")
    v = _of_detection("v", "row of the face centre in the left image")
    bbox = _of_detection("bbox", "(x, y, w, h) in the left image")
    depth_m = _of_detection("depth_m", "depth of the face centre")
    position = _of_detection("position", "(E, N, H) of the face centre")
    normal = _of_detection("normal_world", "unit face normal (E, N, H) towards the camera, or None")
    pair_index = _reads("record.index", "index of the pair in the drive")
    pair_id = _reads("record.id", "id of the pair")
    time = _reads("record.time", "time of the pair")
    camera_centre = _reads("record.pose.centre", "World position of the left camera of the pair.")


@dataclass(frozen=True)
class FusionConfig:
    gate_m: float = 0.6  # 3D distance from a track's position [m], where gate_sigmas σ of it are less
    vertical_gate_m: float = 0.3  # the same vertically [m]: stacked signs are ~0.7 m apart
    face_gate_deg: float = 60.0  # back-to-back signs face ~180° apart
    max_gap_pairs: int = 4  # a track not seen for longer is closed
    merge_gate_m: float = 0.35  # tracks of one sign from separate passes [m], where gate_sigmas σ are less
    outlier_min_m: float = 0.10  # views beyond max(this [m], gate_sigmas σ, the spread) from the median are left out
    gate_sigmas: float = 3.0  # the gates reach this many σ of the difference they test (precision.gate_distance)
    disparity_sigma_px: float = DepthConfig.disparity_sigma_px  # a face centre's disparity error [px] (mapping sets it)
    # a face centre's image position error [px] (error across Z·σ/f): ~1 at KITTI's size, 2-3 on Full HD's larger faces
    image_sigma_px: float = 1.5
    pose_sigma_m: float = 0.02  # the trajectory's position error per axis [m] (GNSS/INS), added to every view's
    accept_vote_share: float = 0.6
    accept_classification: float = 0.6  # the classifier's threshold for "accepted" (mapping passes it)
    # a sign's voters need this share of the way from that threshold to 1 as their mean: the views of one sign
    # share its print, so a design the classifier misreads (a thin-pen arrow, a German-style priority-road end)
    # is misread in every view with ~0.95, and agreement alone does not make it right. Set on the looked-at drives
    # 801-810 and 1070-1129 (2026-12-04): wrong among accepted 20 of 823 (2.4 %) -> 10 of 776 (1.3 %), the 37
    # right ones lost mostly unusual designs (26 procedural, 11 of 657 official drawings)
    accept_margin: float = 2.0 / 3.0
    # a sign seen in one pair only is accepted on that one reading (when it is very clear and not near the far
    # limit: single_margin, single_max_depth_share) only if this is on. Off by default: of 14 such signs on drives
    # 801-810 and 1040-1059 (2026-12-03) 10 were right, 2 misread and 2 no sign at all, where the signs seen more
    # than once were right in 349 of 358; a surveyor reviews a sign the vehicle saw once
    accept_single_observation: bool = False
    single_margin: float = 0.4  # a sign seen once needs this share of the way from the voters' threshold to 1 on top
    # ...and to be seen nearer than this share of the far limit: near that limit depth is least sure, and a sign
    # beyond the range is measured into it now and then (tune drive 808: a 2.30-30 ~20 m away, seen once,
    # mapped 7 m short at 13.2 m and accepted); a sign really within the range is seen again as the vehicle nears
    single_max_depth_share: float = 0.85
    far_m: float = DepthConfig.far_m  # the mapping's far limit of the search space (mapping passes it)
    min_obs_accepted: int = 2
    # a sign whose every view reads it at a size no standard format of its sign has, or as no catalogue sign
    # (review reasons OFF_FORMAT, NO_ENTRY_MATCHES) is mapped only when seen in at least this many pairs: read
    # once, such a face was a sign beyond the range measured into it or street furniture (a traffic cone)
    # in all 3 cases on drives 9001/9002 with the whole catalogue (2026-12-06)
    doubtful_min_views: int = 2
    # a sign seen only beyond far_m (in the reach) is mapped only when seen in at least this many pairs: one such
    # view places it to a metre at best, and at the drive's end a car's two rear lights 17 m ahead of the last pair
    # were read as cycle-route boards (drive 9002, 2026-12-07)
    far_min_views: int = 2
    # supplementary plates' text (plate_fusion.py): read from the crops of a plate's this many largest (nearest)
    # observations; more add OCR time and rarely a better text
    plate_readings: int = 3
    plate_min_seen_whole: float = 0.95  # views that saw at least this share of a plate (Detection.crop_seen) are
    # read first: a larger view cut by the image's edge or a branch reads part of the text
    plate_well_formed_weight: float = 2.0  # a reading whose lines all have a form plates print counts this much
    # more in the vote on a plate's text: a misreading rarely has one
    # how a crop is prepared for Tesseract (ocr.prepare_crop): its printed black frame (this share of its height on
    # each side) is cut off, as it is no letter...
    ocr_frame_share: float = 0.09
    ocr_crop_height_px: int = 120  # ...it is scaled up to this height (1-3 lines of 30+ px, as Tesseract likes them)
    ocr_max_upscale: float = 8.0  # ...but at most this much (a tiny crop's letters would only grow blur)
    ocr_border_px: int = 12  # ...and given a plain border: Tesseract reads nothing on a line that touches a frame
    # ...and lines across the whole plate (a pole behind a gap, a wire, the frame's remains) painted over: pixels
    # darker than ocr_line_contrast x the paper in a straight run of ocr_line_span x its height or width (1: off)
    ocr_line_span: float = 0.9
    ocr_line_contrast: float = 0.8
    # ...horizontal ones only within this share of the height from the top or bottom (the frame's remains): a row
    # of blurred bold letters is as dark all along (tune drives: 'ausgenommen' painted over at 1.0)
    ocr_line_edge_band: float = 0.15
    # what of Tesseract's reading is print (ocr.TextReading.kept): words at least this share of the height of the
    # words read with ocr_confident_word confidence (smaller "words" are dirt or a frame's remains)...
    ocr_min_word_height_share: float = 0.45
    ocr_confident_word: float = 0.6
    ocr_min_line_confidence: float = 0.35  # ...on lines read with at least this mean confidence (less: a frame's
    # edge, a shadow)
    # the digits of a sign mapped as a speed limit (number_check.py): read in this many of its largest voters' views;
    # an accepted sign goes to review when more of them read another speed limit's number than its own
    number_readings: int = 3
    # a sign's face centre must be this high above the road beside it [m] (plausibility.py): a deliberately loose
    # bound below any sign's mounting (the lowest, keep-left/right signs on traffic-island bollards, stand higher)
    min_centre_above_road_m: float = 0.2
    # ...its face look at most this far from the direction to the trajectory [deg]: a sign beside the road faces along
    # it, one on the back of a pole the other carriageway (both ~90°), a far face's fitted plane errs by up to ~40°
    max_face_turn_deg: float = 150.0
    # ...and it must stand at most this far beside the trajectory [m]: a deliberately loose bound beyond the far side
    # of a four-lane street with pavements, seen from its outer lane
    max_lateral_m: float = 25.0

    def __post_init__(self):
        if not (self.disparity_sigma_px > 0 and self.image_sigma_px > 0):
            raise ValueError(f"disparity_sigma_px and image_sigma_px must be positive (a view's precision), got "
                             f"{self.disparity_sigma_px}, {self.image_sigma_px}")
        if self.pose_sigma_m < 0 or self.gate_sigmas < 0:
            raise ValueError(f"pose_sigma_m and gate_sigmas must not be negative, got {self.pose_sigma_m}, "
                             f"{self.gate_sigmas}")


@dataclass
class FusedSign:
    """One physical sign: class by weighted vote, position from its views by their precision, the observations it
    was fused from."""

    sign_id: int
    template_id: str
    width_m: float
    height_m: float
    format: str
    position: np.ndarray
    n_obs: int
    vote_share: float
    sigma_m: Optional[float]  # 3D standard error of the position [m] (√(σ_along² + 2 σ_across²)); None: unknown
    azimuth: Optional[float]  # direction the face looks towards, degrees from grid north
    detection_indicator: float
    classification_indicator: float
    status: str
    best: Observation  # the voter with the highest indicators: what the review shows first
    observations: list = field(default_factory=list)
    mount_height_m: Optional[float] = None  # lower edge above the road, set when mapping a drive
    plate_of: Optional[int] = None  # a supplementary plate: the sign_id of its sign (plate_fusion)
    text: Optional[str] = None  # a plate's text as read (lines joined by " / "), None when not read
    text_confidence: Optional[float] = None  # 0..1: OCR confidence and agreement of its readings
    review_reason: Optional[str] = None  # why it is in review (review_reasons); None when accepted
    sigma_along_m: Optional[float] = None  # standard error of the position along the mean line of sight [m]
    sigma_across_m: Optional[float] = None  # ...and across it, per axis [m]; None: unknown (a sign added by hand)

    name = _reads("best.name", "template name (of the best observation)")
    colour = _reads("best.colour", "segmented colour (of the best observation)")
    shape = _reads("best.shape", "shape (of the best observation)")
    source = _reads("best.source", 'How the best observation was found: "colour" segmentation or "hough" fallback.')


def _compatible_shape(a: str, b: str) -> bool:
    squareish = {"square", "rectangle", "pointer"}  # a pointer's outline reads as a rectangle
    return a == b or (a in squareish and b in squareish)


def _compatible(a: Observation, b: Observation) -> bool:
    """Same template (whichever of its colours was segmented), or same colour and a compatible shape.

    A two-coloured sign (4.09: blue square, red bar) is found by its red part in
    one pair and by its blue part in the next.
    """
    return a.template_id == b.template_id or (a.colour == b.colour and _compatible_shape(a.shape, b.shape))


def _angle_deg(a: Optional[np.ndarray], b: Optional[np.ndarray]) -> float:
    if a is None or b is None:
        return 0.0
    cos = float(np.dot(a, b) / (np.linalg.norm(a) * np.linalg.norm(b)))
    return float(np.degrees(np.arccos(np.clip(cos, -1.0, 1.0))))


def _horizontal_unit(v: np.ndarray) -> Optional[np.ndarray]:
    h = np.array([v[0], v[1], 0.0], float)
    n = np.linalg.norm(h)
    return h / n if n > 1e-9 else None


def _face_direction(obs: Observation) -> np.ndarray:
    """Horizontal unit direction the face looks to: the measured normal's, else from the sign to the camera.

    Only the horizontal part counts: a face direction is an azimuth, and the
    vertical tilt of a plane fitted to stereo depth is its noisiest part
    (overhead signs especially). A normal that is mostly vertical is not used.
    """
    if obs.normal is not None:
        normal = np.asarray(obs.normal, float)
        horizontal = _horizontal_unit(normal)
        if horizontal is not None and np.hypot(normal[0], normal[1]) >= 0.2 * np.linalg.norm(normal):
            return horizontal
    towards_camera = _horizontal_unit(obs.camera_centre - obs.position)
    return towards_camera if towards_camera is not None else np.array([0.0, 1.0, 0.0])


def mean_face(observations: Sequence[Observation]) -> np.ndarray:
    """Unit mean of the observations' face directions."""
    v = np.sum([_face_direction(o) for o in observations], axis=0)
    n = np.linalg.norm(v)
    return v / n if n > 0 else v


class _Track:
    """Observations of one sign in driving order and the position of all of them (weighted by precision)."""

    def __init__(self, obs: Observation, precision: StereoPrecision):
        self.observations = [obs]
        self.precision = precision
        self.estimate = view_estimate(obs, precision)

    @property
    def last_pair(self) -> int:
        return self.observations[-1].pair_index

    @property
    def face(self) -> np.ndarray:
        return mean_face(self.observations)

    def add(self, obs: Observation) -> None:
        self.observations.append(obs)
        self.estimate = track_estimate(self.observations, self.precision)

    def cost(self, obs: Observation, config: FusionConfig) -> Optional[float]:
        """How far ``obs`` is from this track, in units of the gate (:func:`within_gates`), if it may continue it,
        else None."""
        if not _compatible(obs, self.observations[-1]):
            return None
        if obs.pair_index - self.last_pair > config.max_gap_pairs or obs.pair_index == self.last_pair:
            return None
        distance = within_gates(view_estimate(obs, self.precision), self.estimate, config.gate_m, config)
        if distance is None or _angle_deg(self.face, _face_direction(obs)) > config.face_gate_deg:
            return None
        return distance


def view_estimate(obs: Observation, precision: StereoPrecision) -> Estimate:
    """One view's position and covariance (:mod:`.precision`)."""
    return Estimate(np.asarray(obs.position, float), precision.covariance(obs.position, obs.camera_centre, obs.depth_m))


def track_estimate(observations: Sequence[Observation], precision: StereoPrecision) -> Estimate:
    """The information-weighted position of ``observations`` and its covariance (no view left out)."""
    views = [view_estimate(o, precision) for o in observations]
    return combined([v.position for v in views], [v.covariance for v in views])


def within_gates(a: Estimate, b: Estimate, gate_m: float, config: FusionConfig) -> Optional[float]:
    """The distance of two positions in units of the gate ``gate_m`` (widened to ``gate_sigmas`` σ of their
    difference, :func:`.precision.gate_distance`) when they are within it and within the vertical gate (widened
    alike), else None."""
    delta, covariance = a.position - b.position, a.covariance + b.covariance
    if gate_distance(delta[2:], covariance[2:, 2:], config.vertical_gate_m, config.gate_sigmas) > 1.0:
        return None
    distance = gate_distance(delta, covariance, gate_m, config.gate_sigmas)
    return distance if distance <= 1.0 else None


def _assign_pair(tracks: list, open_ids: list, observations: Sequence[Observation], config: FusionConfig,
                 precision: StereoPrecision):
    """Greedy nearest assignment of one pair's observations to open tracks, one each."""
    candidates = []
    for oi, obs in enumerate(observations):
        for ti in open_ids:
            cost = tracks[ti].cost(obs, config)
            if cost is not None:
                candidates.append((cost, oi, ti))
    used_obs, used_tracks = set(), set()
    for _cost, oi, ti in sorted(candidates):
        if oi in used_obs or ti in used_tracks:
            continue
        tracks[ti].add(observations[oi])
        used_obs.add(oi)
        used_tracks.add(ti)
    for oi, obs in enumerate(observations):
        if oi not in used_obs:
            tracks.append(_Track(obs, precision))


def build_tracks(observations: Sequence[Observation], config: FusionConfig,
                 precision: StereoPrecision) -> list[list[Observation]]:
    """Chain observations in driving order into tracks of one sign each (a pair's observations taken left to
    right, so the tracks do not depend on the order they are given in)."""
    by_pair = defaultdict(list)
    for obs in observations:
        by_pair[obs.pair_index].append(obs)
    tracks: list[_Track] = []
    open_ids: list[int] = []  # tracks still within the gap, in their order: a closed track never reopens
    for pair_index in sorted(by_pair):
        open_ids = [i for i in open_ids if pair_index - tracks[i].last_pair <= config.max_gap_pairs]
        before = len(tracks)
        in_pair = sorted(by_pair[pair_index], key=lambda o: (o.u, o.v, o.template_id or ""))
        _assign_pair(tracks, open_ids, in_pair, config, precision)
        open_ids += range(before, len(tracks))
    return [t.observations for t in tracks]


def _vote(observations: Sequence[Observation], carried_discs: Optional[Mapping[str, str]] = None
          ) -> tuple[str, float]:
    """(class, its share of the weight): each observation weighs classification x detection indicator.

    ``carried_discs``: zone panels (template id -> the disc sign they carry: 2.59.1's "30" ring, 2.59.3's
    pedestrian disc). A view that missed the panel's white around its disc reads the disc alone; in a track
    with a confident (accepted) reading of the panel, doubtful (review) readings of such a disc
    (:func:`.zone_panels.may_be_disc_of`; detection holds one inside white at its own depth for review) are the
    panel's own disc and count for it. Confident ones do not, nor other discs: a speed limit or a 2.14 over a
    plate, read as a panel once from afar and clearly as itself nearer, stays itself (held-out drives 1107 and
    1088).
    """
    weights = defaultdict(float)
    panels = {o.template_id: carried_discs[o.template_id] for o in observations
              if carried_discs and o.template_id in carried_discs and o.status == ACCEPTED}
    for o in observations:
        weight = max(o.classification_indicator, 1e-3) * max(o.detection_indicator, 1e-3)
        panel = next((p for p, disc in panels.items() if o.status != ACCEPTED and may_be_disc_of(disc, o.template_id)),
                     None)
        weights[panel or o.template_id] += weight
    # a view that read no catalogue sign (unknown) outweighs none that read one: its score is its nearest
    # candidate's, no vote for an id; its weight still lowers the winner's share
    named = [k for k in weights if k != UNKNOWN_ID]
    winner = max(named or weights, key=weights.get)
    return winner, weights[winner] / sum(weights.values())


@dataclass
class _TrackSummary:
    """What the merge test reads of a track, computed once per track (and again when it grows)."""

    observations: list
    pairs: set
    estimate: Estimate  # of all its observations (track_estimate)
    colours: set
    winner: str  # the class the weighted vote gives it
    face: np.ndarray

    @property
    def position(self) -> np.ndarray:
        return self.estimate.position

    @classmethod
    def of(cls, observations: list, precision: StereoPrecision) -> _TrackSummary:
        return cls(observations, {o.pair_index for o in observations}, track_estimate(observations, precision),
                   {o.colour for o in observations}, _vote(observations)[0], mean_face(observations))


def _one_sign(a: _TrackSummary, b: _TrackSummary, config: FusionConfig) -> bool:
    """Whether two tracks are one sign (the test of :func:`_merge_tracks`)."""
    if a.pairs & b.pairs:
        return False  # seen side by side in one pair: two signs
    return (within_gates(a.estimate, b.estimate, config.merge_gate_m, config) is not None
            and bool(a.colours & b.colours or a.winner == b.winner)
            and _angle_deg(a.face, b.face) <= config.face_gate_deg)


def _merge_reach(summaries, config: FusionConfig) -> float:
    """The farthest apart (horizontally) two of these tracks can be and still be one sign: the merge gate widened
    by ``gate_sigmas`` σ of the least precise two. Joining tracks only makes their positions more precise."""
    largest = max((float(np.linalg.eigvalsh(s.estimate.covariance[:2, :2])[-1]) for s in summaries), default=0.0)
    return float(np.sqrt(config.merge_gate_m ** 2 + config.gate_sigmas ** 2 * 2.0 * largest))


class _Neighbours:
    """Tracks by the grid cell of their position: only tracks in neighbouring cells can be within the merge gate
    (cells as wide as its reach), so a long drive's thousands of tracks are not all compared with each other."""

    def __init__(self, cell_m: float):
        self.cell_m = cell_m
        self.cells: dict = defaultdict(set)
        self.cell_of: dict = {}

    def _key(self, position: np.ndarray) -> tuple:
        return int(np.floor(position[0] / self.cell_m)), int(np.floor(position[1] / self.cell_m))

    def put(self, index: int, position: np.ndarray) -> None:
        self.drop(index)
        key = self._key(position)
        self.cells[key].add(index)
        self.cell_of[index] = key

    def drop(self, index: int) -> None:
        key = self.cell_of.pop(index, None)
        if key is not None:
            self.cells[key].discard(index)

    def around(self, index: int) -> list:
        """The other tracks in the 3 x 3 cells around this one's, in their order."""
        cx, cy = self.cell_of[index]
        found = set()
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                found |= self.cells.get((cx + dx, cy + dy), set())
        found.discard(index)
        return sorted(found)


def _merge_tracks(tracks: list[list[Observation]], config: FusionConfig,
                  precision: StereoPrecision) -> list[list[Observation]]:
    """Join tracks of one sign: separate passes, a long occlusion, or a sign read two ways.

    Two tracks never seen in the same pair, of one colour, within ``merge_gate_m`` (or ``gate_sigmas`` σ of their
    difference) and facing the same way are one sign even when their classes differ (a zone
    panel read as its inner speed ring in some pairs); the weighted vote then
    decides its class. Distinct signs this close are back-to-back (face gate) or
    stacked (vertical gate).

    Pairs are merged in the order of the tracks (the first pair of tracks, by the earlier one and then the
    later one, that is one sign joins, the later into the earlier, and the search starts again), but only
    tracks in neighbouring cells of a grid are compared, and after a join only the pairs that the grown track
    can have changed: earlier tracks with it first, then it with later ones.
    """
    summaries = {i: _TrackSummary.of(list(t), precision) for i, t in enumerate(tracks)}
    grid = _Neighbours(max(_merge_reach(summaries.values(), config), 0.5))
    for i, summary in summaries.items():
        grid.put(i, summary.position)

    def join(keep: int, gone: int) -> None:
        observations = sorted(summaries[keep].observations + summaries[gone].observations,
                              key=lambda o: o.pair_index)
        summaries[keep] = _TrackSummary.of(observations, precision)
        del summaries[gone]
        grid.drop(gone)
        grid.put(keep, summaries[keep].position)

    order = sorted(summaries)
    k = 0
    while k < len(order):
        i = order[k]
        later = next((j for j in grid.around(i) if j > i and _one_sign(summaries[i], summaries[j], config)), None)
        if later is None:
            k += 1
            continue
        join(i, later)
        while True:  # the grown track may now be one sign with an earlier track: that pair comes first
            earlier = next((j for j in grid.around(i) if j < i and _one_sign(summaries[j], summaries[i], config)),
                           None)
            if earlier is None:
                break
            join(earlier, i)
            i = earlier
        order = sorted(summaries)
        k = order.index(i)
    return [summaries[i].observations for i in sorted(summaries)]


@dataclass(frozen=True)
class SignPosition:
    """Where a sign is and how precisely."""

    estimate: Estimate  # the views' information-weighted position; covariance scaled by their variance factor
    sight: np.ndarray  # unit mean line of sight of those views

    def sigmas(self) -> tuple[float, float, float]:
        """(σ along the line of sight, σ across it per axis, 3D σ) [m]."""
        along, across = along_across(self.estimate.covariance, self.sight)
        return along, across, float(np.sqrt(np.trace(self.estimate.covariance)))


def sign_position(observations: Sequence[Observation], precision: StereoPrecision,
                  config: FusionConfig) -> SignPosition:
    """The position of a sign from all its views, each weighted by its precision (:mod:`.precision`), and its
    covariance. Views that disagree with the rest (:func:`.precision.inliers`: a bad depth in one pair) are left
    out; the covariance grows when the views scatter more than their precision says (``variance_factor``)."""
    views = [view_estimate(o, precision) for o in observations]
    kept = inliers([v.position for v in views], [v.covariance for v in views], config.outlier_min_m,
                   config.gate_sigmas)
    positions, covariances = [views[i].position for i in kept], [views[i].covariance for i in kept]
    estimate = combined(positions, covariances)
    scaled = Estimate(estimate.position, variance_factor(positions, covariances, estimate) * estimate.covariance)
    rays = [(p - observations[i].camera_centre) / max(np.linalg.norm(p - observations[i].camera_centre), 1e-9)
            for i, p in zip(kept, positions)]
    sight = np.sum(rays, axis=0)
    return SignPosition(scaled, sight / max(float(np.linalg.norm(sight)), 1e-9))


def azimuth_deg(direction: np.ndarray) -> Optional[float]:
    """Azimuth (clockwise from grid north) of the horizontal part of ``direction``."""
    if direction is None or np.hypot(direction[0], direction[1]) < 1e-9:
        return None
    return float(np.degrees(np.arctan2(direction[0], direction[1])) % 360.0)


def _share_of_way(threshold: float, share: float) -> float:
    """The value ``share`` of the way from ``threshold`` to 1."""
    return threshold + share * (1.0 - threshold)


def sign_accept_threshold(config: FusionConfig) -> float:
    """The mean classification indicator a sign's voters need for ``accepted``: ``accept_margin`` of the way from
    the classifier's threshold for one view to 1."""
    return _share_of_way(config.accept_classification, config.accept_margin)


def fuse_track(sign_id: int, observations: Sequence[Observation], config: FusionConfig, precision: StereoPrecision,
               carried_discs: Optional[Mapping[str, str]] = None) -> FusedSign:
    """One sign of a track: class by weighted vote (:func:`_vote`); position (:func:`sign_position`), size and
    indicators from the observations that read that class (the voters), accepted when enough of them agree
    clearly."""
    template_id, share = _vote(observations, carried_discs)
    voters = [o for o in observations if o.template_id == template_id]
    located = sign_position(voters, precision, config)
    sigma_along, sigma_across, sigma = located.sigmas()
    formats = defaultdict(float)
    for o in voters:
        formats[(o.format, o.width_m, o.height_m)] += o.classification_indicator
    fmt, width, height = max(formats, key=formats.get)
    best = max(voters, key=lambda o: (o.detection_indicator * o.classification_indicator, -o.depth_m))
    det_ind = float(np.mean([o.detection_indicator for o in voters]))
    cls_ind = float(np.mean([o.classification_indicator for o in voters]))
    needed = sign_accept_threshold(config)
    reason = sign_reason(voters, share, cls_ind, needed, config.min_obs_accepted, config.accept_vote_share, ACCEPTED)
    single = _share_of_way(needed, config.single_margin)
    if config.accept_single_observation and len(voters) == 1 and best.status == ACCEPTED and cls_ind >= single and \
            best.depth_m <= config.single_max_depth_share * config.far_m:
        reason = None  # a single, very clear observation, not at the far end of the range
    accepted = reason is None
    return FusedSign(
        sign_id=sign_id, template_id=template_id, width_m=width, height_m=height, format=fmt,
        position=located.estimate.position, n_obs=len(observations), vote_share=share, sigma_m=sigma,
        azimuth=azimuth_deg(mean_face(voters)), detection_indicator=det_ind, classification_indicator=cls_ind,
        status=ACCEPTED if accepted else REVIEW, best=best, observations=list(observations), review_reason=reason,
        sigma_along_m=sigma_along, sigma_across_m=sigma_across,
    )


def _doubtful(track: Sequence[Observation], config: FusionConfig) -> bool:
    """Whether a track is too little seen for what its views read (a size no standard format has, or no sign of
    the catalogue: ``doubtful_min_views``) or for where they saw it (beyond far only: ``far_min_views``)."""
    views = len({o.pair_index for o in track})
    return (views < config.doubtful_min_views and all(o.review_reason in DOUBTFUL_READINGS for o in track)) or \
        (views < config.far_min_views and all(o.depth_m > config.far_m for o in track))


def fuse_observations(observations: Sequence[Observation], camera: Camera, config: Optional[FusionConfig] = None,
                      carried_discs: Optional[Mapping[str, str]] = None) -> list[FusedSign]:
    """One :class:`FusedSign` per physical sign, numbered from 1 in order of first sight.

    ``camera``: the drive's ``geometry.Camera`` (its focal length and baseline set how precise each view's
    depth is). Each observation's ``sign_id`` is set to the sign it was fused into. ``carried_discs``: the
    catalogue's zone panels and the disc sign each carries (``pipeline.face_extent.carried_discs``; see
    :func:`_vote`).
    """
    config = config or FusionConfig()
    precision = StereoPrecision.of(camera, config)
    tracks = _merge_tracks(build_tracks(observations, config, precision), config, precision)
    tracks = [t for t in tracks if not _doubtful(t, config)]
    tracks.sort(key=lambda t: (t[0].pair_index, t[0].position[0], t[0].position[1]))
    signs = [fuse_track(i, t, config, precision, carried_discs) for i, t in enumerate(tracks, start=1)]
    for sign in signs:
        for obs in sign.observations:
            obs.sign_id = sign.sign_id
    return signs
