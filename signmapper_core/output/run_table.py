"""The run table of an output: what a mapping run records about itself, one key a row, and reading it back.

Every key is declared once here (:data:`RUN_KEYS` from the mapping result, :data:`OUTPUT_RUN_KEYS` from how the
output was written); :func:`read_run_record` is the one reader of the table (the review, the comparison with an
inventory and "Settings from an earlier output" all go through it).
"""

from __future__ import annotations

import dataclasses
import json
import sqlite3
from contextlib import closing
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable, Optional

from .. import __version__
from .schema import OutputContext

RUN_TABLE = "signmapper_run"

# raise when a setting changes its meaning or unit, or the record its layout: older records are then refused
# unless read_versions learns them (version 1: the pipeline settings flat, before the sections)
SETTINGS_VERSION = 2
FLAT_PIPELINE_VERSION = 1
SQLITE_HEADER = b"SQLite format 3\x00"


class RunRecordError(ValueError):
    """An earlier output's run record cannot give the settings; the message names the file and why."""


def settings_dict(settings) -> dict:
    """Field name -> JSON-ready value of a settings dataclass (tuples become lists, sections objects)."""
    return json.loads(json.dumps(dataclasses.asdict(settings)))


@dataclass(frozen=True)
class RunKey:
    """One row of the run table: how a mapping result gives it, and whether the value is JSON or plain text."""

    key: str
    help: str
    read: Callable[[Any], Any]  # MappingResult -> value
    text: bool = False  # written and read back as plain text (paths, names), else as JSON
    setting: Optional[tuple] = None  # (section, name) of the pipeline setting this row repeats for readers


RUN_KEYS = (
    RunKey("software", "Program and version that wrote the file.", lambda r: f"Sign Mapper {__version__}", True),
    RunKey("drive", "Absolute drive folder: where the review finds the images.",
           lambda r: str(r.drive.root.resolve()), True),
    RunKey("crs", "CRS of the drive and the layers.", lambda r: r.drive.crs, True),
    RunKey("catalogue", "Template catalogue folder.", lambda r: str(r.catalogue.folder), True),
    RunKey("near_m", "Near limit of the depth range [m].", lambda r: r.config.depth.near_m,
           setting=("depth", "near_m")),
    RunKey("far_m", "Far limit of the depth range [m].", lambda r: r.config.depth.far_m, setting=("depth", "far_m")),
    RunKey("reach_m", "Farthest depth searched for signs never seen within the far limit [m]; null: none.",
           lambda r: r.config.depth.reach_m, setting=("depth", "reach_m")),
    RunKey("range_from_camera", "Whether the depth range came from the drive's camera (else set by hand).",
           lambda r: r.config.depth.range_from_camera, setting=("depth", "range_from_camera")),
    RunKey("colours", "Sign colours segmented.", lambda r: list(r.config.colour.colours),
           setting=("colour", "colours")),
    RunKey("exclude", "Template ids never assigned.", lambda r: list(r.config.classification.exclude),
           setting=("classification", "exclude")),
    RunKey("detection_threshold", "Minimum detection indicator.", lambda r: r.config.planarity.detection_threshold,
           setting=("planarity", "detection_threshold")),
    RunKey("classifier", "Classifier that ran: cnn (learned network) or ncc (template matching).",
           lambda r: r.classifier_name, True),
    RunKey("classification_threshold", "Classification indicator for a detection's status accepted (the "
           "classifier's own calibrated one unless set); a sign's voters need a mean the fusion setting "
           "accept_margin of the way from it to 1.", lambda r: r.classification_threshold,
           setting=("classification", "classification_threshold")),
    RunKey("run_id", "Identifier of this run (a UUID): exports record it, so the same run is never written twice.",
           lambda r: r.run_id, True),
    RunKey("settings_version", "Version of the recorded settings' meaning (SETTINGS_VERSION).",
           lambda r: SETTINGS_VERSION),
    RunKey("pipeline", "Every setting of the detection pipeline (PipelineConfig) as a JSON object: with fusion, "
           "what 'Settings from an earlier output' maps a drive again with.",
           lambda r: settings_dict(r.config)),
    RunKey("fusion", "Every setting of fusing detections into signs (FusionConfig) as a JSON object.",
           lambda r: settings_dict(r.fusion)),
)
# what the writer chose, not the mapping: read from the OutputContext
OUTPUT_RUN_KEYS = (
    RunKey("language", "Language of names and field aliases.", lambda c: c.language, True),
    RunKey("start_time", "Absolute time of the first pair (drive.json start_time), ISO 8601.",
           lambda c: c.start.isoformat() if c.start is not None else "", True),
    RunKey("crops", "Number of sign crops written beside the GeoPackage.", lambda c: len(c.crops)),
)
_TEXT_KEYS = {k.key for k in RUN_KEYS + OUTPUT_RUN_KEYS if k.text}


def run_record(result, context: Optional[OutputContext] = None) -> dict:
    """Key -> value of the run table for a ``MappingResult`` (and, when given, how it was written)."""
    record = {k.key: k.read(result) for k in RUN_KEYS}
    if context is not None:
        record.update({k.key: k.read(context) for k in OUTPUT_RUN_KEYS})
    return record


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


def read_run_record(path) -> dict:
    """Key -> value of the run table of the GeoPackage ``path`` (values decoded as written).

    Raises :class:`RunRecordError` when the file is missing, no GeoPackage, or has no run table.
    """
    path = Path(path)
    if not path.is_file():
        raise RunRecordError(f"{path}: no such file")
    with open(path, "rb") as fh:
        if fh.read(len(SQLITE_HEADER)) != SQLITE_HEADER:
            raise RunRecordError(f"{path}: not a GeoPackage")
    try:
        with closing(sqlite3.connect(f"{path.resolve().as_uri()}?mode=ro", uri=True)) as db:
            tables = {row[0] for row in db.execute("SELECT name FROM sqlite_master WHERE type = 'table'")}
            if RUN_TABLE not in tables:
                raise RunRecordError(f"{path}: no table '{RUN_TABLE}': not an output of Sign Mapper's "
                                     "'Map traffic signs'")
            rows = db.execute(f'SELECT "key", "value" FROM "{RUN_TABLE}"').fetchall()
    except sqlite3.Error as exc:
        raise RunRecordError(f"{path}: cannot read its table '{RUN_TABLE}': {exc}") from exc
    return {key: decode_run_value(key, text) for key, text in rows if isinstance(key, str) and isinstance(text, str)}


