"""Real drives in: a survey's raw stereo images, calibration and poses converted into a drive folder.

``import_drive(out_dir, source, ImportOptions(...))`` with a source from
``generic_source(GenericInputs(...))`` (image folders, calibration file, pose
CSV) or ``kitti_source(folder)`` (the KITTI raw preset). Command line:
``python -m signmapper_core.importdrive OUT ...`` (``--help``).
"""

from .attitude import CONVENTIONS, convention
from .calibration import StereoCalibration, read_calibrations
from .camera_poses import NORTHS, Orientation
from .epipolar import EpipolarCheck, match_features
from .generic import GenericInputs, generic_source
from .importer import IMAGE_FORMATS, DriveSource, ImportOptions, ImportSummary, import_drive
from .kitti import kitti_source, utm_crs
from .mount import Mount
from .rectify import Rectifier

__all__ = [
    "CONVENTIONS", "IMAGE_FORMATS", "NORTHS", "DriveSource", "EpipolarCheck", "GenericInputs", "ImportOptions",
    "ImportSummary", "Mount", "Orientation", "Rectifier", "StereoCalibration", "convention", "generic_source",
    "import_drive", "kitti_source", "match_features", "read_calibrations", "utm_crs",
]
