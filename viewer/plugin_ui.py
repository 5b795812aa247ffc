"""The drive viewer's place in QGIS: a toolbar button and "Sign Mapper ▸ Drive viewer"; built on first use."""

from __future__ import annotations

from pathlib import Path

from qgis.PyQt.QtCore import Qt

from ..dock_ui import DockUi
from ..ui.drive_viewer import DriveViewerDock


class ViewerUi(DockUi):
    """Owns the viewer action, dock and controller; *Add missed sign* goes through ``review_ui``."""

    text = "Drive viewer"
    object_name = "SignMapperDriveViewer"
    tooltip = "Sign Mapper: step through the drive's images with the mapped signs over them and the vehicle on the map"
    icon = Path(__file__).resolve().parents[1] / "icons" / "drive_viewer.svg"
    area = Qt.BottomDockWidgetArea
    what = "The drive viewer"

    def __init__(self, iface, review_ui=None, ask_drive_folder=None):
        self.review_ui, self.ask_drive_folder = review_ui, ask_drive_folder
        super().__init__(iface)
        if review_ui is not None:
            review_ui.followers.append(self.follow_review)

    def open_at_feature(self, layer, fid: int) -> None:
        """Open the viewer (if closed) at the best pair of a feature, selected (a layer action)."""
        self.action.setChecked(True)
        if self.controller is not None:
            self.controller.show_feature(layer, fid)

    def follow_review(self, layer, pair_id: str) -> None:
        """The review's Follow: an open viewer shows the best pair of the feature under review."""
        if self.controller is not None and self.dock is not None and self.dock.isVisible():
            self.controller.show_pair(layer, pair_id)

    def build(self):
        from .controller import DriveViewerController  # delays OpenCV and numpy until used

        dock = DriveViewerDock(self.iface.mainWindow())
        return dock, DriveViewerController(self.iface, dock, self.ask_drive_folder, add_sign=self._add_sign)

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
