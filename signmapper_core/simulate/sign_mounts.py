"""One sign spot of a street of the whole catalogue: its part of the mix (``sign_mix``) says how it is mounted.

- ``pole``: the standing poles of before (``sign_poles.sign_pole``), in their shares of forms;
- ``post``: one to ``stack`` signs of the part stacked on a post; a pointer sits on it by its blunt end (the way
  its drawing points, master or variant, says which), so pointers of one post may point both ways;
- ``board``: a large board on two posts at the roadside, or overhead on a gantry arm where it would not fit
  before the façade or, in ``BOARD_OVERHEAD_SHARE`` of the cases, anyway;
- ``text panel``: a white text panel pole (``text_panel_poles``).

Everything stands clear of the carriageway (``KERB_CLEAR_M``) and before the façades, and faces the approaching
vehicle like every sign pole.
"""

from __future__ import annotations

import numpy as np

from .face_artwork import MASTER, pointing
from .faces import MEASURED, pick_format
from .panels import PanelLook, PlacedSign
from .scene_pieces import CARRIAGEWAY, KERB_H, PARKING_LEFT, SIDEWALK_LEFT, SIDEWALK_RIGHT, Pieces
from .sign_mix import BOARD, POLE, POST, TEXT_PANEL, SignMix
from .sign_poles import POLE_STANDOFF_M, make_face, mount_face, occluder, sign_pole, standing_pole
from .street_body import FacadeSpan
from .text_panel_poles import TWO_POLES_FROM_M, text_panel_pole

# shares of the forms of a standing pole, drawn in this order from one number (as the drives of before did)
POLE_FORM_SHARES = (("overhead", 0.08), ("stacked", 0.22), ("back-to-back", 0.10), ("single", 0.60))
RIGHT_SIDE_SHARE = 0.75  # of the sign spots: on the right of the street (the rest on the left)
KERB_CLEAR_M = (0.3, 0.8)  # a post's or board's nearest edge from the carriageway (or parking lane)
FACADE_CLEAR_M = 0.2  # ... and its farthest edge before the façade
OPEN_ROOM_M = 2.0  # beyond the sidewalk where no façade stands (a gap with trees)
POST_LOWER_EDGE_M = (1.8, 2.5)  # a post's lowest sign above the sidewalk (people walk beneath)
POST_GAP_M = (0.03, 0.08)  # between the signs of a post
POINTER_TUCK_M = 0.05  # a pointer's blunt end reaches this far past its post's axis
BOARD_LOWER_EDGE_M = (1.5, 2.2)  # a roadside board's lower edge
BOARD_OVERHEAD_SHARE = 0.3  # of the boards: overhead even where one would fit at the roadside
OCCLUDED_SHARE = 0.2  # of the posts and boards: a branch or pole stands in front (as of the sign poles)


def pole_form(u: float) -> str:
    """The form of a standing pole for a uniform number ``u``."""
    for form, share in POLE_FORM_SHARES:
        if u < share:
            return form
        u -= share
    return POLE_FORM_SHARES[-1][0]


def roadside_room(facades: list[FacadeSpan], s: float, side: int) -> float:
    """Metres from the carriageway's (right) or parking lane's (left) outer edge to the nearest façade at ``s``."""
    edge = CARRIAGEWAY[1] if side > 0 else PARKING_LEFT[0]
    fronts = [abs(f.l_f) for f in facades if f.side == side and f.s0 - 1.0 <= s <= f.s1 + 1.0]
    sidewalk = SIDEWALK_RIGHT[1] if side > 0 else SIDEWALK_LEFT[0]
    far = min(fronts) if fronts else abs(sidewalk) + OPEN_ROOM_M
    return far - abs(edge)


def sign_spot(pieces: Pieces, look: PanelLook, s: float, mix: SignMix, rng: np.random.Generator,
              text_rng: np.random.Generator, facades: list[FacadeSpan], right_share: float = RIGHT_SIDE_SHARE
              ) -> list[PlacedSign]:
    """The signs of one spot at ``s``: a part of ``mix`` by weight, mounted its way, on the right in
    ``right_share`` of the spots; draws from ``rng`` (text panels from ``text_rng``)."""
    u = rng.random()
    side = 1 if rng.random() < right_share else -1
    part, kinds = mix.pick_part(rng)
    if part.mount == TEXT_PANEL:
        return text_panel_pole(pieces, look, s, text_rng, side)
    kind = kinds[int(rng.integers(len(kinds)))]
    if part.mount == POST:
        return sign_post(pieces, look, s, kinds, part.stack, rng, side, facades, first=kind)
    if part.mount == BOARD:
        return board(pieces, look, s, kind, rng, side, facades)
    form = pole_form(u)
    return sign_pole(pieces, look, s, mix.only(POLE), rng, 1 if form == "overhead" else side, form, first=kind)


def _facing(pieces: Pieces, s: float, rng: np.random.Generator, side: int) -> tuple[float, float]:
    """(facing, tilt) in degrees of a sign at ``s`` turned a little towards the road, as the sign poles are."""
    heading = np.degrees(pieces.street.heading(s))
    yaw = rng.uniform(-4, 4) + side * rng.uniform(0, 6)
    return heading + 180.0 - yaw, rng.uniform(-3, 3)


def sign_post(pieces: Pieces, look: PanelLook, s: float, kinds, stack: int, rng: np.random.Generator, side: int,
              facades: list[FacadeSpan], first=None) -> list[PlacedSign]:
    """One to ``stack`` signs of ``kinds`` (one width for all) on a post at ``s``: as many as fit between the
    carriageway and the façade, the first always (the widest sign of a part fits before the nearest façade). A
    pointer's blunt end is at the post, so its centre lies half its width off."""
    count = int(rng.integers(1, stack + 1))
    chosen = [first or kinds[int(rng.integers(len(kinds)))]]
    chosen += [kinds[int(rng.integers(len(kinds)))] for _ in range(count - 1)]
    rule = chosen[0].measured
    value = float(rng.uniform(rule.lo, rule.hi)) if rule is not None else None
    room = roadside_room(facades, s, side) - FACADE_CLEAR_M - KERB_CLEAR_M[0]  # for the signs' lateral reach
    faces = []
    towards_road = away = 0.0  # how far the post's signs reach from its axis, towards the road and away
    for kind in chosen:
        fmt = pick_format(kind, rng) if value is None or kind.measured is None \
            else (MEASURED, *kind.measured.size(kind.formats[0][1:], value))
        face, key = make_face(pieces, look, kind, fmt)
        way = pointing(kind.template_id, face.drawing) if face.artwork == MASTER else 0
        offset = way * (fmt[1] / 2 - POINTER_TUCK_M)  # the sign's centre from the axis, along the face's right
        # the face's right is the street's right (+l), so the road lies towards -side
        road_reach = max(towards_road, -side * offset + fmt[1] / 2)
        away_reach = max(away, side * offset + fmt[1] / 2)
        if faces and road_reach + away_reach > room:
            continue  # no room for this one
        towards_road, away = road_reach, away_reach
        faces.append((kind, fmt, face, key, offset))
    slack = room - towards_road - away  # the kerb clearance takes what the façade leaves, within its range
    clear = float(rng.uniform(KERB_CLEAR_M[0], KERB_CLEAR_M[0] + float(np.clip(slack, 0.0, np.ptp(KERB_CLEAR_M)))))
    edge = CARRIAGEWAY[1] if side > 0 else PARKING_LEFT[0]
    l_axis = edge + side * (clear + towards_road)
    facing, tilt = _facing(pieces, s, rng, side)
    st = pieces.street
    lower = float(rng.uniform(*POST_LOWER_EDGE_M)) + KERB_H
    top, placed, reach, centred = lower, [], 0.0, 0.0
    for k, (kind, fmt, face, key, offset) in enumerate(faces):
        if k:
            top += float(rng.uniform(*POST_GAP_M))
        panel_tilt = tilt + rng.uniform(-1, 1)
        centre = st.point(s, l_axis + offset, top + fmt[2] / 2)
        placed.append(mount_face(pieces, face, key, kind.colour, centre, facing, panel_tilt, fmt[1:], s, True))
        reach = max(reach, fmt[2] / 2 * abs(np.sin(np.radians(panel_tilt))))
        top += fmt[2]
        centred = max(centred, fmt[1] if offset == 0 else 0.0)
    _posts(pieces, s, l_axis, facing, centred, reach, top)
    if look.occlusion and rng.random() < OCCLUDED_SHARE:
        occluder(pieces, s, l_axis, max(towards_road + away, top - lower), (lower + top) / 2, rng)
    return placed


def _posts(pieces: Pieces, s: float, l_axis: float, facing: float, centred_width: float, reach: float, top: float
           ) -> None:
    """The post (or two posts under a wide centred sign) behind the signs at ``l_axis``, up to ``top``."""
    phi = np.radians(facing)
    n_h = np.array([np.sin(phi), np.cos(phi), 0.0])
    right = np.array([-np.cos(phi), np.sin(phi), 0.0])
    offsets = [-0.3 * centred_width, 0.3 * centred_width] if centred_width >= TWO_POLES_FROM_M else [0.0]
    for dx in offsets:
        base = pieces.street.point(s, l_axis, KERB_H) + right * dx - n_h * (POLE_STANDOFF_M + reach)
        standing_pole(pieces, base, top + 0.1 - KERB_H, s)


def board(pieces: Pieces, look: PanelLook, s: float, kind, rng: np.random.Generator, side: int,
          facades: list[FacadeSpan]) -> list[PlacedSign]:
    """A large board at ``s``: on two posts at the roadside, or overhead on a gantry arm."""
    fmt = pick_format(kind, rng)
    w_m, h_m = fmt[1], fmt[2]
    room = roadside_room(facades, s, side)
    overhead = rng.random() < BOARD_OVERHEAD_SHARE or KERB_CLEAR_M[0] + w_m > room - FACADE_CLEAR_M
    if overhead:
        return sign_pole(pieces, look, s, [kind], rng, 1, "overhead", first=kind, fmt=fmt)
    clear = float(rng.uniform(KERB_CLEAR_M[0], min(KERB_CLEAR_M[1], room - FACADE_CLEAR_M - w_m)))
    edge = CARRIAGEWAY[1] if side > 0 else PARKING_LEFT[0]
    l_c = edge + side * (clear + w_m / 2)
    facing, tilt = _facing(pieces, s, rng, side)
    lower = float(rng.uniform(*BOARD_LOWER_EDGE_M)) + KERB_H
    face, key = make_face(pieces, look, kind, fmt)
    centre = pieces.street.point(s, l_c, lower + h_m / 2)
    placed = [mount_face(pieces, face, key, kind.colour, centre, facing, tilt, (w_m, h_m), s, True)]
    reach = h_m / 2 * abs(np.sin(np.radians(tilt)))
    _posts(pieces, s, l_c, facing, w_m, reach, lower + h_m)
    if look.occlusion and rng.random() < OCCLUDED_SHARE:
        occluder(pieces, s, l_c, max(w_m, h_m), lower + h_m / 2, rng)
    return placed
