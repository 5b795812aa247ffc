"""The drive viewer dock: steps through a drive's left images with the signs over them.

Widgets only: buttons, slider, keys and clicks become signals; the controller
(``viewer/controller.py``) decodes frames, projects signs and moves the vehicle
on the map. Keys (shown on the buttons) act while the pointer is over the dock.
"""

from __future__ import annotations

from typing import Sequence

from qgis.PyQt.QtCore import Qt, pyqtSignal
from qgis.PyQt.QtGui import QKeySequence
from qgis.PyQt.QtWidgets import (
    QCheckBox,
    QDockWidget,
    QHBoxLayout,
    QLabel,
    QPushButton,
    QSlider,
    QVBoxLayout,
    QWidget,
)

from .hover_focus import FocusOnHover, add_shortcuts, keeps_dock_keys
from .image_view import ImageView, OverlayBox

# name -> (button text, shortcut)
KEYS = {
    "previous": ("◀", "Left"),
    "play": ("▶ Play", "K"),
    "next": ("▶", "Right"),
    "back10": ("◀◀", "PgUp"),
    "forward10": ("▶▶", "PgDown"),
    "pick": ("Pick on map", "O"),
    "add_sign": ("Add missed sign", "M"),
}


class DriveViewerDock(QDockWidget):
    frameRequested = pyqtSignal(int)  # noqa: N815 - index into the drive's pairs
    playToggled = pyqtSignal(bool)  # noqa: N815
    boxClicked = pyqtSignal(str)  # noqa: N815 - "signs:<fid>" or "detections:<fid>"
    addSignClicked = pyqtSignal(str, float, float)  # noqa: N815 - pair id, u, v
    pickOnMapToggled = pyqtSignal(bool)  # noqa: N815
    followToggled = pyqtSignal(bool)  # noqa: N815

    def __init__(self, parent=None):
        super().__init__("Sign Mapper drive viewer", parent)
        self.setObjectName("SignMapperDriveViewer")
        self.index, self.count, self.pair_id = -1, 0, ""
        body = QWidget()
        self.setWidget(body)
        layout = QVBoxLayout(body)
        layout.setContentsMargins(4, 4, 4, 4)
        self.caption = QLabel("Select a layer written by Map traffic signs to look through its drive")
        self.caption.setWordWrap(True)
        self.caption.setStyleSheet("font-weight: bold")
        layout.addWidget(self.caption)
        self.view = ImageView()
        self.view.setMinimumHeight(200)
        self.view.imageClicked.connect(self._image_clicked)
        self.view.boxClicked.connect(self.boxClicked)
        layout.addWidget(self.view, 1)
        self.slider = QSlider(Qt.Horizontal)
        self.slider.setMinimum(0)
        self.slider.setTracking(True)
        self.slider.valueChanged.connect(self._slider_moved)
        layout.addWidget(self.slider)
        layout.addLayout(self._build_buttons())
        self.message = QLabel("Keys act while the pointer is over this panel. Click a box to select its sign; "
                              "solid boxes were detected in this image, dashed ones are mapped signs projected "
                              "into it.")
        self.message.setWordWrap(True)
        layout.addWidget(self.message)
        self._install_keys()
        FocusOnHover(self, self.view)
        self.set_frames([])

    def _button(self, name: str) -> QPushButton:
        text, key = KEYS[name]
        button = QPushButton(f"{text}  [{QKeySequence(key).toString(QKeySequence.NativeText)}]")
        self.buttons[name] = keeps_dock_keys(button)
        return button

    def _build_buttons(self) -> QHBoxLayout:
        self.buttons = {}
        row = QHBoxLayout()
        for name in ("back10", "previous", "play", "next", "forward10"):
            row.addWidget(self._button(name))
        self.buttons["play"].setCheckable(True)
        self.buttons["play"].toggled.connect(self._play_toggled)
        self.buttons["previous"].clicked.connect(lambda: self.step(-1))
        self.buttons["next"].clicked.connect(lambda: self.step(1))
        self.buttons["back10"].clicked.connect(lambda: self.step(-10))
        self.buttons["forward10"].clicked.connect(lambda: self.step(10))
        pick = self._button("pick")
        pick.setCheckable(True)
        pick.setToolTip("Click a trajectory point or a place on the map to open the pair that sees it best")
        pick.toggled.connect(self.pickOnMapToggled)
        row.addWidget(pick)
        add = self._button("add_sign")
        add.setCheckable(True)
        add.setToolTip("Then click the centre of a missed sign in the image")
        add.toggled.connect(self.view.set_picking)
        row.addWidget(add)
        self.follow_box = QCheckBox("Follow")
        self.follow_box.setToolTip("Keep the vehicle in view on the map")
        self.follow_box.setChecked(True)
        self.follow_box.toggled.connect(self.followToggled)
        row.addWidget(self.follow_box)
        return row

    def _install_keys(self) -> None:
        handlers = {
            "previous": lambda: self.step(-1), "next": lambda: self.step(1),
            "back10": lambda: self.step(-10), "forward10": lambda: self.step(10),
            "play": self.buttons["play"].toggle, "pick": self.buttons["pick"].toggle,
            "add_sign": self.buttons["add_sign"].toggle,
        }
        add_shortcuts(self, KEYS, {name: (lambda h=h: h() if self.count else None) for name, h in handlers.items()})

    # requests ----------------------------------------------------------------------------------------
    def step(self, delta: int) -> None:
        if self.count:
            self.frameRequested.emit(max(0, min(self.count - 1, self.index + delta)))

    def _slider_moved(self, value: int) -> None:
        if value != self.index:
            self.frameRequested.emit(value)

    def _play_toggled(self, playing: bool) -> None:
        self.buttons["play"].setText(f"{'❚❚ Pause' if playing else '▶ Play'}  [{KEYS['play'][1]}]")
        self.playToggled.emit(playing)

    def _image_clicked(self, u: float, v: float) -> None:
        if self.buttons["add_sign"].isChecked() and self.pair_id:
            self.buttons["add_sign"].setChecked(False)
            self.addSignClicked.emit(self.pair_id, u, v)

    # slots the controller calls ----------------------------------------------------------------------
    def set_frames(self, pair_ids: Sequence[str]) -> None:
        self.count = len(pair_ids)
        self.index = -1
        self.slider.blockSignals(True)
        self.slider.setMaximum(max(0, self.count - 1))
        self.slider.setValue(0)
        self.slider.blockSignals(False)
        for button in self.buttons.values():
            button.setEnabled(bool(self.count))
        if not self.count:
            self.view.clear_image()
            self.set_playing(False)

    def show_frame(self, index: int, pair_id: str, image, boxes: Sequence[OverlayBox], caption: str) -> None:
        """The image of pair ``index`` with its boxes; the zoom stays where the user put it."""
        self.index, self.pair_id = index, pair_id
        self.view.set_image(image, keep_view=True)
        self.view.set_boxes(boxes)
        self.caption.setText(caption)
        self.slider.blockSignals(True)
        self.slider.setValue(index)
        self.slider.blockSignals(False)

    def set_playing(self, playing: bool) -> None:
        if self.buttons["play"].isChecked() != playing:
            self.buttons["play"].setChecked(playing)

    def set_picking_on_map(self, picking: bool) -> None:
        if self.buttons["pick"].isChecked() != picking:
            self.buttons["pick"].blockSignals(True)
            self.buttons["pick"].setChecked(picking)
            self.buttons["pick"].blockSignals(False)

    def follow(self) -> bool:
        return self.follow_box.isChecked()

    def show_message(self, text: str, error: bool = False) -> None:
        self.message.setText(text)
        self.message.setStyleSheet("color: #c62828" if error else "")
