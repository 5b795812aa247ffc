"""Run ``qgis_process.bin`` with the plugin enabled in a throw-away profile."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sysconfig
from pathlib import Path

QGIS_PROCESS = shutil.which("qgis_process.bin") or "/usr/bin/qgis_process.bin"


def qgis_process_env(plugin_dir: Path, profile_dir: Path) -> dict:
    """Environment that loads the plugin from ``plugin_dir`` with this interpreter's site-packages (OpenCV)."""
    env = dict(os.environ)
    env.update(
        QT_QPA_PLATFORM="offscreen",
        QGIS_PLUGINPATH=str(plugin_dir),
        QGIS_CUSTOM_CONFIG_PATH=str(profile_dir),
        PYTHONPATH=os.pathsep.join(filter(None, [sysconfig.get_paths()["purelib"], env.get("PYTHONPATH")])),
    )
    return env


def enable_plugin(env: dict) -> None:
    """``plugins enable`` exits 1 when the plugin is already enabled; anything else is an error."""
    result = subprocess.run(
        [QGIS_PROCESS, "plugins", "enable", "sign_mapper"], env=env, capture_output=True, text=True, timeout=120
    )
    if result.returncode not in (0, 1):
        raise RuntimeError(f"enabling the plugin failed: {result.stdout}\n{result.stderr}")


def run_algorithm(env: dict, algorithm: str, **params) -> tuple[int, dict | None, str]:
    """Run an algorithm with ``--json``; return (exit code, parsed JSON or None, stderr)."""
    args = [QGIS_PROCESS, "--json", "run", algorithm, "--"] + [f"{k}={v}" for k, v in params.items()]
    result = subprocess.run(args, env=env, capture_output=True, text=True, timeout=900)
    try:
        data = json.loads(result.stdout)
    except json.JSONDecodeError:
        data = None
    return result.returncode, data, result.stdout + result.stderr
