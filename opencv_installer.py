"""One-click installation of missing modules (OpenCV) into the user's site-packages of the Python QGIS runs.

The message bar offers *Install…*; a confirmation shows the exact pip command;
pip runs in a QProcess (QGIS stays responsive) and everything it prints goes to
the *Sign Mapper* tab of the log panel and to a log file in the QGIS profile.
"""

from __future__ import annotations

import importlib
from pathlib import Path
from typing import Callable, List, Optional

from qgis.core import Qgis, QgsApplication, QgsMessageLog
from qgis.PyQt.QtCore import QProcess
from qgis.PyQt.QtWidgets import QMessageBox, QPushButton

from .dependencies import add_install_locations, install_hint, missing_modules, pip_install_command

LOG_TAG = "Sign Mapper"


def log_file() -> Path:
    return Path(QgsApplication.qgisSettingsDirPath()) / "sign_mapper_pip.log"


def ask_with_dialog(parent, command: List[str]) -> bool:
    text = ("Sign Mapper will install its missing modules for the Python that runs QGIS, into your user "
            "site-packages (nothing system-wide):\n\n" + " ".join(command) + "\n\nThis downloads from the Python "
            f"package index and takes a minute. What pip prints is logged to {log_file()}.")
    answer = QMessageBox.question(parent, "Sign Mapper: install OpenCV?", text, QMessageBox.Yes | QMessageBox.No,
                                  QMessageBox.No)
    return answer == QMessageBox.Yes


class ModuleInstaller:
    """Offers, confirms, runs and logs the pip command; ``confirm(command) -> bool`` is injectable for tests."""

    def __init__(self, iface, confirm: Optional[Callable[[List[str]], bool]] = None):
        self.iface = iface
        self.confirm = confirm or (lambda command: ask_with_dialog(iface.mainWindow(), command))
        self.process: Optional[QProcess] = None
        self.command: List[str] = []
        self.output: List[str] = []

    def offer(self, missing: List[str]) -> None:
        """A message bar entry with the install hint and an *Install…* button."""
        bar = self.iface.messageBar()
        item = bar.createMessage(LOG_TAG, install_hint(missing))
        button = QPushButton("Install…")
        button.clicked.connect(lambda: self.install(missing))
        item.layout().addWidget(button)
        bar.pushWidget(item, Qgis.Warning, 0)

    def install(self, missing: List[str]) -> bool:
        """Ask, then start pip; False when the user declined or pip is already running."""
        if self.process is not None:
            return False
        self.command = pip_install_command(missing)
        if not self.confirm(self.command):
            self._log(f"Installation declined: {' '.join(self.command)}")
            return False
        self.output = []
        self._log(f"Running: {' '.join(self.command)}")
        self.process = QProcess()
        self.process.setProcessChannelMode(QProcess.MergedChannels)
        self.process.readyReadStandardOutput.connect(self._read)
        self.process.finished.connect(self._finished)
        self.process.errorOccurred.connect(self._failed_to_start)
        self.process.start(self.command[0], self.command[1:])
        return True

    def _read(self) -> None:
        text = bytes(self.process.readAllStandardOutput()).decode("utf-8", "replace")
        for line in text.splitlines():
            if line.strip():
                self.output.append(line)
                self._log(line)

    def _failed_to_start(self, error) -> None:
        if error == QProcess.FailedToStart:
            self._done(False, f"Could not start {self.command[0]}: is it the Python QGIS runs, with pip?")

    def _finished(self, code: int, _status) -> None:
        self._read()
        if code != 0:
            self._done(False, f"pip failed (exit {code}); see the Sign Mapper log or {log_file()}")
            return
        add_install_locations()
        importlib.invalidate_caches()
        still = missing_modules()
        self._done(not still, "Installed. Restart QGIS to use Sign Mapper's algorithms." if not still else
                   f"pip finished but {', '.join(still)} is still not importable; restart QGIS and check the log")

    def _done(self, ok: bool, message: str) -> None:
        self._log(message, Qgis.Info if ok else Qgis.Critical)
        if self.iface is not None:
            self.iface.messageBar().pushMessage(LOG_TAG, message, Qgis.Success if ok else Qgis.Critical, 0)
        self.process = None

    def _log(self, text: str, level=Qgis.Info) -> None:
        QgsMessageLog.logMessage(text, LOG_TAG, level)
        try:
            with log_file().open("a", encoding="utf-8") as handle:
                handle.write(text + "\n")
        except OSError:
            pass
