"""A QgsProcessingFeedback that keeps everything an algorithm tells the user, for tests to read."""

from qgis.core import QgsProcessingFeedback


class Recorder(QgsProcessingFeedback):
    """Log lines, warnings and errors in ``lines`` (warnings also in ``warnings``), progress in ``steps``."""

    def __init__(self):
        super().__init__()
        self.lines, self.warnings, self.steps = [], [], []
        self.progressChanged.connect(lambda p: self.steps.append(p))

    def reportError(self, error, fatalError=False):  # noqa: N802, N803
        self.lines.append(error)

    def pushWarning(self, warning):  # noqa: N802
        self.lines.append(warning)
        self.warnings.append(warning)

    def pushInfo(self, info):  # noqa: N802
        self.lines.append(info)

    def text(self) -> str:
        return "\n".join(self.lines)
