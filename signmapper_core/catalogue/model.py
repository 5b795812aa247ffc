"""Template catalogue: entries, loading a catalogue folder, rendering templates, rounding sizes.

A catalogue folder holds ``catalogue.json`` and one RGBA master PNG per entry
(see ``templates/README.md``), so users can bring their own signs; the Swiss
catalogue bundled in ``templates/ch`` is just one such folder.
"""

from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Iterable, Iterator

import cv2
import numpy as np

from ..errors import InputFileError
from .faces import pixel_size
from .text_panels import is_text_panel

DEFAULT_CATALOGUE_DIR = Path(__file__).resolve().parents[2] / "templates" / "ch"
FORMAT_ID = "signmapper-catalogue/1"
# colour families of the faces: the colour covering most of a face ("white" also stands for grey and black faces,
# found by their outline rather than their hue)
COLOURS = ("red", "blue", "yellow", "white", "green", "brown", "orange")
# outlines; a "pointer" is a direction sign's panel with one pointed end (either way), a "cross" a St Andrew's cross
SHAPES = ("circle", "triangle", "triangle-down", "octagon", "diamond", "square", "rectangle", "pointer", "cross")
# SSV numbers as Signalo writes them: dotted numbers, "/" in lane signs (4.77/01), "-" before a value or variant
ID_PATTERN = re.compile(r"^[0-9A-Za-z]+([./][0-9A-Za-z]+)*(-[0-9A-Za-z.]+)*$")
UNKNOWN_ID = "unknown"  # the id of a sign-like face that matches no entry well (the open set); no entry has it
STANDARD, MEASURED = "standard", "measured"  # sizing: rounded to a standard format, or reported as measured
SIZINGS = (STANDARD, MEASURED)
MEASURED_SIDE_M = (0.15, 6.0)  # the shorter and longer side of any face without a standard size
MEASURED_ASPECT_FACTOR = 2.0  # ... and its aspect at most this far from its drawing's
# master image path -> (size, mtime_ns) of the version found intact: the catalogue is loaded by every
# algorithm, so each file is checked once per process and again only when it changes
_INTACT: dict[str, tuple[int, int]] = {}


def file_stem(template_id: str) -> str:
    """The file name (without suffix) of an entry's images: its id, with the "/" of lane signs as "_"."""
    return template_id.replace("/", "_")


class CatalogueError(InputFileError):
    """A catalogue folder is malformed; the message names the file and the entry."""


@dataclass(frozen=True)
class TemplateEntry:
    id: str
    names: dict
    colour: str
    shape: str
    formats: dict  # name -> (width_m, height_m) of the face's bounding box
    size_certain: bool = True
    png: str = ""
    svg: str | None = None
    sizing: str = STANDARD  # MEASURED: no standard size exists; the formats only give the face's aspect
    variants: tuple = ()  # further master images of the same sign (other language versions, pointing the other way)

    @property
    def aspect(self) -> float:
        w, h = next(iter(self.formats.values()))
        return w / h

    def name(self, lang: str = "de") -> str:
        return self.names.get(lang) or next(iter(self.names.values()), self.id)


@dataclass(frozen=True)
class SizeMatch:
    format: str
    width_m: float
    height_m: float
    rel_error: float  # max relative deviation of measured width/height from the format
    template_ids: tuple = ()


def shape_mask(shape: str, w: int, h: int) -> np.ndarray:
    """Alpha of an ideal outline of ``shape`` in a w x h box (for masters without alpha)."""
    ss = 4
    mask = np.zeros((h * ss, w * ss), np.uint8)
    W, H = w * ss, h * ss
    if shape == "circle":
        cv2.ellipse(mask, (W // 2, H // 2), (W // 2, H // 2), 0, 0, 360, 255, -1)
    elif shape in ("triangle", "triangle-down"):
        pts = [(W / 2, 0), (W, H), (0, H)] if shape == "triangle" else [(0, 0), (W, 0), (W / 2, H)]
        cv2.fillPoly(mask, [np.round(np.array(pts)).astype(np.int32)], 255)
    elif shape == "octagon":
        a = W / (1 + math.sqrt(2))
        c = (W - a) / 2
        pts = [(c, 0), (W - c, 0), (W, c), (W, H - c), (W - c, H), (c, H), (0, H - c), (0, c)]
        cv2.fillPoly(mask, [np.round(np.array(pts)).astype(np.int32)], 255)
    elif shape == "diamond":
        pts = [(W / 2, 0), (W, H / 2), (W / 2, H), (0, H / 2)]
        cv2.fillPoly(mask, [np.round(np.array(pts)).astype(np.int32)], 255)
    else:
        mask[:] = 255
    return cv2.resize(mask, (w, h), interpolation=cv2.INTER_AREA)


def _read_image(path: Path, shape: str, template_id: str) -> tuple[np.ndarray, np.ndarray]:
    img = cv2.imread(str(path), cv2.IMREAD_UNCHANGED)
    if img is None:
        raise CatalogueError(path, f"cannot read the image of template {template_id!r}")
    if img.ndim == 2:
        img = cv2.cvtColor(img, cv2.COLOR_GRAY2BGR)
    if img.dtype != np.uint8:
        img = (img / 257).astype(np.uint8)
    if img.shape[2] == 4:
        return np.ascontiguousarray(img[:, :, :3]), np.ascontiguousarray(img[:, :, 3])
    return img, shape_mask(shape, img.shape[1], img.shape[0])


def _resize(img: np.ndarray, w: int, h: int) -> np.ndarray:
    shrink = w <= img.shape[1] and h <= img.shape[0]
    return cv2.resize(img, (w, h), interpolation=cv2.INTER_AREA if shrink else cv2.INTER_LINEAR)


@dataclass
class Catalogue:
    folder: Path
    entries: dict = field(default_factory=dict)  # id -> TemplateEntry, in file order
    name: str = ""
    _masters: dict = field(default_factory=dict, repr=False)

    def __getitem__(self, template_id: str) -> TemplateEntry:
        try:
            return self.entries[template_id]
        except KeyError:
            raise KeyError(f"template {template_id!r} is not in catalogue {self.folder}") from None

    def __contains__(self, template_id) -> bool:
        return template_id in self.entries

    def __len__(self) -> int:
        return len(self.entries)

    def __iter__(self) -> Iterator[TemplateEntry]:
        return iter(self.entries.values())

    def ids(self) -> list[str]:
        return list(self.entries)

    def filter(self, colours: Iterable[str] | None = None, shapes: Iterable[str] | None = None,
               exclude: Iterable[str] = (), text_panels: bool = False) -> list[TemplateEntry]:
        """Entries with one of ``colours`` and ``shapes`` (None = any), minus excluded ids, and without the
        generic text panels unless ``text_panels`` (their wording varies: no template matches them and they
        have no standard format; ``text_panels.py``)."""
        colours = None if colours is None else set(colours)
        shapes = None if shapes is None else set(shapes)
        exclude = set(exclude)
        return [e for e in self.entries.values()
                if (colours is None or e.colour in colours) and (shapes is None or e.shape in shapes)
                and e.id not in exclude and (text_panels or not is_text_panel(e.id))]

    def master(self, template_id: str) -> tuple[np.ndarray, np.ndarray]:
        """The full-resolution (bgr, alpha) of an entry, read once and cached."""
        if template_id not in self._masters:
            self._masters[template_id] = self.read_master(template_id)
        return self._masters[template_id]

    def read_master(self, template_id: str) -> tuple[np.ndarray, np.ndarray]:
        """The full-resolution (bgr, alpha) of an entry read from its PNG, not cached (:meth:`master` caches)."""
        entry = self[template_id]
        return _read_image(self.folder / entry.png, entry.shape, template_id)

    def variant_masters(self, template_id: str) -> list[tuple[np.ndarray, np.ndarray]]:
        """(bgr, alpha) of each further drawing of an entry (``variants``), not cached: for training."""
        entry = self[template_id]
        return [_read_image(self.folder / image, entry.shape, template_id) for image in entry.variants]

    def render_variants(self, template_id: str, size_px) -> list[tuple[np.ndarray, np.ndarray]]:
        """(bgr, alpha) of each further drawing of an entry at ``size_px``, as :meth:`render` gives its master;
        read from the PNGs each time (callers keep what they need)."""
        w, h = pixel_size(self[template_id].aspect, size_px)
        return [(_resize(bgr, w, h), _resize(alpha, w, h)) for bgr, alpha in self.variant_masters(template_id)]

    def render(self, template_id: str, size_px, keep_master: bool = True) -> tuple[np.ndarray, np.ndarray]:
        """(bgr, alpha) at ``size_px`` (longer side, or (w, h)); alpha is 255 inside the sign outline.

        ``keep_master``: cache the full-resolution image (:meth:`master`) for the next rendering.
        """
        entry = self[template_id]
        bgr, alpha = self.master(template_id) if keep_master or template_id in self._masters \
            else self.read_master(template_id)
        w, h = pixel_size(entry.aspect, size_px)
        return _resize(bgr, w, h), _resize(alpha, w, h)

    def round_size(self, width_m: float, height_m: float, tolerance: float = 0.15,
                   entries: Iterable[TemplateEntry] | None = None) -> SizeMatch | None:
        """Nearest standard format to a measured face size, or None if none is within ``tolerance``.

        Pass ``entries`` of the detected shape: a triangle measured 10 % too large looks
        like a smaller disc, so the shape must come from the segmentation.
        """
        return round_size(self.entries.values() if entries is None else entries, width_m, height_m, tolerance)

    def pictogram_path(self, template_id: str, kind: str = "svg") -> Path:
        """Path of the entry's SVG marker or PNG master (for QGIS symbols)."""
        entry = self[template_id]
        if kind == "png":
            return self.folder / entry.png
        if kind == "svg":
            if not entry.svg:
                raise FileNotFoundError(f"template {template_id!r} of {self.folder} has no SVG pictogram")
            return self.folder / entry.svg
        raise ValueError(f"kind must be 'svg' or 'png', got {kind!r}")


def round_size(entries: Iterable[TemplateEntry], width_m: float, height_m: float,
               tolerance: float = 0.15) -> SizeMatch | None:
    """The format (name, size) nearest to a measured size in log space, if within ``tolerance``.

    Entries without a standard size (``sizing`` MEASURED) come in only where no standard format fits: a
    :class:`SizeMatch` named ``measured`` with the measured size, for those whose face could be that size
    (:func:`fits_measured`).
    """
    if not (width_m > 0 and height_m > 0):
        return None
    entries = list(entries)
    candidates: dict = {}
    for e in entries:
        if e.sizing != STANDARD:
            continue
        for name, (w, h) in e.formats.items():
            key = (name, round(w, 4), round(h, 4))
            candidates.setdefault(key, []).append(e.id)
    best = None
    for (name, w, h), ids in candidates.items():
        lw, lh = math.log(width_m / w), math.log(height_m / h)
        score = lw * lw + lh * lh
        if best is None or score < best[0]:
            best = (score, name, w, h, ids)
    if best is not None:
        _, name, w, h, ids = best
        rel = max(abs(width_m / w - 1.0), abs(height_m / h - 1.0))
        if rel <= tolerance:
            return SizeMatch(name, w, h, rel, tuple(ids))
    measured = tuple(e.id for e in entries if e.sizing == MEASURED and fits_measured(e, width_m, height_m))
    return SizeMatch(MEASURED, width_m, height_m, 0.0, measured) if measured else None


def fits_measured(entry: TemplateEntry, width_m: float, height_m: float) -> bool:
    """Whether a face of an entry without a standard size could measure ``width_m`` x ``height_m``: its sides
    within ``MEASURED_SIDE_M`` and its aspect within ``MEASURED_ASPECT_FACTOR`` of the drawing's (the wording
    makes a panel wider or taller, not a bar of a square)."""
    lo, hi = MEASURED_SIDE_M
    if not (lo <= min(width_m, height_m) and max(width_m, height_m) <= hi):
        return False
    ratio = (width_m / height_m) / entry.aspect
    return 1.0 / MEASURED_ASPECT_FACTOR <= ratio <= MEASURED_ASPECT_FACTOR


def _entry_from_json(path: Path, raw: dict, index: int) -> TemplateEntry:
    where = f"entry {index}"
    try:
        tid = str(raw["id"])
        where = f"entry {tid!r}"
        colour, shape = raw["colour"], raw["shape"]
        formats = {str(k): (float(v[0]), float(v[1])) for k, v in raw["formats"].items()}
        png = raw.get("png") or f"png/{file_stem(tid)}.png"
    except (KeyError, TypeError, ValueError, IndexError) as exc:
        raise CatalogueError(path, f"{where}: missing or malformed field ({exc})") from None
    if not ID_PATTERN.match(tid) or tid == UNKNOWN_ID:
        raise CatalogueError(path, f"{where}: id must look like '2.30-50' (and {UNKNOWN_ID!r} is taken)")
    if colour not in COLOURS:
        raise CatalogueError(path, f"{where}: colour {colour!r} not in {COLOURS}")
    if shape not in SHAPES:
        raise CatalogueError(path, f"{where}: shape {shape!r} not in {SHAPES}")
    if not formats or any(w <= 0 or h <= 0 for w, h in formats.values()):
        raise CatalogueError(path, f"{where}: formats must map names to positive [width_m, height_m]")
    names = {str(k): str(v) for k, v in (raw.get("names") or {}).items()} or {"de": tid}
    sizing = raw.get("sizing", STANDARD)
    if sizing not in SIZINGS:
        raise CatalogueError(path, f"{where}: sizing {sizing!r} not in {SIZINGS}")
    variants = raw.get("variants") or []
    if not isinstance(variants, list) or not all(isinstance(v, str) and v for v in variants):
        raise CatalogueError(path, f"{where}: variants must be a list of image paths")
    for image in [png] + variants:
        if not (path.parent / image).is_file():
            raise CatalogueError(path, f"{where}: image {image} not found")
        check_master_image(path.parent / image, where)
    return TemplateEntry(tid, names, colour, shape, formats, bool(raw.get("size_certain", True)), png,
                         raw.get("svg"), sizing, tuple(variants))


def check_master_image(path: Path, where: str) -> None:
    """Raise CatalogueError unless ``path`` is an intact image, without decoding it where possible.

    A PNG's chunks are read and their checksums verified (Pillow's ``verify``:
    truncation and corrupt bytes show, at about a tenth of the cost of decoding);
    other formats are decoded (Pillow). Files found intact are remembered by size and
    modification time.
    """
    from PIL import Image

    stat = path.stat()
    stamp = (stat.st_size, stat.st_mtime_ns)
    if _INTACT.get(str(path)) == stamp:
        return
    try:
        with Image.open(path) as img:
            if img.format == "PNG":
                img.verify()
            else:
                img.load()  # raises on truncated data, where OpenCV would fill in grey
    except Exception as exc:  # Pillow raises many types for broken files
        raise CatalogueError(path, f"{where}: the template image is corrupt or unreadable "
                                   f"({exc.__class__.__name__}: {exc})") from None
    _INTACT[str(path)] = stamp


def load_catalogue(folder=None) -> Catalogue:
    """Load a catalogue folder (None = the bundled Swiss catalogue); validates every entry up front."""
    folder = Path(folder) if folder is not None else DEFAULT_CATALOGUE_DIR
    path = folder / "catalogue.json"
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise CatalogueError(path, "catalogue.json not found") from None
    except json.JSONDecodeError as exc:
        raise CatalogueError(path, f"not valid JSON: {exc}") from None
    if not isinstance(data, dict) or not isinstance(data.get("entries"), list):
        raise CatalogueError(path, "expected an object with an 'entries' list")
    entries: dict = {}
    for i, raw in enumerate(data["entries"]):
        entry = _entry_from_json(path, raw, i)
        if entry.id in entries:
            raise CatalogueError(path, f"duplicate id {entry.id!r}")
        entries[entry.id] = entry
    return Catalogue(folder=folder, entries=entries, name=str(data.get("name", folder.name)))
