"""What a mapping run is set up with: the catalogue, the pipeline and fusion settings, checked before any work.

The one way every front end assembles a run (the ``mapsigns`` algorithm, ``python -m signmapper_core.map``):
the settings recorded by an earlier output when one is given, else the defaults; the front end's own choices
over them; then the checks a run would otherwise fail late on (depth range, excluded ids, the classifier's
model). Errors name the input in the front end's words (``labels``).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any, Mapping, Optional

from ..catalogue import load_catalogue  # the whole run needs OpenCV anyway
from ..catalogue.model import Catalogue
from ..errors import InputFileError
from ..fusion.signs import FusionConfig
from ..output.run_settings import load_run_settings
from ..output.run_table import RunRecordError
from ..pipeline.classifiers import ClassifierError, classifier_for
from ..pipeline.config import PipelineConfig, default, with_settings
from ..progress import WarnCallback

Setting = tuple  # (section, name) of a PipelineConfig setting
NEAR, FAR = ("depth", "near_m"), ("depth", "far_m")
RANGE_FROM_CAMERA, REACH = ("depth", "range_from_camera"), ("depth", "reach_m")
EXCLUDE = ("classification", "exclude")
# what the messages call each input unless the front end names it: keys of ``labels``
INPUT_WORDS = {"settings_from": "Settings from an earlier output", "catalogue": "Template catalogue",
               "near_m": "Near limit", "far_m": "Far limit", "exclude": "Sign types to exclude",
               "classifier": "Classifier", "colours": "Sign colours"}


class RunSetupError(ValueError):
    """A run cannot be set up as asked; the message names the input and what is wrong with it."""


@dataclass(frozen=True)
class RunSetup:
    catalogue: Catalogue
    config: PipelineConfig
    fusion: FusionConfig


def is_default(setting: Setting, value: Any) -> bool:
    """Whether ``value`` is the setting's default (colours in any order)."""
    if setting == ("colour", "colours"):
        return set(value) == set(default(*setting))
    return value == default(*setting)


def assemble_run(choices: Mapping[Setting, Any], settings_from=None, catalogue_folder=None,
                 defaults_yield: bool = False, warn: Optional[WarnCallback] = None,
                 labels: Optional[Mapping[str, str]] = None) -> RunSetup:
    """The catalogue and settings of a run, checked.

    ``choices``: {(section, name): value} chosen by the front end, over the settings recorded in the output
    ``settings_from`` (a GeoPackage path; notes on its record go to ``warn``) or the defaults.
    ``defaults_yield``: a choice equal to its default yields to the record (a dialog always gives every value;
    only the ones a person changed should win). ``catalogue_folder``: None = the record's, else the bundled one.
    Raises :class:`RunSetupError` naming the input (``labels`` maps the keys of :data:`INPUT_WORDS` to the front
    end's words).
    """
    words = {**INPUT_WORDS, **(labels or {})}
    earlier = None
    if settings_from:
        try:
            earlier = load_run_settings(settings_from, warn)
        except RunRecordError as exc:
            raise RunSetupError(f"{words['settings_from']}: {exc}") from None
    folder = catalogue_folder
    if folder is None and earlier is not None and earlier.catalogue:
        folder = earlier.catalogue
        if not Path(folder).is_dir():
            raise RunSetupError(f"{words['settings_from']}: its catalogue folder {folder} does not exist here; "
                                f"set '{words['catalogue']}'")
    try:
        catalogue = load_catalogue(folder)
    except (InputFileError, OSError, ValueError) as exc:  # the catalogue's own errors name the file
        raise RunSetupError(f"{words['catalogue']}: {exc}") from None
    if earlier is not None and defaults_yield:
        choices = {k: v for k, v in choices.items() if not is_default(k, v)}
    base = earlier.config if earlier is not None else PipelineConfig()
    choices = fixed_range(choices)
    _check_choices(choices, base, catalogue, words)
    changes: dict = {}
    for (section, name), value in choices.items():
        changes.setdefault(section, {})[name] = value
    try:
        config = with_settings(base, changes)
    except ValueError as exc:
        raise RunSetupError(str(exc)) from None
    try:
        classifier_for(catalogue, config)  # a missing or broken model is said before any work
    except ClassifierError as exc:
        raise RunSetupError(f"{words['classifier']}: {exc}") from None
    return RunSetup(catalogue, config, earlier.fusion if earlier is not None else FusionConfig())


def fixed_range(choices: Mapping[Setting, Any]) -> dict:
    """``choices`` where a near or far limit given (not None) fixes the depth range: no longer from the camera,
    no reach beyond it; a limit given as None is not a choice."""
    out = {k: v for k, v in choices.items() if not (k in (NEAR, FAR) and v is None)}
    if NEAR in out or FAR in out:
        out.update({RANGE_FROM_CAMERA: False, REACH: None})
    return out


def _check_choices(choices: Mapping[Setting, Any], base: PipelineConfig, catalogue, words: Mapping[str, str]):
    near, far = choices.get(NEAR, base.depth.near_m), choices.get(FAR, base.depth.far_m)
    if near >= far:
        raise RunSetupError(f"{words['near_m']} ({near:g} m) must be less than {words['far_m']} ({far:g} m).")
    if ("colour", "colours") in choices and not choices[("colour", "colours")]:
        raise RunSetupError("Choose at least one sign colour to detect.")
    unknown = [i for i in choices.get(EXCLUDE, ()) if i not in catalogue]
    if unknown:
        raise RunSetupError(f"{words['exclude']}: {', '.join(unknown)} not in the catalogue")
