"""Check that the Python that runs QGIS can import what the core needs.

QGIS desktop and ``qgis_process`` run the system interpreter, not the
developer's venv, so a missing OpenCV is the most common installation fault.
It is reported with the command that fixes it instead of a traceback.
"""

from __future__ import annotations

import importlib.util
import sys

# module name -> (pip requirement, Debian package)
REQUIREMENTS = {
    "numpy": ("numpy", "python3-numpy"),
    "cv2": ("opencv-python-headless==4.11.0.86", "python3-opencv"),
    "pyproj": ("pyproj", "python3-pyproj"),
    "PIL": ("Pillow", "python3-pil"),
}


def missing_modules() -> list[str]:
    """Names of required modules the running interpreter cannot import."""
    missing = []
    for module in REQUIREMENTS:
        try:
            if importlib.util.find_spec(module) is None:
                missing.append(module)
        except (ImportError, ValueError):  # ValueError: sys.modules[name] is None
            missing.append(module)
    return missing


def install_hint(missing: list[str]) -> str:
    """A user-facing message naming what is missing and how to install it."""
    pip = " ".join(f'"{REQUIREMENTS[m][0]}"' for m in missing)
    debs = " ".join(REQUIREMENTS[m][1] for m in missing)
    names = ", ".join("OpenCV (cv2)" if m == "cv2" else m for m in missing)
    return (
        f"Sign Mapper needs {names}, which the Python running QGIS ({sys.executable}) cannot import. "
        f"Install it for that Python, e.g. `{sys.executable} -m pip install --user {pip}` "
        f"(on Debian/Ubuntu `sudo apt install {debs}` also works, or run `make setup` in the plugin "
        "folder and start QGIS with the venv's site-packages on PYTHONPATH), then restart QGIS."
    )
