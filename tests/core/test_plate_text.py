"""Reading plate texts: Tesseract on plates set in a real font, normalisation, and a missing engine."""

from __future__ import annotations

import stat
import time

import cv2
import numpy as np
import pytest

from signmapper_core.fusion.signs import FusionConfig
from signmapper_core.plates.ocr import (
    INSTALL_HINT,
    OcrUnavailable,
    find_tesseract,
    parse_tsv,
    prepare_crop,
    read_texts,
    without_long_lines,
)
from signmapper_core.plates.text import is_plate_line, normalise_line, normalise_text
from signmapper_core.simulate.plate_faces import draw_plate


@pytest.mark.parametrize("read, meant", [
    ("2OOm", "200 m"), ("50 m", "50 m"), ("2 km", "2 km"),
    ("7-l9h", "7–19 h"), ("7 - 19 h", "7–19 h"), ("22—6 h", "22–6 h"), ("7:30-11.30h", "7.30–11.30 h"),
    ("Mo-Fr", "Mo–Fr"), ("mo - fr", "mo–fr"), ("lu-ve", "lu–ve"), ("Di~Sa", "Di–Sa"),
    ("ausgenomnen Zubringerdienst", "ausgenommen Zubringerdienst"), ("excepte riverains", "excepté riverains"),
    ("eccetto bus", "eccetto bus"), ("Schule.", "Schule"),
    ("| 8-20 h", "8–20 h"), ("lu-sa =", "lu–sa"), ("8-20 h -", "8–20 h"), ("— 200 m", "200 m"),
    ("6-18 F", "6–18 h"), ("7-19", "7–19 h"),
    ("7.30-11.30", "7.30–11.30 h"),
    ("Mo-5a", "Mo–Sa"), ("Mo-F", "Mo–Fr"), ("o-Sa", "Mo–Sa"), ("lu-v", "lu–ve"), ("u-sa", "lu–sa"),
    ("8-F", "8-F"), ("7-19 h", "7–19 h"),
    # a frame's edge or a pole read as a letter or mark at a line's end, where the rest is a line plates print
    ("1 6-18 h", "6–18 h"), ("J excepté livraisons", "excepté livraisons"), ("‚7-18 h", "7–18 h"),
    ("'9-19 h", "9–19 h"), ("lu-ve i", "lu–ve"), ("9-19 1", "9–19 h"),
    ("a b", "a b"), ("Zone 30 x", "Zone 30 x"),  # no plate line without the end: left as read
])
def test_normalised_spelling(read, meant):
    assert normalise_line(read) == meant


@pytest.mark.parametrize("line, plate_like", [
    ("200 m", True), ("2 km", True), ("7–19 h", True), ("7.30–11.30 h", True), ("Mo–Fr", True), ("lu–sa", True),
    ("ausgenommen", True), ("Zubringerdienst", True), ("excepté", True), ("taxi", True), ("eccetto bus", True),
    ("100 nil", False), ("Mo-F", False), ("o-Sa F", False), ("EE", False), ("", False),
])
def test_plate_lines_are_told_from_misreadings(line, plate_like):
    assert is_plate_line(line) == plate_like


def test_words_that_are_not_days_or_numbers_keep_their_dash():
    assert normalise_line("Ab-Cd") == "Ab-Cd"  # no weekday pair
    assert normalise_line("200 m") == "200 m" and normalise_line("Zone 30") == "Zone 30"  # no time range
    assert normalise_text(["Mo-Fr", "", " 7-19h "]) == "Mo–Fr / 7–19 h"


def test_a_lone_character_on_a_line_of_its_own_is_a_pole_read_as_a_letter():
    assert normalise_text(["ausgenommen", "Anwohner", "1"]) == "ausgenommen / Anwohner"
    assert normalise_text(["l", "200 m"]) == "200 m"
    assert normalise_text(["7"]) == "7"  # alone it is all there is: kept for the vote to weigh


def plate_crop(lines, height_px):
    """A plate set in DejaVu Sans at 3x, then shrunk to ``height_px`` as a camera sees it."""
    width = int(height_px * 2.0)
    big = draw_plate(lines, width * 3, height_px * 3)
    return cv2.resize(big, (width, height_px), interpolation=cv2.INTER_AREA)


PLATES = [["200 m"], ["Mo–Fr", "7–19 h"], ["ausgenommen", "Zubringerdienst"], ["excepté riverains"],
          ["eccetto bus"], ["lu–ve", "8–18 h"]]


def test_tesseract_reads_plates_of_40_px_in_one_run():
    crops = [plate_crop(lines, 40 if len(lines) == 1 else 48) for lines in PLATES]
    readings = read_texts(crops)
    assert len(readings) == len(PLATES)
    texts = [normalise_text(r.lines) for r in readings]
    assert texts == [" / ".join(lines) for lines in PLATES]
    assert all(0.6 <= r.confidence <= 1.0 for r in readings)


def test_crops_shared_over_several_tesseract_calls_read_as_in_one():
    from signmapper_core.plates.ocr import MIN_CROPS_PER_CALL, call_count

    crops = [plate_crop(lines, 40 if len(lines) == 1 else 48) for lines in PLATES] * 3  # 18 crops
    assert call_count(len(crops), 1) == 1 and call_count(len(crops), 2) == 2 and call_count(len(crops), 8) == 2
    assert call_count(MIN_CROPS_PER_CALL - 1, 8) == 1 and call_count(0, 2) == 1
    alone, shared = read_texts(crops, cores=1), read_texts(crops, cores=2)
    assert [(r.lines, r.confidence) for r in shared] == [(r.lines, r.confidence) for r in alone]
    assert [normalise_text(r.lines) for r in shared] == [" / ".join(lines) for lines in PLATES] * 3


def crossed(crop, column):
    """``crop`` with a grey pole's edge (2 px, darker than the paper, lighter than the print) down its full height."""
    out = crop.copy()
    out[:, column:column + 2] = 140
    return out


def test_a_line_across_the_whole_plate_is_painted_over_and_its_letters_kept():
    crop = cv2.cvtColor(plate_crop(["Anwohner"], 48), cv2.COLOR_BGR2GRAY)
    cut = crossed(crop, 40)
    cleaned = without_long_lines(cut, 0.9, 0.8, 0.15)
    paper = np.median(crop)
    line = np.zeros(crop.shape, bool)
    line[8:-8, 40:42] = True  # inside the printed frame
    ink = crop < 0.5 * paper
    near_ink = cv2.dilate(ink.astype(np.uint8), np.ones((9, 9), np.uint8)) > 0
    assert np.all(cleaned[line & ~near_ink] > 0.9 * paper)  # where it crossed paper, paper again
    letters = ink & ~line
    letters[:8], letters[-8:], letters[:, :8], letters[:, -8:] = False, False, False, False  # the frame goes too
    assert np.count_nonzero(cleaned[letters] < 0.5 * paper) >= 0.95 * np.count_nonzero(letters)
    assert np.array_equal(without_long_lines(crop[8:-8, 8:-8], 0.9, 0.8, 0.15), crop[8:-8, 8:-8])  # no line: as it was


def test_a_dark_row_across_the_middle_is_a_line_of_letters_and_one_at_the_edge_is_the_frame():
    crop = np.full((40, 120), 200, np.uint8)
    crop[18:23, 6:114] = 90  # blurred bold letters, dark all along the row
    crop[1:3, :] = 90  # what is left of the printed frame
    cleaned = without_long_lines(crop, 0.9, 0.8, 0.15)
    assert np.array_equal(cleaned[15:26], crop[15:26])
    assert cleaned[1:3].min() > 150
    assert without_long_lines(crop, 0.9, 0.8, 1.0)[18:23, 20:100].min() > 150  # band over all: the row goes too


def test_tesseract_reads_a_plate_crossed_by_a_pole_edge_once_the_line_is_painted_over():
    crops = [crossed(plate_crop(lines, 48), column) for lines, column in
             ((["ausgenommen", "Anwohner"], 44), (["lu–ve", "6–18 h"], 36), (["9–19 h"], 10))]
    readings = read_texts(crops)
    assert [normalise_text(r.lines) for r in readings] == ["ausgenommen / Anwohner", "lu–ve / 6–18 h", "9–19 h"]
    # the setting turns it off: the crop is prepared as before
    off = FusionConfig(ocr_line_span=1.0)
    assert not np.array_equal(prepare_crop(crops[0], off), prepare_crop(crops[0]))


def test_a_blank_plate_reads_as_no_text():
    blank = plate_crop([""], 40)
    (reading,) = read_texts([blank])
    assert reading.text == "" and reading.confidence == 0.0


def test_without_tesseract_the_message_says_how_to_install_it(tmp_path, monkeypatch):
    monkeypatch.setenv("PATH", str(tmp_path))  # no tesseract on the PATH
    with pytest.raises(OcrUnavailable) as info:
        find_tesseract()
    assert "not installed" in str(info.value) and INSTALL_HINT in str(info.value)
    with pytest.raises(OcrUnavailable):
        read_texts([plate_crop(["200 m"], 40)])
    assert read_texts([]) == []  # nothing to read needs no engine


def test_tesseract_without_plate_languages_is_unavailable(tmp_path):
    fake = tmp_path / "tesseract"
    fake.write_text("#!/bin/sh\necho 'List of available languages in \"/x\" (2):'\necho eng\necho osd\n")
    fake.chmod(fake.stat().st_mode | stat.S_IXUSR)
    with pytest.raises(OcrUnavailable, match="German, French or Italian"):
        find_tesseract(str(fake))


def test_tsv_words_are_grouped_by_image_and_line():
    header = "level\tpage_num\tblock_num\tpar_num\tline_num\tword_num\tleft\ttop\twidth\theight\tconf\ttext"
    rows = [header,
            "5\t1\t1\t1\t1\t1\t0\t0\t9\t9\t90\tMo-Fr",
            "5\t1\t1\t1\t2\t1\t0\t9\t9\t9\t80\t7-19",
            "5\t1\t1\t1\t2\t2\t9\t9\t9\t9\t70\th",
            "4\t2\t1\t1\t1\t0\t0\t0\t9\t9\t-1\t",
            "5\t3\t1\t1\t1\t1\t0\t0\t9\t9\t-1\t ",
            "5\t3\t1\t1\t1\t2\t0\t0\t9\t9\t60\tbus"]
    first, second, third = parse_tsv("\n".join(rows), 3)
    assert first.lines == ["Mo-Fr", "7-19 h"] and first.confidence == pytest.approx(0.8)
    assert second.text == "" and third.text == "bus"
    # the run's OCR settings decide what is print: a line read with less mean confidence than asked is not
    (first,) = parse_tsv("\n".join(rows[:4]), 1, FusionConfig(ocr_min_line_confidence=0.8))
    assert first.lines == ["Mo-Fr"] and first.confidence == pytest.approx(0.9)


def test_a_hanging_tesseract_is_stopped_by_the_timeout(tmp_path):
    from signmapper_core.plates.ocr import OcrError

    fake = tmp_path / "tesseract"
    fake.write_text("#!/bin/sh\nif [ \"$1\" = --list-langs ]; then echo deu; exit 0; fi\nsleep 30\n")
    fake.chmod(fake.stat().st_mode | stat.S_IXUSR)
    with pytest.raises(OcrError, match="did not finish"):
        read_texts([plate_crop(["200 m"], 40)], executable=str(fake), timeout_s=0.5)
    started = time.monotonic()
    with pytest.raises(OcrError, match="did not finish reading 16 crops"):  # two calls side by side
        read_texts([plate_crop(["200 m"], 40)] * 16, executable=str(fake), timeout_s=0.5, cores=2)
    assert time.monotonic() - started < 10  # the second call was stopped too, not waited for
