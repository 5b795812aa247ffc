"""One pair through the pipeline: its files read, its detections found, or why it was skipped.

What a worker does with a pair, wherever it runs (this process, a worker process, a Dask worker); the mapping of a
whole drive (:mod:`.mapping`) hands pairs out and collects these results.
"""

from __future__ import annotations

import time as _time
import traceback as _traceback
from dataclasses import dataclass, field
from typing import Optional

from ..drive.plausibility import pair_warnings
from ..drive.reader import Drive, PairRecord
from ..errors import DriveFormatError

READ, DETECT = "read", "detect"  # where a skipped pair failed


@dataclass
class PairResult:
    """The detections of one pair, or why the pair was skipped.

    ``stage`` says where an ``error`` arose: READ (the pair's files) or DETECT (the
    pipeline raised; ``traceback`` then holds the formatted traceback for the log).
    """

    record: PairRecord
    detections: list = field(default_factory=list)  # pipeline.Detection
    error: Optional[str] = None
    seconds: float = 0.0  # loading and detecting
    load_seconds: float = 0.0  # of which decoding the files
    stage: Optional[str] = None
    traceback: Optional[str] = None
    warnings: list = field(default_factory=list)  # readable but useless input: no depth, no colour


def load_pair(drive: Drive, record: PairRecord):
    """(left, depth, right) of one pair as the pipeline takes them: right is only read where no depth is given."""
    left = drive.load_left(record)
    depth = drive.load_depth(record)
    right = drive.load_right(record) if depth is None else None
    return left, depth, right


def map_pair(drive: Drive, record: PairRecord, catalogue, config, detect=None) -> PairResult:
    """The detections of one pair, or why it was skipped (files unreadable, or the detection raised)."""
    from ..pipeline.depth_range import config_for_pair  # delays numpy until used

    if detect is None:
        from ..pipeline import detect_pair as detect  # OpenCV is imported only when mapping actually runs
    start = _time.perf_counter()
    try:
        left, depth, right = load_pair(drive, record)
    except DriveFormatError as exc:  # the readers report unreadable files as ImageReadError
        return PairResult(record, error=str(exc), seconds=_time.perf_counter() - start, stage=READ)
    loaded = _time.perf_counter()
    try:
        detections = detect(left, depth, right, drive.camera, record.pose, catalogue,
                            config_for_pair(config, record.ahead_m))
    except Exception as exc:  # noqa: BLE001 - one pair's failure is reported, the run goes on
        return PairResult(record, error=f"detection failed: {type(exc).__name__}: {exc}",
                          seconds=_time.perf_counter() - start, load_seconds=loaded - start, stage=DETECT,
                          traceback=_traceback.format_exc())
    return PairResult(record, detections, seconds=_time.perf_counter() - start, load_seconds=loaded - start,
                      warnings=pair_warnings(record, left, depth))
