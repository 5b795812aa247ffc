"""Synthetic stereo drives with ground truth, for tests, demos and benchmarks.

``generate_drive(out_dir, SimulationConfig(...))`` writes a drive folder
(``drive-format.md`` v1) with ``truth.csv``; ``true_poses(config)`` gives the
poses the images were rendered from (poses.csv holds them with GNSS/INS noise).
"""

from ..progress import Cancelled
from .config import DRAWABLE_SIGNS, LEGACY_FACES, SimulationConfig, SimulationSummary
from .generator import generate_drive, recorded_poses, true_poses

__all__ = ["DRAWABLE_SIGNS", "LEGACY_FACES", "Cancelled", "SimulationConfig", "SimulationSummary", "generate_drive",
           "recorded_poses", "true_poses"]
