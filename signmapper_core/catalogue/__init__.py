"""Sign template catalogue: loader, renderer, size rounding and the procedural Swiss sign drawer.

Building the Swiss masters from the official drawings (``build``, ``official``,
``svg_compose``, ``svg_render``) is build-time only and not imported here.

Public API (see docs/core-api.md, section "Catalogue")::

    load_catalogue(folder=None) -> Catalogue      # None -> bundled Swiss catalogue
    Catalogue.filter / render / round_size / pictogram_path
    render_face(template_id, size_px, style=None) -> (bgr, alpha)
"""

from .faces import render_face
from .model import (
    COLOURS,
    DEFAULT_CATALOGUE_DIR,
    SHAPES,
    UNKNOWN_ID,
    Catalogue,
    CatalogueError,
    SizeMatch,
    TemplateEntry,
    load_catalogue,
    round_size,
    shape_mask,
)
from .style import FaceStyle

__all__ = [
    "COLOURS",
    "DEFAULT_CATALOGUE_DIR",
    "SHAPES",
    "UNKNOWN_ID",
    "Catalogue",
    "CatalogueError",
    "FaceStyle",
    "SizeMatch",
    "TemplateEntry",
    "load_catalogue",
    "render_face",
    "round_size",
    "shape_mask",
]
