"""Running slow work (image decoding, detect_in_window) off the GUI thread.

Results come back through a queued signal on the GUI thread; a caller that
moved on (another feature selected) drops a job with :meth:`forget`, so a late
result never overwrites a newer view.
"""

from __future__ import annotations

import traceback
from typing import Callable, Dict, Optional, Tuple

from qgis.PyQt.QtCore import QObject, QRunnable, QThreadPool, pyqtSignal


class _Relay(QObject):
    done = pyqtSignal(int, object)
    failed = pyqtSignal(int, str)


class _Job(QRunnable):
    def __init__(self, token: int, work: Callable[[], object], relay: _Relay):
        super().__init__()
        self.token, self.work, self.relay = token, work, relay

    def run(self):
        try:
            result = self.work()
        except Exception as exc:  # reported to the dock, never lost in a worker thread
            self.relay.failed.emit(self.token, f"{type(exc).__name__}: {exc}\n{traceback.format_exc(limit=3)}")
            return
        self.relay.done.emit(self.token, result)


class BackgroundRunner(QObject):
    """A small private thread pool whose results are delivered to callbacks on the GUI thread."""

    def __init__(self, parent=None, threads: int = 2):
        super().__init__(parent)
        self.pool = QThreadPool(self)
        self.pool.setMaxThreadCount(threads)
        self._relay = _Relay()
        self._relay.done.connect(self._done)
        self._relay.failed.connect(self._failed)
        self._callbacks: Dict[int, Tuple[Callable, Optional[Callable]]] = {}
        self._next = 0

    def submit(self, work: Callable[[], object], on_done: Callable[[object], None],
               on_error: Optional[Callable[[str], None]] = None) -> int:
        self._next += 1
        self._callbacks[self._next] = (on_done, on_error)
        self.pool.start(_Job(self._next, work, self._relay))
        return self._next

    def forget(self, token: Optional[int]) -> None:
        self._callbacks.pop(token, None)

    def busy(self) -> bool:
        """True while a job's result has not been delivered (or forgotten)."""
        return bool(self._callbacks)

    def shutdown(self, timeout_ms: int = 10000) -> None:
        self._callbacks.clear()
        self.pool.clear()
        self.pool.waitForDone(timeout_ms)

    def _done(self, token: int, result) -> None:
        callbacks = self._callbacks.pop(token, None)
        if callbacks is not None:
            callbacks[0](result)

    def _failed(self, token: int, message: str) -> None:
        callbacks = self._callbacks.pop(token, None)
        if callbacks is not None and callbacks[1] is not None:
            callbacks[1](message)


class Jobs:
    """Background jobs by purpose ("image", "thumbnails", "add"): a new job replaces the pending one of its purpose.

    The replaced job's result is dropped, so a slow decode never overwrites what
    the user asked for since. Failures go to ``on_error(first line of the message)``.
    """

    def __init__(self, runner: BackgroundRunner, on_error: Callable[[str], None]):
        self.runner, self.on_error = runner, on_error
        self._pending: Dict[str, int] = {}  # purpose -> token of the job whose result is still wanted

    def submit(self, purpose: str, work: Callable[[], object], on_done: Callable[[object], None]) -> None:
        self.runner.forget(self._pending.pop(purpose, None))

        def done(result):
            self._pending.pop(purpose, None)
            on_done(result)

        def failed(message: str):
            self._pending.pop(purpose, None)
            self.on_error(message.splitlines()[0])

        self._pending[purpose] = self.runner.submit(work, done, failed)

    def forget_all(self) -> None:
        for purpose in list(self._pending):
            self.runner.forget(self._pending.pop(purpose))
