"""Plate templates (SSV 5.xx): loaded from a catalogue's ``plates/`` folder.

``plates/plates.json`` (written by ``catalogue.plate_build``) lists each rendering
of an official drawing: id, language variant, kind (``pictogram``, ``layout`` or
``text``, see ``catalogue.plates_ch``), names, the words printed on it, a layout
plate's text field, whether its drawing prints in colour and its aspect (width /
height). Pictogram and layout plates
are told by their drawing (``drawn_plates``); text plates by what they say, their
rendering only shows the review what they look like. An entry without ``kind`` is
a pictogram plate (the folders of before text plates were typed). A catalogue
without that folder has no plate templates: its plates are all read as text. No
OpenCV at import: front ends read the names and sizes.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Optional

import numpy as np

from ..errors import InputFileError
from .formats import PLATE_FORMATS

FORMAT = "signmapper-plates/1"
PLATE_WIDTHS_M = sorted({w for w, _ in PLATE_FORMATS.values()})
PICTOGRAM, LAYOUT, TEXT = "pictogram", "layout", "text"  # as catalogue.plates_ch writes them
KINDS = (PICTOGRAM, LAYOUT, TEXT)


class PlateCatalogueError(InputFileError):
    """plates.json or one of its images cannot be used."""


@dataclass(frozen=True)
class PlateTemplate:
    id: str
    variant: str
    names: dict
    text: str  # words printed on the plate ("" for a pictogram alone; a layout plate's text is read)
    aspect: float  # width / height
    grey: np.ndarray  # the master, grey uint8
    kind: str = PICTOGRAM
    field: tuple = ()  # a layout plate's text field: (x0, y0, x1, y1), shares of its width and height
    png: str = ""  # the master's file (in colour: what a synthetic drive prints)
    coloured: bool = False  # its drawing prints in colour too (5.10's red and blue), not only black

    def name(self, lang: str = "de") -> str:
        return self.names.get(lang) or next(iter(self.names.values()), self.id)

    def size_m(self, span_m: float) -> tuple:
        """(width, height) of this plate with its longer side ``span_m`` (as wide as a text plate, or as high as
        one is wide for an upright plate such as 5.05)."""
        if self.aspect >= 1.0:
            return float(span_m), round(float(span_m) / self.aspect, 3)
        return round(float(span_m) * self.aspect, 3), float(span_m)


def plates_folder(catalogue_folder) -> Path:
    return Path(catalogue_folder) / "plates"


def pictogram_png(catalogue, template_id: str) -> str:
    """The PNG a person sees for a type (review dock, atlas): its catalogue drawing, else a pictogram plate's
    (German version first); "" for a text plate or an id the catalogue lacks."""
    if template_id and template_id in catalogue:
        return str(catalogue.pictogram_path(template_id, "png"))
    for path in sorted((plates_folder(catalogue.folder) / "png").glob(f"{template_id}_*.png")):
        return str(path)
    return ""


@lru_cache(maxsize=4)
def load_plate_templates(catalogue_folder) -> tuple:
    """The pictogram plate templates of the catalogue in ``catalogue_folder`` (empty without ``plates/``)."""
    import cv2

    path = plates_folder(catalogue_folder) / "plates.json"
    if not path.is_file():
        return ()
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as exc:
        raise PlateCatalogueError(path, f"not readable as JSON: {exc}") from exc
    if data.get("format") != FORMAT:
        raise PlateCatalogueError(path, f"format {data.get('format')!r} is not {FORMAT!r}")
    out = []
    for k, entry in enumerate(data.get("plates", [])):
        try:
            png = path.parent / entry["png"]
            grey = cv2.imread(str(png), cv2.IMREAD_GRAYSCALE)
            if grey is None:
                raise PlateCatalogueError(path, f"plate {k + 1}: image {png} is missing or unreadable")
            kind = str(entry.get("kind", PICTOGRAM))
            if kind not in KINDS:
                raise PlateCatalogueError(path, f"plate {k + 1}: kind {kind!r} is none of {', '.join(KINDS)}")
            field = tuple(float(v) for v in entry.get("field", ()))
            if (kind == LAYOUT) != bool(field) or (field and not (len(field) == 4 and 0 <= field[0] < field[2] <= 1
                                                                   and 0 <= field[1] < field[3] <= 1)):
                raise PlateCatalogueError(path, f"plate {k + 1}: a layout plate, and only one, has a text field "
                                                f"x0 < x1, y0 < y1 within 0..1 (kind {kind}, field {list(field)})")
            out.append(PlateTemplate(str(entry["id"]), str(entry["variant"]), dict(entry["names"]),
                                     str(entry.get("text", "")), float(entry["aspect"]), grey, kind, field,
                                     str(png), bool(entry.get("coloured", False))))
        except KeyError as exc:
            raise PlateCatalogueError(path, f"plate {k + 1} lacks the field {exc}") from exc
    return tuple(out)


def drawn_plates(templates) -> tuple:
    """The templates told by their drawing: pictogram and layout plates (not text plates)."""
    return tuple(t for t in templates if t.kind != TEXT)


def template_by_id(templates, template_id: str) -> Optional[PlateTemplate]:
    return next((t for t in templates if t.id == template_id), None)


def pictogram_formats(templates) -> dict:
    """Plate sizes the plates told by their drawing add to the text plates' (``PLATE_FORMATS``): name -> (width,
    height)."""
    return {f"{t.id}@{w:.2f}": t.size_m(w) for t in drawn_plates(templates) for w in PLATE_WIDTHS_M}
