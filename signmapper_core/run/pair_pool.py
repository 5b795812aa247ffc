"""Pairs mapped in worker processes, their results handed back in driving order.

Pairs are independent until fusion, so each worker process decodes and detects
whole pairs on its own (its own OpenCV, its own classifier network, loaded once
per process by ``classifiers.classifier_for``). The caller consumes the results
in driving order, exactly as from the in-process loop, so progress, cancel,
skipped-pair reporting and the output do not depend on the number of workers.
Only a few pairs are in flight at a time (``AHEAD`` per worker): memory stays
flat however long the drive is.

The catalogue's templates are rendered once, here, while the workers start
(:class:`TemplateHandoff`): each worker's imports and network load overlap the
rendering instead of waiting for it.

Workers are started with ``spawn`` (not ``fork``): a QGIS process has Qt and
OpenCV threads that a forked child would inherit half-locked. Inside QGIS,
``sys.executable`` is the QGIS binary, so the workers' Python is looked up
(:func:`python_executable`). ``spawn`` would also run the caller's main script
again in each worker, which a PyQGIS script without a main guard cannot
survive; the workers need nothing of it, so it is kept from them
(:func:`_main_kept_from_workers`). When no worker starts at all, ``PoolNotStarted``
says so before any pair, and the caller maps in its own process.
"""

from __future__ import annotations

import multiprocessing
import os
import pickle
import sys
import tempfile
import threading
from concurrent.futures import ProcessPoolExecutor
from concurrent.futures import TimeoutError as FutureTimeout
from concurrent.futures.process import BrokenProcessPool
from contextlib import contextmanager
from dataclasses import replace
from pathlib import Path
from typing import Callable, Iterator, Optional

from ..errors import MappingError
from ..machine import available_cores
from ..progress import CancelCheck, check_cancelled
from .pair import map_pair

AHEAD = 2  # pairs queued per worker beyond the one it is working on
POLL_S = 0.1  # how often the cancel button is asked while waiting for a pair
OPENCV_THREADS_PER_WORKER = 1  # n workers x 1 thread: the cores are shared out by processes, not threads

_worker_state: dict = {}  # in a worker process: drive, catalogue, config and detector of the run
_MAIN_LOCK = threading.Lock()  # runs side by side in one process (QGIS) hide and restore __main__ in turn


class PoolNotStarted(RuntimeError):
    """No worker process could start (no Python found, the start failed, every worker died before its first
    pair): the pairs can still be mapped in the calling process."""


@contextmanager
def _main_kept_from_workers():
    """While workers are started: the caller's ``__main__`` names no file or module, so ``spawn`` does not run
    it again in each worker (a script without ``if __name__ == "__main__":`` would map again in each worker and
    fail). The pool's functions and ``detect`` are imported by their own module names."""
    main = sys.modules.get("__main__")
    with _MAIN_LOCK:
        hidden = {name: vars(main).pop(name) for name in ("__file__", "__spec__")
                  if main is not None and name in vars(main)}
        if main is not None:
            main.__spec__ = None
        try:
            yield
        finally:
            if main is not None:
                vars(main).pop("__spec__", None)
                vars(main).update(hidden)


def worker_count(requested: Optional[int], pairs: int) -> int:
    """Workers to start: ``requested`` (None or 0 = all available cores), never more than there are pairs."""
    if requested is not None and requested < 0:
        raise ValueError(f"worker processes must be 0 (all cores) or more, not {requested}")
    wanted = available_cores() if not requested else requested
    return max(1, min(wanted, pairs))


def python_executable() -> str:
    """The Python interpreter that runs worker processes: the one of the installation running this code.

    Not simply ``sys.executable``: in an application embedding Python (QGIS,
    qgis_process) that is the application, or whatever 'python3' the PATH finds.
    """
    version = f"{sys.version_info.major}.{sys.version_info.minor}"
    prefix = Path(sys.exec_prefix)
    candidates = [prefix / "bin" / f"python{version}", prefix / "bin" / "python3", prefix / "python.exe",
                  Path(sys.executable)]
    for candidate in candidates:
        if candidate.name.lower().startswith("python") and candidate.is_file():
            return str(candidate)
    raise RuntimeError(f"no Python interpreter found for worker processes in {prefix} "
                       f"(looked for {', '.join(str(c) for c in candidates)}); map with 1 worker process")


class TemplateHandoff:
    """The rendered templates handed from the pool's parent to workers that are already starting.

    The parent writes them to a file and then sets an event; a worker waits for the
    event only after its own imports and network load. A file, not a queue: a
    queue's unread megabytes would block the parent at exit if a worker never
    started. No file when the parent had none to give: the worker renders its own.
    """

    def __init__(self, context):
        self.ready = context.Event()
        handle, self.path = tempfile.mkstemp(prefix="signmapper-templates-", suffix=".pickle")
        os.close(handle)
        os.unlink(self.path)  # the name only: the file appears when the templates are written

    def send(self, templates: Optional[dict]) -> None:
        """Write ``templates`` (None: nothing to give) and let the workers go on."""
        try:
            if templates:
                partial = f"{self.path}.part"
                with open(partial, "wb") as out:
                    pickle.dump(templates, out, protocol=pickle.HIGHEST_PROTOCOL)
                os.replace(partial, self.path)
        finally:
            self.ready.set()

    def receive(self) -> Optional[dict]:
        """In a worker: the templates once the parent has sent them; None when it had none or has gone."""
        parent = multiprocessing.parent_process()
        while not self.ready.wait(1.0):
            if parent is not None and not parent.is_alive():
                return None
        try:
            with open(self.path, "rb") as source:
                return pickle.load(source)
        except FileNotFoundError:
            return None

    def close(self) -> None:
        """Release waiting workers and remove the file (call after the workers have ended)."""
        self.ready.set()
        for path in (self.path, f"{self.path}.part"):
            try:
                os.unlink(path)
            except FileNotFoundError:
                pass


def _run_file(drive, catalogue, config, detect: Optional[Callable]) -> str:
    """The run's drive, catalogue, settings and detector in a file the workers read as they start.

    Not in the workers' start arguments: ``spawn`` writes those into a pipe the
    parent also holds open, and a worker that dies before reading them all (its
    Python lacks OpenCV) would leave the parent waiting forever. What is sent at
    the start stays small; a worker that fails reading this file fails its start.
    """
    handle, path = tempfile.mkstemp(prefix="signmapper-run-", suffix=".pickle")
    with os.fdopen(handle, "wb") as out:
        pickle.dump((drive, catalogue, config, detect), out, protocol=pickle.HIGHEST_PROTOCOL)
    return path


def _start_worker(run_file: str, opencv_threads: int, templates: Optional[TemplateHandoff] = None,
                  started=None) -> None:
    import cv2

    with open(run_file, "rb") as source:
        drive, catalogue, config, detect = pickle.load(source)
    cv2.setNumThreads(opencv_threads)
    from ..pipeline.classifiers import classifier_for  # delays OpenCV until used
    from ..pipeline.detect import detect_pair  # noqa: F401  (imported lazily by the package)

    try:
        classifier_for(catalogue, config)  # the network, loaded once per process, also while the parent renders
    except Exception:  # noqa: BLE001  the parent loaded it; if it fails here, each pair reports why
        pass
    rendered = templates.receive() if templates is not None else None
    if rendered:
        from ..pipeline.classify import seed_canonical_templates  # delays OpenCV until used

        seed_canonical_templates(catalogue, rendered)
    _worker_state.update(drive=drive, catalogue=catalogue, config=config, detect=detect)
    if started is not None:
        started.set()  # a worker ran: a broken pool from now on is a crash while mapping, not a failed start


def _map_in_worker(index: int):
    state = _worker_state
    return map_pair(state["drive"], state["drive"].pairs[index], state["catalogue"], state["config"],
                    state["detect"])


def _is_project_catalogue(catalogue) -> bool:
    """Whether ``catalogue`` is one of the project's (a test's stand-in has no templates to render)."""
    from ..catalogue import Catalogue  # delays OpenCV until used

    return isinstance(catalogue, Catalogue)


def pooled_pairs(drive, catalogue, config, workers: int, is_cancelled: Optional[CancelCheck] = None,
                 detect: Optional[Callable] = None) -> Iterator:
    """Yield a ``mapping.PairResult`` per pair in driving order, mapped by ``workers`` processes.

    ``detect`` (None = ``pipeline.detect_pair``) must be importable by name in a
    fresh process (a module-level function). ``Cancelled`` is raised between pairs
    and while waiting for one; queued pairs are dropped, the pairs being mapped
    finish and the workers stop before it propagates (so nothing runs on).
    ``PoolNotStarted`` before the first pair when no worker could start.
    """
    try:
        context = multiprocessing.get_context("spawn")
        context.set_executable(python_executable())
        started = context.Event()
    except (RuntimeError, OSError) as exc:
        raise PoolNotStarted(str(exc)) from exc
    what = f"mapping drive {drive.root}"
    pairs = drive.pairs
    # the workers read pairs: the ground truth and what was wrong with it (an exception) stay here
    pairs_only = replace(drive, truth=None, truth_error=None, warnings=[])
    run_file = _run_file(pairs_only, catalogue, config, detect)
    handoff = TemplateHandoff(context) if _is_project_catalogue(catalogue) else None
    executor = ProcessPoolExecutor(workers, mp_context=context, initializer=_start_worker,
                                   initargs=(run_file, OPENCV_THREADS_PER_WORKER, handoff, started))
    pending, submitted = {}, 0

    def queue_up_to(index: int) -> None:
        nonlocal submitted
        with _main_kept_from_workers():  # submitting starts the workers
            while submitted < len(pairs) and submitted < index + workers * (1 + AHEAD):
                pending[submitted] = executor.submit(_map_in_worker, submitted)
                submitted += 1

    try:
        try:
            queue_up_to(0)
        except (OSError, BrokenProcessPool) as exc:  # the system refused new processes
            raise PoolNotStarted(str(exc)) from exc
        if handoff is not None:
            from ..pipeline.classify import canonical_templates  # delays OpenCV until used

            # rendered here once for all, on every core while the workers wait for them after their imports
            handoff.send(canonical_templates(catalogue, threads=available_cores()))
        for index in range(len(pairs)):
            queue_up_to(index)
            future = pending.pop(index)
            while True:
                check_cancelled(is_cancelled, what)
                try:
                    result = future.result(timeout=POLL_S)
                    break
                except FutureTimeout:
                    continue
                except BrokenProcessPool as exc:  # killed (out of memory) or crashed inside native code
                    if not started.is_set():
                        raise PoolNotStarted(f"{exc}; the workers' own error is in the log above") from exc
                    # every unfinished future fails alike: the pair that killed its worker is one of those in flight
                    raise MappingError(f"a worker process ended abruptly while mapping pairs {pairs[index].id} to "
                                       f"{pairs[submitted - 1].id} of {drive.root} (out of memory, or a crash: see "
                                       f"the log above); mapping with 1 worker process shows which pair") from exc
            result.record = pairs[index]  # the caller's record, not the worker's copy
            yield result
    finally:
        if handoff is not None:
            handoff.ready.set()  # workers still waiting for templates (a failed rendering, cancel) go on and stop
        executor.shutdown(wait=True, cancel_futures=True)
        os.unlink(run_file)
        if handoff is not None:
            handoff.close()
