"""The Swiss masters from the official ASTRA drawings: provenance, formats, and the build from SVG folders."""

from __future__ import annotations

import json
import os
import re
from pathlib import Path

import cv2
import numpy as np
import pytest

from signmapper_core.catalogue import DEFAULT_CATALOGUE_DIR, load_catalogue, render_face, svg_render
from signmapper_core.catalogue import build as catalogue_build
from signmapper_core.catalogue.official import (
    ArtworkError,
    Cutout,
    Drawing,
    Glyph,
    Relettered,
    master_from_rendering,
    relettered_svg,
    render_artwork,
)
from signmapper_core.catalogue.official_ch import ARTWORK, ARTWORK_SOURCE, FRAMED, OWN_DRAWING
from signmapper_core.catalogue.official_entries import OFFICIAL_ENTRIES
from signmapper_core.catalogue.signs_ch import SIGNS
from signmapper_core.catalogue.svg_compose import SvgDocument

needs_renderer = pytest.mark.skipif(not svg_render.renderer_available(),
                                    reason="rsvg-convert (Debian package librsvg2-bin) is not installed")
RED, WHITE, BLUE = "#ee2b2e", "#ffffff", "#1967bb"


@pytest.fixture(scope="module")
def cat():
    return load_catalogue()


@pytest.fixture(scope="module")
def committed():
    return json.loads((DEFAULT_CATALOGUE_DIR / "catalogue.json").read_text(encoding="utf-8"))


def test_every_entry_has_a_master_with_the_aspect_of_its_formats(cat):
    for e in cat:
        img = cv2.imread(str(DEFAULT_CATALOGUE_DIR / e.png), cv2.IMREAD_UNCHANGED)
        assert img is not None and img.shape[2] == 4, e.id
        h, w = img.shape[:2]
        assert max(w, h) == 512, e.id
        # a pixel of the shorter side (the aspect error of rounding it), in aspect units
        assert abs(w / h - e.aspect) <= max(w / h, h / w) / min(w, h), (e.id, w, h, e.aspect)
        alpha = img[:, :, 3]
        assert alpha.max() == 255 and (alpha[0].max() > 0 and alpha[-1].max() > 0), e.id  # cropped to the face
        assert alpha[:, 0].max() > 0 and alpha[:, -1].max() > 0, e.id


def test_transparent_pixels_carry_the_rim_colour(cat):
    """One colour outside the outline: the one that dominates the opaque band along it."""
    for tid in ("1.01", "2.30-50", "3.01", "3.03", "2.33"):
        img = cv2.imread(str(DEFAULT_CATALOGUE_DIR / "png" / f"{tid}.png"), cv2.IMREAD_UNCHANGED)
        clear = img[:, :, 3] == 0
        assert clear.any(), tid
        outside = img[:, :, :3][clear].astype(int)
        assert np.ptp(outside, axis=0).max() == 0, tid
        depth = cv2.distanceTransform((img[:, :, 3] > 0).astype(np.uint8), cv2.DIST_L2, 3)
        band = (img[:, :, 3] == 255) & (depth <= 10)  # 2 % of 512 px
        near = np.abs(img[:, :, :3][band].astype(int) - outside[0]).max(axis=1) < 40
        assert near.mean() > 0.5, (tid, near.mean())


def test_artwork_of_every_entry_is_recorded_and_matches_the_mapping(committed):
    entries = {e["id"]: e for e in committed["entries"]}
    assert set(entries) == set(SIGNS) | set(OFFICIAL_ENTRIES)
    own = {tid for tid, e in entries.items() if e["artwork"] == catalogue_build.OWN}
    assert own == set(OWN_DRAWING) == set(SIGNS) - set(ARTWORK)
    for tid, spec in ARTWORK.items():
        framed = f", its field in the frame of {FRAMED[tid]}" if tid in FRAMED else ""
        assert entries[tid]["artwork"] == f"ASTRA {spec.describe()}{framed}", tid
    assert len(ARTWORK) == 108 and len(own) == 7
    # the signs the project does not draw: the drawing Signalo names for them, or the part of it ARTWORK cuts
    assert entries["4.31-1"]["artwork"] == "ASTRA 431-1-l.svg"
    assert entries["1.17"]["artwork"] == "ASTRA 117.svg, part (0.7, 0.3, 43.2, 142.0)"
    assert entries["2.54-30"]["artwork"] == "ASTRA 254.svg"
    assert committed["artwork_source"] == ARTWORK_SOURCE
    assert re.fullmatch(r"[0-9a-f]{40}", ARTWORK_SOURCE["commit"])


def test_readme_lists_exactly_the_entries_with_the_own_drawing():
    text = (DEFAULT_CATALOGUE_DIR.parent / "README.md").read_text(encoding="utf-8")
    section = text.split("<!-- own-drawings -->")[1].split("<!-- /own-drawings -->")[0]
    listed = set(re.findall(r"`([0-9][0-9.]*(?:-[0-9.]+)?)`", section))
    assert listed == set(OWN_DRAWING)


def test_own_drawing_masters_are_the_procedural_drawing(committed):
    own = [e["id"] for e in committed["entries"] if e["artwork"] == catalogue_build.OWN and e["id"] not in FRAMED]
    assert own == ["2.53-50"]
    for tid in own:
        on_disk = cv2.imread(str(DEFAULT_CATALOGUE_DIR / "png" / f"{tid}.png"), cv2.IMREAD_UNCHANGED)
        assert int(np.abs(on_disk.astype(int) - catalogue_build.master_rgba(tid).astype(int)).max()) <= 1, tid


@pytest.mark.parametrize("tid", sorted(FRAMED))
def test_framed_masters_have_the_official_rim_and_their_own_field(tid):
    """The rim of every framed entry is the official 2.01's; its field differs from the empty one (the value)."""
    read = lambda t: cv2.imread(str(DEFAULT_CATALOGUE_DIR / "png" / f"{t}.png"), cv2.IMREAD_UNCHANGED)  # noqa: E731
    framed, frame = read(tid).astype(int), read("2.01").astype(int)
    yy, xx = np.mgrid[0:512, 0:512]
    r = np.hypot(xx - 255.5, yy - 255.5) / 256
    rim = (r > 0.75) & (r < 0.95)
    field = r < 0.55
    assert np.abs(framed[rim] - frame[rim]).max() <= 2
    assert np.abs(framed[field][:, :3] - frame[field][:, :3]).mean() > 10


def test_official_templates_are_not_the_generators_procedural_faces(cat):
    """The point of the official artwork: the templates are not our own drawing, which the generator uses."""
    for tid in ("2.30-50", "1.22", "3.01", "4.08", "2.44"):
        t_bgr, t_alpha = cat.render(tid, 64)
        f_bgr, f_alpha = render_face(tid, 64)
        inside = (t_alpha > 200) & (f_alpha > 200)
        assert np.abs(t_bgr.astype(int) - f_bgr)[inside].mean() > 10, tid


# --------------------------------------------------------------------------- building from SVG folders

def _svg(view_w, view_h, body, unit="pt") -> str:
    return (f'<?xml version="1.0" encoding="UTF-8"?>\n<svg xmlns="http://www.w3.org/2000/svg" '
            f'width="{view_w}{unit}" height="{view_h}{unit}" viewBox="0 0 {view_w} {view_h}">\n{body}\n</svg>\n')


def _tiny_official_folder(folder: Path, disc_as_square: bool = False) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    disc = (f'<rect x="1" y="1" width="84" height="84" fill="{RED}"/>' if disc_as_square else
            f'<circle cx="43" cy="43" r="42" fill="{RED}"/>')
    (folder / "201.svg").write_text(_svg(86, 86, disc + f'<circle cx="43" cy="43" r="28" fill="{WHITE}"/>'))
    # a danger triangle with the box aspect of the rounded official one (1.140)
    (folder / "101.svg").write_text(_svg(121, 106, f'<polygon points="3,103 117.02,103 60.01,3" fill="{RED}"/>'
                                                   f'<polygon points="24,91 96,91 60,29" fill="{WHITE}"/>'))
    (folder / "408.svg").write_text(_svg(72, 72, f'<rect x="1" y="1" width="70" height="70" fill="{BLUE}"/>'
                                                 f'<rect x="31" y="12" width="10" height="48" fill="{WHITE}"/>'))
    return folder


@needs_renderer
def test_build_from_a_tiny_svg_folder_falls_back_and_lists_the_rest(tmp_path):
    svg_dir = _tiny_official_folder(tmp_path / "svg")
    report = catalogue_build.build(tmp_path / "out", svg_dir)
    assert set(report.official) == {"2.01", "1.01", "4.08"}
    assert set(report.own) == set(SIGNS) - {"2.01", "1.01", "4.08"}
    assert "301.svg: official drawing not found" in report.own["3.01"]
    assert report.own["2.30-70"] == OWN_DRAWING["2.30-70"] + "; own value in the official frame 201.svg"
    # the signs the project does not draw cannot be built without their drawing: left out, and said why
    assert set(report.missing) == set(OFFICIAL_ENTRIES)
    assert "431-1-l.svg: official drawing not found" in report.missing["4.31-1"]
    cat = load_catalogue(tmp_path / "out")
    assert len(cat) == len(SIGNS)
    data = json.loads((tmp_path / "out" / "catalogue.json").read_text(encoding="utf-8"))
    artwork = {e["id"]: e["artwork"] for e in data["entries"]}
    assert artwork["2.01"] == "ASTRA 201.svg" and artwork["3.01"] == catalogue_build.OWN
    bgr, alpha = cat.master("2.01")
    assert bgr.shape == (512, 512, 3)
    assert tuple(int(v) for v in bgr[256, 256]) == (255, 255, 255)  # white centre
    b, g, r = (int(v) for v in bgr[256, 20])  # red ring
    assert r > 200 and g < 80 and b < 80
    assert alpha[0, 0] == 0 and alpha[256, 256] == 255
    assert tuple(int(v) for v in bgr[0, 0]) == (b, g, r)  # transparent corner carries the rim colour
    bgr, alpha = cat.master("1.01")
    assert bgr.shape[:2] == (449, 512) and alpha[-1, 256] > 127 and alpha[-3, 256] == 255 and alpha[0, 0] == 0
    assert np.array_equal(cat.master("3.01")[0], catalogue_build.master_rgba("3.01")[:, :, :3])


@needs_renderer
def test_official_masters_are_deterministic(tmp_path):
    svg_dir = _tiny_official_folder(tmp_path / "svg")
    first = [cv2.imencode(".png", catalogue_build.official_master(t, svg_dir))[1].tobytes() for t in ("2.01", "1.01")]
    second = [cv2.imencode(".png", catalogue_build.official_master(t, svg_dir))[1].tobytes() for t in ("2.01", "1.01")]
    assert first == second


@needs_renderer
def test_a_drawing_that_does_not_fit_its_entry_stops_the_build(tmp_path):
    svg_dir = _tiny_official_folder(tmp_path / "svg", disc_as_square=True)
    with pytest.raises(ArtworkError, match=r"2\.01 \(201\.svg\).*circle"):
        catalogue_build.build(tmp_path / "out", svg_dir)
    bgra, from_shape = render_artwork(Drawing("408.svg"), svg_dir)
    with pytest.raises(ArtworkError, match="aspect 1.000"):
        master_from_rendering(bgra, from_shape, "rectangle", (357, 500), "4.11 (408.svg)")


def test_a_folder_without_any_official_drawing_is_an_error(tmp_path, capsys):
    (tmp_path / "svg").mkdir()
    assert catalogue_build.main([str(tmp_path / "out"), "--svg", str(tmp_path / "svg")]) == 1
    assert "none of the official drawings" in capsys.readouterr().out


def test_a_missing_renderer_is_named_with_its_package(tmp_path, monkeypatch, capsys):
    svg_dir = _tiny_official_folder(tmp_path / "svg")
    monkeypatch.setattr(svg_render.shutil, "which", lambda name: None)
    with pytest.raises(svg_render.RendererMissing, match="rsvg-convert.*librsvg2-bin"):
        svg_render.render_svg(b"<svg/>", 1.0)
    assert catalogue_build.main([str(tmp_path / "out"), "--svg", str(svg_dir)]) == 1
    assert "librsvg2-bin" in capsys.readouterr().out
    assert not (tmp_path / "out" / "catalogue.json").exists()


@needs_renderer
def test_relettering_places_the_new_glyph_in_the_old_slot_at_the_reference_scale(tmp_path):
    # base: a "A0" inscription (glyph + a "0" with counter); source: a glyph and its "0" at half the size
    (tmp_path / "base.svg").write_text(_svg(100, 100, (
        f'<circle cx="50" cy="50" r="49" fill="{WHITE}"/>'
        '<rect x="20" y="30" width="20" height="40" fill="#222222"/>'
        '<rect x="60" y="30" width="20" height="40" fill="#222222"/>'
        f'<rect x="65" y="40" width="10" height="20" fill="{WHITE}"/>'), unit="px"))
    (tmp_path / "src.svg").write_text(_svg(50, 50, (
        '<polygon points="4,34 14,34 9,12" fill="#222222"/>'  # the new glyph, 2 units above the baseline
        '<rect x="20" y="16" width="10" height="20" fill="#222222"/>'
        f'<rect x="22" y="20" width="6" height="12" fill="{WHITE}"/>'), unit="px"))
    spec = Relettered("base.svg", ((1,), (2, 3)), ((0, Glyph("src.svg", (0,), reference=(1, 2))),), reference=1,
                      recolour=("#0000ff", "#00ff00"), elements=(("base.svg", 4), ("src.svg", 3)))
    docs = {name: SvgDocument.load(tmp_path / name) for name in ("base.svg", "src.svg")}
    out = tmp_path / "out.svg"
    out.write_bytes(relettered_svg(spec, docs))
    doc = SvgDocument.load(out)
    assert len(doc.elements) == 4  # old glyph dropped, new one added
    x0, y0, x1, y1 = doc.box([3])
    assert (x0 + x1) / 2 == pytest.approx(30, abs=0.3)  # centred in the old slot
    assert y1 == pytest.approx(66, abs=0.3) and y1 - y0 == pytest.approx(44, abs=0.3)  # scale 2, 2 units up
    assert doc.fill(3) == "#0000ff"
    bad = Relettered("base.svg", spec.slots, spec.replace, reference=1, elements=(("base.svg", 5),))
    with pytest.raises(ArtworkError, match="has 4 drawable elements"):
        relettered_svg(bad, docs)


@needs_renderer
def test_cutout_takes_the_sign_around_the_area_centre_with_the_shape_as_outline(tmp_path):
    (tmp_path / "sheet.svg").write_text(
        '<svg xmlns="http://www.w3.org/2000/svg" width="100" height="50">'
        f'<rect width="100" height="50" fill="{BLUE}"/>'
        f'<circle cx="25" cy="25" r="20" fill="{RED}"/><circle cx="75" cy="25" r="20" fill="{RED}"/>'
        f'<circle cx="75" cy="25" r="13" fill="{WHITE}"/></svg>')
    bgra, from_shape = render_artwork(Cutout("sheet.svg", (52, 2, 98, 48), (0xEE, 0x2B, 0x2E)), tmp_path)
    assert from_shape and abs(bgra.shape[0] - bgra.shape[1]) <= 2
    master = master_from_rendering(bgra, from_shape, "circle", (64, 64), "cut")
    assert master[0, 0, 3] == 0 and master[32, 32, 3] == 255
    assert tuple(int(v) for v in master[32, 32, :3]) == (255, 255, 255)  # the right-hand disc, white inside
    b, g, r = (int(v) for v in master[0, 0, :3])
    assert r > 200 and g < 80 and b < 80


@pytest.mark.skipif(not os.environ.get("SIGNMAPPER_OFFICIAL_SVG"),
                    reason="set SIGNMAPPER_OFFICIAL_SVG to signalo's project/images/official/original to run")
@needs_renderer
def test_rebuild_from_the_official_drawings_gives_the_committed_files(tmp_path):
    catalogue_build.build(tmp_path, Path(os.environ["SIGNMAPPER_OFFICIAL_SVG"]))
    built = 0
    for path in sorted(DEFAULT_CATALOGUE_DIR.rglob("*")):
        rel = path.relative_to(DEFAULT_CATALOGUE_DIR)
        # what this build writes: not the classifier (make train-classifier) or the plates (plate_build)
        if path.is_file() and rel.parts[0] not in ("classifier", "plates"):
            assert (tmp_path / rel).read_bytes() == path.read_bytes(), rel
            built += 1
    cat = load_catalogue()
    # a master and a marker per sign, its variants, and catalogue.json
    assert built == 2 * len(cat) + sum(len(e.variants) for e in cat) + 1
