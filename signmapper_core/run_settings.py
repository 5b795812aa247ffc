"""A run's settings saved whole in its output's run table, and read back to map a drive again with them.

The run table (``output_schema.RUN_KEYS``) holds every setting of the
``PipelineConfig`` (key ``pipeline``, a JSON object per section) and of the
``FusionConfig`` (key ``fusion``) as JSON, with ``settings_version``.
:func:`load_run_settings` turns the run table of an earlier output back into
those objects, so a drive can be mapped again exactly as it was (``mapsigns``'
"Settings from an earlier output"). Settings (or sections) this version does
not know are reported and ignored; settings the record lacks (added after it
was written) keep their defaults. Version 1 records hold the pipeline settings
as one flat object: each is put into its section by its name (names are unique
across the sections). A record of another settings version is refused, since
its values may mean something else.
"""

from __future__ import annotations

import dataclasses
import json
import sqlite3
from contextlib import closing
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Optional

from .output_schema import RUN_TABLE, decode_run_value
from .progress import WarnCallback

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


def _frozen(value):
    """JSON lists back to the tuples the settings dataclasses hold (they are frozen and hashable)."""
    if isinstance(value, list):
        return tuple(_frozen(v) for v in value)
    if isinstance(value, dict):
        return {k: _frozen(v) for k, v in value.items()}
    return value


def settings_of(cls, data: dict, where: str, warn: Optional[WarnCallback] = None):
    """An instance of the settings dataclass ``cls`` from ``data`` (a :func:`settings_dict`).

    Keys ``cls`` does not have are passed to ``warn`` and ignored; missing ones
    keep their defaults. Values the class refuses raise :class:`RunRecordError`
    naming ``where``.
    """
    if not isinstance(data, dict):
        raise RunRecordError(f"{where}: expected a JSON object of settings, found {type(data).__name__}")
    known = {f.name for f in dataclasses.fields(cls)}
    unknown = sorted(set(data) - known)
    if unknown and warn is not None:
        warn(f"{where}: ignored settings this version does not know: {', '.join(unknown)}")
    try:
        return cls(**{k: _frozen(v) for k, v in data.items() if k in known})
    except (TypeError, ValueError) as exc:
        raise RunRecordError(f"{where}: {exc}") from exc


def pipeline_config_of(data: dict, where: str, warn: Optional[WarnCallback] = None, version: int = SETTINGS_VERSION):
    """The ``PipelineConfig`` of a record's ``pipeline`` object: ``{section: {setting: value}}``.

    ``version`` 1: the settings flat, each put into its section by name. Unknown
    sections and settings are passed to ``warn`` and ignored; values a section
    refuses raise :class:`RunRecordError` naming ``where``.
    """
    from .pipeline.config import SECTION_OF, SECTIONS, PipelineConfig

    if not isinstance(data, dict):
        raise RunRecordError(f"{where}: expected a JSON object of settings, found {type(data).__name__}")
    if version == FLAT_PIPELINE_VERSION:
        unknown = sorted(set(data) - set(SECTION_OF))
        if unknown and warn is not None:
            warn(f"{where}: ignored settings this version does not know: {', '.join(unknown)}")
        sections: dict = {}
        for name, value in data.items():
            if name in SECTION_OF:
                sections.setdefault(SECTION_OF[name], {})[name] = value
        data = sections
    else:
        unknown = sorted(set(data) - set(SECTIONS))
        if unknown and warn is not None:
            warn(f"{where}: ignored sections this version does not know: {', '.join(unknown)}")
    return PipelineConfig(**{name: settings_of(cls, data[name], f"{where}, section {name}", warn)
                             for name, cls in SECTIONS.items() if name in data})


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


@dataclass(frozen=True)
class RunSettings:
    """What an earlier run was mapped with: its pipeline and fusion settings and its catalogue folder."""

    config: Any  # pipeline.PipelineConfig
    fusion: Any  # fusion.FusionConfig
    catalogue: Optional[str]  # folder as recorded; None when the record names none
    software: str = ""


def run_settings(record: dict, where: str, warn: Optional[WarnCallback] = None) -> RunSettings:
    """The settings of a run record (:func:`read_run_record`); ``where`` names it in messages."""
    from .fusion import FusionConfig

    software = record.get("software", "an unknown program")
    version = record.get("settings_version")
    if version is None or "pipeline" not in record:
        raise RunRecordError(f"{where}: written by {software}, which recorded only some of its settings (no "
                             "'settings_version'); map the drive again with this version to record them all")
    if version not in (SETTINGS_VERSION, FLAT_PIPELINE_VERSION):
        raise RunRecordError(f"{where}: settings version {version} (written by {software}); this version of Sign "
                             f"Mapper reads versions {FLAT_PIPELINE_VERSION} and {SETTINGS_VERSION} only")
    config = pipeline_config_of(record["pipeline"], f"{where}, pipeline settings", warn, version)
    fusion = settings_of(FusionConfig, record.get("fusion", {}), f"{where}, fusion settings", warn)
    catalogue = record.get("catalogue")
    return RunSettings(config, fusion, str(catalogue) if catalogue else None, str(software))


def load_run_settings(path, warn: Optional[WarnCallback] = None) -> RunSettings:
    """The settings an earlier output at ``path`` was mapped with; :class:`RunRecordError` says what is wrong."""
    return run_settings(read_run_record(path), str(path), warn)
