"""Synthetic drives with supplementary plates: where they hang, what they say, how truth.csv records them."""

from __future__ import annotations

from dataclasses import replace

import cv2
import numpy as np
import pytest

from signmapper_core.catalogue.model import DEFAULT_CATALOGUE_DIR
from signmapper_core.drive.reader import TruthSign, read_truth
from signmapper_core.drive.writer import write_truth_csv
from signmapper_core.errors import DriveFormatError
from signmapper_core.pipeline import PipelineConfig
from signmapper_core.pipeline.plate_classify import classify_plate
from signmapper_core.plates.catalogue import LAYOUT, PICTOGRAM, TEXT, load_plate_templates
from signmapper_core.plates.formats import PLATE_FORMATS, PLATE_ID
from signmapper_core.plates.text import EXCEPT_WORDS, normalise_text
from signmapper_core.simulate import SimulationConfig
from signmapper_core.simulate.generator import make_scene, make_street
from signmapper_core.simulate.plate_layout import LAYOUT_TEXTS, layout_text, pictogram_face, text_plate


def scene_of(seed, plate_share):
    cfg = SimulationConfig(pairs=120, seed=seed, plate_share=plate_share)
    return make_scene(cfg, make_street(cfg))


def test_plates_hang_right_below_their_sign_facing_the_same_way():
    scenes = [scene_of(seed, 1.0).truth for seed in (3, 5)]
    with_sign = [(t, {s.sign_id: s for s in truth}[t.plate_of]) for truth in scenes for t in truth if t.plate_of]
    plates = [plate for plate, _ in with_sign]
    assert len(plates) >= 12
    templates = load_plate_templates(DEFAULT_CATALOGUE_DIR)
    kind_of = {t.id: t.kind for t in templates}
    for plate, sign in with_sign:
        assert plate.template_id in kind_of and not sign.plate_of
        drawing = next(t for t in templates if t.id == plate.template_id)
        if drawing.kind == TEXT:
            assert (plate.width_m, plate.height_m) in PLATE_FORMATS.values()
            assert plate.text and normalise_text(plate.text.split(" / ")) == plate.text
        else:  # its longer side as wide as a text plate, the other as its drawing's aspect makes it
            assert plate.width_m / plate.height_m == pytest.approx(drawing.aspect, rel=0.01)
            words = {t.text for t in templates if t.id == plate.template_id}
            assert plate.text in words if drawing.kind == PICTOGRAM else normalise_text([plate.text]) == plate.text
        assert max(plate.width_m, plate.height_m) == pytest.approx(
            min((w for w, _ in PLATE_FORMATS.values()), key=lambda w: abs(w - sign.width_m)))
        gap = sign.height - sign.height_m / 2 - (plate.height + plate.height_m / 2)
        assert 0.015 <= gap <= 0.065
        assert np.hypot(plate.easting - sign.easting, plate.northing - sign.northing) < 0.06  # tilted pole
        assert plate.facing == pytest.approx(sign.facing)
    assert {kind_of[p.template_id] for p in plates} == {TEXT, LAYOUT, PICTOGRAM}


def test_layout_plates_print_their_own_text_in_the_field_of_their_drawing():
    templates = {(t.id, t.variant): t for t in load_plate_templates(DEFAULT_CATALOGUE_DIR)}
    template = templates[("5.03", "de")]
    h, w = 80, int(round(80 * template.aspect))
    rng = np.random.default_rng(3)
    text = layout_text(rng, template, "de")
    assert text in LAYOUT_TEXTS["5.03"]
    face = cv2.cvtColor(pictogram_face(template, w, h, rng, text), cv2.COLOR_BGR2GRAY)
    drawn = cv2.resize(template.grey, (w, h), interpolation=cv2.INTER_AREA)
    x0, y0, x1, y1 = (int(round(f * n)) for f, n in zip(template.field, (w, h, w, h)))
    inside = np.zeros((h, w), bool)
    inside[y0:y1, x0:x1] = True
    differs = np.abs(face.astype(float) - drawn) > 60
    assert differs[inside].mean() > 3 * differs[~inside].mean()  # its own text; outside, the edges moved a little
    (found, score) = classify_plate(face, tuple(templates.values()), PipelineConfig())
    assert found.id == "5.03" and score > 0.8
    others = [layout_text(np.random.default_rng(k), templates[("5.31-3", "fr")], "fr") for k in range(40)]
    assert set(others) <= {"riverains", "livraisons", "bus", "taxi"} and len(set(others)) > 2


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


def test_plate_texts_are_spelt_as_normalised_ocr_writes_them_in_three_languages_with_their_ssv_id():
    rng = np.random.default_rng(0)
    plates = [text_plate(rng) for _ in range(400)]
    assert all(normalise_text(lines) == " / ".join(lines) for _, lines in plates)
    joined = " ".join(" ".join(lines) for _, lines in plates)
    for word in ("ausgenommen", "excepté", "eccetto", " m", " h", "Mo–", "lu–"):
        assert word in joined
    assert {len(lines) for _, lines in plates} == {1, 2, 3}
    for ssv, lines in plates:
        if lines[0] in EXCEPT_WORDS.values():
            assert ssv == "5.00-exception" and len(lines) in (2, 3)
        elif len(lines) == 1 and lines[0].endswith(" m"):
            assert ssv == "5.01"
        else:
            assert ssv == f"5.00-{len(lines)}"
    assert {ssv for ssv, _ in plates} == {"5.00-1", "5.00-2", "5.00-3", "5.00-exception", "5.01"}


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
