"""``scripts.calibrate_classifier``: which photographs it calibrates on (``--source``), on constructed manifests.

The GTSRB tune crops share physical signs with the GTSRB report half; the GTSDB tune scenes, split by scene,
do not. The run here goes through the shipped network on two constructed tune signs with ``--dry-run``: it
checks the path, not a calibration.
"""

from __future__ import annotations

import json

import cv2
import numpy as np
import pytest

from scripts import calibrate_classifier as calibrate
from signmapper_core.catalogue import load_catalogue
from signmapper_core.pipeline.classifiers import model_card_path
from signmapper_core.validation import MANIFEST_COLUMNS, SCENE_COLUMN


def _write_csv(path, header, rows):
    path.write_text("\n".join([",".join(header)] + [",".join(map(str, r)) for r in rows]) + "\n", encoding="utf-8")


@pytest.fixture(scope="module")
def real_like(tmp_path_factory, shipped_catalogue):
    """crops.csv (a tune and a report crop) and scenes.csv (two tune signs, one report sign) of rendered faces."""
    root = tmp_path_factory.mktemp("real")
    crop = np.full((60, 60, 3), 120, np.uint8)
    bgr, alpha = shipped_catalogue.render("3.02", 50)
    a, (h, w) = alpha[..., None] / 255.0, alpha.shape
    crop[5:5 + h, 5:5 + w] = (bgr * a + crop[5:5 + h, 5:5 + w] * (1 - a)).astype(np.uint8)
    cv2.imwrite(str(root / "crop.png"), crop)
    scene = np.full((200, 300, 3), 110, np.uint8)
    scene[20:80, 20:80] = crop
    scene[100:160, 200:260] = crop
    cv2.imwrite(str(root / "scene.png"), scene)
    other = np.full((200, 300, 3), 110, np.uint8)
    other[20:80, 20:80] = crop
    cv2.imwrite(str(root / "other.png"), other)
    _write_csv(root / "crops.csv", (*MANIFEST_COLUMNS, SCENE_COLUMN),
               [["crop.png", 5, 5, 55, 55, "3.02", "same", "tune", "gtsrb-test", ""],
                ["crop.png", 6, 6, 54, 54, "3.02", "same", "report", "gtsrb-test", ""]])
    _write_csv(root / "scenes.csv", (*MANIFEST_COLUMNS, SCENE_COLUMN),
               [["scene.png", 25, 25, 75, 75, "3.02", "same", "tune", "gtsdb", "00001"],
                ["scene.png", 205, 105, 255, 155, "3.02", "same", "tune", "gtsdb", "00001"],
                ["other.png", 25, 25, 75, 75, "3.02", "same", "report", "gtsdb", "00007"]])
    return root


def test_the_source_picks_the_manifest_and_the_tune_half_only(real_like, shipped_catalogue):
    ids = {e.id for e in shipped_catalogue}
    crops = calibrate.calibration_signs(real_like, "gtsrb", "tune", ids, shipped_catalogue)
    assert [(s.image.name, s.source, s.split) for s in crops] == [("crop.png", "gtsrb-test", "tune")]
    scenes = calibrate.calibration_signs(real_like, "gtsdb", "tune", ids, shipped_catalogue)
    assert [(s.image.name, s.bbox, s.scene) for s in scenes] == [("scene.png", (25, 25, 50, 50), "00001"),
                                                                  ("scene.png", (205, 105, 50, 50), "00001")]
    assert len(calibrate.calibration_signs(real_like, "gtsdb", "tune", ids, shipped_catalogue, limit=1)) == 1
    assert "split by scene" in calibrate.SOURCES["gtsdb"][1]
    assert "share physical signs" in calibrate.SOURCES["gtsrb"][1]


def test_a_dry_run_on_gtsdb_tune_signs_reads_them_and_leaves_the_card_alone(real_like, capsys):
    card = model_card_path(load_catalogue().folder)
    before = card.read_bytes()
    assert calibrate.main(["--data", str(real_like), "--source", "gtsdb", "--dry-run", "--limit", "2"]) == 0
    out = capsys.readouterr().out
    assert f"2 real signs ({real_like / 'scenes.csv'}, split tune)" in out
    assert card.read_bytes() == before
    assert json.loads(before)["calibration"]["data"].startswith("real photographs (GTSRB test crops)")


def test_limit_without_dry_run_and_report_split_are_refused(real_like):
    with pytest.raises(SystemExit) as stop:
        calibrate.main(["--data", str(real_like), "--source", "gtsdb", "--limit", "2"])
    assert stop.value.code == 2
    with pytest.raises(SystemExit) as stop:
        calibrate.main(["--data", str(real_like), "--split", "report", "--dry-run"])
    assert stop.value.code == 2


def test_a_network_is_calibrated_for_the_catalogue_it_sits_in(real_like, tmp_path, capsys):
    """An open-set network (``training.left_out``) reads among its own catalogue's entries: here a catalogue
    without 3.02 and the shipped network with 3.02's class renamed, so the tune signs (all 3.02) are none they
    know, and the run says so instead of refusing the manifest or failing."""
    import shutil

    from training.left_out import catalogue_without

    shipped = load_catalogue()
    folder = tmp_path / "without"
    catalogue_without(shipped.folder, folder, ["3.02"])
    shutil.copytree(model_card_path(shipped.folder).parent, folder / "classifier")
    card = json.loads((folder / "classifier" / "model.json").read_text(encoding="utf-8"))
    card["classes"] = ["left-out" if c == "3.02" else c for c in card["classes"]]
    (folder / "classifier" / "model.json").write_text(json.dumps(card), encoding="utf-8")
    assert calibrate.model_catalogue(folder / "classifier") == folder.resolve()
    assert calibrate.model_catalogue(tmp_path) is None
    code = calibrate.main(["--data", str(real_like), "--model", str(folder / "classifier"), "--dry-run"])
    assert code == 1
    assert f"no tune signs of an id that catalogue {folder.resolve()} and the network" in capsys.readouterr().err
    assert calibrate.main(["--data", str(real_like), "--model", str(model_card_path(shipped.folder).parent),
                           "--catalogue", str(folder), "--dry-run"]) == 1  # the catalogue decides too
