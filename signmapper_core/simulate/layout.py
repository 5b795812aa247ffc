"""Scene layout: which objects stand where along the street, as planar surfaces.

Geometry is decided up front (small); pixels are made lazily per object with
its own seed. Signs are only placed where the drive passes them, so each sign is
seen from several pairs between 14 m and 4 m; signs whose face is turned away
from the vehicle are distractors (grey backs) and are not in the truth.

The parts, each building one kind of thing onto the scene's :class:`~.scene_pieces.Pieces`:
``street_body`` (road, buildings, trees, lamp posts), ``sign_poles`` (panels, poles,
occluders), ``text_panel_poles`` (white place-name and direction panels), ``plate_layout``
(supplementary plates, white text plates on façades), ``distractors`` (cars, cones, shop signs, sign backs).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from ..drive.reader import TruthSign
from .distractors import distractors, white_sign_distractors
from .faces import FaceOptions, SignKind
from .panels import PanelLook, PlacedSign
from .plate_layout import white_distractors
from .scene_pieces import CARRIAGEWAY, PARKING_LEFT, SIDEWALK_RIGHT, Pieces, TextureKeys
from .sign_mix import SignMix
from .sign_mounts import RIGHT_SIDE_SHARE, pole_form, sign_spot
from .sign_poles import sign_pole
from .street import Street
from .street_body import buildings, lamp_post, road
from .surfaces import Surface
from .text_panel_poles import TEXT_PANEL_SHARE, text_panel_pole
from .wide_street import FACADE_BEHIND_M, move_aside

BIN_M = 10.0

__all__ = ["CARRIAGEWAY", "PARKING_LEFT", "PlacedSign", "Scene", "build_scene"]


class Scene:
    """Surfaces binned along the street so a view only looks at what is near it."""

    def __init__(self, street: Street, surfaces: list[Surface], signs: list[PlacedSign]):
        self.street = street
        self.signs = signs
        self._bins: dict[int, list[Surface]] = {}
        for surf in surfaces:
            for b in range(int(np.floor(surf.s_min / BIN_M)), int(np.floor(surf.s_max / BIN_M)) + 1):
                self._bins.setdefault(b, []).append(surf)

    def surfaces_between(self, s0: float, s1: float) -> list[Surface]:
        seen: set[int] = set()
        out = []
        for b in range(int(np.floor(s0 / BIN_M)), int(np.floor(s1 / BIN_M)) + 1):
            for surf in self._bins.get(b, ()):
                if id(surf) not in seen:
                    seen.add(id(surf))
                    out.append(surf)
        return out

    @property
    def truth(self) -> list[TruthSign]:
        return [p.truth for p in self.signs if p.truth is not None]


def build_scene(street: Street, seed: int, s_cam_first: float, s_cam_last: float, fx: float,
                sign_density: float, distractor_density: float, kinds: list[SignKind], realism: dict,
                face_options: FaceOptions | None = None, plate_share: float = 0.0,
                white_kinds: list[SignKind] | None = None, white_share: float = 0.0, mix: SignMix | None = None,
                sign_offset_m: tuple[float, float] | None = None, right_share: float | None = None) -> Scene:
    """Lay out the whole street: road, buildings, signs (where the drive passes them), distractors.

    ``mix``: the signs of the whole catalogue (``sign_mix``), each spot mounted as its part says
    (``sign_mounts``), white distractors included; ``kinds`` then only give the sign backs among the
    distractors. Without it (the drives of before): ``kinds`` on every pole, each equally likely, and
    ``white_share`` the share of the poles carrying signs of ``white_kinds`` (the white and grey family) instead
    of ``kinds``; white signs stand on single or stacked poles (none hangs overhead), about a third of the
    white poles carry a text panel instead (``text_panel_poles``), and white distractors join the others.
    ``plate_share``: share of the poles whose lowest sign carries a supplementary plate (``plate_layout``).
    ``sign_offset_m``: a wide street (``wide_street``), each spot's first sign at a lateral distance from the track
    drawn uniformly in this range, façades set back behind; ``right_share``: share of the spots on the right
    (None: ``RIGHT_SIDE_SHARE``). Both left as they are, the drives of before come out as they were.
    """
    right_share = RIGHT_SIDE_SHARE if right_share is None else right_share
    keys = TextureKeys(seed)
    pieces = Pieces(street, keys)
    look = PanelLook(fx, face_options or FaceOptions(), realism["weathering"], realism["shadows"],
                     realism["occlusion"], plate_share)
    rng = keys.rng(1, 1)
    s_end = street.length
    # signs between 8 m ahead of the first pair and 12 m ahead of the last: each is seen within 4-14 m
    s_lo, s_hi = s_cam_first + 8.0, s_cam_last + 12.0
    spots: list[float] = []
    if s_hi > s_lo:
        n_poles = max(1, rng.poisson(sign_density * (s_hi - s_lo) / 100.0)) if sign_density > 0 else 0
        spots = sorted(rng.uniform(s_lo, s_hi, n_poles).tolist())
        # keep poles at least 4 m apart so panels do not overlap in the images
        kept: list[float] = []
        for s in spots:
            if not kept or s - kept[-1] >= 4.0:
                kept.append(s)
        spots = kept
    zebras = [float(s) for s in rng.uniform(s_cam_first + 10, s_end - 20, max(0, int((s_end - 30) // 150)))]
    road(pieces, s_end, zebras, realism["shadows"])
    facades = buildings(pieces, s_end, 0.0 if sign_offset_m is None else max(sign_offset_m) + FACADE_BEHIND_M)
    for s in np.arange(rng.uniform(5, 25), s_end, rng.uniform(25, 35)):
        if all(abs(s - x) > 2 for x in spots):
            lamp_post(pieces, float(s), SIDEWALK_RIGHT[0] + 0.5)
    sign_rng = keys.rng(1, 2)
    text_panel_rng = keys.rng(1, 33)  # drawn from only on white poles
    offset_rng = keys.rng(1, 34)  # drawn from only on wide streets
    signs: list[PlacedSign] = []
    for s in spots:
        first_surface, first_sign = len(pieces.surfaces), len(signs)
        signs += _spot(pieces, look, s, mix, kinds, sign_rng, text_panel_rng, facades, white_kinds, white_share,
                       right_share)
        if sign_offset_m is not None:
            move_aside(pieces, signs[first_sign:], first_surface, s, float(offset_rng.uniform(*sign_offset_m)))
    if distractor_density > 0:
        signs += distractors(pieces, look, s_cam_first, s_end - 10, distractor_density, keys.rng(1, 3), spots, kinds,
                             facades)
        if plate_share > 0:
            white_distractors(pieces, s_cam_first, s_end - 10, distractor_density / 2, keys.rng(1, 31), facades)
        if (white_kinds and white_share > 0) or mix is not None:
            white_sign_distractors(pieces, s_cam_first, s_end - 10, distractor_density / 2, keys.rng(1, 32),
                                   facades)
    _number_truth(signs)
    return Scene(street, pieces.surfaces, signs)


def _spot(pieces: Pieces, look: PanelLook, s: float, mix: SignMix | None, kinds: list[SignKind],
          sign_rng: np.random.Generator, text_panel_rng: np.random.Generator, facades, white_kinds, white_share: float,
          right_share: float) -> list[PlacedSign]:
    """The signs of the spot at ``s``: of the whole catalogue's ``mix``, or of the drives of before."""
    if mix is not None:
        return sign_spot(pieces, look, s, mix, sign_rng, text_panel_rng, facades, right_share)
    u = sign_rng.random()
    side = 1 if sign_rng.random() < right_share else -1
    # drawn only when white signs are asked for, so drives without them stay as they were
    white = bool(white_kinds) and white_share > 0 and sign_rng.random() < white_share
    pole_kinds = white_kinds if white else kinds
    form = pole_form(u)
    if white and form == "overhead":
        form = "stacked"  # no white sign hangs overhead
    if white and text_panel_rng.random() < TEXT_PANEL_SHARE:
        return text_panel_pole(pieces, look, s, text_panel_rng, side)
    return sign_pole(pieces, look, s, pole_kinds, sign_rng, 1 if form == "overhead" else side, form)


def _number_truth(signs: list[PlacedSign]) -> None:
    """Truth ids s001, s002, ... in the order the signs were placed; a plate names its sign's (``plate_of``)."""
    n = 0
    for p in signs:
        if p.truth is not None:
            n += 1
            p.truth = replace(p.truth, sign_id=f"s{n:03d}")
    for p in signs:
        if p.truth is not None and p.host is not None:
            p.truth = replace(p.truth, plate_of=p.host.truth.sign_id)
