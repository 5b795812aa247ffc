"""The review dock (Cavegn 2011, section 4: a person verifies doubtful candidates and adds missed signs).

The dock only shows a :class:`ReviewItem` and turns button presses, shortcuts and
clicks into signals; :class:`review.controller.ReviewController` reads layers,
decodes images and writes the decisions. That keeps this widget testable alone.
"""

from __future__ import annotations

import html
from typing import List, Optional, Sequence

from qgis.PyQt.QtCore import QSize, Qt, pyqtSignal
from qgis.PyQt.QtGui import QIcon, QKeySequence, QPixmap
from qgis.PyQt.QtWidgets import (
    QApplication,
    QCheckBox,
    QComboBox,
    QDockWidget,
    QFrame,
    QGridLayout,
    QGroupBox,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QListView,
    QListWidget,
    QListWidgetItem,
    QMessageBox,
    QProgressBar,
    QPushButton,
    QScrollArea,
    QSizePolicy,
    QVBoxLayout,
    QWidget,
)

from ..signmapper_core.statuses import ACCEPTED, REJECTED, STATUS_COLOURS
from .hover_focus import FocusOnHover, add_shortcuts, keeps_dock_keys
from .image_view import ImageView
from .review_item import ObservationView, ReviewItem
from .template_picker import CHOICE_KEYS, TemplateChoice, TemplatePicker

# action name -> (button text, shortcut); the shortcuts act while the pointer is over the dock (or it has the focus)
SHORTCUTS = {
    "accept": ("Accept", "A"),
    "reject": ("Reject", "R"),
    "reclassify": ("Reclassify…", "C"),
    "previous": ("◀ Previous", "P"),
    "next": ("Next ▶", "N"),
    "next_review": ("To review", "Space"),
    "zoom": ("Zoom map", "Z"),
    "add_sign": ("Add missed", "M"),
    "undo": ("Undo", "U"),
}
CLOSE_PICKER_KEY = "Escape"
REJECT_COLOUR = "#c62828"
TOOLTIPS = {"next_review": "Next feature to review", "add_sign": "Add a missed sign: then click the centre of the "
            "sign in the image", "undo": "Undo the last decision",
            "reclassify": "Choose another sign type: keys 1-3 take the classifier's next choices, typing (or '/') "
            "searches, Escape closes"}
PICTOGRAM_PX = 56
# the lines of facts under the image: key -> what the line shows (its tooltip)
INFO_LINES = (("template", "Sign type (SSV) and name"), ("status", "Status and why the mapping left it for review"),
              ("format", "Colour, shape, format and size"), ("indicators", "Detection and classification indicators"),
              ("pair", "Best pair, its time and the depth"), ("extra", "Fusion: observations, vote share, spread"),
              ("plate", "Text read: a plate's, or a speed limit's digits"))
IMAGE_MIN_PX = 150  # the image gives way first: the dock lays out in 700 px with the picker open


def _fmt(value, digits=2) -> str:
    return "–" if value is None else f"{value:.{digits}f}"


class ReviewDock(QDockWidget):
    """Shows one feature of a Sign Mapper layer and asks for a decision on it."""

    acceptRequested = pyqtSignal()  # noqa: N815
    rejectRequested = pyqtSignal()  # noqa: N815
    reclassifyRequested = pyqtSignal(str)  # noqa: N815 - new template id
    nextRequested = pyqtSignal()  # noqa: N815
    previousRequested = pyqtSignal()  # noqa: N815
    nextReviewRequested = pyqtSignal()  # noqa: N815
    zoomRequested = pyqtSignal()  # noqa: N815
    addSignClicked = pyqtSignal(str, float, float)  # noqa: N815 - pair id, u, v
    undoRequested = pyqtSignal()  # noqa: N815
    pairRequested = pyqtSignal(str)  # noqa: N815 - show a pair's image (to add a sign where nothing was found)
    observationRequested = pyqtSignal(int)  # noqa: N815 - index into the item's observations
    textEdited = pyqtSignal(str)  # noqa: N815 - a plate's text as a person set it
    followToggled = pyqtSignal(bool)  # noqa: N815 - Follow switched on or off

    def __init__(self, parent=None):
        super().__init__("Sign Mapper review", parent)
        self.setObjectName("SignMapperReviewDock")
        self.item: Optional[ReviewItem] = None
        self.pair_id = ""
        body = QWidget()
        # the body scrolls inside the dock: an open picker or a long strip never grows the main window
        scroll = QScrollArea()
        scroll.setWidgetResizable(True)
        scroll.setFrameShape(QFrame.NoFrame)
        scroll.setHorizontalScrollBarPolicy(Qt.ScrollBarAlwaysOff)
        scroll.setWidget(body)
        self.setWidget(scroll)
        self.scroll = scroll
        layout = QVBoxLayout(body)
        layout.setContentsMargins(4, 4, 4, 4)
        layout.setSpacing(4)

        self.title = QLabel("Select a feature of a Sign Mapper signs or detections layer")
        self.title.setWordWrap(True)
        self.title.setStyleSheet("font-weight: bold")
        layout.addWidget(self.title)
        self.progress = QProgressBar()
        self.progress.setTextVisible(True)
        self.progress.setMaximumHeight(16)
        self.progress.setVisible(False)
        layout.addWidget(self.progress)

        self.image_caption = QLabel("")  # shown only for an image that is not the feature's own pair's
        self.image_caption.setWordWrap(True)
        self.image_caption.setVisible(False)
        layout.addWidget(self.image_caption)
        self.image_view = ImageView()
        self.image_view.setMinimumHeight(IMAGE_MIN_PX)
        self.image_view.imageClicked.connect(self._image_clicked)
        layout.addWidget(self.image_view, 4)

        layout.addLayout(self._build_info())

        # the picker opens here, in place of the observations, right under the sign it reclassifies
        self.picker_box = QGroupBox("Reclassify  ·  [Esc] closes")
        self.picker = TemplatePicker(icon_px=32)
        self.picker.templateChosen.connect(self._template_chosen)
        picker_layout = QVBoxLayout(self.picker_box)
        picker_layout.setContentsMargins(2, 2, 2, 2)
        picker_layout.addWidget(self.picker)
        self.picker_box.setVisible(False)
        layout.addWidget(self.picker_box, 2)

        self.strip_box = QGroupBox("Observations")
        self.strip = QListWidget()
        self.strip.setViewMode(QListView.IconMode)
        self.strip.setFlow(QListView.LeftToRight)
        self.strip.setWrapping(False)
        self.strip.setIconSize(QSize(64, 64))
        self.strip.setFixedHeight(122)
        self.strip.setGridSize(QSize(88, 102))
        self.strip.setTextElideMode(Qt.ElideNone)
        self.strip.setWordWrap(True)
        self.strip.setMovement(QListView.Static)
        self.strip.itemClicked.connect(lambda item: self.observationRequested.emit(self.strip.row(item)))
        strip_layout = QVBoxLayout(self.strip_box)
        strip_layout.setContentsMargins(2, 2, 2, 2)
        strip_layout.addWidget(self.strip)
        self.strip_box.setVisible(False)
        layout.addWidget(self.strip_box)

        layout.addLayout(self._build_buttons())
        layout.addWidget(self._build_plate_text())

        self.message = QLabel("Keys (in brackets on the buttons) act while the pointer is over this panel.")
        self.message.setWordWrap(True)
        layout.addWidget(self.message)
        self._install_shortcuts()
        FocusOnHover(self, self.image_view)
        self.set_item_enabled(False)
        self.set_navigation_enabled(False)

    # construction -------------------------------------------------------------------------------------
    def _build_info(self) -> QHBoxLayout:
        """The pictogram beside one line per fact; no title column (each line says what it is, its tooltip
        names it), so the lines rarely wrap and the dock stays short. Lines with nothing to say are hidden."""
        row = QHBoxLayout()
        self.pictogram = QLabel()
        self.pictogram.setFixedSize(PICTOGRAM_PX, PICTOGRAM_PX)
        self.pictogram.setAlignment(Qt.AlignCenter)
        row.addWidget(self.pictogram, 0, Qt.AlignTop)
        lines = QVBoxLayout()
        lines.setSpacing(0)
        self.info = {}
        for key, label in INFO_LINES:
            value = QLabel("–")
            value.setToolTip(label)
            value.setTextInteractionFlags(Qt.TextSelectableByMouse)
            value.setWordWrap(True)
            value.setSizePolicy(QSizePolicy.Expanding, QSizePolicy.Preferred)
            self.info[key] = value
            lines.addWidget(value)
        lines.addStretch(1)
        row.addLayout(lines, 1)
        return row

    def _build_plate_text(self) -> QGroupBox:
        """The text of a supplementary plate, as read, for a person to correct: shown only for plates."""
        self.plate_box = QGroupBox("Plate text")
        row = QHBoxLayout(self.plate_box)
        row.setContentsMargins(2, 2, 2, 2)
        self.plate_text = QLineEdit()
        self.plate_text.setPlaceholderText("as printed, lines separated by /  (e.g. Mo–Fr / 7–19 h)")
        self.plate_text.returnPressed.connect(lambda: self.textEdited.emit(self.plate_text.text()))
        row.addWidget(self.plate_text, 1)
        self.set_text_button = QPushButton("Set text")
        self.set_text_button.setToolTip("Write this text to the plate (accepts and marks it reviewed)")
        self.set_text_button.clicked.connect(lambda: self.textEdited.emit(self.plate_text.text()))
        row.addWidget(self.set_text_button)
        self.plate_box.setVisible(False)
        return self.plate_box

    def _button(self, name: str) -> QPushButton:
        text, key = SHORTCUTS[name]
        button = QPushButton(f"{text} [{key}]")
        button.setToolTip(f"{TOOLTIPS.get(name, text)} ({key})")
        self.buttons[name] = keeps_dock_keys(button)
        return button

    def _build_buttons(self) -> QGridLayout:
        self.buttons = {}
        grid = QGridLayout()
        grid.setSpacing(3)
        # three columns keep the dock narrow enough for a laptop screen beside the map
        for col, name in enumerate(("previous", "next", "next_review")):
            grid.addWidget(self._button(name), 0, col)
        for col, name in enumerate(("accept", "reject", "reclassify")):
            grid.addWidget(self._button(name), 1, col)
        for col, name in enumerate(("zoom", "undo")):
            grid.addWidget(self._button(name), 2, col)
        # coloured only while enabled: a plain "color" would make a disabled button look usable; Reject is red,
        # not the grey of the rejected status, which would look disabled
        for name, colour in (("accept", STATUS_COLOURS[ACCEPTED]), ("reject", REJECT_COLOUR)):
            self.buttons[name].setStyleSheet(f"QPushButton:enabled {{ color: {colour}; font-weight: bold }}")
        self.buttons["reclassify"].setCheckable(True)
        add = self._button("add_sign")
        add.setCheckable(True)
        add.setEnabled(False)
        add.toggled.connect(self.image_view.set_picking)
        grid.addWidget(add, 2, 2)
        self.pair_box = QComboBox()
        self.pair_box.setToolTip("Show another pair of the drive, e.g. to add a sign no detection points to")
        self.pair_box.activated.connect(lambda i: self.pairRequested.emit(self.pair_box.itemText(i)))
        grid.addWidget(self.pair_box, 3, 0)
        self.advance_box = QCheckBox("Advance")
        self.advance_box.setToolTip("After a decision, go to the next feature needing review")
        self.advance_box.setChecked(True)
        grid.addWidget(self.advance_box, 3, 1)
        self.follow_box = QCheckBox("Follow")
        self.follow_box.setToolTip("Pan the map to each feature shown (zooming in when it is far out) and open its "
                                   "best pair in the drive viewer")
        self.follow_box.setChecked(True)
        self.follow_box.toggled.connect(self.followToggled)
        grid.addWidget(self.follow_box, 3, 2)
        for box in (self.pair_box, self.advance_box, self.follow_box):
            keeps_dock_keys(box)

        b = self.buttons
        b["accept"].clicked.connect(self.acceptRequested)
        b["reject"].clicked.connect(self.rejectRequested)
        b["reclassify"].toggled.connect(self.show_picker)
        b["previous"].clicked.connect(self.previousRequested)
        b["next"].clicked.connect(self.nextRequested)
        b["next_review"].clicked.connect(self.nextReviewRequested)
        b["zoom"].clicked.connect(self.zoomRequested)
        b["undo"].clicked.connect(self.undoRequested)
        b["undo"].setEnabled(False)
        return grid

    def _install_shortcuts(self) -> None:
        handlers = {name: (lambda name=name: self._if_enabled(name)) for name in SHORTCUTS}  # its button's click
        keys = {name: SHORTCUTS[name] for name in handlers}
        for i, key in enumerate(CHOICE_KEYS):  # the picker's next choices, while it is open
            handlers[f"choice{i + 1}"] = lambda i=i: self.picker_box.isVisible() and self.picker.choose_suggestion(i)
            keys[f"choice{i + 1}"] = (f"Next choice {key}", key)
        handlers["close_picker"] = lambda: self.picker_box.isVisible() and self.show_picker(False)
        keys["close_picker"] = ("Close the picker", CLOSE_PICKER_KEY)
        self.picker.set_reserved(QKeySequence(key).toString() for _text, key in keys.values())
        add_shortcuts(self, keys, handlers)

    def _if_enabled(self, name: str) -> None:
        button = self.buttons[name]
        if button.isEnabled():
            button.click()

    # slots the controller calls ----------------------------------------------------------------------
    def set_template_choices(self, choices: Sequence[TemplateChoice]) -> None:
        self.picker.set_choices(choices)

    def has_template_choices(self) -> bool:
        return bool(self.picker.choices())

    def set_pairs(self, pair_ids: Sequence[str]) -> None:
        self.pair_box.clear()
        self.pair_box.addItems(list(pair_ids))
        if self.pair_id:
            self.pair_box.setCurrentText(self.pair_id)

    def set_item_enabled(self, enabled: bool, status: str = "", reviewed: bool = False,
                         has_position: bool = True) -> None:
        """Decisions only where they change something: no Accept on an accepted reviewed feature, etc."""
        self.buttons["accept"].setEnabled(enabled and not (status == ACCEPTED and reviewed))
        self.buttons["reject"].setEnabled(enabled and status != REJECTED)
        self.buttons["reclassify"].setEnabled(enabled)
        self.buttons["zoom"].setEnabled(enabled and has_position)
        if not enabled:
            self.buttons["reclassify"].setChecked(False)

    def set_navigation_enabled(self, enabled: bool, can_add: bool = False) -> None:
        """Previous/Next need a layer; adding a sign needs the drive's images."""
        for name in ("previous", "next", "next_review"):
            self.buttons[name].setEnabled(enabled)
        self.buttons["add_sign"].setEnabled(enabled and can_add)
        if not (enabled and can_add):
            self.buttons["add_sign"].setChecked(False)
        self.pair_box.setEnabled(enabled and can_add)

    def set_progress(self, to_review: int, reviewed: int, total: int) -> None:
        """Review progress of the layer: how many features a person decided on, how many still need a look."""
        self.progress.setVisible(total > 0)
        self.progress.setRange(0, max(total, 1))
        self.progress.setValue(reviewed)
        self.progress.setFormat(f"{to_review} to review · {reviewed} of {total} reviewed")

    def confirm(self, title: str, question: str) -> bool:
        """Ask the user a yes/no question (the controller decides what follows)."""
        answer = QMessageBox.question(self, title, question, QMessageBox.Yes | QMessageBox.No, QMessageBox.No)
        return answer == QMessageBox.Yes

    def set_undo_enabled(self, enabled: bool, text: str = "") -> None:
        self.buttons["undo"].setEnabled(enabled)
        self.buttons["undo"].setToolTip(f"Undo: {text} (U)" if text else "Undo last decision (U)")

    def advance_after_decision(self) -> bool:
        return self.advance_box.isChecked()

    def following(self) -> bool:
        """Follow: the map and the drive viewer go to each feature shown."""
        return self.follow_box.isChecked()

    def show_message(self, text: str, error: bool = False) -> None:
        self.message.setText(text)
        self.message.setStyleSheet("color: #c62828" if error else "")

    def show_empty(self, text: str) -> None:
        """No reviewable feature: no image of a feature that is gone, decisions disabled."""
        self.item = None
        self.title.setText(text)
        for value in self.info.values():
            value.setText("–")
        self.pictogram.clear()
        self.strip_box.setVisible(False)
        self.plate_box.setVisible(False)
        self.picker.set_suggestions([])
        self.clear_image()
        self.set_item_enabled(False)

    def show_item(self, item: ReviewItem) -> None:
        """Show a feature's attributes now; its image and observations may follow via set_image/set_observations."""
        self.item = item
        self.title.setText(item.title)
        colour = STATUS_COLOURS.get(item.status, "#555")
        self.info["template"].setText(f"<b>{item.template_id or '–'}</b> {item.name}")
        reviewed = " · reviewed" if item.reviewed else ""
        reason = f" · <i>{html.escape(item.review_reason)}</i>" if item.review_reason else ""
        self.info["status"].setText(f"<span style='color:{colour}; font-weight:bold'>{item.status}</span>{reviewed}"
                                    f"{reason}")
        w, h = item.size_m
        self.info["format"].setText(f"{item.colour} {item.shape}, {item.format} {w:.2f} × {h:.2f} m")
        self.info["indicators"].setText(
            f"detection {_fmt(item.detection_indicator)} · classification {_fmt(item.classification_indicator)}"
        )
        depth = f" · depth {item.depth_m:.1f} m" if item.depth_m is not None else ""
        self.info["pair"].setText(f"pair {item.pair_id or '–'} · t = {_fmt(item.time, 2)} s{depth}")
        self.info["extra"].setText(" · ".join(f"{k} {v}" for k, v in item.extra))
        self.show_plate(item)
        for key in ("extra", "plate"):
            self.info[key].setVisible(self.info[key].text() not in ("", "–"))
        pix = QPixmap(item.pictogram_path) if item.pictogram_path else QPixmap()
        if pix.isNull():
            self.pictogram.setText("no\npictogram")
        else:
            self.pictogram.setPixmap(pix.scaled(PICTOGRAM_PX - 4, PICTOGRAM_PX - 4, Qt.KeepAspectRatio,
                                                Qt.SmoothTransformation))
        self.picker.set_filter(item.colour, item.shape, "")
        self.picker.select(item.template_id)
        self.picker.set_suggestions([a for a in item.alternatives if a[0] != item.template_id])  # after a reclassify
        self.set_item_enabled(True, item.status, item.reviewed, item.position is not None)
        if item.image is not None:
            self.set_image(item.pair_id, item.image, item.crop, item.bbox, item.centroid)
        elif self.image_view.has_image():
            self.clear_image()  # another feature's image must not stand beside this one's attributes
        if item.pair_id and self.pair_box.findText(item.pair_id) >= 0:
            self.pair_box.setCurrentText(item.pair_id)
        self.set_observations(item.observations)

    def show_plate(self, item: ReviewItem) -> None:
        """A plate's sign and text (with its OCR confidence); its text in the editor. For a speed limit the number
        its digits read (which sent it to review if it is another one's); nothing for other signs."""
        self.plate_box.setVisible(item.is_plate)
        if not item.is_plate:
            share = f" · in {_fmt(item.text_confidence)} of its views" if item.text_confidence is not None else ""
            self.info["plate"].setText(f"digits read “{item.text}”{share}" if item.text else "–")
            return
        read = f"“{item.text}”" if item.text else "no text read"
        confidence = f" · text confidence {_fmt(item.text_confidence)}" if item.text_confidence is not None else ""
        self.info["plate"].setText(f"plate of sign {item.plate_of} · {read}{confidence}")
        self.plate_text.setText(item.text or "")

    def set_image(self, pair_id: str, image, crop=None, bbox=None, centroid=None) -> None:
        """Show a left image; the caption says whose it is, so it never contradicts the panel below."""
        self.pair_id = pair_id
        self.image_view.set_image(image, crop, bbox, centroid)
        if self.pair_box.findText(pair_id) >= 0:
            self.pair_box.setCurrentText(pair_id)
        if self.item is None:
            self.image_caption.setText(f"Image: pair {pair_id} (no feature selected)")
        elif pair_id == self.item.pair_id:
            self.image_caption.setText(f"Image: pair {pair_id}")  # as the Pair line says: no caption needed
        else:
            self.image_caption.setText(f"<b>Image: pair {pair_id}</b> — the feature below is from pair "
                                       f"{self.item.pair_id or '–'}")
        self.image_caption.setVisible(self.item is None or pair_id != self.item.pair_id)

    def clear_image(self) -> None:
        self.pair_id = ""
        self.image_view.clear_image()
        self.image_caption.setText("")
        self.image_caption.setVisible(False)

    def set_observations(self, observations: Optional[List[ObservationView]]) -> None:
        self.strip.clear()
        self.strip_box.setVisible(observations is not None and not self.picker_box.isVisibleTo(self))
        if observations is None:
            return
        self.strip_box.setTitle(f"Observations ({len(observations)})")
        for obs in observations:
            icon = QIcon(QPixmap.fromImage(obs.thumbnail)) if obs.thumbnail is not None else QIcon()
            entry = QListWidgetItem(icon, obs.label)
            entry.setToolTip(f"pair {obs.pair_id}: {obs.template_id} (classification indicator)")
            self.strip.addItem(entry)

    def show_picker(self, visible: bool) -> None:
        """The picker in place of the observations, the keyboard on its choices; closed, the keys are the dock's."""
        had_focus = self.picker_box.isAncestorOf(QApplication.focusWidget())
        self.picker_box.setVisible(visible)
        self.strip_box.setVisible(not visible and self.item is not None and self.item.observations is not None)
        if self.buttons["reclassify"].isChecked() != visible:
            self.buttons["reclassify"].setChecked(visible)
        if visible:
            self.picker.search.clear()
            self.picker.focus_choices()
            self.scroll.ensureWidgetVisible(self.picker_box, 0, 0)
        elif had_focus:
            self.image_view.setFocus()  # the focus must not fall to a button, out of the shortcuts' reach

    def adding_sign(self) -> bool:
        return self.buttons["add_sign"].isChecked()

    def _template_chosen(self, template_id: str) -> None:
        """A choice closes the picker (the keys are the dock's again), then asks for the reclassification."""
        self.show_picker(False)
        self.reclassifyRequested.emit(template_id)

    # clicks -----------------------------------------------------------------------------------------
    def _image_clicked(self, u: float, v: float) -> None:
        if self.adding_sign() and self.pair_id:
            self.buttons["add_sign"].setChecked(False)
            self.addSignClicked.emit(self.pair_id, u, v)
