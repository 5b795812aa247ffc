import cv2
import numpy as np
import pytest
from pipeline_scenes import noisy_background, paste

from signmapper_core.catalogue import FaceStyle, load_catalogue, render_face
from signmapper_core.catalogue.text_panels import TEXT_PANELS
from signmapper_core.pipeline.classify import classify_segment
from signmapper_core.pipeline.config import DEFAULT_HSV_RANGES, ClassificationConfig, PipelineConfig
from signmapper_core.pipeline.face_extent import candidate_entries, carried_discs, colour_extent, hole_part
from signmapper_core.simulate.face_artwork import has_procedural

CONFIG = PipelineConfig()
GROW = CONFIG.classification.surround_grow

ALL_COLOURS = ("red", "blue", "yellow", "white")


def _candidates(catalogue, template_id):
    entry = catalogue[template_id]
    shapes = ("square", "rectangle") if entry.shape in ("square", "rectangle") else (entry.shape,)
    return [e.id for e, _ in candidate_entries(catalogue, entry.colour, shapes, DEFAULT_HSV_RANGES, ALL_COLOURS)]


def _perspective(bgr, alpha, turn=0.08):
    """The face seen slightly from the side: its right edge shorter by ``turn``."""
    h, w = alpha.shape
    src = np.float32([[0, 0], [w, 0], [w, h], [0, h]])
    dst = np.float32([[0, 0], [w, turn * h / 2], [w, h * (1 - turn / 2)], [0, h]])
    m = cv2.getPerspectiveTransform(src, dst)
    return (cv2.warpPerspective(bgr, m, (w, h), flags=cv2.INTER_LINEAR),
            cv2.warpPerspective(alpha, m, (w, h), flags=cv2.INTER_LINEAR))


def _degraded_scene(face_bgr, face_alpha, seed):
    rng = np.random.default_rng(seed)
    image = noisy_background(200, 200, seed=seed)
    paste(image, face_bgr, face_alpha, 60, 50)
    image = cv2.GaussianBlur(image, (0, 0), 0.9)
    image = np.clip(image + rng.normal(0, 6, image.shape), 0, 255).astype(np.uint8)
    h, w = face_alpha.shape
    return image, (60, 50, w, h)


@pytest.mark.parametrize("template_id", ["2.30-50", "2.30-80", "1.01", "1.23", "3.01", "3.02", "2.36", "4.17"])
@pytest.mark.parametrize("size_px", [56, 90])
def test_template_under_blur_noise_and_perspective_is_recognised(catalogue, template_id, size_px):
    bgr, alpha = catalogue.render(template_id, size_px)
    bgr, alpha = _perspective(bgr, alpha)
    image, bbox = _degraded_scene(bgr, alpha, seed=size_px)
    result = classify_segment(image, bbox, catalogue, _candidates(catalogue, template_id), CONFIG)
    assert result.template_id == template_id
    assert result.score > 0.8


@pytest.fixture(scope="module")
def network(catalogue):
    from signmapper_core.pipeline.classifiers import make_classifier

    return make_classifier("cnn", catalogue)


@pytest.mark.parametrize("template_id", ["2.30-50", "2.30-80", "1.01", "1.23", "3.01", "3.02", "2.36", "4.17"])
@pytest.mark.parametrize("size_px", [30, 56, 90])
def test_network_reads_official_faces_under_blur_noise_and_perspective(catalogue, network, template_id, size_px):
    bgr, alpha = catalogue.render(template_id, size_px)
    bgr, alpha = _perspective(bgr, alpha)
    image, bbox = _degraded_scene(bgr, alpha, seed=size_px)
    result = network.classify(image, bbox, _candidates(catalogue, template_id))
    assert result.template_id == template_id
    assert result.score >= network.accept_threshold


def test_network_reads_most_faces_of_another_artwork(catalogue, network):
    """Our procedural drawings (other strokes, palette, font) were never trained on. Measured 2026-12-02 with the
    committed model: 163 of 224 faces (73 %) read right (the model before, which lacked four white entries: 155
    of 216, 72 %; the one before that 129, 60 %); real photographs do better
    (README), these drawings differ from the official ones more than most real print runs do. A regression bar,
    not a goal."""
    right, total = 0, 0
    # trained on every entry, the white family's and (since 2026-12-03) the text panels' too; the text panels are
    # told apart by their layout and never asked of the network, so they are not read here
    assert network.knows([entry.id for entry in catalogue])
    # the procedural drawer knows the entries of before the whole catalogue (simulate.face_artwork.has_procedural)
    known = [entry for entry in catalogue if entry.id not in TEXT_PANELS and has_procedural(entry.id)]
    for k, (font, seed) in enumerate([("duplex", 3), ("simplex", 5)]):
        style = FaceStyle(stroke_scale=1.1, rim_scale=0.9, palette_jitter=0.5, font=font, detail_jitter=0.3,
                          seed=seed)
        for entry in known:
            bgr, alpha = render_face(entry.id, 70, style)
            image, bbox = _degraded_scene(bgr, alpha, seed=7 + k)
            ids = [t for t in _candidates(catalogue, entry.id) if network.knows([t])]
            right += network.classify(image, bbox, ids).template_id == entry.id
            total += 1
    assert total == 2 * len(known)
    assert right >= 0.66 * total


def test_network_gives_a_non_sign_a_low_indicator(catalogue, network):
    image = noisy_background(200, 200, seed=5)
    cv2.circle(image, (90, 80), 30, (40, 40, 200), -1)  # a plain red disc: no white field, no pictogram
    result = network.classify(image, (60, 50, 61, 61), _candidates(catalogue, "2.30-50"))
    assert result.score < network.accept_threshold


def test_network_probabilities_of_the_candidates_and_background_sum_to_one(catalogue, network):
    bgr, alpha = catalogue.render("2.30-50", 60)
    image, bbox = _degraded_scene(bgr, alpha, seed=1)
    result = network.classify(image, bbox, _candidates(catalogue, "2.30-50"))
    assert 0.0 < sum(result.scores.values()) <= 1.0
    assert max(result.scores, key=result.scores.get) == result.template_id


def test_network_reads_only_ids_it_was_trained_on(catalogue, network):
    bgr, alpha = catalogue.render("2.30-50", 60)
    image, bbox = _degraded_scene(bgr, alpha, seed=1)
    result = network.classify(image, bbox, ["9.99", "2.30-50"])
    assert result.template_id == "2.30-50" and set(result.scores) == {"2.30-50"}
    assert network.classify(image, bbox, ["9.99"]).template_id is None
    assert network.unknown(["2.30-50", "9.99", "4.77/01"]) == ["9.99"]  # trained on the whole catalogue


@pytest.mark.parametrize("bbox", [(-20, 30, 60, 60), (160, 150, 60, 60), (-30, -30, 50, 50), (195, 0, 30, 30)])
def test_network_classifies_boxes_past_the_image_edge(catalogue, network, bbox):
    image = noisy_background(200, 200, seed=2)
    result = network.classify(image, bbox, _candidates(catalogue, "2.30-50"))
    assert result.template_id in _candidates(catalogue, "2.30-50")


def test_a_non_sign_scores_low(catalogue):
    image = noisy_background(200, 200, seed=5)
    cv2.circle(image, (90, 80), 30, (40, 40, 200), -1)  # a plain red disc: no white field, no pictogram
    result = classify_segment(image, (60, 50, 61, 61), catalogue, _candidates(catalogue, "2.30-50"), CONFIG)
    assert result.score < 0.6


def test_no_candidates_gives_no_template(catalogue):
    image = noisy_background(100, 100)
    assert classify_segment(image, (10, 10, 40, 40), catalogue, [], CONFIG).template_id is None


def test_face_at_the_image_border_is_matched_without_error(catalogue):
    bgr, alpha = catalogue.render("2.30-50", 60)
    image = noisy_background(120, 120)
    paste(image, bgr, alpha, 0, 0)
    result = classify_segment(image, (0, 0, 60, 60), catalogue, _candidates(catalogue, "2.30-50"), CONFIG)
    assert result.template_id == "2.30-50"


def test_colour_extent_of_rimmed_and_panel_faces(catalogue):
    # the priority road's yellow lies inside a white rim (official drawing: 22 % of the box on each side);
    # a zone sign's red ring inside the panel, under the word "ZONE"
    x0, y0, x1, y1 = colour_extent(catalogue, "3.03", "yellow", DEFAULT_HSV_RANGES)
    assert 0.2 < x0 < 0.25 and 0.75 < x1 < 0.8
    x0, y0, x1, y1 = colour_extent(catalogue, "2.59.1-30", "red", DEFAULT_HSV_RANGES)
    assert y0 > 0.2 and y1 < 0.8
    assert colour_extent(catalogue, "2.30-50", "red", DEFAULT_HSV_RANGES) == (0.0, 0.0, 1.0, 1.0)
    assert colour_extent(catalogue, "2.30-50", "blue", DEFAULT_HSV_RANGES) is None


def test_the_zone_panels_are_the_panels_that_carry_a_disc(catalogue):
    # what fusion lets a zone panel's disc, read alone, vote for (fusion._vote)
    carried = carried_discs(catalogue, DEFAULT_HSV_RANGES)
    expected = {"2.59.1-30": "2.30-30", "2.59.3": "2.61", "2.41.2": "2.37", "2.41.2a": "2.38", "2.41.2b": "2.36",
                "4.77/10-2": "2.30-80", "4.77/11-2": "2.30-80"}  # zone panels, dangerous-goods panels, lane signs
    assert expected.items() <= carried.items() and len(carried) == 9
    # measured once and kept; a caller changing its copy does not change the next run's
    carried_discs(catalogue, DEFAULT_HSV_RANGES).clear()
    assert carried_discs(catalogue, DEFAULT_HSV_RANGES) == carried
    # no red taken from the panels: no red disc is found in them
    without_red = {colour: ranges for colour, ranges in DEFAULT_HSV_RANGES.items() if colour != "red"}
    assert {k: v for k, v in carried_discs(catalogue, without_red).items() if k.startswith("2.59")} == \
        {"2.59.3": "2.61", "2.59.1-NP": "2.34"}


def test_colour_extents_follow_the_runs_colour_table(catalogue):
    """The extents are measured once per template and kept: a later run with other thresholds for a colour (a
    run record's colour table) must get them measured with its own, not the first run's."""
    before = colour_extent(catalogue, "3.03", "yellow", DEFAULT_HSV_RANGES)
    field_before = hole_part(catalogue, "2.30-50", "red", DEFAULT_HSV_RANGES)
    assert before is not None and field_before[0] is not None
    no_yellow = dict(DEFAULT_HSV_RANGES, yellow=((100, 101, 250, 255, 250, 255),))  # blue hues only: no pixel
    no_red = dict(DEFAULT_HSV_RANGES, red=((100, 101, 250, 255, 250, 255),))
    assert colour_extent(catalogue, "3.03", "yellow", no_yellow) is None
    assert hole_part(catalogue, "2.30-50", "red", no_red) == (None, None)
    assert colour_extent(catalogue, "3.03", "yellow", DEFAULT_HSV_RANGES) == before  # each table its own
    assert hole_part(catalogue, "2.30-50", "red", DEFAULT_HSV_RANGES) == field_before
    # thresholds given as lists (as JSON reads them) are the same thresholds
    as_lists = {colour: [list(r) for r in ranges] for colour, ranges in no_yellow.items()}
    assert colour_extent(catalogue, "3.03", "yellow", as_lists) is None


def test_surround_tells_a_zone_panel_from_a_round_sign_on_a_wall(catalogue):
    from signmapper_core.pipeline.classify import surround_score

    extent = colour_extent(catalogue, "2.59.1-30", "red", DEFAULT_HSV_RANGES)
    panel_bgr, panel_alpha = catalogue.render("2.59.1-30", (60, 90))
    panel = noisy_background(200, 200, seed=1)
    paste(panel, panel_bgr, panel_alpha, 50, 40)
    assert surround_score(panel, (50, 40, 60, 90), catalogue, "2.59.1-30", extent, GROW) > 0.8
    disc_bgr, disc_alpha = catalogue.render("2.30-30", 52)  # where the panel's ring would be
    wall = noisy_background(200, 200, seed=1)
    paste(wall, disc_bgr, disc_alpha, 50 + int(extent[0] * 60), 40 + int(extent[1] * 90))
    assert surround_score(wall, (50, 40, 60, 90), catalogue, "2.59.1-30", extent, GROW) < 0.3


def test_pole_across_a_flat_field_sign_does_not_read_as_stripes():
    """3.03 (plain yellow field) behind a grey pole must not become 3.04 (black stripes) in a close call."""
    catalogue = load_catalogue()
    face, alpha = catalogue.render("3.03", 110)
    scene = np.full((160, 160, 3), 120, np.uint8)
    inside = alpha > 127
    scene[25:25 + face.shape[0], 25:25 + face.shape[1]][inside] = face[inside]
    scene[:, 62:72] = (128, 128, 128)  # the sign's own pole, in front of the face
    scene = cv2.GaussianBlur(scene, (3, 3), 0)
    # tie_margin=1 hands every decision to the close-call rule, which is what this test is about
    result = classify_segment(scene, (25, 25, face.shape[1], face.shape[0]), catalogue, ["3.03", "3.04"],
                              PipelineConfig(classification=ClassificationConfig(tie_margin=1.0)))
    assert result.template_id == "3.03", result.scores


def test_templates_rendered_for_worker_processes_are_those_a_worker_renders_and_its_catalogue_reads_no_png():
    import pickle

    from signmapper_core.pipeline.classify import canonical_template, canonical_templates, seed_canonical_templates

    here = load_catalogue()
    rendered = canonical_templates(here, threads=2)  # as the pool's parent renders them
    assert set(rendered) == set(here.ids())
    assert not here._masters  # the full-size images are not kept
    worker = pickle.loads(pickle.dumps(load_catalogue()))  # what a worker process receives
    seed_canonical_templates(worker, pickle.loads(pickle.dumps(rendered)))
    fresh = load_catalogue()
    for template_id in here.ids():
        for got, want in zip(canonical_template(worker, template_id), canonical_template(fresh, template_id)):
            assert got.shape == want.shape and np.array_equal(got, want)
    assert not worker._masters and len(fresh._masters) == len(here)  # the seeded one decoded no PNG


def test_templates_rendered_on_several_threads_are_those_rendered_one_after_the_other():
    from signmapper_core.pipeline.classify import canonical_templates

    serial, threaded = canonical_templates(load_catalogue()), canonical_templates(load_catalogue(), threads=3)
    assert list(threaded) == list(serial)  # catalogue order
    for template_id, (bgr, alpha) in serial.items():
        assert np.array_equal(threaded[template_id][0], bgr) and np.array_equal(threaded[template_id][1], alpha)


def test_a_pale_blue_sky_around_a_disc_is_no_zone_panel(catalogue):
    """A no-parking disc (2.50) high on a pole against a pale blue sky, read from its blue field: by grey levels its
    red ring and the sky matched the ring and white of the no-parking zone panel 2.59.1-NP around that field, and
    the panel was accepted; the sky's colour tells it apart."""
    from signmapper_core.pipeline.classify import surround_score

    ring = colour_extent(catalogue, "2.59.1-NP", "red", DEFAULT_HSV_RANGES)
    field = colour_extent(catalogue, "2.59.1-NP", "blue", DEFAULT_HSV_RANGES)
    panel_bgr, panel_alpha = catalogue.render("2.59.1-NP", (60, 90))
    panel = noisy_background(200, 200, seed=1)
    paste(panel, panel_bgr, panel_alpha, 50, 40)
    assert surround_score(panel, (50, 40, 60, 90), catalogue, "2.59.1-NP", field, GROW, 60) > 0.5
    sky = np.zeros((200, 200, 3), np.uint8)
    sky[:] = cv2.cvtColor(np.uint8([[[113, 73, 229]]]), cv2.COLOR_HSV2BGR)[0, 0]  # as measured on a drive
    disc_bgr, disc_alpha = catalogue.render("2.50", (int((ring[2] - ring[0]) * 60), int((ring[3] - ring[1]) * 90)))
    paste(sky, disc_bgr, disc_alpha, 50 + int(ring[0] * 60), 40 + int(ring[1] * 90))
    assert surround_score(sky, (50, 40, 60, 90), catalogue, "2.59.1-NP", field, GROW) > 0.3  # grey levels alone
    assert surround_score(sky, (50, 40, 60, 90), catalogue, "2.59.1-NP", field, GROW, 60) == -1.0
