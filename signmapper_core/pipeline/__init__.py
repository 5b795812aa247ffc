"""Detection core of Sign Mapper (Cavegn 2011): one module per pipeline step.

Entry points: :func:`detect_pair` for a whole stereo pair and
:func:`detect_in_window` for the review step "add a missed sign by clicking it".
They are imported on first use (OpenCV with them), so the settings
(:class:`PipelineConfig`) can be read where OpenCV is not installed.
"""

from .config import PipelineConfig
from .detection import Detection

__all__ = ["Detection", "PipelineConfig", "detect_in_window", "detect_pair"]


def __getattr__(name):
    if name in ("detect_pair", "detect_in_window"):
        from . import detect  # delays OpenCV until used

        return getattr(detect, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
