"""Shared idioms of Sign Mapper's algorithms: groups, help, dependency check, safe outputs, feedback.

Every algorithm implements :meth:`SignMapperAlgorithm.process`; the base class's
``processAlgorithm`` checks the paths, runs it inside :class:`.run_outputs.RunOutputs`
(every file output written whole or not at all) and turns the core's output and
file errors into messages.
"""

from __future__ import annotations

import html
from pathlib import Path

from qgis.core import (
    Qgis,
    QgsApplication,
    QgsProcessingAlgorithm,
    QgsProcessingException,
    QgsProcessingParameterDefinition,
    QgsProcessingParameterEnum,
    QgsProcessingParameterFile,
)
from qgis.PyQt.QtCore import QCoreApplication
from qgis.PyQt.QtGui import QIcon

from ..dependencies import install_hint, missing_modules
from ..signmapper_core.errors import OutputFileError
from ..signmapper_core.output.file_paths import shown
from ..signmapper_core.output.schema import LANGUAGE_NAMES, LANGUAGES
from .output_paths import output_problem, path_problems
from .run_outputs import RunOutputs

ICONS = Path(__file__).resolve().parents[1] / "icons"
ENUM_NAMES = "signmapper_names"   # metadata of an enum parameter: the names its options are chosen by
OUTPUTS_HELP = (
    "<p><b>Outputs</b> are written whole or not at all: a failed or cancelled run leaves earlier files as they were, "
    "and a second run writing the same file at the same time is refused. A layer written into an existing "
    "GeoPackage keeps the file's other layers; a layer of the same name is replaced only when Sign Mapper wrote "
    "it. To add a layer under a name of your own, choose 'Save to GeoPackage…' or give FILE.gpkg|layername=NAME.</p>"
)


class SignMapperAlgorithm(QgsProcessingAlgorithm):
    """Base class: subclasses set NAME, DISPLAY_NAME, GROUP_ID, HELP, add parameters and implement
    :meth:`process`."""

    NAME = ""
    DISPLAY_NAME = ""
    GROUP_ID = "mapping"
    HELP = ""
    ICON = ""  # file in icons/
    OWNED_LAYERS: dict = {}  # GeoPackage file output -> the layers it (re)writes; the file's others are kept
    run_outputs = None  # the RunOutputs of the run in progress

    GROUPS = {"mapping": "Mapping", "tools": "Tools", "quality": "Quality", "inventory": "Inventory"}

    def tr(self, text):
        return QCoreApplication.translate("SignMapper", text)

    def createInstance(self):  # noqa: N802
        return type(self)()

    def name(self):
        return self.NAME

    def icon(self):
        return QIcon(str(ICONS / self.ICON)) if self.ICON else super().icon()

    def displayName(self):  # noqa: N802
        return self.tr(self.DISPLAY_NAME)

    def group(self):
        return self.tr(self.GROUPS[self.GROUP_ID])

    def groupId(self):  # noqa: N802
        return self.GROUP_ID

    def shortHelpString(self):  # noqa: N802
        """The algorithm's help followed by every parameter's own help text and how outputs are written."""
        lines = [self.help_html(self.HELP), "", "<b>Parameters</b>", "<ul>"]
        for param in self.parameterDefinitions():
            help_text = param.help() if hasattr(param, "help") else ""
            lines.append(f"<li><b>{html.escape(param.description())}</b>: {html.escape(help_text, quote=False)}</li>")
        lines.append("</ul>")
        if self.destinationParameterDefinitions():
            lines.append(self.tr(OUTPUTS_HELP))
        return "\n".join(lines)

    def help_html(self, text: str) -> str:
        """Plain help text as the HTML the help panel shows: 'depth/<id>.npy' must not lose '<id>' as a tag."""
        return html.escape(self.tr(text), quote=False)

    def add_parameter(self, param, help_text: str, advanced: bool = False):
        """Add a parameter with its help text (shown in the dialog and in shortHelpString).

        ``advanced`` parameters are folded under "Advanced Parameters" in the dialog.
        """
        text = self.tr(help_text)
        if isinstance(param, QgsProcessingParameterEnum):
            several = ", several separated by commas" if param.allowMultiple() else ""
            text += f" By name in qgis_process: {', '.join(enum_names(param))} (or the option's number{several})."
        param.setHelp(text)
        if advanced:
            param.setFlags(param.flags() | QgsProcessingParameterDefinition.FlagAdvanced)
        self.addParameter(param)
        return param

    def named_enum(self, name: str, description: str, choices, **kwargs) -> QgsProcessingParameterEnum:
        """An enum parameter chosen by number or by name (:func:`enum_numbers`): ``choices`` are (name, title)
        pairs, the title shown in the dialog, or names shown as they are. ``kwargs`` go to QGIS (defaultValue,
        allowMultiple, optional)."""
        pairs = [(choice, choice) if isinstance(choice, str) else choice for choice in choices]
        param = QgsProcessingParameterEnum(name, self.tr(description), options=[self.tr(t) for _, t in pairs],
                                           **kwargs)
        param.setMetadata({**param.metadata(), ENUM_NAMES: [n for n, _ in pairs]})
        return param

    def add_language_parameter(self, name: str, first: str, help_text: str, advanced: bool = False):
        """The output language, offered by name after ``first`` (what an algorithm does when none is chosen)."""
        choices = [("auto", first)] + [(code, LANGUAGE_NAMES[code]) for code in LANGUAGES]
        return self.add_parameter(self.named_enum(name, "Language of the output", choices, defaultValue=0),
                                  help_text, advanced)

    def chosen_language(self, parameters, name: str, context):
        """The language code chosen, None for the first option (the algorithm's own default)."""
        code = self.chosen_name(parameters, name, context)
        return None if code == "auto" else code

    def chosen_name(self, parameters, name: str, context) -> str:
        """The name (:meth:`named_enum`) of the option chosen for the enum parameter ``name``."""
        return enum_names(self.parameterDefinition(name))[self.parameterAsEnum(parameters, name, context)]

    def add_drive_parameter(self, name: str):
        """The drive folder input every drive-reading algorithm starts with."""
        return self.add_parameter(
            QgsProcessingParameterFile(name, self.tr("Drive folder"), behavior=QgsProcessingParameterFile.Folder),
            "Folder of one drive in the stereo-drive/1 layout: drive.json, poses.csv, left/ and right/ or depth/.",
        )

    def checkParameterValues(self, parameters, context):  # noqa: N802
        """QGIS's own checks, then ours (:meth:`check_inputs`), before the run starts; enum options given by name
        are checked here (QGIS's own check wants numbers, so it sees them as numbers)."""
        try:
            parameters = enum_numbers(self, parameters)
        except QgsProcessingException as exc:
            return False, str(exc)
        ok, message = super().checkParameterValues(parameters, context)
        if not ok:
            return ok, message

        try:
            problem = path_problems(self, parameters, context)  # first: Python's own checks raise on such a path
            if problem:
                return False, problem
            self.check_inputs(parameters, context)
        except QgsProcessingException as exc:
            return False, str(exc)
        except OSError as exc:  # a file the checks read: named, never a traceback (qgis_process would abort)
            return False, file_error(exc)
        return True, ""

    def processAlgorithm(self, parameters, context, feedback):  # noqa: N802
        """:meth:`process` with its file outputs written as partial outputs, moved in only when it returns."""

        try:
            self.check_outputs(parameters, context)
            self.run_outputs = outputs = RunOutputs(self, parameters, context)
        except BaseException as exc:
            raise self.user_error(exc) from None
        try:
            return outputs.commit(self.process(parameters, context, feedback))
        except BaseException as exc:
            unchanged = outputs.unchanged()
            outputs.discard()
            raise self.user_error(exc, f". Nothing written{unchanged}.") from None
        finally:
            self.run_outputs = None

    @staticmethod
    def user_error(exc: BaseException, written: str = "") -> BaseException:
        """What a run that failed with ``exc`` tells the user: a QgsProcessingException naming the file for an
        output or file error (``written``: what became of the outputs), any other exception as it is.

        In ``qgis_process`` the message is shown once: it echoes every error of the message log to the console,
        where Processing logs a failed run's error twice more after printing it. With ``--json`` it prints no
        feedback of a failed run, so there the message goes to the log once, as the only one echoed.
        """

        if isinstance(exc, OutputFileError):
            exc = QgsProcessingException(f"{exc}{written}")
        elif isinstance(exc, OSError) and exc.filename:
            exc = QgsProcessingException(f"{file_error(exc)}{written}")
        if isinstance(exc, QgsProcessingException) and QgsApplication.platform() == "qgis_process":
            log = QgsApplication.messageLog()
            if "--json" in QCoreApplication.arguments():
                log.logMessage(str(exc), "Processing", Qgis.Critical)
            log.blockSignals(True)  # the process ends with this error
        return exc

    def process(self, parameters, context, feedback) -> dict:
        """The algorithm's work (what ``processAlgorithm`` is elsewhere); its outputs are committed after it."""
        raise NotImplementedError

    def parameterAsEnum(self, parameters, name, context):  # noqa: N802 - QGIS's name
        """QGIS's option number, also of an option given by name (:func:`enum_numbers`)."""
        return super().parameterAsEnum(enum_numbers(self, parameters, name), name, context)

    def parameterAsEnums(self, parameters, name, context):  # noqa: N802 - QGIS's name
        """QGIS's option numbers, also of options given by name (comma-separated in qgis_process)."""
        return super().parameterAsEnums(enum_numbers(self, parameters, name), name, context)

    def parameterAsSink(self, parameters, name, context, *args, **kwargs):  # noqa: N802 - QGIS's name
        """QGIS's sink; during a run, for an output given as a file, one that writes the run's partial output and
        raises when a write fails (:mod:`.run_outputs`). The id returned is the final layer's."""
        def create(params):
            return super(SignMapperAlgorithm, self).parameterAsSink(params, name, context, *args, **kwargs)

        if self.run_outputs is None:
            return create(parameters)
        return self.run_outputs.sink(name, parameters, create)

    def parameterAsFileOutput(self, parameters, name, context):  # noqa: N802 - QGIS's name
        """QGIS's file; during a run, for an output given as a file, where the run's partial output is written
        (committed under the file's name when the run succeeds)."""
        path = self.run_outputs.file_output(name) if self.run_outputs is not None else None
        return path if path is not None else super().parameterAsFileOutput(parameters, name, context)

    def output_target(self, parameters, name, context) -> str:
        """The file an output becomes once the run has succeeded (for messages and results)."""
        target = self.run_outputs.target(name) if self.run_outputs is not None else None
        return str(target) if target is not None else super().parameterAsFileOutput(parameters, name, context)

    def check_inputs(self, parameters, context) -> None:
        """QgsProcessingException naming what is wrong: the outputs (no folder, writable, not an input,
        ``output_paths``), and in algorithms that read their inputs up front, those too."""
        self.check_outputs(parameters, context)

    def check_outputs(self, parameters, context) -> None:
        """The output check of ``checkParameterValues`` at the start of a run (models may skip the former); done
        once per run: once the run holds its outputs, another check would find them busy."""

        if self.run_outputs is not None:
            return
        problem = output_problem(self, parameters, context)
        if problem:
            raise QgsProcessingException(problem)

    def require_dependencies(self):
        """Raise a clear QgsProcessingException naming what to install when OpenCV & co. are missing."""
        missing = missing_modules()
        if missing:
            raise QgsProcessingException(install_hint(missing))


class CoreFeedback:
    """The core's progress protocol (``signmapper_core.progress``) on a QgsProcessingFeedback.

    The core reports fractions 0..1 of its operation; they fill ``span`` percent
    of the algorithm's bar from ``start``. Cancel is the feedback's; warnings are
    warnings (``qgis_process`` prints them as WARNING, never as ERROR).
    """

    def __init__(self, feedback, start: float = 0.0, span: float = 100.0):
        self.feedback, self.start, self.span = feedback, start, span

    def progress(self, fraction: float, message: str = "") -> None:
        self.feedback.setProgress(self.start + self.span * fraction)
        if message:
            self.feedback.setProgressText(message)

    def is_cancelled(self) -> bool:
        return self.feedback.isCanceled()

    def warn(self, message: str) -> None:
        self.feedback.pushWarning(message)


def enum_names(param) -> list[str]:
    """The names an enum parameter's options are chosen by: those :meth:`SignMapperAlgorithm.named_enum` gave, else
    the options' texts."""
    return list(param.metadata().get(ENUM_NAMES) or param.options())


def _option_number(param, value):
    """The option number of one value: a number (or its text) as it is, a name or an option's text (any case) as
    its number; anything else is QGIS's business."""
    if not isinstance(value, str) or not value.strip() or value.strip().lstrip("-").isdigit():
        return value
    wanted = value.strip().casefold()
    for choices in (enum_names(param), param.options()):
        folded = [choice.casefold() for choice in choices]
        if wanted in folded:
            return folded.index(wanted)
    raise QgsProcessingException(
        f"{param.name()} ({param.description()}): {value.strip()!r} is not one of its options; give one of "
        f"{', '.join(enum_names(param))}, or the option's number 0 to {len(param.options()) - 1}")


def enum_numbers(alg, parameters: dict, only: str | None = None) -> dict:
    """``parameters`` with every enum option given by name (case-insensitive; a comma-separated list for a
    multiple choice) replaced by its number, as QGIS wants it; only parameter ``only`` when given.
    QgsProcessingException naming the parameter and its valid names for a name it does not have."""
    numbered = dict(parameters or {})
    for param in alg.parameterDefinitions():
        if not isinstance(param, QgsProcessingParameterEnum) or (only and param.name() != only):
            continue
        value = numbered.get(param.name())
        if isinstance(value, str) and param.allowMultiple() and "," in value:
            value = [part for part in value.split(",") if part.strip()]
        if isinstance(value, (list, tuple)):
            numbered[param.name()] = [_option_number(param, v) for v in value]
        elif isinstance(value, str):
            numbered[param.name()] = _option_number(param, value)
    return numbered


def file_error(exc: OSError) -> str:
    """An OSError as a message naming the file (shortened when very long) and what the system said."""

    where = f"{shown(exc.filename)}: " if exc.filename else ""
    return f"{where}{exc.strerror or exc}"
