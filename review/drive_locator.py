"""Finding a run's drive folder, asking once when it moved and remembering the answer.

The GeoPackage records the absolute folder it was mapped from (``signmapper_run``,
key ``drive``). Drives get copied between disks, so a missing folder is asked for
once and the answer is kept in QgsSettings under the old path.
"""

from __future__ import annotations

import hashlib
from pathlib import Path
from typing import Callable, Dict, Optional

from qgis.core import QgsSettings

SETTINGS_GROUP = "sign_mapper/review/moved_drives"
AskFolder = Callable[[str], Optional[str]]  # old path -> new path or None (cancelled)


def ask_with_dialog(old_path: str) -> Optional[str]:
    """Ask for a moved drive folder with a folder dialog."""
    from qgis.PyQt.QtWidgets import QFileDialog

    answer = QFileDialog.getExistingDirectory(
        None, f"Sign Mapper: drive folder {old_path} was not found — where is it now?", str(Path(old_path).parent)
    )
    return answer or None


def is_drive_folder(path) -> bool:
    return bool(path) and (Path(path) / "drive.json").is_file()


class DriveLocator:
    """Resolves recorded drive folders and opens (and caches) the drives."""

    def __init__(self, ask: Optional[AskFolder] = None, settings: Optional[QgsSettings] = None):
        self.ask = ask or ask_with_dialog
        self.settings = settings or QgsSettings()
        self._asked = set()  # recorded paths already asked for in this session
        self._drives: Dict[str, object] = {}

    @staticmethod
    def settings_key(old_path: str) -> str:
        digest = hashlib.sha1(str(old_path).encode("utf-8")).hexdigest()[:16]
        return f"{SETTINGS_GROUP}/{digest}"

    def remembered(self, old_path: str) -> Optional[str]:
        value = self.settings.value(self.settings_key(old_path), "")
        return value if is_drive_folder(value) else None

    def resolve(self, recorded: str) -> Optional[str]:
        """The folder to read the drive from, or None if it is gone and the user gave none."""
        if not recorded:
            return None
        if is_drive_folder(recorded):
            return recorded
        remembered = self.remembered(recorded)
        if remembered:
            return remembered
        if recorded in self._asked:
            return None
        self._asked.add(recorded)
        answer = self.ask(recorded)
        if not is_drive_folder(answer):
            return None
        self.settings.setValue(self.settings_key(recorded), str(answer))
        return str(answer)

    def open(self, recorded: str):
        """The opened Drive of a recorded folder (None if unresolved); errors of a broken drive propagate."""
        folder = self.resolve(recorded)
        if folder is None:
            return None
        if folder not in self._drives:
            from ..signmapper_core.drive.reader import open_drive  # delays numpy until used

            # image headers are not checked here: a long drive would block the GUI; a bad image shows when loaded
            self._drives[folder] = open_drive(folder, check_images=False)
        return self._drives[folder]
