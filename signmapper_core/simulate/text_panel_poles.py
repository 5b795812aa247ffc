"""White text panels on poles among the white signs: place-name (4.29), place-end (4.30) and direction
panels (4.33, sometimes two stacked), facing the traffic.

Their face is set from their wording (``place_names``, ``text_panel_faces``) and then ages like every
other sign face: :class:`TextPanelFace` is a :class:`~.faces.SignFace` whose clean artwork is the set
panel, so print, sheeting, wear, dirt, marks, dents and the back come from the same code. The truth row
has the face's bounding box (pointer included) and the printed lines joined by " / ".
"""

from __future__ import annotations

from dataclasses import dataclass, fields

import numpy as np

from ..catalogue.text_panels import DIRECTION, TEXT_PANELS
from .face_artwork import PROCEDURAL
from .faces import SignFace, draw_sign_face
from .panels import PanelLook, PlacedSign
from .place_names import panel_lines
from .scene_pieces import CARRIAGEWAY, KERB_H, PARKING_LEFT, Pieces
from .sign_poles import POLE_STANDOFF_M, mount_face, occluder, standing_pole
from .text_panel_faces import PanelPlan, draw_text_panel, plan_panel

TEXT_PANEL_SHARE = 0.35  # of the white poles: one text panel (or two stacked direction panels) instead
TEXT_PANEL_IDS = tuple(sorted(TEXT_PANELS))  # equally likely
STACKED_DIRECTION_SHARE = 0.35  # of the direction panel poles: two panels, one above the other
LOWER_EDGE_M = (1.5, 2.5)  # the lowest panel's lower edge above the road
STACK_GAP_M = (0.04, 0.12)
TWO_POLES_FROM_M = 1.2  # place-name and place-end panels at least this wide stand on two poles
MAX_FACE_PX = 800  # longer side of a panel's face texture


@dataclass(frozen=True)
class TextPanelFace(SignFace):
    """A text panel's physical face: the panel set from its wording, then a sign face's physical life."""

    plan: PanelPlan | None = None
    px_per_m: float = 0.0

    @property
    def artwork(self) -> str:
        return PROCEDURAL

    def clean(self) -> tuple[np.ndarray, np.ndarray]:
        return draw_text_panel(self.plan, self.px_per_m)


def text_panel(pieces: Pieces, look: PanelLook, plan: PanelPlan, centre, facing_deg, tilt_deg, s) -> PlacedSign:
    """Face, back and truth row of one text panel at ``centre`` (it faces the vehicle)."""
    px_per_m = min(look.fx / 3.0, MAX_FACE_PX / max(plan.width_m, plan.height_m))
    key, rng = pieces.keys.key("text panel")
    physical = draw_sign_face(plan.kind_id, plan.size_px(px_per_m), plan.width_m, rng, look.face_options,
                              look.weathering, look.shadows)
    face = TextPanelFace(**{f.name: getattr(physical, f.name) for f in fields(SignFace)}, plan=plan,
                         px_per_m=px_per_m)
    return mount_face(pieces, face, key, "white", centre, facing_deg, tilt_deg, (plan.width_m, plan.height_m), s,
                      True, text=" / ".join(plan.lines))


def _pole_offsets(plans: list[PanelPlan]) -> list[float]:
    """Where the poles stand along the panels, from their centre (metres to the face's right): under the
    rectangular part of a pointer, two poles under a wide panel, else one in the middle."""
    if any(p.point for p in plans):
        return [float(np.mean([p.point_m / 2 * (1 if p.point == "left" else -1) for p in plans]))]
    width = max(p.width_m for p in plans)
    return [-0.3 * width, 0.3 * width] if width >= TWO_POLES_FROM_M else [0.0]


def text_panel_pole(pieces: Pieces, look: PanelLook, s: float, rng: np.random.Generator, side: int
                    ) -> list[PlacedSign]:
    """A pole (or two) at ``s`` on ``side`` (1 right, -1 left) with a text panel, or two stacked direction
    panels, facing the approaching traffic; every draw comes from ``rng``."""
    kind_id = TEXT_PANEL_IDS[int(rng.integers(len(TEXT_PANEL_IDS)))]
    stacked = TEXT_PANELS[kind_id].layout == DIRECTION and rng.random() < STACKED_DIRECTION_SHARE
    plans = [plan_panel(kind_id, panel_lines(kind_id, rng), "left" if rng.random() < 0.5 else "right")
             for _ in range(2 if stacked else 1)]
    st = pieces.street
    heading = np.degrees(st.heading(s))
    yaw = rng.uniform(-4, 4) + side * rng.uniform(0, 6)  # turned a little towards the road
    facing = heading + 180.0 - yaw
    tilt = rng.uniform(-3, 3)
    width = max(p.width_m for p in plans)
    edge = CARRIAGEWAY[1] if side > 0 else PARKING_LEFT[0]
    l_c = edge + side * (rng.uniform(0.3, 2.0) + width / 2)
    lower = rng.uniform(*LOWER_EDGE_M)
    placed: list[PlacedSign] = []
    top, reach = lower, 0.0
    for k, plan in enumerate(plans):
        if k:
            top += rng.uniform(*STACK_GAP_M)
        panel_tilt = tilt + rng.uniform(-1, 1)
        centre = st.point(s, l_c, top + plan.height_m / 2)
        placed.append(text_panel(pieces, look, plan, centre, facing, panel_tilt, s))
        reach = max(reach, plan.height_m / 2 * abs(np.sin(np.radians(panel_tilt))))
        top += plan.height_m
    phi = np.radians(facing)
    n_h = np.array([np.sin(phi), np.cos(phi), 0.0])
    right = np.array([-np.cos(phi), np.sin(phi), 0.0])
    for dx in _pole_offsets(plans):
        base = st.point(s, l_c, KERB_H) + right * dx - n_h * (POLE_STANDOFF_M + reach)
        standing_pole(pieces, base, top + 0.1 - KERB_H, s)
    if look.occlusion and rng.random() < 0.2:
        occluder(pieces, s, l_c, max(width, top - lower), (lower + top) / 2, rng)
    return placed
