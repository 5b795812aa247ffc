"""Where sign faces come from: the one place the generator asks for a sign's pixels.

A face is printed from one of two artworks, chosen per sign by a seeded draw
(``face_artwork.py``): the catalogue's master image or one of the entry's
variant drawings (another language, the other pointing direction), resampled,
or the catalogue's procedural drawer with a random style (only the signs it
knows). The physical sign then gets its own print run, reflective
sheeting, wear, dirt, stickers or a tag and dents, each switchable and each with
a seeded random strength (``face_print.py`` ... ``face_dents.py``), and the
older weathering here (fading, dirt blotches, cast shadow). All of it happens
in the face's texture space; no rendered face is a pixel copy of a template.
"""

from __future__ import annotations

from dataclasses import dataclass, fields

import cv2
import numpy as np

from ..catalogue import load_catalogue
from ..catalogue.text_panels import is_text_panel
from . import face_dirt, face_marks, face_print, face_sheeting, face_wear
from .face_artwork import (
    MASTER,
    PROCEDURAL,
    choose_artwork,
    drawing_stems,
    has_procedural,
    master_face,
    procedural_face,
)
from .face_dents import DentWarp, dent_warp
from .face_layers import ink_layers
from .textures import metal, smooth_noise

SIGN_COLOURS = ("red", "blue", "yellow")

# seed streams of one face, one per variation, so switching one off leaves the others as they were
_ARTWORK, _PRINT, _SHEETING, _WEAR, _DIRT, _MARKS, _DENTS, _BACK, _SHEEN, _DRAWING = range(10)

LONGER_SIDE, SCALE = "longer side", "scale"
MEASURED = "measured"  # the format name of a face sized by a MeasuredSize


@dataclass(frozen=True)
class MeasuredSize:
    """How large a sign without a standard size is made: its longer side in metres (``LONGER_SIDE``) or its
    drawing's nominal size (the catalogue's format, the drawing at 1:20) times a factor (``SCALE``), uniform
    within ``lo``..``hi``; the aspect is always the drawing's."""

    rule: str
    lo: float
    hi: float

    def size(self, nominal_wh: tuple[float, float], value: float) -> tuple[float, float]:
        """(width_m, height_m) of a face of ``nominal_wh``'s aspect at ``value`` (a longer side or a factor)."""
        w, h = nominal_wh
        factor = value / max(w, h) if self.rule == LONGER_SIDE else value
        return w * factor, h * factor


@dataclass(frozen=True)
class SignKind:
    """What the layout needs to know about a template: id, colour, shape and standard formats; for the whole
    catalogue's street (``sign_mix``) also the size rule of a sign without a standard size and its mounting."""

    template_id: str
    colour: str
    shape: str
    formats: tuple[tuple[str, float, float], ...]  # (name, width_m, height_m), sorted by name
    measured: MeasuredSize | None = None  # set for the catalogue's ``sizing: measured`` entries
    mount: str = "pole"  # sign_mix.MOUNTS


def sign_kind(entry, **extra) -> SignKind | None:
    """The SignKind of a catalogue entry (None when it has no format to size it by)."""
    formats = tuple(sorted((name, float(w), float(h)) for name, (w, h) in entry.formats.items()))
    return SignKind(entry.id, entry.colour, entry.shape, formats, **extra) if formats else None


def sign_kinds(colours: tuple[str, ...] = SIGN_COLOURS) -> list[SignKind]:
    """Catalogue entries of ``colours`` (red, blue and yellow by default) in id order (deterministic).

    Only the signs the procedural drawer knows (``has_procedural``): the generator prints each either way.
    """

    catalogue = load_catalogue()
    kinds = []
    entries = [e for e in catalogue.filter(colours=list(colours)) if has_procedural(e.id)]
    for entry in sorted(entries, key=lambda e: e.id):
        kind = sign_kind(entry)
        if kind is not None:
            kinds.append(kind)
    if not kinds:
        raise RuntimeError(f"the template catalogue has no {', '.join(colours)} signs to place")
    return kinds


def white_sign_kinds() -> list[SignKind]:
    """The white and grey family (end-of-restriction discs, end-of-zone panels) in id order.

    Without the generic text panels (4.29, 4.30, 4.33): their wording and size change from panel to panel,
    so they are set from text (``text_panel_poles``), never printed from a master image.
    """

    return [k for k in sign_kinds(("white",)) if not is_text_panel(k.template_id)]


def pick_format(kind: SignKind, rng: np.random.Generator) -> tuple[str, float, float]:
    """'normal' mostly, 'small' sometimes, otherwise any format the sign has; a sign without a standard size
    (``kind.measured``) gets a size of its rule, named ``measured``."""
    if kind.measured is not None:
        rule = kind.measured
        return (MEASURED, *rule.size(kind.formats[0][1:], float(rng.uniform(rule.lo, rule.hi))))
    by_name = {f[0]: f for f in kind.formats}
    if "normal" in by_name and "small" in by_name:
        return by_name["small"] if rng.random() < 0.3 else by_name["normal"]
    if "normal" in by_name:
        return by_name["normal"]
    return kind.formats[int(rng.integers(len(kind.formats)))]


@dataclass(frozen=True)
class FaceOptions:
    """Which artworks and physical variations sign faces get (the face fields of SimulationConfig)."""

    face_artwork: str = "mixed"
    master_share: float = 0.7
    face_variants: bool = True
    face_print: bool = True
    face_sheeting: bool = True
    face_wear: bool = True
    face_dirt: bool = True
    face_marks: bool = True
    face_dents: bool = True
    back_mounts: bool = True

    @classmethod
    def from_config(cls, config) -> FaceOptions:
        return cls(**{f.name: getattr(config, f.name) for f in fields(cls)})


PROCEDURAL_ONLY = FaceOptions(face_artwork="procedural", face_variants=False, face_print=False, face_sheeting=False,
                              face_wear=False, face_dirt=False, face_marks=False, face_dents=False, back_mounts=False)


@dataclass(frozen=True)
class SignFace:
    """Recipe of one physical sign's face: artwork, variations and their seeds; pixels on demand."""

    template_id: str
    size_wh: tuple[int, int]
    width_m: float
    style_seed: int
    variation_seed: int
    options: FaceOptions = PROCEDURAL_ONLY
    # the older weathering: fading, dirt blotches, a cast shadow
    effect_seed: int = 0
    faded: float = 0.0
    dirt: float = 0.0
    shadow: bool = False

    def rng(self, stream: int) -> np.random.Generator:
        return np.random.default_rng([self.variation_seed, stream])

    @property
    def artwork(self) -> str:
        """``master`` or ``procedural`` (the master when the procedural drawer does not know the sign)."""
        if not has_procedural(self.template_id):
            return MASTER
        if self.options.face_artwork == "procedural":
            return PROCEDURAL
        return choose_artwork(self.rng(_ARTWORK), self.options.master_share)

    @property
    def drawing(self) -> int:
        """Which official drawing a master face is printed from: 0 the entry's master, k its k-th variant (another
        language, the other pointing direction), each equally likely; always 0 without ``face_variants``."""
        if not self.options.face_variants or self.artwork != MASTER:
            return 0
        count = len(drawing_stems(self.template_id))
        return int(self.rng(_DRAWING).integers(count)) if count > 1 else 0

    @property
    def drawing_name(self) -> str:
        """The file stem of the drawing printed, for the truth; "" for a procedural face or without variants."""
        if not self.options.face_variants or self.artwork != MASTER:
            return ""
        return drawing_stems(self.template_id)[self.drawing]

    def clean(self) -> tuple[np.ndarray, np.ndarray]:
        """(bgr, alpha) of the artwork as printed, before any physical variation."""
        if self.artwork == MASTER:
            rng = self.rng(_ARTWORK)
            rng.random()  # the artwork choice
            return master_face(self.template_id, self.size_wh, rng, self.drawing)
        return procedural_face(self.template_id, self.size_wh, np.random.default_rng(self.style_seed))

    def dents(self) -> DentWarp | None:
        if not self.options.face_dents:
            return None
        rng = self.rng(_DENTS)
        if rng.random() >= 0.3:
            return None
        return dent_warp(self.size_wh, rng, float(rng.uniform(0.3, 1.0)), bend=rng.random() < 0.35)

    def outline(self) -> np.ndarray:
        """Alpha of the panel (for its back): the artwork's outline, dented like the face."""
        alpha = self.clean()[1]
        warp = self.dents()
        return alpha if warp is None else warp.outline(alpha)

    def pixels(self, notes: list | None = None) -> tuple[np.ndarray, np.ndarray]:
        """(bgr uint8, alpha uint8) of the face as the camera will see it in texture space.

        ``notes`` (if given) receives the artwork and the variations applied, for contact sheets.
        """
        notes = [] if notes is None else notes
        bgr, alpha = self.clean()
        notes.append(self.artwork)
        opt = self.options
        if any((opt.face_print, opt.face_sheeting, opt.face_wear, opt.face_dirt, opt.face_marks)):
            bgr = physical_variation(self, bgr, alpha, notes)
        bgr = weather_face(bgr, alpha, np.random.default_rng(self.effect_seed), self.faded, self.dirt, self.shadow)
        notes += [name for name, on in (("faded", self.faded > 0), ("blotches", self.dirt > 0),
                                         ("shadow", self.shadow)) if on]
        warp = self.dents()
        if warp is not None:
            notes.append("dents")
            bgr = np.clip(warp.apply(bgr), 0, 255).astype(np.uint8)
            alpha = warp.outline(alpha)
        return np.ascontiguousarray(bgr), np.ascontiguousarray(alpha)

    def back(self, base_rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
        """(bgr, alpha) of the panel's back: galvanised metal, with mounting rails and clamp if switched on."""
        w, h = self.size_wh
        alpha = self.outline()
        bgr = metal(base_rng, h, w)
        if self.options.back_mounts:
            bgr = back_mounts(bgr, alpha, self.rng(_BACK))
        return bgr, alpha


def draw_sign_face(template_id: str, size_wh: tuple[int, int], width_m: float, rng: np.random.Generator,
                   options: FaceOptions, weathering: bool = True, shadows: bool = True) -> SignFace:
    """A random physical sign face: its seeds and the older weathering, drawn from ``rng`` in a fixed order."""
    style_seed = int(rng.integers(2**63))
    faded = float(rng.uniform(0.15, 0.45)) if weathering and rng.random() < 0.2 else 0.0
    dirt = float(rng.uniform(0.2, 0.5)) if weathering and rng.random() < 0.2 else 0.0
    shadow = bool(shadows and rng.random() < 0.25)
    effect_seed = int(rng.integers(2**63))
    variation_seed = int(rng.integers(2**63))
    return SignFace(template_id, (int(size_wh[0]), int(size_wh[1])), float(width_m), style_seed, variation_seed,
                    options, effect_seed, faded, dirt, shadow)


def physical_variation(face: SignFace, bgr: np.ndarray, alpha: np.ndarray, notes: list | None = None
                       ) -> np.ndarray:
    """The switched-on print, sheeting, wear, dirt and marks of one face, each with its own seeded strength.

    ``notes`` (if given) receives a short name and strength of each variation applied.
    """
    opt = face.options
    px_per_m = face.size_wh[0] / face.width_m
    labels = ink_layers(bgr)
    img = bgr.astype(np.float32)
    notes = [] if notes is None else notes
    if opt.face_print:
        rng = face.rng(_PRINT)
        strength = float(rng.uniform(0.3, 1.0))
        img = face_print.print_variation(img, labels, rng, strength, px_per_m)
        notes.append(f"print {strength:.1f}")
    if opt.face_sheeting:
        rng = face.rng(_SHEETING)
        img = face_sheeting.prism_texture(img, rng, float(rng.uniform(0.5, 1.0)), px_per_m)
    if opt.face_wear:
        rng = face.rng(_WEAR)
        strength = float(rng.beta(1.1, 4.0))  # mostly mild: mean 0.22, one sign in twelve beyond 0.5
        img = face_wear.uv_ageing(img, labels, rng, strength)
        notes.append(f"wear {strength:.1f}")
        if rng.random() < 0.06 + 0.2 * strength:
            img = face_wear.peel(img, alpha, rng, float(rng.uniform(0.5, 1.0)))
            notes.append("peel")
    if opt.face_dirt:
        rng = face.rng(_DIRT)
        strength = float(rng.beta(1.2, 3.0))
        img = face_dirt.grime(img, rng, strength)
        notes.append(f"grime {strength:.1f}")
        if rng.random() < 0.5:
            img = face_dirt.spots(img, alpha, rng, strength)
            notes.append("spots")
        if rng.random() < 0.4:
            img = face_dirt.rain_streaks(img, rng, strength)
            notes.append("streaks")
    if opt.face_marks:
        rng = face.rng(_MARKS)
        if rng.random() < 0.08:
            img = face_marks.sticker(img, alpha, rng)
            notes.append("sticker")
        if rng.random() < 0.05:
            img = face_marks.graffiti_tag(img, alpha, rng)
            notes.append("tag")
    if opt.face_sheeting:  # light on the film comes last: it lies over dirt and stickers alike
        rng = face.rng(_SHEEN)
        hot_spot = rng.random() < 0.3
        img = face_sheeting.sheen(img, alpha, rng, float(rng.uniform(0.3, 1.0)), hot_spot=hot_spot)
        notes.append("hot spot" if hot_spot else "sheen")
    return np.clip(img, 0, 255).astype(np.uint8)


def back_mounts(bgr: np.ndarray, alpha: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """Two horizontal mounting rails and a pole clamp on the back of a panel (the face shows no bolts)."""
    h, w = bgr.shape[:2]
    img = bgr.astype(np.float32)
    rail = np.array([150.0, 152.0, 150.0]) + rng.uniform(-10, 10)
    thick = max(2, int(round(0.06 * h)))
    inside = alpha > 128
    for frac in (0.27, 0.73):
        y = int(frac * h)
        band = np.zeros((h, w), bool)
        band[max(0, y - thick // 2):y + thick // 2 + 1] = True
        band &= inside
        img[band] = rail
        img[np.roll(band, thick // 2 + 1, axis=0) & ~band & inside] *= 0.75  # shadow under the rail
    clamp_w = max(2, int(round(0.12 * w)))
    x0 = w // 2 - clamp_w // 2
    for frac in (0.27, 0.73):
        y = int(frac * h)
        cv2.rectangle(img, (x0, y - thick), (x0 + clamp_w, y + thick), (120.0, 122.0, 122.0), -1)
        cv2.circle(img, (x0 + clamp_w // 4, y), max(1, thick // 3), (90.0, 92.0, 92.0), -1)
        cv2.circle(img, (x0 + 3 * clamp_w // 4, y), max(1, thick // 3), (90.0, 92.0, 92.0), -1)
    return np.clip(img, 0, 255).astype(np.uint8)


def weather_face(bgr: np.ndarray, alpha: np.ndarray, rng: np.random.Generator, faded: float, dirt: float,
                 shadow: bool) -> np.ndarray:
    """Fading (loss of saturation and contrast), dirt blotches and a cast shadow, in texture space."""
    h, w = bgr.shape[:2]
    img = bgr.astype(np.float32)
    if faded > 0:
        grey = img.mean(axis=2, keepdims=True)
        img = img * (1 - faded) + (0.6 * grey + 0.4 * 200.0) * faded
    if dirt > 0:
        blot = np.clip(smooth_noise(rng, h, w, max(4.0, w / 12.0)), 0, None)[..., None]
        img = img * (1 - dirt * blot) + np.array([60, 75, 85], np.float32) * (dirt * blot)
    if shadow:
        yy, xx = np.mgrid[0:h, 0:w].astype(np.float32)
        ang = rng.uniform(0, np.pi)
        offset = rng.uniform(-0.3, 0.3) * w
        dist = (xx - w / 2) * np.cos(ang) + (yy - h / 2) * np.sin(ang) - offset
        edge = np.clip(dist / (0.04 * w) + smooth_noise(rng, h, w, max(3.0, w / 8.0)), -1, 1)
        img *= (0.78 + 0.22 * (edge[..., None] < 0)) if rng.random() < 0.5 else (0.6 + 0.2 * (edge[..., None] + 1))
    img = cv2.GaussianBlur(img, (0, 0), 0.6)
    return np.clip(img, 0, 255).astype(np.uint8)
