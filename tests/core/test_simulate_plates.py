"""Synthetic drives with supplementary plates: where they hang, what they say, how truth.csv records them."""

from __future__ import annotations

from dataclasses import replace

import cv2
import numpy as np
import pytest

from signmapper_core.catalogue.model import DEFAULT_CATALOGUE_DIR
from signmapper_core.drive import TruthSign, read_truth
from signmapper_core.drive_writer import write_truth_csv
from signmapper_core.errors import DriveFormatError
from signmapper_core.pipeline import PipelineConfig
from signmapper_core.pipeline.plate_classify import classify_plate
from signmapper_core.plate_catalogue import load_plate_templates
from signmapper_core.plate_formats import PLATE_FORMATS, PLATE_ID
from signmapper_core.plate_text import normalise_text
from signmapper_core.simulate import SimulationConfig
from signmapper_core.simulate.generator import make_scene, make_street
from signmapper_core.simulate.plate_layout import pictogram_face, plate_lines


def scene_of(seed, plate_share):
    cfg = SimulationConfig(pairs=120, seed=seed, plate_share=plate_share)
    return make_scene(cfg, make_street(cfg))


def test_plates_hang_right_below_their_sign_facing_the_same_way():
    truth = scene_of(3, 1.0).truth
    by_id = {t.sign_id: t for t in truth}
    plates = [t for t in truth if t.plate_of]
    assert len(plates) >= 5
    pictograms = {t.id: t for t in load_plate_templates(DEFAULT_CATALOGUE_DIR)}
    for plate in plates:
        sign = by_id[plate.plate_of]
        assert plate.template_id in {PLATE_ID} | set(pictograms) and not sign.plate_of
        if plate.template_id == PLATE_ID:
            assert (plate.width_m, plate.height_m) in PLATE_FORMATS.values()
            assert plate.text and normalise_text(plate.text.split(" / ")) == plate.text
        else:  # as wide as a text plate, as high as its drawing's aspect makes it
            assert plate.height_m == pytest.approx(plate.width_m / pictograms[plate.template_id].aspect, abs=1e-3)
            assert plate.text in {t.text for t in load_plate_templates(DEFAULT_CATALOGUE_DIR)
                                  if t.id == plate.template_id}
        assert plate.width_m == pytest.approx(min((w for w, _ in PLATE_FORMATS.values()),
                                                  key=lambda w: abs(w - sign.width_m)))
        gap = sign.height - sign.height_m / 2 - (plate.height + plate.height_m / 2)
        assert 0.015 <= gap <= 0.065
        assert np.hypot(plate.easting - sign.easting, plate.northing - sign.northing) < 0.06  # tilted pole
        assert plate.facing == pytest.approx(sign.facing)
    kinds = [p.template_id == PLATE_ID for p in plates]
    assert 0 < sum(kinds) < len(kinds)  # text plates and pictogram plates


def test_pictogram_plate_faces_are_worn_prints_of_their_drawing_not_its_pixels():
    templates = load_plate_templates(DEFAULT_CATALOGUE_DIR)
    template = next(t for t in templates if t.id == "5.31-2" and t.variant == "fr")
    h, w = 60, int(round(60 * template.aspect))
    faces = [pictogram_face(template, w, h, np.random.default_rng(seed)) for seed in (1, 2)]
    drawn = cv2.resize(template.grey, (w, h), interpolation=cv2.INTER_AREA).astype(float)
    for face in faces:
        grey = cv2.cvtColor(face, cv2.COLOR_BGR2GRAY).astype(float)
        assert 1.0 < np.abs(grey - drawn).mean() < 40.0  # the same drawing, not the same pixels
        (best, score) = classify_plate(face, templates, PipelineConfig())
        assert (best.id, best.variant) == ("5.31-2", "fr") and score > 0.8
    assert np.abs(faces[0].astype(float) - faces[1]).mean() > 1.0  # each plate its own print and wear


def test_plates_leave_the_rest_of_the_scene_as_it_was():
    with_plates = scene_of(4, 1.0).truth
    without = scene_of(4, 0.0).truth
    signs = [replace(t, sign_id="") for t in with_plates if not t.plate_of]
    assert signs == [replace(t, sign_id="") for t in without]
    assert len(with_plates) > len(without)


def test_plate_texts_are_spelt_as_normalised_ocr_writes_them_in_three_languages():
    rng = np.random.default_rng(0)
    texts = [plate_lines(rng) for _ in range(300)]
    assert all(normalise_text(lines) == " / ".join(lines) for lines in texts)
    joined = " ".join(" ".join(lines) for lines in texts)
    for word in ("ausgenommen", "excepté", "eccetto", " m", " h", "Mo–", "lu–"):
        assert word in joined
    assert {len(lines) for lines in texts} == {1, 2}


def test_truth_csv_round_trips_plates_and_rejects_a_plate_of_no_sign(tmp_path):
    sign = TruthSign("s001", "2.30-50", 2600000.0, 1200000.0, 401.0, 0.6, 0.6, 90.0)
    plate = TruthSign("s002", PLATE_ID, 2600000.0, 1200000.0, 400.5, 0.6, 0.2, 90.0, plate_of="s001",
                      text="Mo–Fr / 7–19 h")
    path = write_truth_csv(tmp_path, [sign, plate])
    assert path.read_text(encoding="utf-8").splitlines()[0].endswith(",plate_of,text")
    back = read_truth(path)
    assert back[1].plate_of == "s001" and back[1].text == "Mo–Fr / 7–19 h" and back[1].is_plate
    assert back[0].plate_of == "" and not back[0].is_plate
    write_truth_csv(tmp_path, [sign])  # no plate: the columns of version 1 only
    assert path.read_text().splitlines()[0] == "sign_id,template_id,easting,northing,height,width_m,height_m,facing"
    assert read_truth(path)[0].text == ""
    write_truth_csv(tmp_path, [replace(sign, artwork="procedural"), plate])
    assert path.read_text().splitlines()[0].endswith(",plate_of,text,face_artwork")
    assert [t.artwork for t in read_truth(path)] == ["procedural", ""]
    write_truth_csv(tmp_path, [sign, replace(plate, plate_of="s009")])
    with pytest.raises(DriveFormatError) as info:
        read_truth(path)
    assert info.value.line == 3 and info.value.field == "plate_of" and "s009" in str(info.value)
