"""Set-up without PYTHONPATH: where OpenCV is looked for, which Python the message names, the pip command."""

import importlib.util
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
spec = importlib.util.spec_from_file_location("sm_dependencies", REPO / "dependencies.py")
deps = importlib.util.module_from_spec(spec)
spec.loader.exec_module(deps)


@pytest.fixture
def fake_python(tmp_path, monkeypatch):
    """A QGIS-like process: prefix with bin/python3.X, sys.executable the QGIS binary found through a shim PATH."""
    prefix = tmp_path / "usr"
    python = prefix / "bin" / f"python{sys.version_info.major}.{sys.version_info.minor}"
    python.parent.mkdir(parents=True)
    python.write_text("")
    shim = tmp_path / ".pyenv" / "shims" / "python3"
    shim.parent.mkdir(parents=True)
    shim.write_text("")
    for name in ("base_exec_prefix", "exec_prefix", "base_prefix"):
        monkeypatch.setattr(sys, name, str(prefix))
    monkeypatch.setattr(sys, "executable", str(shim))
    return python


def test_the_python_qgis_runs_is_found_from_its_prefix_not_from_path(fake_python):
    assert deps.qgis_python() == fake_python


def test_message_names_that_python_and_a_user_install_command(fake_python, monkeypatch):
    monkeypatch.setattr(deps, "externally_managed", lambda: True)
    hint = deps.install_hint(["cv2"])
    assert f"({fake_python}, Python {sys.version_info.major}.{sys.version_info.minor})" in hint
    assert f"`{fake_python} -m pip install --user --break-system-packages \"opencv-python-headless==4.11.0.86\"`" \
        in hint
    assert "shims" not in hint and "python3-opencv" in hint and "PYTHONPATH" not in hint


def test_pip_command_only_breaks_system_packages_where_the_python_is_externally_managed(fake_python, monkeypatch):
    monkeypatch.setattr(deps, "externally_managed", lambda: False)
    assert deps.pip_install_command(["cv2", "PIL"]) == [str(fake_python), "-m", "pip", "install", "--user",
                                                        "opencv-python-headless==4.11.0.86", "Pillow"]
    monkeypatch.setattr(deps, "externally_managed", lambda: True)
    assert "--break-system-packages" in deps.pip_install_command(["cv2"])


def test_opencv_is_found_in_the_plugins_venv_and_the_user_site(tmp_path, monkeypatch):
    plugin = tmp_path / "sign_mapper"
    venv_site = plugin / ".venv" / "lib" / f"python{sys.version_info.major}.{sys.version_info.minor}" / \
        "site-packages"
    (venv_site / "fakecv_for_test").mkdir(parents=True)
    (venv_site / "fakecv_for_test" / "__init__.py").write_text("VALUE = 42\n")
    user_site = tmp_path / "user-site"
    user_site.mkdir()
    monkeypatch.setattr(deps.site, "getusersitepackages", lambda: str(user_site))
    monkeypatch.setattr(deps.site, "ENABLE_USER_SITE", True)
    monkeypatch.setattr(sys, "path", [p for p in sys.path if p not in (str(user_site), str(venv_site))])
    assert deps.extra_site_dirs(plugin) == [user_site, venv_site]
    added = deps.add_install_locations(plugin)
    assert added == [str(user_site), str(venv_site)] and sys.path[-2:] == added  # after QGIS's own paths
    assert importlib.import_module("fakecv_for_test").VALUE == 42
    assert deps.add_install_locations(plugin) == []  # once
