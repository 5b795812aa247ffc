"""A Sign Mapper dock's place in QGIS: a checkable toolbar button and an entry in the "Sign Mapper" menu.

The dock and its controller are built the first time the action is checked, so
starting QGIS costs nothing and a missing OpenCV only matters when the dock is
opened. The controller follows layers only while the dock is visible; closing
the dock with its own button unchecks the action. ``unload`` removes it all.
"""

from __future__ import annotations

from pathlib import Path

from qgis.core import Qgis
from qgis.PyQt.QtCore import Qt
from qgis.PyQt.QtGui import QIcon
from qgis.PyQt.QtWidgets import QAction

MENU = "&Sign Mapper"


class DockUi:
    """Owns one dock's action, the dock and its controller. Subclasses name the action and build the two."""

    text = ""  # the action's text
    object_name = ""
    tooltip = ""
    icon: Path
    area = Qt.RightDockWidgetArea
    height = 0  # px the dock claims beside the other docks of its area (0: what Qt gives it)
    what = "The dock"  # for "... cannot start"

    def __init__(self, iface):
        self.iface = iface
        self.dock = None
        self.controller = None
        self.action = QAction(QIcon(str(self.icon)), self.text, iface.mainWindow())
        self.action.setObjectName(self.object_name)
        self.action.setCheckable(True)
        self.action.setToolTip(self.tooltip)
        self.action.toggled.connect(self.set_visible)
        iface.addToolBarIcon(self.action)
        iface.addPluginToMenu(MENU, self.action)

    def build(self):
        """(dock, controller); ImportError when something they need is missing (e.g. OpenCV)."""
        raise NotImplementedError

    def set_visible(self, visible: bool) -> None:
        new = visible and self.dock is None
        if new and not self._create_dock():
            self._set_checked(False)
            return
        if self.dock is not None:
            self.dock.setVisible(visible)
        if new and self.height:
            claim_height(self.iface.mainWindow(), self.dock, self.height)

    def _create_dock(self) -> bool:
        try:
            self.dock, self.controller = self.build()
        except ImportError as exc:  # say so instead of a traceback
            self.iface.messageBar().pushMessage("Sign Mapper", f"{self.what} cannot start: {exc}", Qgis.Warning, 0)
            return False
        self.dock.visibilityChanged.connect(self._visibility_changed)
        self.iface.addDockWidget(self.area, self.dock)
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


def claim_height(window, dock, height: int) -> None:
    """Give ``dock`` ``height`` px (or what the window has) when it shares its area with other docks, and them
    the rest: Qt splits an area evenly, which left the review 284 px beside QGIS's Layers panel."""
    from qgis.PyQt.QtWidgets import QApplication, QDockWidget

    QApplication.processEvents()  # the dock is laid out in its area before it is resized
    area = window.dockWidgetArea(dock)
    if area == Qt.NoDockWidgetArea:  # not in the window's layout (floating, or a test's stand-in window)
        return
    others = [d for d in window.findChildren(QDockWidget) if d is not dock and d.isVisible() and not d.isFloating()
              and window.dockWidgetArea(d) == area and not window.tabifiedDockWidgets(d)]
    total = dock.height() + sum(d.height() for d in others)
    rest = max(total - height, 0) // max(len(others), 1)
    window.resizeDocks([dock] + others, [height] + [rest] * len(others), Qt.Vertical)
