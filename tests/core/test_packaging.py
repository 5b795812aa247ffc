"""The installable zip holds the plugin under ``sign_mapper/`` and leaves tests and CI out."""

import configparser
import subprocess
import sys
import zipfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]


def test_plugin_zip_layout(tmp_path):
    out = tmp_path / "sign_mapper.zip"
    subprocess.run([sys.executable, "-m", "scripts.build_zip", str(out)], check=True, cwd=REPO)
    names = zipfile.ZipFile(out).namelist()
    assert all(n.startswith("sign_mapper/") for n in names)
    for required in ("metadata.txt", "__init__.py", "provider/provider.py", "signmapper_core/drive/reader.py"):
        assert f"sign_mapper/{required}" in names
    assert not any(n.startswith(("sign_mapper/tests/", "sign_mapper/.ci/", "sign_mapper/bench/",
                                 "sign_mapper/training/")) for n in names)


def test_metadata_has_what_the_plugin_manager_needs():
    meta = configparser.ConfigParser()
    meta.read(REPO / "metadata.txt")
    general = meta["general"]
    for key in ("name", "qgisMinimumVersion", "description", "about", "version", "author", "email", "repository"):
        assert general.get(key, "").strip(), key
    assert general["hasProcessingProvider"] == "yes"
    assert (REPO / general["icon"]).is_file()


def test_core_never_imports_qgis_or_qt():
    offenders = []
    for path in (REPO / "signmapper_core").rglob("*.py"):
        for line in path.read_text().splitlines():
            stripped = line.strip()
            if stripped.startswith(("import ", "from ")) and any(
                mod in stripped.split()[1] for mod in ("qgis", "PyQt", "PySide", "sip")
            ):
                offenders.append(f"{path.relative_to(REPO)}: {stripped}")
    assert offenders == []
