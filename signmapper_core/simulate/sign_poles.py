"""Sign panels on their poles (single, stacked, back to back, overhead, turned away), and what may
stand between a sign and the approaching vehicle."""

from __future__ import annotations

import numpy as np

from ..drive.reader import TruthSign
from . import textures as tx
from .faces import SignFace, SignKind, draw_sign_face, pick_format
from .panels import PanelLook, PlacedSign, face_shape
from .plate_layout import PLATE_MAX_GAP_M, add_plate
from .scene_pieces import CARRIAGEWAY, KERB_H, LANE_CENTRE, PARKING_LEFT, SIDEWALK_RIGHT, UP, Pieces
from .sign_mix import pick_kind
from .surfaces import Texture, TextureSource, rect_surface

POLE_FORMS = ("single", "stacked", "back-to-back", "overhead", "away")
POLE_STANDOFF_M = 0.04  # pole axis behind an upright panel (a 6 cm pole: 1 cm clear of it)
OVERHEAD_REACH_M = 0.3  # how far an overhead panel may reach over the right sidewalk


def make_face(pieces: Pieces, look: PanelLook, kind: SignKind, fmt) -> tuple[SignFace, str]:
    """A physical face of ``kind`` in format ``fmt`` (name, width_m, height_m), and its texture key."""
    _name, w_m, h_m = fmt
    size_px = int(np.clip(look.fx * max(w_m, h_m) / 3.0, 48, 640))
    fh, fw = face_shape(size_px, w_m, h_m)
    key, rng = pieces.keys.key("face")
    return draw_sign_face(kind.template_id, (fw, fh), float(w_m), rng, look.face_options, look.weathering,
                          look.shadows), key


def sign_panel(pieces: Pieces, look: PanelLook, kind: SignKind, centre, facing_deg, tilt_deg, fmt, s,
               towards_vehicle: bool) -> PlacedSign:
    """Face and grey back of one panel (truth if it faces the vehicle)."""
    sign_face, key = make_face(pieces, look, kind, fmt)
    return mount_face(pieces, sign_face, key, kind.colour, centre, facing_deg, tilt_deg, fmt[1:], s,
                      towards_vehicle)


def mount_face(pieces: Pieces, sign_face: SignFace, key: str, colour: str, centre, facing_deg, tilt_deg,
               size_m: tuple[float, float], s, towards_vehicle: bool, text: str = "") -> PlacedSign:
    """A drawn face (texture ``key``) and its grey back as a panel of ``size_m`` at ``centre``; the truth row
    (with ``text``, the printed lines) if it faces the vehicle."""
    w_m, h_m = size_m
    fw, fh = sign_face.size_wh
    phi, tau = np.radians(facing_deg), np.radians(tilt_deg)
    n_h = np.array([np.sin(phi), np.cos(phi), 0.0])
    normal = n_h * np.cos(tau) + UP * np.sin(tau)
    right = np.array([-np.cos(phi), np.sin(phi), 0.0])
    up = UP * np.cos(tau) - n_h * np.sin(tau)

    def make_face():
        return Texture(*sign_face.pixels())

    face_src = TextureSource(key, fw, fh, make_face)
    corner = centre - right * w_m / 2 + up * h_m / 2
    face = rect_surface(corner, right * w_m, -up * h_m, face_src, two_sided=False, s_range=(s - 2, s + 2))
    bkey, brng = pieces.keys.key("back")

    def make_back():
        return Texture(*sign_face.back(brng))

    back_src = TextureSource(bkey, fw, fh, make_back)
    b_corner = centre - normal * 0.012 + right * w_m / 2 + up * h_m / 2
    back = rect_surface(b_corner, -right * w_m, -up * h_m, back_src, two_sided=False, s_range=(s - 2, s + 2))
    pieces.surfaces += [face, back]
    truth = None
    if towards_vehicle:
        truth = TruthSign("", sign_face.template_id, float(centre[0]), float(centre[1]), float(centre[2]),
                          float(w_m), float(h_m), float(facing_deg % 360.0), text=text, artwork=sign_face.artwork,
                          drawing=sign_face.drawing_name)
    return PlacedSign(truth, colour, centre, [face, back])


def standing_pole(pieces: Pieces, base, height: float, s) -> None:
    """The galvanised pole a panel stands on, from ``base`` up ``height`` metres."""
    pieces.crossed(base, 0.06, height, None, None, s, (140, 145, 145))


def sign_pole(pieces: Pieces, look: PanelLook, s, kinds, rng, side, form: str = "single",
              first: SignKind | None = None, fmt=None) -> list[PlacedSign]:
    """A pole with its panels (``form``: one of ``POLE_FORMS``); right-side signs face approaching traffic,
    ``away`` ones the other way (distractors, not in the truth). ``kinds``: a list (each equally likely) or a
    ``SignMix``; ``first``, ``fmt``: the lowest panel's kind and format when the caller has chosen them."""
    if form not in POLE_FORMS:
        raise ValueError(f"unknown pole form {form!r}; choose one of {', '.join(POLE_FORMS)}")
    away = form == "away"
    st = pieces.street
    heading = np.degrees(st.heading(s))
    first = first or pick_kind(kinds, rng)
    fmt = fmt or pick_format(first, rng)
    w_m, h_m = fmt[1], fmt[2]
    yaw = rng.uniform(-4, 4) + side * rng.uniform(0, 6)  # turned a little towards the road
    facing = heading + 180.0 - yaw if not away else heading + rng.uniform(-4, 4)
    tilt = rng.uniform(-3, 3)
    if form == "overhead":
        # over the right lane, a wide board no further right than the sidewalk's edge (never reached before boards)
        l_c = min(CARRIAGEWAY[1] / 2 + rng.uniform(-0.6, 0.6), SIDEWALK_RIGHT[0] + OVERHEAD_REACH_M - w_m / 2)
        lower = rng.uniform(4.3, 4.7)
        centre = st.point(s, l_c, lower + h_m / 2)
        placed = [sign_panel(pieces, look, first, centre, facing, tilt, fmt, s, True)]
        pole_l = SIDEWALK_RIGHT[0] + 0.5
        top = lower + h_m + 0.3
        pieces.crossed(st.point(s + 0.05, pole_l, KERB_H), 0.12, top - KERB_H + 0.1, None, None, s, (120, 125, 125))
        arm_a, arm_b = st.point(s + 0.05, l_c - w_m / 2 - 0.2, top), st.point(s + 0.05, pole_l, top)
        pieces.wall(arm_a, arm_b, top - 0.1, top, None, (120, 125, 125), (s - 2, s + 2))
        return placed
    edge = CARRIAGEWAY[1] if side > 0 else PARKING_LEFT[0]
    offset = rng.uniform(0.3, 2.0)
    l_c = edge + side * (offset + w_m / 2)
    lower = rng.uniform(0.6, 2.5)
    ground = KERB_H
    centres = [(first, fmt, lower + h_m / 2)]
    if form == "stacked":
        second = pick_kind(kinds, rng)
        fmt2 = pick_format(second, rng)
        # about 0.7 m between the panel centres, never overlapping
        gap = max(0.7, (h_m + fmt2[2]) / 2 + 0.05)
        centres.append((second, fmt2, lower + h_m / 2 + gap))
    top = 0.0
    placed = []
    reach = 0.0  # how far a tilted panel or its plate reaches behind the vertical through the panel centres
    for k, (kind, f, h_c) in enumerate(centres):
        centre = st.point(s, l_c, ground + h_c)
        panel_tilt = tilt + rng.uniform(-1, 1)
        lean = abs(np.sin(np.radians(panel_tilt)))
        placed.append(sign_panel(pieces, look, kind, centre, facing, panel_tilt, f, s, not away))
        reach = max(reach, f[2] / 2 * lean)
        if k == 0 and look.plate_share > 0 and kind.measured is None:  # the lowest sign may carry a plate
            plates = add_plate(pieces, look, placed[-1], centre, facing, panel_tilt, f, s)
            reach = max([reach] + [(f[2] / 2 + PLATE_MAX_GAP_M + p.truth.height_m) * lean for p in plates])
            placed += plates
        top = max(top, h_c + f[2] / 2)
    # the pole stands behind every panel and plate on their clamps, never through a tilted one's lower part
    standoff = POLE_STANDOFF_M + reach
    n_h = np.array([np.sin(np.radians(facing)), np.cos(np.radians(facing)), 0.0])
    if form == "back-to-back":
        other = pick_kind(kinds, rng)
        f = pick_format(other, rng)
        centre = st.point(s, l_c, ground + lower + h_m / 2) - n_h * 2 * standoff
        placed.append(sign_panel(pieces, look, other, centre, facing + 180.0, tilt, f, s, False))
    pole_base = st.point(s, l_c, ground) - n_h * standoff
    standing_pole(pieces, pole_base, top + 0.1, s)
    if look.occlusion and rng.random() < 0.2:
        occluder(pieces, s, l_c, max(w_m, h_m), ground + lower + h_m / 2, rng)
    return placed


def occluder(pieces: Pieces, s, l_sign, size_m, h_sign, rng) -> None:
    """A branch or a pole between the sign and the approaching vehicle, covering part of it.

    Placed next to the line of sight from about 9 m, offset so that it hides
    roughly a quarter to a half of the face rather than all of it.
    """
    d_before = rng.uniform(1.0, 2.5)
    l_cam = LANE_CENTRE
    frac = d_before / 9.0  # where the line of sight from ~9 m crosses
    l_sight = l_sign + (l_cam - l_sign) * frac
    h_sight = h_sign + (2.4 - h_sign) * frac
    apparent = size_m * (1 - frac)  # the face's size where the occluder stands
    if rng.random() < 0.5:
        l_o = l_sight + rng.choice([-1.0, 1.0]) * rng.uniform(0.1, 0.35) * apparent
        base = pieces.street.point(s - d_before, l_o, KERB_H)
        pieces.crossed(base, 0.1, h_sign + 2.0, None, None, s - d_before, (95, 100, 100))
    else:
        key, trng = pieces.keys.key("branch")
        n = 64
        dark = bool(rng.random() < 0.5)
        size = rng.uniform(0.5, 0.8)
        src = TextureSource(key, n, n, lambda: tx.foliage(trng, n, n, dark=dark))
        ang = rng.uniform(0, 2 * np.pi)
        shift = (size / 2 + apparent / 2) * rng.uniform(0.55, 0.8)
        centre = pieces.street.point(s - d_before, l_sight + shift * np.cos(ang), h_sight + shift * np.sin(ang))
        pieces.crossed(centre - UP * size / 2, size, size, src, src, s - d_before)
