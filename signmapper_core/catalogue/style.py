"""Face styles: the knobs that make a generated sign face differ from its template.

``FaceStyle()`` is the reference look used for the catalogue masters; the
synthetic generator draws random styles so that its faces are never pixel
copies of the templates the detector matches against.
"""

from __future__ import annotations

import colorsys
from dataclasses import dataclass

import numpy as np

# Reference colours (RGB) of the Swiss signal palette, approximations of the RAL tones.
PALETTE_RGB: dict[str, tuple[int, int, int]] = {
    "red": (200, 20, 32),
    "blue": (0, 82, 160),
    "yellow": (250, 200, 0),
    "white": (255, 255, 255),
    "black": (22, 22, 22),
    "grey": (135, 135, 135),
    "green": (0, 135, 75),
    "orange": (240, 125, 0),
}

FONTS = ("simplex", "duplex", "triplex", "complex")


@dataclass(frozen=True)
class FaceStyle:
    """Variations of the procedural drawer; the defaults are the reference look."""

    stroke_scale: float = 1.0  # pictogram stroke widths
    rim_scale: float = 1.0  # width of the coloured rim / border
    corner_scale: float = 1.0  # corner radius of triangles, squares, octagon
    palette_jitter: float = 0.0  # 0..1: random hue/saturation/value shift of each colour
    font: str = "simplex"  # OpenCV Hershey font: simplex, duplex, triplex, complex
    text_scale: float = 1.0
    text_weight: float = 1.0
    detail_jitter: float = 0.0  # 0..1: random shift/scale of pictogram parts
    simplify: bool = False  # drop small details (windows, wheel hubs)
    seed: int = 0

    @classmethod
    def random(cls, rng: np.random.Generator, strength: float = 1.0) -> FaceStyle:
        """A plausible random variation; ``strength`` 0 gives the reference look."""
        s = float(strength)
        return cls(
            stroke_scale=1.0 + s * rng.uniform(-0.2, 0.25),
            rim_scale=1.0 + s * rng.uniform(-0.2, 0.2),
            corner_scale=1.0 + s * rng.uniform(-0.4, 0.5),
            palette_jitter=s * rng.uniform(0.2, 1.0),
            font=str(rng.choice(FONTS)) if s > 0 else "simplex",
            text_scale=1.0 + s * rng.uniform(-0.1, 0.06),
            text_weight=1.0 + s * rng.uniform(-0.25, 0.25),
            detail_jitter=s * rng.uniform(0.2, 1.0),
            simplify=bool(s > 0 and rng.random() < 0.3),
            seed=int(rng.integers(0, 2**31 - 1)),
        )

    def palette(self) -> dict[str, tuple[int, int, int]]:
        """The palette as BGR tuples, jittered when ``palette_jitter`` > 0 (deterministic per seed)."""
        out = {}
        rng = np.random.default_rng(self.seed + 7919)
        for name, (r, g, b) in PALETTE_RGB.items():
            j = self.palette_jitter
            dh, ds, dv = rng.uniform(-1, 1, 3) * j
            if j > 0 and name not in ("white", "black", "grey"):
                h, s, v = colorsys.rgb_to_hsv(r / 255, g / 255, b / 255)
                h = (h + dh * 0.015) % 1.0
                s = min(1.0, max(0.55, s + ds * 0.12))
                v = min(1.0, max(0.45, v + dv * 0.15))
                r, g, b = (round(c * 255) for c in colorsys.hsv_to_rgb(h, s, v))
            elif j > 0:
                shift = round(dv * 12)
                r, g, b = (min(255, max(0, c + shift)) for c in (r, g, b))
            out[name] = (int(b), int(g), int(r))
        return out


REFERENCE_STYLE = FaceStyle()
