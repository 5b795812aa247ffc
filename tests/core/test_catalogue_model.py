"""Catalogue loading, ids, filtering, size rounding, user catalogues and the committed build."""

from __future__ import annotations

import json
import re
from collections import Counter

import cv2
import numpy as np
import pytest

from signmapper_core.catalogue import (
    DEFAULT_CATALOGUE_DIR,
    CatalogueError,
    load_catalogue,
)
from signmapper_core.catalogue.build import OWN, STANDARD_FORMATS, catalogue_json, master_rgba, svg_text
from signmapper_core.catalogue.model import STANDARD, file_stem
from signmapper_core.catalogue.official_ch import FRAMED
from signmapper_core.catalogue.official_entries import OFFICIAL_ENTRIES
from signmapper_core.catalogue.signs_ch import SIGNS

# SSV numbers as Signalo writes them: 1.01, 2.30-50, 2.59.1-NP, 4.77/01, 4.07a, 0.1-2.1, 2.63-1-a
ID_RE = re.compile(r"^[0-5]\.\d{1,2}[a-d]?(\.\d)?(/\d{2})?(\.\d)?[a-b]?(-(\d+(\.\d+)?|[A-Z]+|[a-d]|\d+-[a-d]))?$")


@pytest.fixture(scope="module")
def cat():
    return load_catalogue()


def test_bundled_catalogue_is_the_default(cat):
    assert cat.folder == DEFAULT_CATALOGUE_DIR
    assert "2.30-50" in cat and "3.01" in cat
    assert len(cat) == len(list(cat)) == len(cat.entries)


def test_ids_unique_and_well_formed(cat):
    ids = [e.id for e in cat]
    assert len(ids) == len(set(ids))
    bad = [i for i in ids if not ID_RE.match(i)]
    assert not bad, bad
    raw = json.loads((DEFAULT_CATALOGUE_DIR / "catalogue.json").read_text(encoding="utf-8"))
    assert len(raw["entries"]) == len({e["id"] for e in raw["entries"]})


def test_required_signs_present(cat):
    required = ["1.01", "1.05", "1.07", "1.14", "1.15", "1.16", "1.22", "1.23", "1.27", "1.30", "1.32",
                "2.01", "2.02", "2.20-10", "2.30.1", "2.31-60", "2.41.1", "2.42", "2.44", "2.49", "2.50",
                "2.60", "2.61", "2.62", "2.63", "2.64", "3.01", "3.02", "3.03", "3.04", "3.05", "3.08", "3.09",
                "3.10", "4.08", "4.09", "4.11", "4.14", "4.17", "4.20"]
    required += [f"2.30-{v}" for v in (20, 30, 40, 50, 60, 70, 80, 100, 120)]
    missing = [i for i in required if i not in cat]
    assert not missing, missing


def test_at_least_70_coloured_entries(cat):
    coloured = cat.filter(colours=("red", "blue", "yellow"))
    assert len(coloured) >= 70
    per_colour = Counter(e.colour for e in coloured)
    assert per_colour["red"] >= 40 and per_colour["blue"] >= 15 and per_colour["yellow"] >= 1


def test_entries_have_names_and_consistent_formats(cat):
    for e in cat:
        assert set(e.names) == {"de", "fr", "it"} and all(e.names.values()), e.id
        aspects = [w / h for w, h in e.formats.values()]
        assert max(aspects) / min(aspects) < 1.01, (e.id, e.formats)
    assert cat["1.22"].formats["normal"] == (0.849, 0.744)  # 90 cm side, rounded corners (official drawing)
    assert cat["2.30-50"].formats["normal"] == (0.6, 0.6)
    assert cat["3.01"].shape == "octagon" and cat["3.02"].shape == "triangle-down"
    assert cat["3.03"].colour == "yellow" and cat["3.03"].shape == "diamond"
    assert cat["2.33"].colour == "blue" and cat["4.08"].colour == "blue"


def test_filter_by_colour_shape_and_exclude(cat):
    blue_discs = cat.filter(colours=["blue"], shapes=["circle"])
    assert blue_discs and all(e.colour == "blue" and e.shape == "circle" for e in blue_discs)
    assert "2.33" in {e.id for e in blue_discs}
    without = cat.filter(colours=["blue"], shapes=["circle"], exclude=["2.33"])
    assert {e.id for e in blue_discs} - {e.id for e in without} == {"2.33"}
    # the generic text panels only when asked for: no template route matches them
    assert {e.id for e in cat} - {e.id for e in cat.filter()} == {"4.29", "4.30", "4.33"}
    assert len(cat.filter(text_panels=True)) == len(cat)


def _separable(formats, name, margin):
    """True when every other format differs by more than 2 * margin, so +-margin is unambiguous."""
    w = formats[name][0]
    return all(abs(w2 / w - 1) > 2.05 * margin for n, (w2, _) in formats.items() if n != name)


@pytest.mark.parametrize("factor", [0.9, 0.95, 1.0, 1.05, 1.1])
def test_round_size_picks_the_format_within_10_percent(cat, factor):
    """Measured sizes +-10 % round to their format, given the detected shape.

    Stop 0.60 / 0.50 are only 20 % apart, so for them the margin is +-5 %.
    """
    margin = abs(factor - 1)
    checked = 0
    for shape in ("circle", "triangle", "octagon", "triangle-down", "diamond", "square", "rectangle"):
        entries = [e for e in cat.filter(shapes=[shape]) if e.sizing == STANDARD]
        for e in entries[:3]:
            for name, (w, h) in e.formats.items():
                if not _separable(e.formats, name, margin):
                    continue
                # rectangles are panels of different kinds: compare within the sign's own formats
                pool = [e] if shape == "rectangle" else entries
                m = cat.round_size(w * factor, h * factor, entries=pool)
                assert m is not None, (e.id, name, factor)
                assert m.format == name and (m.width_m, m.height_m) == (w, h), (e.id, name, factor, m)
                assert e.id in m.template_ids
                assert m.rel_error == pytest.approx(margin, abs=1e-3)
                checked += 1
    assert checked >= 40
    stop = cat.filter(shapes=["octagon"])
    assert cat.round_size(0.63, 0.63, entries=stop).format == "normal"
    assert cat.round_size(0.48, 0.48, entries=stop).format == "small"


def test_round_size_rejects_sizes_far_from_every_format(cat):
    discs = cat.filter(shapes=["circle"])
    assert cat.round_size(0.75, 0.75, entries=discs) is None  # between 0.60 and 0.90
    standard = [e for e in cat if e.sizing == STANDARD]
    assert cat.round_size(2.5, 2.5, entries=standard) is None
    assert cat.round_size(2.5, 2.5).format == "measured"  # a board of that size exists (4.63, 4.77/02, ...)
    assert cat.round_size(0.1, 0.1) is None
    assert cat.round_size(0.0, 0.6) is None
    m = cat.round_size(0.61, 0.6, entries=discs)
    assert m.format == "normal" and "2.30-50" in m.template_ids and "1.22" not in m.template_ids


def test_pictogram_paths_exist(cat):
    for e in cat:
        assert cat.pictogram_path(e.id).is_file()
        assert cat.pictogram_path(e.id, "png").is_file()
    with pytest.raises(ValueError):
        cat.pictogram_path("2.01", "gif")
    with pytest.raises(KeyError):
        cat["9.99"]


def _write_user_catalogue(folder, with_alpha=True):
    (folder / "png").mkdir(parents=True)
    img = np.zeros((200, 300, 4 if with_alpha else 3), np.uint8)
    img[..., :3] = (40, 140, 20)  # green panel
    cv2.putText(img, "LOCAL", (20, 120), cv2.FONT_HERSHEY_SIMPLEX, 2.0, (255, 255, 255, 255), 5)
    if with_alpha:
        img[..., 3] = 255
    cv2.imwrite(str(folder / "png" / "X.1-7.png"), img)
    data = {"format": "signmapper-catalogue/1", "name": "My signs", "entries": [
        {"id": "X.1-7", "names": {"de": "Lokal"}, "colour": "white", "shape": "rectangle",
         "formats": {"normal": [0.75, 0.5]}, "size_certain": False, "png": "png/X.1-7.png"}]}
    (folder / "catalogue.json").write_text(json.dumps(data), encoding="utf-8")


@pytest.mark.parametrize("with_alpha", [True, False])
def test_user_catalogue_folder_loads_and_renders(tmp_path, with_alpha):
    _write_user_catalogue(tmp_path, with_alpha)
    cat = load_catalogue(tmp_path)
    assert len(cat) == 1 and cat.name == "My signs"
    e = cat["X.1-7"]
    assert e.formats == {"normal": (0.75, 0.5)} and e.size_certain is False and e.svg is None
    bgr, alpha = cat.render("X.1-7", 60)
    assert bgr.shape == (40, 60, 3) and alpha.shape == (40, 60) and bgr.dtype == np.uint8
    assert alpha.min() == 255
    assert tuple(int(v) for v in bgr[2, 2]) == (40, 140, 20)
    bgr, alpha = cat.render("X.1-7", (30, 20))
    assert bgr.shape == (20, 30, 3)
    assert cat.round_size(0.7, 0.48).template_ids == ("X.1-7",)
    with pytest.raises(FileNotFoundError):
        cat.pictogram_path("X.1-7")


def test_malformed_user_catalogues_are_rejected_with_the_culprit(tmp_path):
    _write_user_catalogue(tmp_path)
    path = tmp_path / "catalogue.json"
    data = json.loads(path.read_text())
    data["entries"][0]["shape"] = "hexagon"
    path.write_text(json.dumps(data))
    with pytest.raises(CatalogueError, match="hexagon"):
        load_catalogue(tmp_path)
    data["entries"][0]["shape"] = "circle"
    data["entries"].append(dict(data["entries"][0]))
    path.write_text(json.dumps(data))
    with pytest.raises(CatalogueError, match="duplicate"):
        load_catalogue(tmp_path)
    with pytest.raises(CatalogueError, match="not found"):
        load_catalogue(tmp_path / "nowhere")


def test_committed_catalogue_matches_the_build():
    """catalogue.json, markers and own-drawing masters follow the definitions (official masters:
    test_catalogue_official). What the drawings decide (the measured signs' nominal size, the variants) is
    taken from the committed file; the rebuild test compares those with the drawings."""
    committed = json.loads((DEFAULT_CATALOGUE_DIR / "catalogue.json").read_text(encoding="utf-8"))
    entries = committed["entries"]
    artwork = {e["id"]: e["artwork"] for e in entries if e["artwork"] != OWN}

    class FromFile:  # what the build made of an entry: standard formats from the definitions, the rest as written
        def __init__(self, e):
            self.formats = {k: tuple(v) for k, v in e["formats"].items()}
            if e["id"] in SIGNS:
                self.formats = SIGNS[e["id"]].formats
            elif OFFICIAL_ENTRIES[e["id"]].size in STANDARD_FORMATS:
                self.formats = STANDARD_FORMATS[OFFICIAL_ENTRIES[e["id"]].size]
            self.size_certain, self.sizing = e["size_certain"], e.get("sizing", STANDARD)
            self.variants = e.get("variants", [])

    built = {e["id"]: FromFile(e) for e in entries}
    assert committed == catalogue_json(built, artwork), \
        "templates/ch is stale: run make catalogue SVG=<folder of the official drawings>"
    ids = [e["id"] for e in entries]
    for tid in ids[::9] + [i for i in ids if i not in artwork]:
        if tid in SIGNS:  # the others' markers are their master's picture
            assert (DEFAULT_CATALOGUE_DIR / "svg" / f"{file_stem(tid)}.svg").read_text(encoding="utf-8") == \
                svg_text(tid)
        on_disk = cv2.imread(str(DEFAULT_CATALOGUE_DIR / "png" / f"{file_stem(tid)}.png"), cv2.IMREAD_UNCHANGED)
        assert on_disk.shape == (*on_disk.shape[:2], 4) and max(on_disk.shape[:2]) == 512
        if tid not in artwork and tid not in FRAMED:  # framed ones: test_catalogue_official
            assert int(np.abs(on_disk.astype(int) - master_rgba(tid).astype(int)).max()) <= 1, tid


@pytest.mark.parametrize("damage", ["truncated", "flipped byte", "not an image"])
def test_corrupt_master_image_is_found_when_the_catalogue_loads(tmp_path, damage):
    _write_user_catalogue(tmp_path)
    load_catalogue(tmp_path)  # intact, and remembered as intact
    png = tmp_path / "png" / "X.1-7.png"
    data = bytearray(png.read_bytes())
    if damage == "truncated":
        data = data[: len(data) // 2]
    elif damage == "flipped byte":
        data[len(data) // 2] ^= 0xFF
    else:
        data = bytearray(b"GIF? no, a text file")
    png.write_bytes(bytes(data))  # a changed file is checked again
    with pytest.raises(CatalogueError) as info:
        load_catalogue(tmp_path)
    assert str(info.value).startswith(f"{png}: entry 'X.1-7': the template image is corrupt or unreadable (")


def test_a_jpeg_master_is_decoded_to_check_it(tmp_path):
    _write_user_catalogue(tmp_path)
    data = json.loads((tmp_path / "catalogue.json").read_text())
    img = cv2.imread(str(tmp_path / "png" / "X.1-7.png"), cv2.IMREAD_COLOR)
    jpeg = tmp_path / "png" / "X.1-7.jpg"
    jpeg.write_bytes(cv2.imencode(".jpg", img)[1].tobytes()[:-300])
    data["entries"][0]["png"] = "png/X.1-7.jpg"
    (tmp_path / "catalogue.json").write_text(json.dumps(data))
    with pytest.raises(CatalogueError, match="corrupt or unreadable"):
        load_catalogue(tmp_path)
