"""The open set: a sign-like face that matches no catalogue entry well is mapped as 'unknown', never as a wrong id."""

from __future__ import annotations

import json
import shutil

import numpy as np
import pytest
from pipeline_scenes import CAMERA, POSE, sign_scene

from signmapper_core.catalogue import UNKNOWN_ID, CatalogueError, load_catalogue
from signmapper_core.output.schema import OutputContext
from signmapper_core.pipeline import PipelineConfig, detect_pair
from signmapper_core.pipeline.classifiers import load_model_card
from signmapper_core.pipeline.config import ClassificationConfig

FORWARD, RIGHT, DOWN = POSE.rotation[:, 2], POSE.rotation[:, 0], POSE.rotation[:, 1]
SIGN = POSE.centre + 7.0 * FORWARD + 1.5 * RIGHT - 0.4 * DOWN


def _with_card(folder, catalogue, **fields):
    """A copy of the catalogue in ``folder`` whose model card has ``fields`` changed (images linked)."""
    folder.mkdir()
    for name in ("png", "svg"):
        (folder / name).symlink_to(catalogue.folder / name)
    shutil.copy(catalogue.folder / "catalogue.json", folder / "catalogue.json")
    (folder / "classifier").mkdir()
    shutil.copy(catalogue.folder / "classifier" / "model.onnx", folder / "classifier" / "model.onnx")
    card = json.loads((catalogue.folder / "classifier" / "model.json").read_text(encoding="utf-8"))
    card.update(fields)
    (folder / "classifier" / "model.json").write_text(json.dumps(card), encoding="utf-8")
    return load_catalogue(folder)


def test_a_face_its_network_matches_less_well_than_its_limit_is_unknown_in_review(catalogue, tmp_path):
    strict = _with_card(tmp_path / "strict", catalogue, unknown_logit=99.0)  # no face reaches it
    left, depth, _ = sign_scene(catalogue, "2.30-50", "normal", SIGN)
    (det,) = detect_pair(left, depth, None, CAMERA, POSE, strict, PipelineConfig())
    assert (det.template_id, det.status, det.review_reason) == (UNKNOWN_ID, "review", "matches no catalogue sign well")
    assert det.shape == "circle" and det.format == "normal" and det.width_m == pytest.approx(0.6)
    assert max(det.scores, key=det.scores.get) == "2.30-50"  # the next choices: what it came closest to
    assert np.linalg.norm(det.position - SIGN) < 0.05
    # switched off, or a card without a limit: read as before
    off = PipelineConfig(classification=ClassificationConfig(open_set=False))
    assert [d.template_id for d in detect_pair(left, depth, None, CAMERA, POSE, strict, off)] == ["2.30-50"]
    lenient = _with_card(tmp_path / "lenient", catalogue, unknown_logit=None)
    assert load_model_card(lenient.folder / "classifier" / "model.json").unknown_logit is None
    assert [d.template_id for d in detect_pair(left, depth, None, CAMERA, POSE, lenient, PipelineConfig())] == \
        ["2.30-50"]


def test_the_shipped_network_reads_a_known_face_above_its_limit(catalogue):
    card = load_model_card(catalogue.folder / "classifier" / "model.json")
    assert card.unknown_logit is not None
    left, depth, _ = sign_scene(catalogue, "2.30-50", "normal", SIGN)
    (det,) = detect_pair(left, depth, None, CAMERA, POSE, catalogue, PipelineConfig())
    assert (det.template_id, det.status) == ("2.30-50", "accepted")


@pytest.mark.parametrize("template_id", ["1.28", "4.79"])
def test_a_sign_the_run_excludes_is_unknown_not_another_id(catalogue, template_id):
    """Excluded ids stand for signs the catalogue does not hold: airplanes among the danger signs, a camp site
    among the blue panels."""
    left, depth, _ = sign_scene(catalogue, template_id, "normal", SIGN)
    config = PipelineConfig(classification=ClassificationConfig(exclude=(template_id,)))
    dets = detect_pair(left, depth, None, CAMERA, POSE, catalogue, config)
    assert [(d.template_id, d.status) for d in dets] == [(UNKNOWN_ID, "review")]


def test_no_entry_may_take_the_open_sets_id(tmp_path):
    (tmp_path / "png").mkdir()
    import cv2

    cv2.imwrite(str(tmp_path / "png" / "x.png"), np.full((10, 10, 4), 255, np.uint8))
    entry = {"id": UNKNOWN_ID, "colour": "red", "shape": "circle", "formats": {"normal": [0.6, 0.6]},
             "png": "png/x.png"}
    (tmp_path / "catalogue.json").write_text(json.dumps({"entries": [entry]}), encoding="utf-8")
    with pytest.raises(CatalogueError, match="is taken"):
        load_catalogue(tmp_path)


@pytest.mark.parametrize("language, name", [("de", "Unbekanntes Signal"), ("fr", "Signal inconnu"),
                                            ("it", "Segnale sconosciuto"), ("en", "Unknown sign")])
def test_unknown_is_named_in_the_output_language(catalogue, language, name):
    assert OutputContext(language=language, catalogue=catalogue).name(UNKNOWN_ID, "x") == name
