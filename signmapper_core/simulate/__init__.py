"""Synthetic stereo drives with ground truth, for tests, demos and benchmarks.

``generate_drive(out_dir, SimulationConfig(...))`` writes a drive folder
(``drive-format.md`` v1) with ``truth.csv``; ``true_poses(config)`` gives the
poses the images were rendered from (poses.csv holds them with GNSS/INS noise).
The generator is imported on first use (OpenCV with it), so the settings
(:class:`SimulationConfig`) can be read where OpenCV is not installed.
"""

from ..progress import Cancelled
from .config import DRAWABLE_SIGNS, LEGACY_FACES, SimulationConfig, SimulationSummary

__all__ = ["DRAWABLE_SIGNS", "LEGACY_FACES", "Cancelled", "SimulationConfig", "SimulationSummary", "generate_drive",
           "recorded_poses", "true_poses"]


def __getattr__(name):
    if name in ("generate_drive", "recorded_poses", "true_poses"):
        from . import generator  # delays OpenCV until used

        return getattr(generator, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
