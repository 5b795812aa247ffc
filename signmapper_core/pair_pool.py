"""Pairs mapped in worker processes, their results handed back in driving order.

Pairs are independent until fusion, so each worker process decodes and detects
whole pairs on its own (its own OpenCV, its own classifier network, loaded once
per process by ``classifiers.classifier_for``). The caller consumes the results
in driving order, exactly as from the in-process loop, so progress, cancel,
skipped-pair reporting and the output do not depend on the number of workers.
Only a few pairs are in flight at a time (``AHEAD`` per worker): memory stays
flat however long the drive is.

Workers are started with ``spawn`` (not ``fork``): a QGIS process has Qt and
OpenCV threads that a forked child would inherit half-locked. Inside QGIS,
``sys.executable`` is the QGIS binary, so the workers' Python is looked up
(:func:`python_executable`).
"""

from __future__ import annotations

import multiprocessing
import os
import sys
from concurrent.futures import ProcessPoolExecutor
from concurrent.futures import TimeoutError as FutureTimeout
from concurrent.futures.process import BrokenProcessPool
from dataclasses import replace
from pathlib import Path
from typing import Callable, Iterator, Optional

from .errors import MappingError
from .progress import CancelCheck, check_cancelled

AHEAD = 2  # pairs queued per worker beyond the one it is working on
POLL_S = 0.1  # how often the cancel button is asked while waiting for a pair
OPENCV_THREADS_PER_WORKER = 1  # n workers x 1 thread: the cores are shared out by processes, not threads

_worker_state: dict = {}  # in a worker process: drive, catalogue, config and detector of the run


def available_cores() -> int:
    """Cores this process may run on (its affinity, not the machine's count)."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # not on Linux
        return max(1, os.cpu_count() or 1)


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


def _start_worker(drive, catalogue, config, detect: Optional[Callable], opencv_threads: int,
                  templates: Optional[dict] = None) -> None:
    import cv2

    cv2.setNumThreads(opencv_threads)
    if templates:
        from .pipeline.classify import seed_canonical_templates

        seed_canonical_templates(catalogue, templates)
    _worker_state.update(drive=drive, catalogue=catalogue, config=config, detect=detect)


def _map_in_worker(index: int):
    from .mapping import map_pair

    state = _worker_state
    return map_pair(state["drive"], state["drive"].pairs[index], state["catalogue"], state["config"],
                    state["detect"])


def _rendered_templates(catalogue) -> Optional[dict]:
    """The catalogue's templates rendered once here for all workers (each would decode the PNGs itself); None
    for a catalogue that is not one of the project's (a test's stand-in)."""
    from .catalogue import Catalogue
    from .pipeline.classify import canonical_templates

    return canonical_templates(catalogue) if isinstance(catalogue, Catalogue) else None


def pooled_pairs(drive, catalogue, config, workers: int, is_cancelled: Optional[CancelCheck] = None,
                 detect: Optional[Callable] = None) -> Iterator:
    """Yield a ``mapping.PairResult`` per pair in driving order, mapped by ``workers`` processes.

    ``detect`` (None = ``pipeline.detect_pair``) must be importable by name in a
    fresh process (a module-level function). ``Cancelled`` is raised between pairs
    and while waiting for one; queued pairs are dropped, the pairs being mapped
    finish and the workers stop before it propagates (so nothing runs on).
    """
    context = multiprocessing.get_context("spawn")
    context.set_executable(python_executable())
    what = f"mapping drive {drive.root}"
    pairs = drive.pairs
    # the workers read pairs: the ground truth and what was wrong with it (an exception) stay here
    pairs_only = replace(drive, truth=None, truth_error=None, warnings=[])
    executor = ProcessPoolExecutor(workers, mp_context=context, initializer=_start_worker,
                                   initargs=(pairs_only, catalogue, config, detect, OPENCV_THREADS_PER_WORKER,
                                             _rendered_templates(catalogue)))
    try:
        pending, submitted = {}, 0
        for index in range(len(pairs)):
            while submitted < len(pairs) and submitted < index + workers * (1 + AHEAD):
                pending[submitted] = executor.submit(_map_in_worker, submitted)
                submitted += 1
            future = pending.pop(index)
            while True:
                check_cancelled(is_cancelled, what)
                try:
                    result = future.result(timeout=POLL_S)
                    break
                except FutureTimeout:
                    continue
                except BrokenProcessPool as exc:  # killed (out of memory) or crashed inside native code
                    # every unfinished future fails alike: the pair that killed its worker is one of those in flight
                    raise MappingError(f"a worker process ended abruptly while mapping pairs {pairs[index].id} to "
                                       f"{pairs[submitted - 1].id} of {drive.root} (out of memory, or a crash: see "
                                       f"the log above); mapping with 1 worker process shows which pair") from exc
            result.record = pairs[index]  # the caller's record, not the worker's copy
            yield result
    finally:
        executor.shutdown(wait=True, cancel_futures=True)
