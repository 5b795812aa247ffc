"""What travels between a Dask client and its workers: one pair's job out, its detections back, as plain data.

A worker imports the core as the top-level package ``signmapper_core`` (its
PYTHONPATH holds the plugin folder), whatever name the client imported it under
(inside QGIS it is ``sign_mapper.signmapper_core``, and a worker has no QGIS to
import that package). So neither direction pickles the core's classes: a job is
a dict of strings, numbers and the settings as JSON-ready dicts; a result is the
detections as dicts of numbers and arrays. The task function itself is named
by the workers' module name (:func:`worker_function`); the scheduler unpickles
each task too, so it imports this module (nothing else of the core): the core's modules are imported inside
the functions that run on a worker, keeping numpy and OpenCV out of the scheduler. No Dask import here:
workers import this module, and so does the client, only when a cluster is used.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import dataclasses
import importlib
import json
import os
import sys
from functools import lru_cache
from pathlib import Path
from typing import Optional

from .. import __version__
from ..output.run_settings import pipeline_config_of
from ..output.run_table import settings_dict

WORKER_PACKAGE = "signmapper_core"  # the core's name on a worker: its PYTHONPATH holds the plugin folder
TASK_MODULE = f"{WORKER_PACKAGE}.{__name__.rpartition(WORKER_PACKAGE + '.')[2]}"  # this module, on a worker


class _Module:
    """A module, pickled as its name: unpickled by importing it in the process that unpickles."""

    def __init__(self, name: str):
        self.name = name

    def __reduce__(self):
        return importlib.import_module, (self.name,)


class _ByName:
    """A function of this module, pickled as ``signmapper_core.run.cluster_task.<name>`` whatever the client calls
    the core; called in the client it runs the client's own copy (Dask only needs it callable there)."""

    def __init__(self, name: str):
        self.name = name
        self.__name__ = name  # Dask names a task's key after its function

    def __call__(self, *args, **kwargs):
        return globals()[self.name](*args, **kwargs)

    def __reduce__(self):
        return getattr, (_Module(TASK_MODULE), self.name)


def worker_function(name: str):
    """The function ``name`` of this module as the workers import it."""
    if name not in ("map_pair_task", "worker_report", "scheduler_report"):
        raise ValueError(f"no worker function '{name}'")
    return _ByName(name)


def scheduler_report() -> dict:
    """What the scheduler runs: the core's version (it unpickles every task, so it imports this module too)."""
    return {"version": __version__}


def worker_report() -> dict:
    """What a worker runs: the core's version and OpenCV's (an ImportError names what it lacks)."""
    import cv2

    return {"version": __version__, "opencv": cv2.__version__}


def pair_job(drive, record, catalogue, config, detect=None) -> dict:
    """The job of one pair: the drive's paths, camera and the pair's pose; the catalogue folder (None: the
    worker's own bundled catalogue) and the pipeline settings as JSON-ready dicts."""
    from ..catalogue.model import DEFAULT_CATALOGUE_DIR  # delays OpenCV and numpy until used

    folder = Path(catalogue.folder)
    bundled = folder.resolve() == DEFAULT_CATALOGUE_DIR.resolve()
    return {
        "root": str(drive.root), "crs": drive.crs, "camera": dataclasses.asdict(drive.camera),
        "record": {"index": record.index, "id": record.id, "time": record.time,
                   "pose": dataclasses.asdict(record.pose), "left_path": str(record.left_path),
                   "right_path": _text(record.right_path), "depth_path": _text(record.depth_path),
                   "ahead_m": record.ahead_m},
        "catalogue": None if bundled else str(folder), "config": settings_dict(config), "detect": detect,
    }


def _text(path) -> Optional[str]:
    return None if path is None else str(path)


def _path(text) -> Optional[Path]:
    return None if text is None else Path(text)


@lru_cache(maxsize=4)
def _catalogue(folder: Optional[str]):
    from ..catalogue import load_catalogue  # delays OpenCV and numpy until used

    return load_catalogue(folder)


@lru_cache(maxsize=8)
def _config(settings: str):
    """The PipelineConfig of a job's settings (as sorted JSON, so a worker builds each config once)."""

    return pipeline_config_of(json.loads(settings), "pipeline settings of the job")


# glibc mallopt parameters: the largest buffer still taken from the heap, and the free heap top kept
M_TRIM_THRESHOLD, M_MMAP_THRESHOLD = -1, -3
IMAGE_BUFFER_BYTES = 32 * 1024 * 1024  # glibc's own ceiling for the adaptive threshold (64-bit): a Full-HD depth map


@lru_cache(maxsize=1)
def heap_for_images() -> bool:
    """Let image-sized buffers come from the heap again in a Dask worker (once per process; True if done).

    Dask's nanny starts workers with MALLOC_TRIM_THRESHOLD_ set (to hand memory back to the system). Setting it
    turns off glibc's adaptive mmap threshold, so every buffer over 128 kB, i.e. every image, depth map and mask
    of a pair, becomes a fresh mmap that the kernel zero-fills page by page: measured 1.6x the time per pair of
    a process-pool worker. Raising the threshold as the adaptive one would restores the pool's speed.
    """
    if "MALLOC_TRIM_THRESHOLD_" not in os.environ or not sys.platform.startswith("linux"):
        return False
    try:
        libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6")
        return bool(libc.mallopt(M_MMAP_THRESHOLD, IMAGE_BUFFER_BYTES)) and \
            bool(libc.mallopt(M_TRIM_THRESHOLD, 2 * IMAGE_BUFFER_BYTES))
    except (OSError, AttributeError):  # not glibc: nothing to undo
        return False


def map_pair_task(job: dict) -> dict:
    """Run on a worker: map the pair of ``job`` (reading its files from the shared path), return plain data."""
    import cv2

    from ..drive.reader import Drive, PairRecord  # delays numpy until used
    from ..geometry import Camera, Pose  # delays numpy until used
    from .pair import map_pair  # delays numpy until used

    heap_for_images()
    cv2.setNumThreads(1)  # a worker runs a pair per thread: the cores are shared out by Dask's threads
    r = job["record"]
    record = PairRecord(r["index"], r["id"], r["time"], Pose(**r["pose"]), Path(r["left_path"]),
                        _path(r["right_path"]), _path(r["depth_path"]), r.get("ahead_m"))
    drive = Drive(Path(job["root"]), job["crs"], Camera(**job["camera"]), [record])
    config = _config(json.dumps(job["config"], sort_keys=True))
    result = map_pair(drive, record, _catalogue(job["catalogue"]), config, job["detect"])
    return {"index": record.index, "detections": [dataclasses.asdict(d) for d in result.detections],
            "error": result.error, "seconds": result.seconds, "load_seconds": result.load_seconds,
            "stage": result.stage, "traceback": result.traceback, "warnings": list(result.warnings)}


def pair_result(data: dict, record):
    """The client's ``mapping.PairResult`` of a worker's answer, for the client's own ``record``."""
    from ..pipeline.detection import Detection  # delays numpy until used
    from .pair import PairResult  # delays numpy until used

    if data["index"] != record.index:
        raise ValueError(f"a worker answered for pair index {data['index']}, expected {record.index} ({record.id})")
    detections = [Detection(**d) for d in data["detections"]]
    return PairResult(record, detections, error=data["error"], seconds=data["seconds"],
                      load_seconds=data["load_seconds"], stage=data["stage"], traceback=data["traceback"],
                      warnings=data["warnings"])
