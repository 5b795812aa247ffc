"""A grid of template pictograms to reclassify a sign, filtered by colour, shape and a search text.

Above the grid, the classifier's next choices for the sign (its ``alternatives``)
as one-click buttons: a misread sign's true id is most often among them.

It is given plain :class:`TemplateChoice` records (the controller builds them
from the catalogue), so it neither reads the catalogue nor writes layers.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Iterable, List, Optional, Sequence, Tuple

from qgis.PyQt.QtCore import QEvent, QSize, Qt, pyqtSignal
from qgis.PyQt.QtGui import QIcon
from qgis.PyQt.QtWidgets import (
    QComboBox,
    QHBoxLayout,
    QLineEdit,
    QListView,
    QListWidget,
    QListWidgetItem,
    QPushButton,
    QToolButton,
    QVBoxLayout,
    QWidget,
)

from .hover_focus import keeps_dock_keys

ANY = ""
ID_ROLE = Qt.UserRole
CHOICE_KEYS = ("1", "2", "3")  # the classifier's next choices, best first (the review dock binds them)
SEARCH_KEY = "/"  # opens the search box without typing into it


@dataclass(frozen=True)
class TemplateChoice:
    """What the picker needs to know of one catalogue entry."""

    id: str
    name: str
    colour: str
    shape: str
    icon_path: str = ""

    def matches(self, colour: str, shape: str, text: str) -> bool:
        text = text.strip().lower()
        return ((not colour or self.colour == colour) and (not shape or self.shape == shape)
                and (not text or text in self.id.lower() or text in self.name.lower()))


class _Grid(QListWidget):
    """The grid of types: it asks for no more height than one row, so the dock around it (a scroll area sizing
    its content by preferred heights) fits a short screen; any height left over goes to it by stretch."""

    def sizeHint(self):  # noqa: N802 - Qt override
        return QSize(super().sizeHint().width(), self.minimumHeight())


class TemplatePicker(QWidget):
    """Emits ``templateChosen(id)`` on a next choice, a double click, Enter or the Reclassify button.

    Keyboard first: it opens with the focus on the grid, where the arrow keys move
    and Enter chooses; the first character typed that is none of the dock's keys
    (``reserved``) goes to the search box ('/' only opens it: an id starts with a
    digit, and 1-3 choose), so a decision key never lands in it as text, and QGIS's
    own one-letter shortcuts (S toggles snapping) do not take a search's first letter.
    """

    templateChosen = pyqtSignal(str)  # noqa: N815

    def __init__(self, parent=None, icon_px: int = 40):
        super().__init__(parent)
        self._choices: List[TemplateChoice] = []
        self._reserved = set(CHOICE_KEYS)
        self.colour_box = QComboBox()
        self.colour_box.setToolTip("Show only templates of this dominant colour")
        self.shape_box = QComboBox()
        self.shape_box.setToolTip("Show only templates of this shape")
        self.search = QLineEdit()
        self.search.setPlaceholderText("Type to search id or name…")
        self.search.setToolTip("Start typing (or '/') to search; Enter reclassifies as the first match, "
                               "Escape closes the picker")
        self.search.setClearButtonEnabled(True)
        self.search.setFocusPolicy(Qt.ClickFocus)  # Tab never lands here: typing does (see eventFilter)
        self.grid = _Grid()
        self.grid.setViewMode(QListView.IconMode)
        self.grid.setIconSize(QSize(icon_px, icon_px))
        self._icon_px = icon_px
        self.grid.setGridSize(QSize(icon_px + 56, icon_px + 30))
        self.grid.setResizeMode(QListView.Adjust)
        self.grid.setMovement(QListView.Static)
        self.grid.setWordWrap(True)
        self.grid.setTextElideMode(Qt.ElideNone)  # ids are short: show them whole, never "2…."
        self.grid.setUniformItemSizes(False)  # a uniform size is the first item's, its id wrapped: "2.…" for all
        self.grid.setMinimumHeight(icon_px + 38)  # one row; the grid scrolls
        self.grid.setMaximumHeight(3 * (icon_px + 30) + 8)
        self.choose_button = QPushButton("Choose")
        self.choose_button.setToolTip("Reclassify as the type selected in the grid (or double click it, or Enter)")
        keeps_dock_keys(self.choose_button)
        self.choose_button.setEnabled(False)
        self._suggested: List[Tuple[str, float]] = []
        self._suggestion_buttons: List[QToolButton] = []
        self.suggestions = QWidget()
        self.suggestions.setToolTip("The classifier's next choices after the current id, with their scores")
        self._suggestion_row = QHBoxLayout(self.suggestions)
        self._suggestion_row.setContentsMargins(0, 0, 0, 0)
        self.suggestions.setVisible(False)

        filters = QHBoxLayout()
        filters.addWidget(self.colour_box)
        filters.addWidget(self.shape_box)
        filters.addWidget(self.search, 1)
        filters.addWidget(self.choose_button)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(2)
        layout.addWidget(self.suggestions)
        layout.addLayout(filters)
        layout.addWidget(self.grid, 1)

        self.colour_box.currentIndexChanged.connect(self._refilter)
        self.shape_box.currentIndexChanged.connect(self._refilter)
        self.search.textChanged.connect(self._refilter)
        self.grid.itemDoubleClicked.connect(lambda item: self.templateChosen.emit(item.data(ID_ROLE)))
        self.grid.activated.connect(lambda _index: self._choose_current())  # Enter on the grid
        self.grid.currentItemChanged.connect(lambda cur, _prev: self.choose_button.setEnabled(cur is not None))
        self.choose_button.clicked.connect(self._choose_current)
        self.search.returnPressed.connect(self._choose_first_match)
        self.grid.installEventFilter(self)
        self.search.installEventFilter(self)

    # keyboard ------------------------------------------------------------------------------------------
    def focus_choices(self) -> None:
        """Where the keyboard starts when the picker opens: the grid, not the search box."""
        self.grid.setFocus()

    def set_reserved(self, keys) -> None:
        """The keys that stay the dock's while the grid has the focus (its shortcuts): they never start a search."""
        self._reserved = {str(k).lower() for k in keys}

    def eventFilter(self, watched, event):  # noqa: N802 - Qt override
        if watched is self.grid and event.type() == QEvent.ShortcutOverride and self._starts_typing(event):
            event.accept()  # a search's first letter: no window shortcut of QGIS may take it
            return True
        if event.type() != QEvent.KeyPress:
            return False
        if watched is self.grid and self._starts_typing(event):
            self.search.setFocus()
            if event.text() != SEARCH_KEY:
                self.search.insert(event.text())
            return True
        if watched is self.search and event.key() == Qt.Key_Down and self.grid.count():
            self.grid.setFocus()  # from the search to the matches
            if self.grid.currentRow() < 0:
                self.grid.setCurrentRow(0)
            return True
        return False

    def _starts_typing(self, event) -> bool:
        """A character typed on the grid that is none of the dock's keys starts a search."""
        text = event.text()
        return bool(text) and text.isprintable() and not text.isspace() and text.lower() not in self._reserved \
            and not event.modifiers() & (Qt.ControlModifier | Qt.AltModifier)

    def choose_suggestion(self, index: int) -> bool:
        """Reclassify as the ``index``-th next choice (0 = best); False when there is none."""
        if 0 <= index < len(self._suggestion_buttons):
            self._suggestion_buttons[index].click()
            return True
        return False

    def set_choices(self, choices: Iterable[TemplateChoice]) -> None:
        self._choices = list(choices)
        metrics = self.grid.fontMetrics()
        widest = max((metrics.horizontalAdvance(c.id) for c in self._choices), default=0)
        self.grid.setGridSize(QSize(max(self._icon_px + 24, widest + 16), self._icon_px + metrics.height() + 14))
        colours = sorted({c.colour for c in self._choices})
        shapes = sorted({c.shape for c in self._choices})
        for box, values, label in ((self.colour_box, colours, "Any colour"), (self.shape_box, shapes, "Any shape")):
            box.blockSignals(True)
            box.clear()
            box.addItem(label, ANY)
            for value in values:
                box.addItem(value, value)
            box.blockSignals(False)
        self._refilter()
        self._show_suggestions()

    def choices(self) -> List[TemplateChoice]:
        return list(self._choices)

    def set_filter(self, colour: str = ANY, shape: str = ANY, text: Optional[str] = None) -> None:
        """Preset the filters, e.g. to the colour and shape of the sign under review."""
        for box, value in ((self.colour_box, colour), (self.shape_box, shape)):
            index = box.findData(value or ANY)
            box.blockSignals(True)
            box.setCurrentIndex(max(index, 0))
            box.blockSignals(False)
        if text is not None:
            self.search.blockSignals(True)
            self.search.setText(text)
            self.search.blockSignals(False)
        self._refilter()

    def set_suggestions(self, alternatives: Sequence[Tuple[str, float]]) -> None:
        """The classifier's next choices (id, score), best first; ids the catalogue lacks are not offered."""
        self._suggested = list(alternatives)
        self._show_suggestions()

    def suggested_ids(self) -> List[str]:
        return [button.property("template_id") for button in self._suggestion_buttons]

    def _show_suggestions(self) -> None:
        while self._suggestion_row.count():
            widget = self._suggestion_row.takeAt(0).widget()
            if widget is not None:
                widget.setParent(None)  # gone from the row now, not at the next event loop turn
                widget.deleteLater()
        self._suggestion_buttons = []
        known = {c.id: c for c in self._choices}
        offered = [(known[tid], score) for tid, score in self._suggested if tid in known]
        for key, (choice, score) in zip(CHOICE_KEYS, offered):
            button = QToolButton()
            button.setProperty("template_id", choice.id)
            button.setToolButtonStyle(Qt.ToolButtonTextBesideIcon)
            keeps_dock_keys(button)
            if choice.icon_path:
                button.setIcon(QIcon(choice.icon_path))
                button.setIconSize(QSize(self._icon_px, self._icon_px))
            button.setText(f"[{key}] {choice.id}\n{score:.2f}")
            button.setToolTip(f"Reclassify as {choice.id} {choice.name} (classifier score {score:.2f}; key {key})")
            button.clicked.connect(lambda _checked=False, tid=choice.id: self.templateChosen.emit(tid))
            self._suggestion_row.addWidget(button)
            self._suggestion_buttons.append(button)
        self.suggestions.setVisible(bool(offered))

    def visible_ids(self) -> List[str]:
        return [self.grid.item(i).data(ID_ROLE) for i in range(self.grid.count())]

    def select(self, template_id: str) -> bool:
        for i in range(self.grid.count()):
            if self.grid.item(i).data(ID_ROLE) == template_id:
                self.grid.setCurrentRow(i)
                return True
        return False

    def _refilter(self) -> None:
        colour, shape, text = self.colour_box.currentData() or ANY, self.shape_box.currentData() or ANY, \
            self.search.text()
        self.grid.clear()
        for choice in self._choices:
            if choice.matches(colour, shape, text):
                item = QListWidgetItem(QIcon(choice.icon_path) if choice.icon_path else QIcon(), choice.id)
                item.setData(ID_ROLE, choice.id)
                item.setToolTip(f"{choice.id} {choice.name}")
                self.grid.addItem(item)
        self.choose_button.setEnabled(False)

    def _choose_current(self) -> None:
        item = self.grid.currentItem()
        if item is not None:
            self.templateChosen.emit(item.data(ID_ROLE))

    def _choose_first_match(self) -> None:
        """Enter in the search box: the selected match, else the first one."""
        item = self.grid.currentItem() or (self.grid.item(0) if self.grid.count() else None)
        if item is not None:
            self.templateChosen.emit(item.data(ID_ROLE))
