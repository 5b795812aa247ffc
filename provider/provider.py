"""The Processing provider ``signmapper`` that lists Sign Mapper's algorithms."""

from __future__ import annotations

from pathlib import Path

from qgis.core import Qgis, QgsMessageLog, QgsProcessingProvider
from qgis.PyQt.QtGui import QIcon

from ..algorithms import algorithm_classes

PROVIDER_ID = "signmapper"
ICON_PATH = Path(__file__).resolve().parents[1] / "icon.svg"


class SignMapperProvider(QgsProcessingProvider):
    """Registers every algorithm of :mod:`..algorithms`."""

    def id(self):
        return PROVIDER_ID

    def name(self):
        return "Sign Mapper"

    def longName(self):  # noqa: N802
        return "Sign Mapper: traffic sign inventory from stereo mobile mapping"

    def icon(self):
        return QIcon(str(ICON_PATH))

    def loadAlgorithms(self):  # noqa: N802
        for cls in algorithm_classes(on_error=self.report_broken_algorithm):
            self.addAlgorithm(cls())

    @staticmethod
    def report_broken_algorithm(module: str, exc: Exception) -> None:
        QgsMessageLog.logMessage(f"Algorithm module '{module}' failed to load: {exc!r}", "Sign Mapper",
                                 Qgis.Critical)
