"""Processing algorithms of Sign Mapper: thin wrappers around ``signmapper_core``.

Algorithm modules import the core lazily inside ``process`` so the
provider loads (and explains what to install) even when OpenCV is missing.
"""

import importlib

# module -> class, in the order the toolbox lists them
ALGORITHMS = (
    ("map_signs", "MapSignsAlgorithm"),
    ("evaluate", "EvaluateAlgorithm"),
    ("changes", "ChangesAlgorithm"),
    ("export_inventory", "ExportInventoryAlgorithm"),
    ("inventory_atlas", "InventoryAtlasAlgorithm"),
    ("export_signalo", "ExportToSignaloAlgorithm"),
    ("import_drive", "ImportDriveAlgorithm"),
    ("drive_trajectory", "DriveTrajectoryAlgorithm"),
    ("synthetic_drive", "SyntheticDriveAlgorithm"),
)


def algorithm_classes(on_error=None):
    """Every algorithm class that imports; ``on_error(module, exception)`` hears of those that do not.

    An exception escaping QgsProcessingProvider.loadAlgorithms aborts QGIS, so
    one broken module must cost only its own algorithm.
    """
    classes = []
    for module, name in ALGORITHMS:
        try:
            classes.append(getattr(importlib.import_module(f".{module}", __name__), name))
        except Exception as exc:  # noqa: BLE001 - reported, never fatal
            if on_error is None:
                raise
            on_error(module, exc)
    return classes
