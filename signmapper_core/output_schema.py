"""The output of mapping a drive, declared once: layers, fields, status values, run table.

Writing the GeoPackage (``gpkg/fields.py``), recognising our layers,
the review's reading and writing, the layer styles, the review dock and the run
table all derive from the tables below. Adding an output field is one row in
:data:`FIELDS` (and a test; the golden GeoPackage in ``tests/qgis/golden`` is
regenerated).

A row says how the value is read from a fused sign (``FusedSign``, layer
``signs``), from a detection in its pair (``fusion.Observation``, layer
``detections``) and, for what a person may change by reclassifying, from a
catalogue entry and its chosen format. A layer carries the fields that have a
reader for it, in the order of the table. REAL values are rounded to
``decimals`` when written: more digits than the method measures are noise.
"""

from __future__ import annotations

import json
import operator
from dataclasses import dataclass
from typing import Any, Callable, Optional

from . import __version__

SIGNS, DETECTIONS = "signs", "detections"
LAYERS = (SIGNS, DETECTIONS)
RUN_TABLE = "signmapper_run"

ACCEPTED, REVIEW, REJECTED, MANUAL = "accepted", "review", "rejected", "manual"
# status -> colour: the review dock's status text and buttons and the detections' layer style
STATUS_COLOURS = {ACCEPTED: "#2e7d32", REVIEW: "#f57c00", REJECTED: "#9e9e9e", MANUAL: "#1565c0"}

TEXT, INTEGER, REAL = "text", "integer", "real"

Reader = Callable[[Any], Any]


@dataclass(frozen=True)
class Field:
    """One attribute of the output layers."""

    name: str
    kind: str  # TEXT, INTEGER or REAL
    help: str
    sign: Optional[Reader] = None  # value of a FusedSign; None: not in the signs layer
    detection: Optional[Reader] = None  # value of an Observation; None: not in the detections layer
    template: Optional[Callable[[Any, str], Any]] = None  # (catalogue entry, format name) -> value on reclassify
    decimals: Optional[int] = None  # REAL: rounded to this many decimals when written
    length: int = 0  # TEXT: longest value, 0 = unlimited
    required: bool = False  # the review cannot show a feature without it: it marks our layers

    def reader(self, layer: str) -> Optional[Reader]:
        return self.sign if layer == SIGNS else self.detection

    def value(self, layer: str, item) -> Any:
        """The value written for ``item`` in ``layer``: typed, rounded, None for unknown."""
        return self.typed(self.reader(layer)(item))

    def typed(self, value, rounded: bool = True) -> Any:
        """``value`` as this field's Python type (None stays None); REAL rounded to ``decimals`` if ``rounded``."""
        if value is None:
            return None
        if self.kind == REAL:
            value = float(value)
            return value if self.decimals is None or not rounded else round(value, self.decimals)
        return int(value) if self.kind == INTEGER else str(value)


def _both(name: str) -> dict:
    """The same attribute of a fused sign and of an observation."""
    read = operator.attrgetter(name)
    return {"sign": read, "detection": read}


def _best(name: str) -> dict:
    """Of an observation; a fused sign gives its best observation's (the one the review shows first)."""
    return {"sign": lambda sign: getattr(sign.best, name), "detection": lambda obs: getattr(obs, name)}


def _bbox(i: int) -> dict:
    return {"sign": lambda sign: sign.best.bbox[i], "detection": lambda obs: obs.bbox[i]}


FIELDS = (
    Field("sign_id", INTEGER, "Number of the physical sign, from 1 in order of first sight.", required=True,
          sign=lambda s: s.sign_id),
    Field("template_id", TEXT, "Catalogue id (SSV number, '-<value>' for a sign with a number), by weighted vote "
          "for a sign.", required=True, template=lambda entry, fmt: entry.id, **_both("template_id")),
    Field("name", TEXT, "German name of the template.", template=lambda entry, fmt: entry.name("de"),
          **_both("name")),
    Field("colour", TEXT, "Dominant colour segmented: red, blue, yellow (or white).",
          template=lambda entry, fmt: entry.colour, **_both("colour")),
    Field("shape", TEXT, "Shape of the face: circle, triangle, triangle-down, octagon, diamond, square, rectangle.",
          template=lambda entry, fmt: entry.shape, **_both("shape")),
    Field("width_m", REAL, "Standard width of the format [m] (the face's bounding box).",
          template=lambda entry, fmt: entry.formats[fmt][0], **_both("width_m")),
    Field("height_m", REAL, "Standard height of the format [m] (the face's bounding box).",
          template=lambda entry, fmt: entry.formats[fmt][1], **_both("height_m")),
    Field("format", TEXT, "Standard format the measured size was rounded to (e.g. normal, large).",
          template=lambda entry, fmt: fmt, **_both("format")),
    Field("detection_indicator", REAL, "Planar share of the face, 0-1: is it a sign? Mean of the voters for a sign.",
          decimals=4, **_both("detection_indicator")),
    Field("classification_indicator", REAL, "Template-matching score, 0-1: is it this sign? Mean of the voters "
          "for a sign.", decimals=4, **_both("classification_indicator")),
    Field("status", TEXT, "accepted, review (a person should look), rejected (by a person) or manual (added by a "
          "person).", required=True, **_both("status")),
    Field("reviewed", INTEGER, "1 once a person decided on the feature, else 0.", required=True,
          sign=lambda s: int(s.status == MANUAL), detection=lambda o: int(o.status == MANUAL)),
    Field("source", TEXT, "How the face was found: colour segmentation or the Hough fallback for round signs.",
          **_best("source")),
    Field("n_obs", INTEGER, "Number of detections fused into the sign.", required=True, sign=lambda s: s.n_obs),
    Field("vote_share", REAL, "Share of the weighted vote its template won, 0-1.", decimals=3,
          sign=lambda s: s.vote_share),
    Field("sigma_m", REAL, "RMS 3D distance of the voters' positions from the fused one [m].", decimals=4,
          sign=lambda s: s.sigma_m),
    Field("azimuth", REAL, "Direction the face looks towards, degrees clockwise from grid north.", decimals=1,
          sign=lambda s: s.azimuth),
    Field("mount_height_m", REAL, "Lower edge of the face above the road [m]; empty when the drive does not state "
          "its camera height.", decimals=2, sign=lambda s: s.mount_height_m),
    Field("best_pair_id", TEXT, "Pair of the best observation, the one the review shows first.", required=True,
          sign=lambda s: s.best.pair_id),
    Field("pair_id", TEXT, "Stereo pair (poses.csv id) the detection was made in.", required=True,
          detection=lambda o: o.pair_id),
    Field("time", REAL, "Time of that pair [s].", **_best("time")),
    Field("u", REAL, "Column of the face centre in the left image [px].", decimals=2, required=True, **_best("u")),
    Field("v", REAL, "Row of the face centre in the left image [px].", decimals=2, required=True, **_best("v")),
    Field("bbox_x", INTEGER, "Left column of the face's box in the left image [px].", required=True, **_bbox(0)),
    Field("bbox_y", INTEGER, "Top row of the face's box [px].", required=True, **_bbox(1)),
    Field("bbox_w", INTEGER, "Width of the face's box [px].", required=True, **_bbox(2)),
    Field("bbox_h", INTEGER, "Height of the face's box [px].", required=True, **_bbox(3)),
    Field("depth_m", REAL, "Depth of the face centre along the optical axis [m].", decimals=3, **_best("depth_m")),
    Field("sign_id", INTEGER, "The sign this detection was fused into (signs.sign_id).",
          detection=lambda o: o.sign_id),
)


def fields(layer: str) -> tuple[Field, ...]:
    """The fields of ``layer`` in their order."""
    if layer not in LAYERS:
        raise ValueError(f"no output layer '{layer}'; the layers are {', '.join(LAYERS)}")
    return tuple(f for f in FIELDS if f.reader(layer) is not None)


def field(layer: str, name: str) -> Field:
    for f in fields(layer):
        if f.name == name:
            return f
    raise KeyError(f"layer '{layer}' has no field '{name}'")


def required_names(layer: str) -> set[str]:
    """Names a layer must have to be one of ours: what the review cannot do without."""
    return {f.name for f in fields(layer) if f.required}


def values(layer: str, item) -> dict:
    """Field name -> written value of a fused sign (``signs``) or an observation (``detections``)."""
    return {f.name: f.value(layer, item) for f in fields(layer)}


def template_values(layer: str, entry, format_name: str) -> dict:
    """What reclassifying as catalogue ``entry`` in format ``format_name`` writes."""
    return {f.name: f.typed(f.template(entry, format_name)) for f in fields(layer) if f.template is not None}


@dataclass(frozen=True)
class RunKey:
    """One row of the run table: how a mapping result gives it, and whether the value is JSON or plain text."""

    key: str
    help: str
    read: Callable[[Any], Any]  # MappingResult -> value
    text: bool = False  # written and read back as plain text (paths, names), else as JSON


RUN_KEYS = (
    RunKey("software", "Program and version that wrote the file.", lambda r: f"Sign Mapper {__version__}", True),
    RunKey("drive", "Absolute drive folder: where the review finds the images.",
           lambda r: str(r.drive.root.resolve()), True),
    RunKey("crs", "CRS of the drive and the layers.", lambda r: r.drive.crs, True),
    RunKey("catalogue", "Template catalogue folder.", lambda r: str(r.catalogue.folder), True),
    RunKey("near_m", "Near limit of the depth range [m].", lambda r: r.config.near_m),
    RunKey("far_m", "Far limit of the depth range [m].", lambda r: r.config.far_m),
    RunKey("colours", "Sign colours segmented.", lambda r: list(r.config.colours)),
    RunKey("exclude", "Template ids never assigned.", lambda r: list(r.config.exclude)),
    RunKey("detection_threshold", "Minimum detection indicator.", lambda r: r.config.detection_threshold),
    RunKey("classifier", "Classifier that ran: cnn (learned network) or ncc (template matching).",
           lambda r: r.classifier_name, True),
    RunKey("classification_threshold", "Classification indicator for status accepted (the classifier's own "
           "calibrated one unless set).", lambda r: r.classification_threshold),
)
_TEXT_KEYS = {k.key for k in RUN_KEYS if k.text}


def run_record(result) -> dict:
    """Key -> value of the run table for a ``MappingResult``."""
    return {k.key: k.read(result) for k in RUN_KEYS}


def encode_run_value(value) -> str:
    return value if isinstance(value, str) else json.dumps(value)


def decode_run_value(key: str, text: str):
    """A run-table value as written: plain text for text keys, JSON otherwise (text if it is not JSON)."""
    if key in _TEXT_KEYS:
        return text
    try:
        return json.loads(text)
    except ValueError:
        return text


def _check() -> None:
    for layer in LAYERS:
        names = [f.name for f in fields(layer)]
        duplicates = {n for n in names if names.count(n) > 1}
        if duplicates:
            raise ValueError(f"output schema: layer '{layer}' lists {', '.join(sorted(duplicates))} twice")
    for f in FIELDS:
        if f.kind not in (TEXT, INTEGER, REAL) or not f.help or (f.sign is None and f.detection is None):
            raise ValueError(f"output schema: field '{f.name}' needs a kind, help text and a layer")


_check()
