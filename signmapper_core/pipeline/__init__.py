"""Detection core of Sign Mapper (Cavegn 2011): one module per pipeline step.

Entry points: :func:`detect_pair` for a whole stereo pair and
:func:`detect_in_window` for the review step "add a missed sign by clicking it".
"""

from .config import PipelineConfig
from .detect import detect_in_window, detect_pair
from .detection import Detection

__all__ = ["Detection", "PipelineConfig", "detect_in_window", "detect_pair"]
