"""The digits of speed-limit signs read by OCR: which ids print which number, the band read, the verdict, and
an accepted sign whose digits say another number sent to review."""

from __future__ import annotations

import cv2
import numpy as np
import pytest
from test_fusion import CAMERA, seen_from

from signmapper_core.catalogue import load_catalogue
from signmapper_core.fusion.signs import fuse_observations
from signmapper_core.pipeline.detect import with_number_band
from signmapper_core.plates.number_check import check_speed_numbers, judge_numbers
from signmapper_core.plates.ocr import INSTALL_HINT, OcrUnavailable, read_numbers
from signmapper_core.plates.printed_numbers import band_box, number_band, prepared_band, printed_number, printed_numbers

SPEEDS = frozenset({"20", "30", "40", "50", "60", "70", "80", "100", "120"})


def test_speed_limits_print_their_number_and_no_other_sign_does():
    assert printed_number("2.30-30") == "30" and printed_number("2.30-120") == "120"
    assert printed_number("2.30.1") == "50"  # the general limit in built-up areas
    for other in ("2.31-60", "2.53-50", "2.16-3.5", "1.01", "2.59.1-30", "", None):
        assert printed_number(other) is None
    assert printed_numbers(load_catalogue().ids()) == SPEEDS


@pytest.mark.parametrize("mapped, readings, number, share, contradicts", [
    ("80", ["30", "30", ""], "30", 2 / 3, True),  # a heavy "30" the network took for 80
    ("80", ["80", "30", ""], "80", 1 / 3, False),  # one view against one: the id stands
    ("30", ["30", "", ""], "30", 1 / 3, False),
    ("30", ["404", "0", "16"], None, 0.0, False),  # no view read a speed limit's number
    ("50", ["", "60", ""], "60", 1 / 3, True),  # the only number read says another speed limit
    ("50", ["90", "90", "50"], "50", 1 / 3, False),  # 90 is no speed limit's number: a misreading of 50
    ("120", ["20", "20", ""], None, 0.0, False),  # the thin "1" lost at the band's edge: no evidence
    ("20", ["120", "", ""], None, 0.0, False),  # a "1" gained from the ring's edge: no evidence either
])
def test_the_verdict_counts_only_numbers_a_speed_limit_prints(mapped, readings, number, share, contradicts):
    verdict = judge_numbers(mapped, readings, SPEEDS)
    assert verdict.number == number and verdict.share == pytest.approx(share)
    assert verdict.contradicts is contradicts


def speed_face(number: str, px: int, thickness_share: float) -> np.ndarray:
    """A speed-limit face ``px`` wide on grey: red ring, white field, black digits of the given stroke weight
    (a heavy "30" is what the classifier took for 80 on the drives)."""
    image = np.full((px + 40, px + 40, 3), 110, np.uint8)
    centre, radius = (px // 2 + 20, px // 2 + 20), px // 2
    cv2.circle(image, centre, radius, (40, 30, 200), -1, cv2.LINE_AA)
    cv2.circle(image, centre, int(radius * 0.8), (235, 235, 235), -1, cv2.LINE_AA)
    thickness = max(1, int(round(thickness_share * px)))
    (w1, h1), _ = cv2.getTextSize(number, cv2.FONT_HERSHEY_SIMPLEX, 1.0, thickness)
    scale = min(0.36 * px / h1, 0.6 * px / w1)  # digits ~0.36 of the face high, within the field
    (w, h), _ = cv2.getTextSize(number, cv2.FONT_HERSHEY_SIMPLEX, scale, thickness)
    cv2.putText(image, number, (centre[0] - w // 2, centre[1] + h // 2), cv2.FONT_HERSHEY_SIMPLEX, scale,
                (20, 20, 20), thickness, cv2.LINE_AA)
    return image


def on_grey(face: np.ndarray, alpha: np.ndarray, px: int) -> np.ndarray:
    """A drawn face ``px`` wide pasted on grey with a 20-px margin."""
    face = cv2.resize(face, (px, px), interpolation=cv2.INTER_AREA).astype(float)
    cover = cv2.resize(alpha, (px, px), interpolation=cv2.INTER_AREA)[..., None] / 255.0
    image = np.full((px + 40, px + 40, 3), 110, np.uint8)
    image[20:20 + px, 20:20 + px] = (face * cover + 110 * (1 - cover)).astype(np.uint8)
    return image


def read_faces(faces) -> list:
    """What Tesseract reads in the band of each (image, px) face drawn at (20, 20)."""
    return read_numbers([prepared_band(number_band(image, (20, 20, px, px))) for image, px in faces])


def test_tesseract_reads_the_digits_of_the_official_speed_limits_from_40_px():
    from signmapper_core.pipeline.classify import canonical_template

    catalogue = load_catalogue()
    ids = [i for i in catalogue.ids() if printed_number(i)]
    faces, wanted = [], []
    for template_id in ids:
        bgr, alpha = canonical_template(catalogue, template_id)
        for px in (40, 64, 120):
            faces.append((on_grey(bgr, alpha, px), px))
            wanted.append(printed_number(template_id))
    read = read_faces(faces)
    assert len(ids) == 10 and sum(r == w for r, w in zip(read, wanted)) >= 28, list(zip(wanted, read))  # 30 of 30


def test_digits_in_another_print_are_read_or_left_unread_never_read_as_another_speed():
    plain = [(speed_face(n, px, 0.05), px) for n in sorted(SPEEDS) for px in (60, 120)]
    heavy = [(speed_face(n, 120, 0.09), 120) for n in sorted(SPEEDS)]  # blobby strokes, as a worn heavy print
    wanted = [n for n in sorted(SPEEDS) for _ in (60, 120)] + sorted(SPEEDS)
    read = read_faces(plain + heavy)
    assert sum(r == w for r, w in zip(read[:18], wanted[:18])) >= 14, list(zip(wanted, read))  # measured: 15 of 18
    assert not [(w, r) for r, w in zip(read, wanted) if r != w and r in SPEEDS]  # a wrong number would demote


def test_the_band_is_kept_only_where_the_face_lies_inside_the_image():
    image = speed_face("30", 100, 0.05)
    assert band_box((20, 20, 100, 100)) == (32, 47, 108, 93)
    assert number_band(image, (20, 20, 100, 100)).shape == (46, 76)
    assert number_band(image, (90, 20, 100, 100)) is None  # the band runs past the right edge
    assert number_band(image, (20, 20, 10, 10)) is None  # too small to hold a legible digit


def test_detections_of_speed_limits_carry_their_band_and_others_none():
    image = speed_face("30", 100, 0.05)
    speed = seen_from(np.array([20.0, 3.0, 2.5]), [3])[0].detection
    speed.bbox = (20, 20, 100, 100)
    assert with_number_band(speed, image).crop.shape == (46, 76)
    danger = with_number_band(seen_from(np.array([20.0, 3.0, 2.5]), [3], template_id="1.01")[0].detection, image)
    assert danger.crop is None


def signs_with_bands(template_id: str, count: int, heights=(60, 70, 80, 50)):
    observations = seen_from(np.array([20.0, 3.0, 2.5]), range(3, 3 + count), template_id=template_id,
                             cls=0.98)
    for obs, height in zip(observations, heights):
        obs.detection.bbox = (0, 0, height, height)
        obs.detection.crop = np.full((height // 2, height), 200, np.uint8)
    return fuse_observations(observations, CAMERA)


def test_an_accepted_speed_limit_whose_digits_read_another_number_goes_to_review():
    (eighty,) = signs_with_bands("2.30-80", 4)
    (fifty,) = signs_with_bands("2.30-50", 3)
    assert eighty.status == fifty.status == "accepted"
    calls = []

    def fake_read(images):  # what Tesseract would read, by the band's height
        calls.append([i.shape for i in images])
        return ["30", "30", "", "50", "50", "50"]

    assert check_speed_numbers([eighty, fifty], SPEEDS, read=fake_read) == 1
    assert len(calls) == 1 and len(calls[0]) == 6  # one OCR run: the three largest views of each
    assert all(shape[0] == 96 + 40 for shape in calls[0])  # prepared: 96 px high and a 20-px border
    assert eighty.status == "review" and eighty.template_id == "2.30-80"  # the person decides on the id
    assert eighty.review_reason == "digits read as 30" and fifty.review_reason is None
    assert eighty.text == "30" and eighty.text_confidence == pytest.approx(2 / 3)
    assert fifty.status == "accepted" and fifty.text == "50" and fifty.text_confidence == pytest.approx(1.0)


def test_without_tesseract_speed_limits_keep_their_status_and_the_run_hears_why():
    (eighty,) = signs_with_bands("2.30-80", 3)
    (danger,) = signs_with_bands("1.01", 3)

    def missing(images):
        raise OcrUnavailable(f"no tesseract; {INSTALL_HINT}")

    heard = []
    assert check_speed_numbers([eighty, danger], SPEEDS, heard.append, read=missing) == 0
    assert eighty.status == "accepted" and eighty.text is None
    assert len(heard) == 1 and "digits not read on 1 speed-limit sign:" in heard[0] and INSTALL_HINT in heard[0]
    assert check_speed_numbers([danger], SPEEDS, heard.append, read=missing) == 0 and len(heard) == 1  # nothing read
