"""The drive viewer's place in QGIS: a toolbar button and "Sign Mapper ▸ Drive viewer"; built on first use."""

from __future__ import annotations

from pathlib import Path

from qgis.core import Qgis
from qgis.PyQt.QtCore import Qt
from qgis.PyQt.QtGui import QIcon
from qgis.PyQt.QtWidgets import QAction

from ..review.plugin_ui import MENU

ICON = Path(__file__).resolve().parents[1] / "icons" / "drive_viewer.svg"


class ViewerUi:
    """Owns the viewer action, dock and controller; *Add missed sign* goes through ``review_ui``."""

    def __init__(self, iface, review_ui=None, ask_drive_folder=None):
        self.iface, self.review_ui, self.ask_drive_folder = iface, review_ui, ask_drive_folder
        self.dock = None
        self.controller = None
        self.action = QAction(QIcon(str(ICON)), "Drive viewer", iface.mainWindow())
        self.action.setObjectName("SignMapperDriveViewer")
        self.action.setCheckable(True)
        self.action.setToolTip("Sign Mapper: step through the drive's images with the mapped signs over them "
                               "and the vehicle on the map")
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
            from ..ui.drive_viewer import DriveViewerDock
            from .controller import DriveViewerController
        except ImportError as exc:  # e.g. OpenCV missing
            self.iface.messageBar().pushMessage("Sign Mapper", f"The drive viewer cannot start: {exc}",
                                                Qgis.Warning, 0)
            return False
        self.dock = DriveViewerDock(self.iface.mainWindow())
        self.controller = DriveViewerController(self.iface, self.dock, self.ask_drive_folder, add_sign=self._add_sign)
        self.dock.visibilityChanged.connect(self._visibility_changed)
        self.iface.addDockWidget(Qt.BottomDockWidgetArea, self.dock)
        return True

    def _add_sign(self, layer, pair_id: str, u: float, v: float) -> None:
        """Open the review on the viewer's layer and let it find and add the clicked sign."""
        review = self.review_ui
        if review is None:
            return
        review.action.setChecked(True)
        if review.controller is None:
            return
        self.iface.setActiveLayer(layer)
        if review.controller.layer is not layer:
            review.controller.set_layer(layer)
        review.controller.decisions.add_sign(pair_id, u, v)

    def _set_checked(self, checked: bool) -> None:
        self.action.blockSignals(True)
        self.action.setChecked(checked)
        self.action.blockSignals(False)

    def _visibility_changed(self, visible: bool) -> None:
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
