"""Keyboard shortcuts of a dock that work whenever the pointer is over it, not only after a click into it.

Qt delivers shortcuts of a dock (``Qt.WidgetWithChildrenShortcut``) only while
the focus is inside it; so the dock takes the focus when the pointer enters —
unless the user is typing somewhere (a text field keeps its focus).
"""

from __future__ import annotations

from qgis.PyQt.QtCore import QEvent, QObject
from qgis.PyQt.QtWidgets import QAbstractSpinBox, QApplication, QComboBox, QLineEdit, QPlainTextEdit, QTextEdit

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
