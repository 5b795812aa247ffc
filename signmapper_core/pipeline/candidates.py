"""Colour and shape without depth: where the faces of a photograph may be, and which signs each may be.

Steps 3-4 of the pipeline on a whole image (or a single photograph, where there
is no depth and so no size step): colour segments of all passes, faces split by
a bar or pole merged before their pieces are judged, Hough circles for round
rims whose colour is too weak, then the shape and the catalogue entries colour
and shape allow, with the face box of each reading. This is what the colour
step offers the later steps; :mod:`.detect` runs the same segments through
size, planarity and classification when depth is known.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import List, Optional, Sequence, Tuple

import numpy as np

from .boxes import box_iou
from .colour import Segment, faces_with_split_pieces_merged, find_colour_segments
from .config import PipelineConfig
from .detect import segment_candidates, segment_shapes
from .face_extent import FULL, face_bbox, rim_face_bboxes, ring_edge_bbox
from .half_discs import with_half_discs
from .hough import find_circles, hough_scale, hough_segments


@dataclass(frozen=True)
class FaceReading:
    """One reading of where a segment's face is: its box and the catalogue ids that fit it."""

    bbox: Tuple[int, int, int, int]  # x, y, w, h of the face (may reach past the image border)
    template_ids: Tuple[str, ...]


@dataclass(frozen=True)
class FaceCandidate:
    """A segment that may be a sign face: its outline shape and its readings."""

    segment: Segment
    shape: str
    readings: Tuple[FaceReading, ...]

    @property
    def template_ids(self) -> Tuple[str, ...]:
        return tuple(dict.fromkeys(t for r in self.readings for t in r.template_ids))


def readings_of(seg: Segment, shapes, catalogue, config: PipelineConfig,
                image: Optional[np.ndarray] = None) -> Tuple[FaceReading, ...]:
    """The face boxes (grouped by colour extent) and candidate ids of a segment of outline ``shapes``.

    With ``image``, a face with a white rim around its coloured part also gets the
    readings of its rim as measured in the image (:func:`.face_extent.rim_face_bboxes`).
    """
    groups: dict = {}
    for entry, ext in segment_candidates(seg, shapes, catalogue, config, image):
        key = tuple(round(v, 2) for v in ext)
        groups.setdefault(key, (ext, [], []))[1].append(entry.id)
        groups[key][2].append(entry.shape)
    readings = []
    for ext, ids, entry_shapes in groups.values():
        readings.append(FaceReading(face_bbox(seg.bbox, ext), tuple(ids)))
        if image is not None and ext != FULL and seg.source == "colour" and shapes[0] in entry_shapes:
            same = tuple(i for i, s in zip(ids, entry_shapes) if s == shapes[0])
            for rim in rim_face_bboxes(image, seg.bbox, seg.mask, ext, shapes[0], config):
                readings.append(FaceReading(rim, same))
    if image is not None and seg.source == "hole":
        same = tuple(dict.fromkeys(i for _, ids, entry_shapes in groups.values()
                                   for i, s in zip(ids, entry_shapes) if s == shapes[0]))
        ring = ring_edge_bbox(image, seg.bbox, shapes[0], config) if same else None
        # a reading of about this box that holds only some of the ids (another template's extent happening to
        # match the ring, e.g. a lettered ring) does not stand for the others
        if ring is not None and not any(box_iou(ring, r.bbox) >= config.rims.rim_same_iou
                                        and set(same) <= set(r.template_ids) for r in readings):
            readings.append(FaceReading(ring, same))
    return tuple(readings)


def weak_rim_circles(image: np.ndarray, config: PipelineConfig, taken: Sequence[Tuple[int, int, int, int]],
                     search: Optional[np.ndarray] = None) -> List[Segment]:
    """Hough circles of ``hough.hough_min_face_px`` .. ``hough.max_face_px`` (of ``config``) no face candidate covers.

    A circle counts as covered when a candidate's box matches it (IoU >= ``hough_covered_iou``); a colour
    segment that swallowed the disc together with a neighbour (blue sky, a second sign)
    does not cover it. White circles stay: end-of-restriction signs have no colour.
    """
    search = np.ones(image.shape[:2], bool) if search is None else search
    r_min, r_max = max(3, config.hough.hough_min_face_px // 2), max(4, config.hough.max_face_px // 2)
    out = []
    scale = hough_scale(r_min, config.hough.hough_scale, config.hough.hough_min_radius_px)
    for seg in hough_segments(image, find_circles(image, search, r_min, r_max, scale, config), config):
        if (seg.colour in config.colour.colours or seg.colour == "white") and not any(
                box_iou(seg.bbox, box) >= config.hough.hough_covered_iou for box in taken):
            out.append(seg)
    return out


def face_candidates(image: np.ndarray, catalogue, config: Optional[PipelineConfig] = None,
                    search: Optional[np.ndarray] = None, hough: bool = True) -> List[FaceCandidate]:
    """Every segment of ``image`` that colour and shape let be a sign, with its readings.

    No depth is used: ``search`` (bool) may limit the image, the small-ring pass
    looks for faces down to ``config.colour.min_face_px``. Segments cut by the image
    border are left out, like in the full pipeline.
    """
    return colour_step(image, catalogue, config, search, hough)[1]


def colour_step(image: np.ndarray, catalogue, config: Optional[PipelineConfig] = None,
                search: Optional[np.ndarray] = None, hough: bool = True) -> Tuple[List[Segment], List[FaceCandidate]]:
    """(all segments looked at, the face candidates among them): :func:`face_candidates` with its cost."""
    config = config or PipelineConfig()
    segments = find_colour_segments(image, search, config, None)
    segments = faces_with_split_pieces_merged(segments, config)
    segments = with_half_discs(segments, (image.shape[1], image.shape[0]), config)
    out = []
    for seg in segments:
        candidate = _candidate(seg, catalogue, config, image)
        if candidate is not None:
            out.append(candidate)
    if hough and config.hough.hough_enabled:
        circles = weak_rim_circles(image, config, [c.segment.bbox for c in out], search)
        segments = segments + circles
        for seg in circles:
            candidate = _candidate(seg, catalogue, config)
            if candidate is not None:
                out.append(candidate)
    return segments, out


def _candidate(seg: Segment, catalogue, config: PipelineConfig, image=None) -> Optional[FaceCandidate]:
    if seg.touches_border:
        return None
    shapes = segment_shapes(seg, config)
    if not shapes:
        return None
    readings = readings_of(seg, shapes, catalogue, config, image)
    return FaceCandidate(seg, shapes[0], readings) if readings else None
