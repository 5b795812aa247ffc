"""Facts of the machine this process runs on, for whatever sizes its work by them (worker pools, OCR)."""

from __future__ import annotations

import os


def available_cores() -> int:
    """Cores this process may run on (its affinity, not the machine's count)."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # not on Linux
        return max(1, os.cpu_count() or 1)
