"""Keyboard shortcuts of a dock that work whenever the pointer is over it, not only after a click into it.

Qt delivers shortcuts of a dock (``Qt.WidgetWithChildrenShortcut``) only while
the focus is inside it; so the dock takes the focus when the pointer enters —
unless the user is typing somewhere (a text field keeps its focus).
"""

from __future__ import annotations

from typing import Callable, Mapping, Tuple

from qgis.PyQt.QtCore import QEvent, QObject, Qt
from qgis.PyQt.QtGui import QKeySequence
from qgis.PyQt.QtWidgets import QAbstractSpinBox, QAction, QApplication, QComboBox, QLineEdit, QPlainTextEdit, QTextEdit

TYPING = (QLineEdit, QTextEdit, QPlainTextEdit, QAbstractSpinBox)


def typing_somewhere() -> bool:
    focus = QApplication.focusWidget()
    return isinstance(focus, TYPING) or (isinstance(focus, QComboBox) and focus.isEditable())


class FocusOnHover(QObject):
    """Installed on a dock: when the pointer enters, ``target`` takes the focus (if nobody is typing)."""

    def __init__(self, dock, target):
        super().__init__(dock)
        self.target = target
        dock.installEventFilter(self)

    def eventFilter(self, watched, event):  # noqa: N802 - Qt override
        if event.type() == QEvent.Enter and not typing_somewhere() and not self.target.hasFocus():
            focus = QApplication.focusWidget()
            if focus is None or not watched.isAncestorOf(focus):
                self.target.setFocus()
        return False


def keeps_dock_keys(widget):
    """``widget``, reached by Tab but not focused by a click: a click on a button or box in a dock must not take the
    keys from the dock's shortcuts (:func:`add_shortcuts`)."""
    widget.setFocusPolicy(Qt.TabFocus)
    return widget


def add_shortcuts(dock, keys: Mapping[str, Tuple[str, str]], handlers: Mapping[str, Callable[[], object]]) -> None:
    """An action on ``dock`` for each handler, named as it is and with the (text, key) of ``keys[name]``.

    The shortcuts act while the focus is in the dock (``Qt.WidgetWithChildrenShortcut``), which
    :class:`FocusOnHover` gives it when the pointer enters: two docks share the QGIS window's keys.
    """
    for name, handler in handlers.items():
        text, key = keys[name]
        action = QAction(text, dock)
        action.setObjectName(name)
        action.setShortcut(QKeySequence(key))
        action.setShortcutContext(Qt.WidgetWithChildrenShortcut)
        action.triggered.connect(lambda _checked=False, h=handler: h())
        dock.addAction(action)
