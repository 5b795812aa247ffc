"""Processing algorithms of Sign Mapper: thin wrappers around ``signmapper_core``.

Algorithm modules import the core lazily inside ``processAlgorithm`` so the
provider loads (and explains what to install) even when OpenCV is missing.
"""


def algorithm_classes():
    """Every algorithm class the provider registers."""
    from .drive_trajectory import DriveTrajectoryAlgorithm
    from .evaluate import EvaluateAlgorithm
    from .map_signs import MapSignsAlgorithm
    from .synthetic_drive import SyntheticDriveAlgorithm

    return [MapSignsAlgorithm, EvaluateAlgorithm, DriveTrajectoryAlgorithm, SyntheticDriveAlgorithm]
