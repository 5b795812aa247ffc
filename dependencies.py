"""Check that the Python that runs QGIS can import what the core needs, and say how to fix it if not.

QGIS desktop and ``qgis_process`` run the system interpreter, not the
developer's venv, so a missing OpenCV is the most common installation fault.
Before checking, the places the README installs OpenCV to are put on the path
(the user site-packages of QGIS's Python, and ``.venv`` in the plugin folder
from ``make setup``), so nobody needs PYTHONPATH. What is still missing is
reported with the command that fixes it, for the interpreter QGIS really runs
(inside QGIS ``sys.executable`` is the QGIS binary, or whatever ``python3`` is
first on PATH, e.g. a pyenv shim). No QGIS import here: tests check the
messages and commands without QGIS and without running pip.
"""

from __future__ import annotations

import importlib.util
import site
import sys
import sysconfig
from pathlib import Path
from typing import List, Optional

PLUGIN_DIR = Path(__file__).resolve().parent

# module name -> (pip requirement, Debian package)
REQUIREMENTS = {
    "numpy": ("numpy", "python3-numpy"),
    "cv2": ("opencv-python-headless==4.11.0.86", "python3-opencv"),
    "pyproj": ("pyproj", "python3-pyproj"),
    "PIL": ("Pillow", "python3-pil"),
}


def _version_dir() -> str:
    return f"python{sys.version_info.major}.{sys.version_info.minor}"


def extra_site_dirs(plugin_dir: Path = PLUGIN_DIR) -> List[Path]:
    """Existing folders where the README installs OpenCV for this Python, in the order they are tried."""
    candidates = []
    if site.ENABLE_USER_SITE is not False:
        candidates.append(Path(site.getusersitepackages()))
    candidates.append(plugin_dir / ".venv" / "lib" / _version_dir() / "site-packages")  # make setup
    candidates.append(plugin_dir / ".venv" / "Lib" / "site-packages")  # a venv made on Windows
    return [c for c in candidates if c.is_dir()]


def add_install_locations(plugin_dir: Path = PLUGIN_DIR) -> List[str]:
    """Append the install folders to ``sys.path`` (after QGIS's own, so Debian's numpy stays first); returns
    the folders added."""
    added = []
    for folder in extra_site_dirs(plugin_dir):
        if str(folder) not in sys.path:
            sys.path.append(str(folder))
            added.append(str(folder))
    if added:
        importlib.invalidate_caches()
    return added


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


def qgis_python() -> Optional[Path]:
    """The interpreter binary of the Python QGIS runs, found from its prefix (never from PATH)."""
    version = _version_dir()
    candidates = []
    for prefix in dict.fromkeys((sys.base_exec_prefix, sys.exec_prefix, sys.base_prefix)):
        root = Path(prefix)
        candidates += [root / "bin" / version, root / "bin" / "python3", root / "python.exe", root / "python3.exe",
                       root / "apps" / "Python3" / "python.exe"]
    executable = Path(sys.executable) if sys.executable else None
    if executable is not None and executable.name.startswith("python") and "shims" not in executable.parts:
        candidates.append(executable)
    return next((c for c in candidates if c.is_file()), None)


def externally_managed() -> bool:
    """Debian and others mark their Python with EXTERNALLY-MANAGED: pip then needs --break-system-packages
    even for --user (it only adds to the user's site-packages; Debian's own packages are untouched)."""
    return (Path(sysconfig.get_path("stdlib")) / "EXTERNALLY-MANAGED").is_file()


def pip_install_command(missing: list[str], python: Optional[Path] = None) -> List[str]:
    """The pip command that installs ``missing`` modules into the user's site-packages of QGIS's Python."""
    python = python or qgis_python() or Path("python3")
    command = [str(python), "-m", "pip", "install", "--user"]
    if externally_managed():
        command.append("--break-system-packages")
    return command + [REQUIREMENTS[m][0] for m in missing]


def install_hint(missing: list[str]) -> str:
    """A user-facing message naming what is missing, the Python that lacks it and how to install it."""
    debs = " ".join(REQUIREMENTS[m][1] for m in missing)
    names = ", ".join("OpenCV (cv2)" if m == "cv2" else m for m in missing)
    python = qgis_python()
    which = f"{python}, Python {sys.version_info.major}.{sys.version_info.minor}" if python else \
        f"Python {sys.version_info.major}.{sys.version_info.minor} in {sys.base_exec_prefix}"
    command = " ".join(f'"{part}"' if "=" in part or " " in part else part for part in pip_install_command(missing))
    return (
        f"Sign Mapper needs {names}, which the Python running QGIS ({which}) cannot import. "
        f"Install it for that Python: `{command}` "
        f"(on Debian/Ubuntu `sudo apt install {debs}` also works), then restart QGIS."
    )
