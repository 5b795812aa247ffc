"""A run's settings saved whole in its output's run table, and read back to map a drive again with them.

The run table (``output.run_table.RUN_KEYS``) holds every setting of the
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
import typing
from dataclasses import dataclass
from typing import Any, Optional

from ..progress import WarnCallback, send_warning
from .run_table import FLAT_PIPELINE_VERSION, RUN_KEYS, SETTINGS_VERSION, RunRecordError, read_run_record


def _frozen(value):
    """JSON lists back to the tuples the settings dataclasses hold (they are frozen and hashable)."""
    if isinstance(value, list):
        return tuple(_frozen(v) for v in value)
    if isinstance(value, dict):
        return {k: _frozen(v) for k, v in value.items()}
    return value


def _describe(hint, many: bool = False) -> str:
    """A type as a record's reader would say it ("a list of 6 whole numbers"); ``many``: in the plural."""
    origin, args = typing.get_origin(hint), typing.get_args(hint)
    if origin is typing.Union:
        return " or ".join("null" if a is type(None) else _describe(a, many) for a in args)
    a_list = "lists" if many else "a list"
    if origin is tuple and args[-1:] == (Ellipsis,) or origin is list:
        return f"{a_list} of {_describe(args[0], True)}"
    if origin is tuple:
        kinds = {_describe(a, True) for a in args}
        return f"{a_list} of {len(args)} {kinds.pop() if len(kinds) == 1 else 'values'}"
    if origin is dict:
        return f"{'objects' if many else 'an object'} of {_describe(args[1], True)}"
    words = {float: ("a number", "numbers"), int: ("a whole number", "whole numbers"), bool: ("true or false",) * 2,
             str: ("a text", "texts")}.get(hint, (str(hint),) * 2)
    return words[many]


def _misfit(value, hint, path: str = ""):
    """(where in ``value``, the type expected, the value found there) where a JSON value does not fit the type
    ``hint``; None if it fits.

    A record is only used once every setting has the type its class declares: a wrong one (a text for an HSV
    range) would otherwise fail pair after pair with an IndexError, blamed on the images.
    """
    origin, args = typing.get_origin(hint), typing.get_args(hint)
    if origin is typing.Union:
        misfits = [_misfit(value, a, path) for a in args]
        return None if None in misfits else (path, _describe(hint), value)
    if origin is tuple or origin is list:
        if not isinstance(value, (list, tuple)):
            return path, _describe(hint), value
        items = args[:1] * len(value) if origin is list or args[-1:] == (Ellipsis,) else args
        if len(items) != len(value):
            return path, _describe(hint), value
        return next(filter(None, (_misfit(v, h, f"{path}[{i}]") for i, (v, h) in enumerate(zip(value, items)))),
                    None)
    if origin is dict:
        if not isinstance(value, dict):
            return path, _describe(hint), value
        return next(filter(None, (_misfit(v, args[1], f"{path}[{k!r}]") for k, v in value.items())), None)
    fits = {float: lambda v: isinstance(v, (int, float)) and not isinstance(v, bool),
            int: lambda v: isinstance(v, int) and not isinstance(v, bool),
            bool: lambda v: isinstance(v, bool), str: lambda v: isinstance(v, str),
            type(None): lambda v: v is None}.get(hint)
    return None if fits is None or fits(value) else (path, _describe(hint), value)


def settings_of(cls, data: dict, where: str, warn: Optional[WarnCallback] = None):
    """An instance of the settings dataclass ``cls`` from ``data`` (a :func:`settings_dict`).

    Keys ``cls`` does not have are passed to ``warn`` and ignored; missing ones
    keep their defaults. Values of another type than the class declares, or that
    the class refuses, raise :class:`RunRecordError` naming ``where`` and the setting.
    """
    if not isinstance(data, dict):
        raise RunRecordError(f"{where}: expected a JSON object of settings, found {type(data).__name__}")
    known = {f.name for f in dataclasses.fields(cls)}
    unknown = sorted(set(data) - known)
    if unknown and warn is not None:
        warn(f"{where}: ignored settings this version does not know: {', '.join(unknown)}")
    hints = typing.get_type_hints(cls)
    for name in sorted(set(data) & known):
        misfit = _misfit(data[name], hints[name])
        if misfit is not None:
            path, expected, found = misfit
            raise RunRecordError(f"{where}: setting {name}{path} must be {expected}, found {json.dumps(found)}")
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
    from ..pipeline.config import SECTION_OF, SECTIONS, PipelineConfig  # delays numpy until used

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
    data = with_fixed_range(data)
    return PipelineConfig(**{name: settings_of(cls, data[name], f"{where}, section {name}", warn)
                             for name, cls in SECTIONS.items() if name in data})


def with_fixed_range(sections: dict) -> dict:
    """``{section: {setting: value}}`` where a depth section recorded before the range followed the camera (no
    ``range_from_camera``) keeps its range as recorded: that run searched exactly its near..far."""
    depth = sections.get("depth")
    if not isinstance(depth, dict) or "range_from_camera" in depth:
        return sections
    return {**sections, "depth": {**depth, "range_from_camera": False}}


@dataclass(frozen=True)
class RunSettings:
    """What an earlier run was mapped with: its pipeline and fusion settings and its catalogue folder."""

    config: Any  # pipeline.PipelineConfig
    fusion: Any  # fusion.FusionConfig
    catalogue: Optional[str]  # folder as recorded; None when the record names none
    software: str = ""


def run_settings(record: dict, where: str, warn: Optional[WarnCallback] = None) -> RunSettings:
    """The settings of a run record (:func:`read_run_record`); ``where`` names it in messages."""
    from ..fusion.signs import FusionConfig  # delays OpenCV and numpy until used

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
    _note_contradictions(record, config, where, warn)
    catalogue = record.get("catalogue")
    return RunSettings(config, fusion, str(catalogue) if catalogue else None, str(software))


def _note_contradictions(record: dict, config, where: str, warn: Optional[WarnCallback]) -> None:
    """Tell ``warn`` where the run table's own rows (near_m, …) contradict its pipeline settings: those win, being
    what the run was mapped with (the rows repeat them for readers of the table)."""
    for key in RUN_KEYS:
        if key.setting is None or key.key not in record:
            continue
        section, name = key.setting
        used = getattr(getattr(config, section), name)
        if used is not None and _frozen(record[key.key]) != used:  # None: the classifier's own threshold
            send_warning(warn, f"{where}: its run table says {key.key} {json.dumps(record[key.key])}, its pipeline "
                               f"settings {section}.{name} {json.dumps(used)}; the pipeline "
                               "settings are used (they are what that run was mapped with)")


def load_run_settings(path, warn: Optional[WarnCallback] = None) -> RunSettings:
    """The settings an earlier output at ``path`` was mapped with; :class:`RunRecordError` says what is wrong."""
    return run_settings(read_run_record(path), str(path), warn)


def recorded_config(record: dict):
    """The ``PipelineConfig`` a run was mapped with, from its run table ``record``: the whole recorded settings;
    for a run recorded before they were saved whole, the settings its own rows repeat (near_m, colours, …) over
    the defaults (defaults for anything missing or invalid)."""
    from ..pipeline.classifier_names import CLASSIFIERS  # the pipeline package: delays numpy until used
    from ..pipeline.config import PipelineConfig, with_settings  # delays numpy until used

    try:
        return run_settings(record, "the run table").config
    except RunRecordError:
        pass
    changes: dict = {}
    for key in RUN_KEYS:
        value = record.get(key.key)
        if key.setting is not None and isinstance(value, (int, float, list)) and not isinstance(value, bool):
            section, name = key.setting
            changes.setdefault(section, {})[name] = tuple(value) if isinstance(value, list) else float(value)
    if record.get("classifier") in CLASSIFIERS:  # the strategy that ran, recorded from the first version on
        changes.setdefault("classification", {})["classifier"] = record["classifier"]
    try:
        return with_settings(PipelineConfig(), with_fixed_range(changes))
    except (TypeError, ValueError):
        return PipelineConfig()
