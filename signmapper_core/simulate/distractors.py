"""Colour distractors along the drive: cars, cones, shop signs, coloured patches, emblems and sign backs."""

from __future__ import annotations

import cv2
import numpy as np

from . import textures as tx
from .faces import SIGN_COLOURS, SignKind
from .panels import PanelLook, PlacedSign
from .scene_pieces import CARRIAGEWAY, PARKING_LEFT, UP, Pieces, fit_texture
from .sign_poles import sign_pole
from .street_body import FacadeSpan
from .surfaces import Texture, TextureSource, rect_surface

CAR_COLOURS = {"red": (35, 35, 190), "blue": (150, 70, 25), "yellow": (25, 185, 230), "white": (225, 225, 225),
               "black": (30, 30, 32), "grey": (120, 120, 118), "silver": (175, 175, 170), "green": (60, 90, 40)}


def distractors(pieces: Pieces, look: PanelLook, s_lo, s_hi, density, rng, sign_spots: list[float],
                kinds: list[SignKind], facades: list[FacadeSpan]) -> list[PlacedSign]:
    """About ``density`` distractors per 100 m between ``s_lo`` and ``s_hi``; shop signs, patches and
    emblems on the ``facades``, sign backs away from the ``sign_spots``. Returns the sign backs placed."""
    n = rng.poisson(density * (s_hi - s_lo) / 100.0)
    choices = ["car", "car", "oncoming", "cones", "shop", "patch", "logo", "back"]
    spots = np.sort(rng.uniform(s_lo, s_hi, n))
    backs: list[PlacedSign] = []
    for s in spots:
        what = choices[int(rng.integers(len(choices)))]
        colour = SIGN_COLOURS[int(rng.integers(3))]
        if what in ("car", "oncoming"):
            if rng.random() < 0.4:
                colour = ["white", "black", "grey", "silver", "green"][int(rng.integers(5))]
            lat = (PARKING_LEFT[0] + PARKING_LEFT[1]) / 2 if what == "car" else -CARRIAGEWAY[1] / 2
            car(pieces, s, lat, CAR_COLOURS[colour], rng)
        elif what == "cones":
            for k in range(int(rng.integers(2, 5))):
                base = pieces.street.point(s + 1.2 * k, CARRIAGEWAY[1] - 0.35, 0.0)
                key, trng = pieces.keys.key("cone")
                src = TextureSource(key, 30, 50, lambda trng=trng: tx.cone(trng, 50))
                pieces.crossed(base, 0.45, 0.75, src, src, s + 1.2 * k)
        elif what in ("shop", "patch", "logo"):
            facade_distractor(pieces, s, colour, what, rng, facades)
        elif all(abs(s - x) > 3 for x in sign_spots):
            same_colour = [k for k in kinds if k.colour == colour] or kinds
            backs += sign_pole(pieces, look, s, same_colour, rng, side=-1, form="away")
    return backs


def car(pieces: Pieces, s, lat, colour_bgr, rng, van: bool = False) -> None:
    """A parked or oncoming car (``van``: a delivery van, longer and taller)."""
    st = pieces.street
    if van:
        length, width, height = rng.uniform(4.8, 5.6), rng.uniform(1.9, 2.05), rng.uniform(1.9, 2.4)
    else:
        length, width, height = rng.uniform(3.9, 4.8), rng.uniform(1.7, 1.85), rng.uniform(1.35, 1.55)
    f, r = st.forward(s), st.right(s)
    c = st.point(s, lat, 0.0)
    body = np.array(colour_bgr, float)
    keys = [pieces.keys.key("car") for _ in range(4)]
    low = 0.6 * height
    # sides (one-sided, facing out), seen with their rounded cabin outline
    for sgn, (key, trng) in zip((1, -1), keys[:2]):
        wpx, hpx = int(length / 0.03), int(height / 0.03)
        src = TextureSource(key, wpx, hpx, lambda trng=trng, wpx=wpx, hpx=hpx: fit_texture(
            tx.car_side(trng, length, height, 0.03, body), wpx, hpx))
        p_back, p_front = c - f * length / 2 + r * sgn * width / 2, c + f * length / 2 + r * sgn * width / 2
        left, right = (p_back, p_front) if sgn > 0 else (p_front, p_back)
        pieces.wall(left, right, c[2] + 0.1, c[2] + 0.1 + height, src, s_range=(s - 3, s + 3), two_sided=False)
    for sgn, (key, trng), front in zip((1, -1), keys[2:], (True, False)):
        wpx, hpx = int(width / 0.03), int(low / 0.03)
        src = TextureSource(key, wpx, hpx, lambda trng=trng, front=front, wpx=wpx, hpx=hpx: fit_texture(tx.car_end(
            trng, width, low, 0.03, body, front), wpx, hpx))
        p_l, p_r = c + f * sgn * length / 2 + r * sgn * width / 2, c + f * sgn * length / 2 - r * sgn * width / 2
        pieces.wall(p_l, p_r, c[2] + 0.1, c[2] + 0.1 + low, src, s_range=(s - 3, s + 3), two_sided=False)
    top = c + UP * (0.1 + height)
    roof_c = top - f * 0.3 * length - r * width / 2
    pieces.surfaces.append(rect_surface(roof_c + f * 0.6 * length, r * width, -f * 0.6 * length, None,
                                        tuple(int(v) for v in body * 0.9), True, (s - 3, s + 3)))
    glass = (50, 42, 38)
    for sgn in (1, -1):
        top_edge = c + UP * (0.1 + height) + f * sgn * 0.3 * length
        low_edge = c + UP * (0.1 + low) + f * sgn * 0.5 * length
        corner = top_edge - r * width / 2 * sgn
        pieces.surfaces.append(rect_surface(corner, r * width * sgn, low_edge - top_edge, None, glass, True,
                                            (s - 3, s + 3)))


def facade_distractor(pieces: Pieces, s, colour, what, rng, facades: list[FacadeSpan]) -> None:
    """A shop sign, a coloured patch or a sign-like emblem on the façade standing at ``s`` (none: nothing)."""
    span = next((f for f in facades if f.s0 + 1 < s < f.s1 - 3), None)
    if span is None:
        return
    l_f, side, bottom = span.l_f, span.side, span.bottom
    if what == "logo":  # sign-like emblem of a shop, in sign colours and shapes, any size
        length = height = rng.uniform(0.25, 1.1)
        lift = rng.uniform(1.8, 3.4)
    else:
        length = rng.uniform(1.5, 3.0) if what == "shop" else rng.uniform(1.0, 2.5)
        height = rng.uniform(0.5, 0.9) if what == "shop" else rng.uniform(1.2, 2.5)
        lift = rng.uniform(2.6, 3.6) if what == "shop" else rng.uniform(0.0, 1.5)
    lat = l_f - side * 0.05
    a, b = pieces.street.point(s, lat), pieces.street.point(s + length, lat)
    left, right = (b, a) if side > 0 else (a, b)
    key, trng = pieces.keys.key(what)
    w, h = int(length / 0.02), int(height / 0.02)
    if what == "logo":
        src = TextureSource(key, w, w, lambda: tx.emblem(trng, w, colour))
        h = w
    elif what == "shop":
        src = TextureSource(key, w, h, lambda: fit_texture(
            Texture(tx.shop_sign(trng, length, height, 0.02, colour)), w, h))
    else:
        src = TextureSource(key, w, h, lambda: Texture(tx.tint(
            tx.SIGNAL_COLOURS[colour], tx.grain(trng, h, w, ((1.0, 0.4), (8.0, 0.6))), 12.0)))
    pieces.wall(left, right, bottom + 0.3 + lift, bottom + 0.3 + lift + height, src, s_range=(s - 1, s + length + 1))


WHITE_PANEL = (232, 234, 233)  # BGR of white sheeting and white paint, before light and weathering


def white_sign_distractors(pieces: Pieces, s_lo, s_hi, density, rng, facades: list[FacadeSpan]) -> None:
    """About ``density`` white things per 100 m that look like white signs to a shape-and-depth step: white
    vans, white shop signs and round white emblems on façades, and free-standing white boards on two posts
    (estate agents, building sites) near the kerb."""
    for s in np.sort(rng.uniform(s_lo, s_hi, rng.poisson(density * max(s_hi - s_lo, 0.0) / 100.0))):
        what = ("van", "shop", "disc", "board")[int(rng.integers(4))]
        if what == "van":
            lat = (PARKING_LEFT[0] + PARKING_LEFT[1]) / 2 if rng.random() < 0.5 else -CARRIAGEWAY[1] / 2
            car(pieces, float(s), lat, CAR_COLOURS["white"], rng, van=True)
        elif what == "board":
            white_board(pieces, float(s), rng)
        else:
            white_facade_panel(pieces, float(s), what, rng, facades)


def _lettering(img: np.ndarray, rng, rows: int) -> None:
    """Dark letter-like blocks in ``rows`` lines across a white panel."""
    h, w = img.shape[:2]
    line_h = max(2, int(0.55 * h / rows))
    for k in range(rows):
        y0 = int((k + 0.5) * h / rows - line_h / 2)
        x = int(rng.uniform(0.06, 0.2) * w)
        while x < 0.88 * w:
            lw = int(rng.uniform(0.4, 0.8) * line_h)
            cv2.rectangle(img, (x, y0), (x + lw, y0 + line_h), (40, 40, 45), max(1, lw // 4))
            x += lw + max(2, line_h // 4)


def white_board(pieces: Pieces, s, rng) -> None:
    """A white board with dark lettering on two posts beside the road, facing the traffic."""
    st = pieces.street
    width, height = rng.uniform(0.6, 1.3), rng.uniform(0.4, 0.9)
    lower = rng.uniform(0.8, 1.6)
    lat = CARRIAGEWAY[1] + rng.uniform(0.4, 1.8) + width / 2
    key, trng = pieces.keys.key("board")
    w, h = int(width / 0.01), int(height / 0.01)

    def make():
        img = tx.tint(WHITE_PANEL, tx.grain(trng, h, w, ((1.0, 0.3), (4.0, 0.3))), 6.0)
        _lettering(img, trng, int(trng.integers(1, 4)))
        return Texture(img)

    src = TextureSource(key, w, h, make)
    right = st.right(s)
    centre = st.point(s, lat, lower + height / 2)
    corner = centre - right * width / 2 + UP * height / 2
    pieces.surfaces.append(rect_surface(corner, right * width, -UP * height, src, two_sided=True,
                                        s_range=(s - 2, s + 2)))
    for side in (-1, 1):
        base = st.point(s + 0.02, lat + side * 0.4 * width, 0.0)
        pieces.crossed(base, 0.05, lower + height, None, None, s, (150, 150, 150))


def white_facade_panel(pieces: Pieces, s, what, rng, facades: list[FacadeSpan]) -> None:
    """A white shop sign with dark lettering, or a round white emblem with a dark ring, on a façade."""
    span = next((f for f in facades if f.s0 + 1 < s < f.s1 - 3), None)
    if span is None:
        return
    if what == "disc":
        length = height = rng.uniform(0.35, 0.9)
        lift = rng.uniform(1.8, 3.4)
    else:
        length, height, lift = rng.uniform(0.6, 2.5), rng.uniform(0.4, 0.9), rng.uniform(2.4, 3.6)
    lat = span.l_f - span.side * 0.05
    a, b = pieces.street.point(s, lat), pieces.street.point(s + length, lat)
    left, right = (b, a) if span.side > 0 else (a, b)
    key, trng = pieces.keys.key("white " + what)
    w, h = int(length / 0.01), int(height / 0.01)

    def make():
        img = tx.tint(WHITE_PANEL, tx.grain(trng, h, w, ((1.0, 0.3), (4.0, 0.3))), 6.0)
        if what == "disc":
            alpha = np.zeros((h, w), np.uint8)
            cv2.circle(alpha, (w // 2, h // 2), w // 2 - 1, 255, -1, cv2.LINE_AA)
            cv2.circle(img, (w // 2, h // 2), int(0.42 * w), (60, 60, 60), max(1, w // 20), cv2.LINE_AA)
            _lettering(img[int(0.35 * h):int(0.65 * h), int(0.2 * w):int(0.8 * w)], trng, 1)
            return Texture(img, alpha)
        _lettering(img, trng, int(trng.integers(1, 3)))
        return Texture(img)

    pieces.wall(left, right, span.bottom + 0.3 + lift, span.bottom + 0.3 + lift + height,
                TextureSource(key, w, h, make), s_range=(s - 1, s + length + 1))
