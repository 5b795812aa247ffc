"""Shared idioms of Sign Mapper's algorithms: groups, help, dependency check, feedback."""

from __future__ import annotations

import html
from pathlib import Path

from qgis.core import (
    QgsProcessingAlgorithm,
    QgsProcessingException,
    QgsProcessingParameterDefinition,
    QgsProcessingParameterFile,
)
from qgis.PyQt.QtCore import QCoreApplication
from qgis.PyQt.QtGui import QIcon

from ..dependencies import install_hint, missing_modules

ICONS = Path(__file__).resolve().parents[1] / "icons"


class SignMapperAlgorithm(QgsProcessingAlgorithm):
    """Base class: subclasses set NAME, DISPLAY_NAME, GROUP_ID, HELP and add parameters."""

    NAME = ""
    DISPLAY_NAME = ""
    GROUP_ID = "mapping"
    HELP = ""
    ICON = ""  # file in icons/

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
        """The algorithm's help followed by every parameter's own help text."""
        lines = [self.help_html(self.HELP), "", "<b>Parameters</b>", "<ul>"]
        for param in self.parameterDefinitions():
            help_text = param.help() if hasattr(param, "help") else ""
            lines.append(f"<li><b>{html.escape(param.description())}</b>: {html.escape(help_text, quote=False)}</li>")
        lines.append("</ul>")
        return "\n".join(lines)

    def help_html(self, text: str) -> str:
        """Plain help text as the HTML the help panel shows: 'depth/<id>.npy' must not lose '<id>' as a tag."""
        return html.escape(self.tr(text), quote=False)

    def add_parameter(self, param, help_text: str, advanced: bool = False):
        """Add a parameter with its help text (shown in the dialog and in shortHelpString).

        ``advanced`` parameters are folded under "Advanced Parameters" in the dialog.
        """
        param.setHelp(self.tr(help_text))
        if advanced:
            param.setFlags(param.flags() | QgsProcessingParameterDefinition.FlagAdvanced)
        self.addParameter(param)
        return param

    def add_language_parameter(self, name: str, first: str, help_text: str, advanced: bool = False):
        """The output language, offered by name after ``first`` (what an algorithm does when none is chosen)."""
        from qgis.core import QgsProcessingParameterEnum

        from ..signmapper_core.output_schema import LANGUAGE_NAMES, LANGUAGES

        options = [first] + [LANGUAGE_NAMES[code] for code in LANGUAGES]
        return self.add_parameter(QgsProcessingParameterEnum(name, self.tr("Language of the output"),
                                                             options=options, defaultValue=0), help_text, advanced)

    def chosen_language(self, parameters, name: str, context):
        """The language code chosen, None for the first option (the algorithm's own default)."""
        from ..signmapper_core.output_schema import LANGUAGES

        choice = self.parameterAsEnum(parameters, name, context)
        return LANGUAGES[choice - 1] if choice > 0 else None

    def add_drive_parameter(self, name: str):
        """The drive folder input every drive-reading algorithm starts with."""
        return self.add_parameter(
            QgsProcessingParameterFile(name, self.tr("Drive folder"), behavior=QgsProcessingParameterFile.Folder),
            "Folder of one drive in the stereo-drive/1 layout: drive.json, poses.csv, left/ and right/ or depth/.",
        )

    def checkParameterValues(self, parameters, context):  # noqa: N802
        """QGIS's own checks, then ours (:meth:`check_inputs`), before the run starts."""
        ok, message = super().checkParameterValues(parameters, context)
        if not ok:
            return ok, message
        try:
            self.check_inputs(parameters, context)
        except QgsProcessingException as exc:
            return False, str(exc)
        return True, ""

    def check_inputs(self, parameters, context) -> None:
        """QgsProcessingException naming what is wrong: the outputs (no folder, writable, not an input,
        ``output_paths``), and in algorithms that read their inputs up front, those too."""
        self.check_outputs(parameters, context)

    def check_outputs(self, parameters, context) -> None:
        """The output check of ``checkParameterValues`` at the start of a run (models may skip the former)."""
        from .output_paths import output_problem

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
    logged as non-fatal errors.
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
        self.feedback.reportError(message, fatalError=False)
