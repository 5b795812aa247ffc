"""The review dock's place in QGIS: a toolbar button and the menu entry "Sign Mapper ▸ Review signs"."""

from __future__ import annotations

from pathlib import Path

from ..dock_ui import DockUi
from ..ui.review_dock import ReviewDock


class ReviewUi(DockUi):
    """Owns the review action, dock and controller; ``unload`` removes all of them."""

    text = "Review signs"
    object_name = "SignMapperReviewSigns"
    tooltip = "Sign Mapper: review detected signs, decide on doubtful ones and add missed signs"
    icon = Path(__file__).resolve().parents[1] / "icon.svg"
    what = "The review dock"
    height = 700  # what its content lays out in, the picker open (ui/review_dock.py)

    def __init__(self, iface, ask_drive_folder=None):
        self.ask_drive_folder = ask_drive_folder
        self.followers = []  # callables (layer, pair id) told of each feature Follow goes to: the drive viewer
        super().__init__(iface)

    def build(self):
        from .controller import ReviewController  # delays OpenCV and numpy until used

        dock = ReviewDock(self.iface.mainWindow())
        controller = ReviewController(self.iface, dock, self.ask_drive_folder)
        controller.featureFollowed.connect(self._followed)
        return dock, controller

    def _followed(self, layer, pair_id: str) -> None:
        for follower in self.followers:
            follower(layer, pair_id)
