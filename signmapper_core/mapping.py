"""Running the detection pipeline over a whole drive, one pair at a time.

This is the loop every front end shares (Processing algorithm, command line,
a distributed engine later): pairs are decoded lazily, a pair whose files are
corrupt is reported and skipped rather than ending the run, and cancellation is
checked between pairs.
"""

from __future__ import annotations

import time as _time
from dataclasses import dataclass, field
from typing import Callable, Iterator, Optional

from .drive import Drive, PairRecord
from .errors import DriveFormatError


@dataclass
class PairResult:
    """The detections of one pair, or why the pair was skipped."""

    record: PairRecord
    detections: list = field(default_factory=list)
    error: Optional[str] = None
    seconds: float = 0.0


def map_drive(drive: Drive, catalogue, config,
              is_cancelled: Optional[Callable[[], bool]] = None) -> Iterator[PairResult]:
    """Yield a :class:`PairResult` per pair in driving order.

    Stops quietly when ``is_cancelled()`` turns true; the caller decides what a
    cancelled run leaves behind.
    """
    from .pipeline import detect_pair  # OpenCV is imported only when mapping actually runs

    for record in drive.pairs:
        if is_cancelled is not None and is_cancelled():
            return
        start = _time.perf_counter()
        try:
            left = drive.load_left(record)
            depth = drive.load_depth(record)
            right = drive.load_right(record) if depth is None else None
        except DriveFormatError as exc:  # the readers report unreadable files as ImageReadError
            yield PairResult(record, error=str(exc), seconds=_time.perf_counter() - start)
            continue
        detections = detect_pair(left, depth, right, drive.camera, record.pose, catalogue, config)
        yield PairResult(record, detections, seconds=_time.perf_counter() - start)
