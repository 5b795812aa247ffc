"""The review dock's place in QGIS: a toolbar button and the menu entry "Sign Mapper ▸ Review signs".

The dock and its controller are built the first time the action is checked, so
starting QGIS costs nothing and a missing OpenCV only matters when reviewing.
The controller follows layers only while the dock is visible.
"""

from __future__ import annotations

from pathlib import Path

from qgis.core import Qgis
from qgis.PyQt.QtCore import Qt
from qgis.PyQt.QtGui import QIcon
from qgis.PyQt.QtWidgets import QAction

MENU = "&Sign Mapper"
ICON = Path(__file__).resolve().parents[1] / "icon.svg"


class ReviewUi:
    """Owns the review action, dock and controller; ``unload`` removes all of them."""

    def __init__(self, iface, ask_drive_folder=None):
        self.iface = iface
        self.ask_drive_folder = ask_drive_folder
        self.dock = None
        self.controller = None
        self.action = QAction(QIcon(str(ICON)), "Review signs", iface.mainWindow())
        self.action.setObjectName("SignMapperReviewSigns")
        self.action.setCheckable(True)
        self.action.setToolTip("Sign Mapper: review detected signs, decide on doubtful ones and add missed signs")
        self.action.toggled.connect(self.set_visible)
        iface.addToolBarIcon(self.action)
        iface.addPluginToMenu(MENU, self.action)

    def set_visible(self, visible: bool) -> None:
        if visible and self.dock is None and not self._create_dock():
            self._set_checked(False)
            return
        if self.dock is not None:
            self.dock.setVisible(visible)

    def _create_dock(self) -> bool:
        try:
            from ..ui.review_dock import ReviewDock
            from .controller import ReviewController
        except ImportError as exc:  # e.g. OpenCV missing: say so instead of a traceback
            self.iface.messageBar().pushMessage("Sign Mapper", f"The review dock cannot start: {exc}", Qgis.Warning, 0)
            return False
        self.dock = ReviewDock(self.iface.mainWindow())
        self.controller = ReviewController(self.iface, self.dock, self.ask_drive_folder)
        self.dock.visibilityChanged.connect(self._visibility_changed)
        self.iface.addDockWidget(Qt.RightDockWidgetArea, self.dock)
        return True

    def _set_checked(self, checked: bool) -> None:
        self.action.blockSignals(True)
        self.action.setChecked(checked)
        self.action.blockSignals(False)

    def _visibility_changed(self, visible: bool) -> None:
        """Closing the dock with its own button unchecks the action; only a visible dock follows layers."""
        self._set_checked(visible)
        if visible:
            self.controller.activate()
        else:
            self.controller.deactivate()

    def unload(self) -> None:
        self.action.toggled.disconnect(self.set_visible)
        self.iface.removeToolBarIcon(self.action)
        self.iface.removePluginMenu(MENU, self.action)
        if self.controller is not None:
            self.controller.shutdown()
            self.controller = None
        if self.dock is not None:
            self.dock.visibilityChanged.disconnect(self._visibility_changed)
            self.iface.removeDockWidget(self.dock)
            self.dock.deleteLater()
            self.dock = None
        self.action.deleteLater()
