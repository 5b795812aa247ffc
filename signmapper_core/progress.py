"""How long operations report progress and learn they are cancelled: one protocol for the whole core.

``open_drive``, ``map_drive``, ``generate_drive`` and ``import_drive`` each take
(``write_sign_crops`` the last two)

- ``progress(fraction, message)``: ``fraction`` of the whole operation done (0..1)
  and what it is doing, in words;
- ``is_cancelled() -> bool``: asked between steps; when it turns true the
  operation raises :class:`Cancelled` and leaves nothing half-done behind;
- where input can be skipped (``map_drive``, ``import_drive``, ``write_sign_crops``,
  ``plate_fusion.read_plate_texts``), ``warn(message)``: something was skipped and the
  operation goes on. The parameter is called ``warn`` in each (the run settings' readers
  too, whose ``warn`` hears of settings they ignored).

They call them through :func:`report`, :func:`check_cancelled` and :func:`send_warning`.

All are optional. Front ends adapt their own feedback to it once
(``algorithms/base.py`` for QGIS Processing).
"""

from __future__ import annotations

from typing import Callable, Optional

ProgressCallback = Callable[[float, str], None]
CancelCheck = Callable[[], bool]
WarnCallback = Callable[[str], None]


class Cancelled(Exception):
    """A long operation stopped because ``is_cancelled()`` said so; it left nothing behind."""


def report(progress: Optional[ProgressCallback], fraction: float, message: str = "") -> None:
    if progress is not None:
        progress(min(max(fraction, 0.0), 1.0), message)


def check_cancelled(is_cancelled: Optional[CancelCheck], what: str) -> None:
    """Raise :class:`Cancelled` (naming ``what`` was cancelled) when ``is_cancelled()`` is true."""
    if is_cancelled is not None and is_cancelled():
        raise Cancelled(f"{what} cancelled")


def send_warning(warn: Optional[WarnCallback], message: str) -> None:
    if warn is not None:
        warn(message)
