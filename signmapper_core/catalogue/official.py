"""Catalogue masters from official SVG drawings: how each entry's drawing is obtained, rendered and checked.

An entry's artwork is one of
- ``Drawing``: an official SVG used as it is;
- ``Relettered``: an official drawing whose value glyphs are replaced by glyphs
  of other official drawings (same typeface), e.g. 2.30-20 from 2.30 "60" and
  the "2" of the zone sign 2.59.5;
- ``Cutout``: a sign that the official artwork shows only inside another
  drawing (the 100 and 120 discs of 4.93), cut out of its rendering;
- ``Region``: one board of a drawing that shows several side by side (the three
  distance beacons of 1.17), rendered from that part of the page.

The rendering is cropped to the sign, checked against the entry's shape and
aspect, and resized to the master size. Build-time only.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import cv2
import numpy as np

from .model import shape_mask
from .svg_compose import Placement, SvgDocument, compose, region
from .svg_render import render_svg

RENDER_PX = 2048  # longer side of the sign in the working rendering (4x the 512 px master)
ASPECT_TOLERANCE = 0.01  # official crop vs catalogue formats
OUTLINE_MIN_IOU = 0.88  # rendered outline vs the ideal outline of the entry's shape
FREE_OUTLINES = ("pointer", "cross")  # shapes whose outline comes from the drawing alone


class ArtworkError(ValueError):
    """An official drawing does not fit its catalogue entry; the message says which and why."""


class DrawingUnavailable(ArtworkError):
    """The official drawing an entry needs is not in the folder, or is another version than expected."""


@dataclass(frozen=True)
class Drawing:
    file: str

    def files(self) -> tuple:
        return (self.file,)

    def describe(self) -> str:
        return self.file


@dataclass(frozen=True)
class Glyph:
    """A glyph of an official drawing: its outline element and counters; ``reference`` is a glyph of the
    same drawing that also occurs in the base (a "0"), fixing scale and baseline. Without a reference the
    source drawing has the same scale and type size as the base."""

    file: str
    elements: tuple
    reference: tuple | None = None


@dataclass(frozen=True)
class Relettered:
    base: str
    slots: tuple  # the base's glyphs in reading order, each a tuple of element indices (outline, counters)
    replace: tuple  # (slot index, Glyph) pairs
    reference: int | None = None  # slot of the base glyph matching the glyphs' references
    recolour: tuple | None = None  # (glyph fill, counter fill) when the base writes in other colours
    elements: tuple = ()  # (file, number of drawable elements) the indices were taken from

    def files(self) -> tuple:
        return tuple(dict.fromkeys([self.base] + [g.file for _, g in self.replace]))

    def describe(self) -> str:
        sources = sorted({g.file for _, g in self.replace})
        return f"{self.base} relettered with glyphs of {', '.join(sources)}"


@dataclass(frozen=True)
class Cutout:
    """The sign whose outline (``ring`` colour, RGB) encloses ``centre`` inside ``area`` of ``file`` (user units)."""

    file: str
    area: tuple  # x0, y0, x1, y1
    ring: tuple  # RGB of the sign's outermost colour in the drawing

    def files(self) -> tuple:
        return (self.file,)

    def describe(self) -> str:
        return f"cut out of {self.file}"


@dataclass(frozen=True)
class Region:
    """The part ``area`` (x0, y0, x1, y1, user units) of ``file``: one board of a row of boards."""

    file: str
    area: tuple

    def files(self) -> tuple:
        return (self.file,)

    def describe(self) -> str:
        return f"{self.file}, part {tuple(round(v, 1) for v in self.area)}"


def _documents(folder: Path, files) -> dict:
    docs = {}
    for name in files:
        path = folder / name
        if not path.is_file():
            raise DrawingUnavailable(f"{path}: official drawing not found")
        docs[name] = SvgDocument.load(path)
    return docs


def _check_elements(spec: Relettered, docs: dict) -> None:
    for name, count in spec.elements:
        found = len(docs[name].elements)
        if found != count:
            raise DrawingUnavailable(f"{docs[name].source}: has {found} drawable elements, the recipe was written "
                                     f"for a version with {count}; not the drawing it expects")


def relettered_svg(spec: Relettered, docs: dict) -> bytes:
    """The base drawing with the replaced slots drawn in the glyphs of the source drawings."""
    _check_elements(spec, docs)
    base = docs[spec.base]
    placements, drop = [], []
    for slot, glyph in spec.replace:
        old = spec.slots[slot]
        drop.extend(old)
        ox0, oy0, ox1, oy1 = base.box(old)
        src = docs[glyph.file]
        gx0, gy0, gx1, gy1 = src.box(glyph.elements)
        if glyph.reference is not None:
            if spec.reference is None:
                raise ArtworkError(f"{spec.base}: glyph of {glyph.file} has a reference but the base has none")
            bx0, by0, bx1, by1 = base.box(spec.slots[spec.reference])
            rx0, ry0, rx1, ry1 = src.box(glyph.reference)
            scale = (by1 - by0) / (ry1 - ry0)
            bottom = by1 + (gy1 - ry1) * scale  # keep the glyph's height over the reference's baseline
        else:
            scale, bottom = 1.0, oy1
        tx = (ox0 + ox1) / 2 - scale * (gx0 + gx1) / 2
        ty = bottom - scale * gy1
        placements.append(Placement(src, glyph.elements, scale, tx, ty, spec.recolour))
    return compose(base, drop, placements)


def _crop_box(mask: np.ndarray) -> tuple:
    ys, xs = np.nonzero(mask)
    if xs.size == 0:
        raise ArtworkError("the rendering is empty")
    return xs.min(), ys.min(), xs.max() + 1, ys.max() + 1


def render_artwork(spec, folder: Path) -> tuple[np.ndarray, bool]:
    """(BGRA rendering of the sign at about RENDER_PX on its longer side, whether its outline must come from
    the entry's shape because the drawing is opaque around it)."""
    docs = _documents(Path(folder), spec.files())
    if isinstance(spec, Drawing):
        doc = docs[spec.file]
        return render_svg(doc.data, RENDER_PX / max(doc.page_px()), doc.source), False
    if isinstance(spec, Relettered):
        doc = docs[spec.base]
        return render_svg(relettered_svg(spec, docs), RENDER_PX / max(doc.page_px()), doc.source), False
    if isinstance(spec, Region):
        doc = docs[spec.file]
        x0, y0, x1, y1 = spec.area
        zoom = RENDER_PX / (max(x1 - x0, y1 - y0) * doc.px_per_unit())
        return render_svg(region(doc, spec.area), zoom, doc.source), False
    if isinstance(spec, Cutout):
        doc = docs[spec.file]
        x0, y0, x1, y1 = spec.area
        zoom = RENDER_PX / (max(x1 - x0, y1 - y0) * doc.px_per_unit())
        img = render_svg(region(doc, spec.area), zoom, doc.source)
        rgb = np.array(spec.ring[::-1], np.int32)
        near = (np.abs(img[:, :, :3].astype(np.int32) - rgb).max(axis=2) < 40).astype(np.uint8)
        n, labels, stats, _ = cv2.connectedComponentsWithStats(near)
        cx, cy = img.shape[1] / 2, img.shape[0] / 2
        enclosing = [i for i in range(1, n) if stats[i, 0] < cx < stats[i, 0] + stats[i, 2]
                     and stats[i, 1] < cy < stats[i, 1] + stats[i, 3]]
        if not enclosing:
            raise ArtworkError(f"{doc.source}: no outline of colour {spec.ring} around the centre of {spec.area}")
        best = max(enclosing, key=lambda i: stats[i, 4])
        x, y, w, h = stats[best, :4]
        return img[y:y + h, x:x + w], True
    raise TypeError(f"unknown artwork spec {spec!r}")  # pragma: no cover


def _field(bgra: np.ndarray) -> tuple[np.ndarray, tuple]:
    """Mask and box (x0, y0, x1, y1) of the white field around the face's centre."""
    hsv = cv2.cvtColor(np.ascontiguousarray(bgra[:, :, :3]), cv2.COLOR_BGR2HSV)
    white = ((bgra[:, :, 3] > 127) & (hsv[:, :, 1] < 60) & (hsv[:, :, 2] > 200)).astype(np.uint8)
    # the content (digits, symbols) splits the field: close it before taking the component at the centre
    k = max(3, int(0.15 * min(white.shape)) | 1)
    closed = cv2.morphologyEx(white, cv2.MORPH_CLOSE, cv2.getStructuringElement(cv2.MORPH_ELLIPSE, (k, k)))
    n, labels = cv2.connectedComponents(closed)
    centre = labels[labels.shape[0] // 2, labels.shape[1] // 2]
    if centre == 0:
        raise ArtworkError("no white field at the centre of the face")
    mask = labels == centre
    return mask, _crop_box(mask)


def framed_master(frame: np.ndarray, own: np.ndarray) -> np.ndarray:
    """The own drawing's field (its value and symbols) set into the white field of an official frame.

    For entries whose value the official glyphs cannot write: the rim, its
    colour and width, stay official, so no classifier can tell these entries
    apart from the others by the style of their frame.
    """
    frame_mask, (fx0, fy0, fx1, fy1) = _field(frame)
    _, (ox0, oy0, ox1, oy1) = _field(own)
    content = cv2.resize(own[oy0:oy1, ox0:ox1, :3], (fx1 - fx0, fy1 - fy0), interpolation=cv2.INTER_AREA)
    out = frame.copy()
    inside = cv2.erode(frame_mask.astype(np.uint8), np.ones((3, 3), np.uint8))[fy0:fy1, fx0:fx1] > 0
    out[fy0:fy1, fx0:fx1, :3][inside] = content[inside]
    return out


def rim_colour(bgr: np.ndarray, alpha: np.ndarray) -> tuple:
    """Median colour of the opaque band along the outline: what transparent pixels are filled with."""
    opaque = (alpha == 255).astype(np.uint8)
    k = max(3, int(round(0.012 * max(alpha.shape))) | 1)
    band = opaque.astype(bool) & ~cv2.erode(opaque, np.ones((k, k), np.uint8)).astype(bool)
    if not band.any():
        band = alpha > 0
    return tuple(int(v) for v in np.median(bgr[band], axis=0))


def fill_enclosed(bgr: np.ndarray, alpha: np.ndarray) -> None:
    """Make transparent parts enclosed by the face white and opaque (in place).

    A few drawings leave the face's white field transparent inside a printed
    frame (kilometre and hectometre plates); the sign is white there.
    """
    clear = (alpha < 128).astype(np.uint8)
    n, labels = cv2.connectedComponents(clear, connectivity=4)
    border = np.unique(np.concatenate([labels[0], labels[-1], labels[:, 0], labels[:, -1]]))
    enclosed = (labels > 0) & ~np.isin(labels, border)
    if enclosed.any():
        a = alpha[enclosed].astype(np.float32)[:, None] / 255.0
        bgr[enclosed] = (bgr[enclosed] * a + 255.0 * (1.0 - a)).astype(np.uint8)
        alpha[enclosed] = 255


def master_from_rendering(bgra: np.ndarray, outline_from_shape: bool, shape: str, size: tuple, name: str,
                          min_overlap: float = OUTLINE_MIN_IOU) -> np.ndarray:
    """BGRA master of ``size`` (w, h): cropped to the outline, checked against ``shape`` and the size's aspect.

    Shapes without one ideal outline (``FREE_OUTLINES``: a pointer points either way, a cross's bars vary) keep
    the drawing's outline unchecked.
    """
    if not outline_from_shape:
        x0, y0, x1, y1 = _crop_box(bgra[:, :, 3] > 0)
        crop = bgra[y0:y1, x0:x1]
        bgr, alpha = np.ascontiguousarray(crop[:, :, :3]), np.ascontiguousarray(crop[:, :, 3])
        fill_enclosed(bgr, alpha)
    else:
        bgr = np.ascontiguousarray(bgra[:, :, :3])
        alpha = shape_mask(shape, bgr.shape[1], bgr.shape[0])
    h, w = alpha.shape
    want = size[0] / size[1]
    if abs((w / h) / want - 1) > ASPECT_TOLERANCE:
        raise ArtworkError(f"{name}: the official drawing is {w}x{h} (aspect {w / h:.3f}), the catalogue formats "
                           f"have aspect {want:.3f}")
    ideal = shape_mask(shape, w, h) > 127
    drawn = alpha > 127
    iou = (ideal & drawn).sum() / max((ideal | drawn).sum(), 1)
    if shape not in FREE_OUTLINES and iou < min_overlap:
        raise ArtworkError(f"{name}: the official outline does not look like a {shape} (overlap {iou:.2f})")
    rim = rim_colour(bgr, alpha)
    bgr[alpha == 0] = rim
    out_bgr = cv2.resize(bgr, size, interpolation=cv2.INTER_AREA)
    out_alpha = cv2.resize(alpha, size, interpolation=cv2.INTER_AREA)
    out_bgr[out_alpha == 0] = rim
    return np.dstack([out_bgr, out_alpha])
