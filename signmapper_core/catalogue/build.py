"""Write the bundled Swiss catalogue folder (``templates/ch``) from the definitions and the official drawings.

``python -m signmapper_core.catalogue.build --svg DIR [OUT]`` renders the master
of every entry that has an official ASTRA drawing in DIR (signalo's
``project/images/official/original``, see ``official_ch``) and draws the others
with the project's own procedural drawing; the build prints which. The entries
the project has no own drawing of (``official_entries``: most of the official
set) come from their drawing alone and are left out, with the reason, where it
is missing. Without ``--svg`` every master is the own drawing. The map markers
(``svg/``) are the own drawings, or the master's picture where there is none.
Deterministic: the same inputs, code and renderer give byte-identical files.
"""

from __future__ import annotations

import argparse
import base64
import json
import re
from dataclasses import dataclass, field
from pathlib import Path

import cv2
import numpy as np

from . import formats as F
from .drawing import to_svg
from .faces import face_drawing, pixel_size, render_face
from .model import DEFAULT_CATALOGUE_DIR, FORMAT_ID, MEASURED, STANDARD, file_stem
from .official import (
    OUTLINE_MIN_IOU,
    ArtworkError,
    Drawing,
    DrawingUnavailable,
    framed_master,
    master_from_rendering,
    render_artwork,
)
from .official_ch import ARTWORK, ARTWORK_SOURCE, FRAMED, OWN_DRAWING
from .official_entries import ARTWORK as OFFICIAL_ARTWORK
from .official_entries import OFFICIAL_ENTRIES, OUTLINE_OVERLAP, VALUE_DRAWINGS, VARIANT_ARTWORK
from .official_signs import official_signs
from .signs_ch import SIGNS
from .svg_compose import SvgDocument

MASTER_PX = 512
SVG_WIDTH_PX = 64
OWN = "own drawing"
DRAWING_SCALE = 20  # the official drawings show the normal format at 1:20
CSS_PX_M = 0.0254 / 96  # one CSS pixel of a drawing's page, in metres
STANDARD_FORMATS = {"round": F.ROUND, "triangle": F.TRIANGLE, "square": F.SQUARE, "tall": F.TALL_INFO}
CERTAIN_FORMATS = ("round", "triangle")  # the other rules' large and small formats are estimates


@dataclass
class BuildReport:
    """Which entries got official artwork (id -> description), which kept the own drawing (id -> reason) and
    which official-only entries were left out (id -> reason)."""

    official: dict = field(default_factory=dict)
    own: dict = field(default_factory=dict)
    missing: dict = field(default_factory=dict)


@dataclass
class Built:
    """What the build made of one entry."""

    master: np.ndarray  # BGRA
    formats: dict
    size_certain: bool
    sizing: str
    variants: list = field(default_factory=list)  # BGRA images of the entry's other drawings


def _clean_name(name: str) -> str:
    """A Signalo name without the line-break hyphen of its source ("Fussgänger- zone" -> "Fussgängerzone")."""
    words = name.split(" ")
    out = []
    for w in words:
        if out and out[-1].endswith("-") and w[:1].islower() and w not in CONJUNCTIONS:
            out[-1] = out[-1][:-1] + w
        else:
            out.append(w)
    return " ".join(out)


CONJUNCTIONS = ("und", "oder", "et", "ou", "e", "o")  # "Rad- und Fussweg": the hyphen stays


def names_of(template_id: str) -> dict:
    """Names de/fr/it: Signalo's where it has the id, the definition's otherwise (per-value and generic panels),
    else Signalo's name of the sign with its value."""
    official = official_signs().get(template_id)
    if official is not None:
        return {lang: _clean_name(n) for lang, n in official.names.items()}
    if template_id in SIGNS:
        return dict(SIGNS[template_id].names)
    base, _, value = template_id.rpartition("-")
    return {lang: f"{_clean_name(n)} {value}" for lang, n in official_signs()[base].names.items()}


def catalogue_ids() -> list:
    """Every entry's id, in SSV number order."""
    return sorted(set(SIGNS) | set(OFFICIAL_ENTRIES), key=ssv_key)


def ssv_key(template_id: str) -> tuple:
    """Sort key of an SSV number: numeric parts as numbers (2.30-80 before 2.30-100, 4.07 before 4.07a)."""
    return tuple((0, int(p), "") if p.isdigit() else (1, 0, p) for p in re.findall(r"\d+|[A-Za-z]+", template_id))


def colour_and_shape(template_id: str) -> tuple:
    d = SIGNS.get(template_id) or OFFICIAL_ENTRIES[template_id]
    return d.colour, d.shape


def catalogue_json(built: dict, artwork: dict | None = None) -> dict:
    """The catalogue.json content of the ``built`` entries; ``artwork`` maps ids to their master's source."""
    artwork = artwork or {}
    entries = []
    for tid in (t for t in catalogue_ids() if t in built):
        b = built[tid]
        colour, shape = colour_and_shape(tid)
        stem = file_stem(tid)
        entry = {
            "id": tid,
            "names": names_of(tid),
            "colour": colour,
            "shape": shape,
            "formats": {name: [round(w, 3), round(h, 3)] for name, (w, h) in b.formats.items()},
            "size_certain": b.size_certain,
        }
        if b.sizing != STANDARD:
            entry["sizing"] = b.sizing
        entry.update({"png": f"png/{stem}.png", "svg": f"svg/{stem}.svg"})
        if b.variants:
            entry["variants"] = [f"png/{stem}~{k + 1}.png" for k in range(len(b.variants))]
        entry["artwork"] = artwork.get(tid, OWN)
        entries.append(entry)
    data = {
        "format": FORMAT_ID,
        "name": "Schweiz / Suisse / Svizzera (SSV, SR 741.21)",
        "country": "CH",
        "note": "Generated by signmapper_core.catalogue.build. Masters: official ASTRA drawings where 'artwork' "
                "names one, else the project's own drawing; map markers (svg/) are own drawings, or the master's "
                "picture. Formats are face bounding boxes in metres; 'sizing' measured: no standard size exists, "
                "the format gives the drawing's size at 1:20 (its aspect).",
        "entries": entries,
    }
    if any(a != OWN for a in artwork.values()):
        data["artwork_source"] = ARTWORK_SOURCE
    return data


def catalogue_json_text(built: dict, artwork: dict | None = None) -> str:
    return json.dumps(catalogue_json(built, artwork), ensure_ascii=False, indent=1) + "\n"


def master_size(template_id: str) -> tuple[int, int]:
    w, h = next(iter(SIGNS[template_id].formats.values()))
    return pixel_size(w / h, MASTER_PX)


def master_rgba(template_id: str) -> np.ndarray:
    """The own (procedural) master: BGRA, MASTER_PX on the longer side."""
    bgr, alpha = render_face(template_id, master_size(template_id))
    return np.dstack([bgr, alpha])


def official_master(template_id: str, svg_dir: Path) -> np.ndarray:
    """The master rendered from the entry's official drawing in ``svg_dir``; ArtworkError if it cannot be."""
    sign = SIGNS[template_id]
    spec = ARTWORK[template_id]
    bgra, outline_from_shape = render_artwork(spec, svg_dir)
    return master_from_rendering(bgra, outline_from_shape, sign.shape, master_size(template_id),
                                 f"{template_id} ({spec.describe()})")


def framed(template_id: str, content: np.ndarray, svg_dir: Path) -> np.ndarray:
    """``content``'s field set into the official frame ``FRAMED`` names, at the entry's master size."""
    sign = SIGNS[template_id]
    bgra, outline_from_shape = render_artwork(Drawing(FRAMED[template_id]), svg_dir)
    frame = master_from_rendering(bgra, outline_from_shape, sign.shape, master_size(template_id),
                                  f"{template_id} ({FRAMED[template_id]})")
    return framed_master(frame, content)


def svg_text(template_id: str) -> str:
    sign = SIGNS[template_id]
    return to_svg(face_drawing(template_id), SVG_WIDTH_PX, f"{sign.id} {sign.names['de']}")


def picture_svg(template_id: str, master: np.ndarray) -> str:
    """A map marker showing the master's picture (an embedded PNG): for entries without an own drawing."""
    h, w = master.shape[:2]
    width, height = SVG_WIDTH_PX, max(1, int(round(SVG_WIDTH_PX * h / w)))
    small = cv2.resize(master, (width * 2, height * 2), interpolation=cv2.INTER_AREA)
    png = base64.b64encode(cv2.imencode(".png", small, [cv2.IMWRITE_PNG_COMPRESSION, 9])[1].tobytes()).decode()
    title = f"{template_id} {names_of(template_id).get('de', '')}".replace("&", "&amp;").replace("<", "&lt;")
    return ('<?xml version="1.0" encoding="UTF-8"?>\n'
            f'<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" '
            f'width="{width}" height="{height}" viewBox="0 0 {width} {height}">\n<title>{title}</title>\n'
            f'<image width="{width}" height="{height}" xlink:href="data:image/png;base64,{png}"/>\n</svg>\n')


def _drawing_size_m(spec, svg_dir: Path, crop_px: tuple, rendered_px: tuple) -> tuple[float, float]:
    """Size in metres of a crop of a rendering of ``spec``: the drawing's page is the normal format at 1:20."""
    doc = SvgDocument.load(Path(svg_dir) / spec.files()[0])
    if isinstance(spec, Drawing):
        page_w = doc.page_px()[0]
    else:  # a part of the page (Region)
        x0, y0, x1, y1 = spec.area
        k = doc.px_per_unit()
        page_w = (x1 - x0) * k
    per_px = page_w / rendered_px[0]  # CSS px of the page per rendered px
    return (crop_px[0] * per_px * CSS_PX_M * DRAWING_SCALE, crop_px[1] * per_px * CSS_PX_M * DRAWING_SCALE)


def _cropped_size(bgra: np.ndarray) -> tuple[int, int]:
    ys, xs = np.nonzero(bgra[:, :, 3] > 0)
    return int(xs.max() - xs.min() + 1), int(ys.max() - ys.min() + 1)


def _official_spec(template_id: str):
    if template_id in OFFICIAL_ARTWORK:
        return OFFICIAL_ARTWORK[template_id]
    if template_id in VALUE_DRAWINGS:
        return Drawing(VALUE_DRAWINGS[template_id])
    return Drawing(official_signs()[template_id].left_drawing)


def variant_specs(template_id: str, master_spec) -> list:
    """The entry's other drawings: language versions and the other pointing direction, or the other boards."""
    if template_id in VARIANT_ARTWORK:
        return list(VARIANT_ARTWORK[template_id])
    official = official_signs().get(template_id)
    if official is None or not isinstance(master_spec, Drawing):
        return []
    return [Drawing(f) for f in official.drawings if f != master_spec.file]


def _variant_masters(template_id: str, specs, shape: str, size: tuple, svg_dir: Path) -> list:
    out = []
    for spec in specs:
        bgra, from_shape = render_artwork(spec, svg_dir)
        out.append(master_from_rendering(bgra, from_shape, shape, size, f"{template_id} ({spec.describe()})",
                                         _min_overlap(template_id)))
    return out


def _min_overlap(template_id: str) -> float:
    return OUTLINE_OVERLAP.get(template_id, OUTLINE_MIN_IOU)


def official_only(template_id: str, svg_dir: Path) -> tuple[Built, str]:
    """An entry the project has no own drawing of, built from its official drawing(s), and its source."""
    definition = OFFICIAL_ENTRIES[template_id]
    spec = _official_spec(template_id)
    bgra, from_shape = render_artwork(spec, svg_dir)
    crop = _cropped_size(bgra)
    if definition.size in STANDARD_FORMATS:
        formats = STANDARD_FORMATS[definition.size]
        sizing, certain = STANDARD, definition.size in CERTAIN_FORMATS
    else:
        w, h = _drawing_size_m(spec, svg_dir, crop, (bgra.shape[1], bgra.shape[0]))
        # to the millimetre, as catalogue.json writes it: the master's aspect follows the written size
        formats, sizing, certain = {"nominal": (round(w, 3), round(h, 3))}, MEASURED, False
    w, h = next(iter(formats.values()))
    size = pixel_size(w / h, MASTER_PX)
    name = f"{template_id} ({spec.describe()})"
    master = master_from_rendering(bgra, from_shape, definition.shape, size, name, _min_overlap(template_id))
    variants = _variant_masters(template_id, variant_specs(template_id, spec), definition.shape, size, svg_dir)
    return Built(master, dict(formats), certain, sizing, variants), f"ASTRA {spec.describe()}"


def _own_built(tid: str, image: np.ndarray, variants=()) -> Built:
    sign = SIGNS[tid]
    return Built(image, dict(sign.formats), sign.size_certain, STANDARD, list(variants))


def masters(svg_dir: Path | None) -> tuple[dict, BuildReport]:
    """id -> :class:`Built` for every entry that can be built, and the report of where each came from."""
    report, out = BuildReport(), {}
    if svg_dir is not None and not any((svg_dir / f).is_file() for spec in ARTWORK.values() for f in spec.files()):
        raise ArtworkError(f"{svg_dir}: none of the official drawings were found there (expected e.g. 101.svg)")
    for tid in catalogue_ids():
        if tid in OFFICIAL_ENTRIES:
            if svg_dir is None:
                report.missing[tid] = "no official drawings given (--svg)"
                continue
            try:
                out[tid], report.official[tid] = official_only(tid, svg_dir)
            except DrawingUnavailable as exc:
                report.missing[tid] = str(exc)
            continue
        if svg_dir is None:
            reason = "no official drawings given (--svg)"
        elif tid in FRAMED and tid not in ARTWORK:
            try:
                out[tid] = _own_built(tid, framed(tid, master_rgba(tid), svg_dir))
                report.own[tid] = f"{OWN_DRAWING[tid]}; own value in the official frame {FRAMED[tid]}"
                continue
            except DrawingUnavailable as exc:
                reason = str(exc)
        elif tid not in ARTWORK:
            reason = OWN_DRAWING.get(tid, "no official drawing mapped")
        else:
            try:
                image = official_master(tid, svg_dir)
                report.official[tid] = f"ASTRA {ARTWORK[tid].describe()}"
                if tid in FRAMED:
                    image = framed(tid, image, svg_dir)
                    report.official[tid] += f", its field in the frame of {FRAMED[tid]}"
                    variants = []
                else:
                    specs = variant_specs(tid, ARTWORK[tid])
                    variants = _variant_masters(tid, specs, SIGNS[tid].shape, master_size(tid), svg_dir)
                out[tid] = _own_built(tid, image, variants)
                continue
            except DrawingUnavailable as exc:  # a drawing that does not fit its entry is an error, not this
                reason = str(exc)
        out[tid] = _own_built(tid, master_rgba(tid))
        report.own[tid] = reason
    return out, report


def _write_png(path: Path, img: np.ndarray) -> None:
    cv2.imwrite(str(path), img, [cv2.IMWRITE_PNG_COMPRESSION, 9])


def build(out: Path = DEFAULT_CATALOGUE_DIR, svg_dir: Path | None = None) -> BuildReport:
    out = Path(out)
    built, report = masters(None if svg_dir is None else Path(svg_dir))
    (out / "png").mkdir(parents=True, exist_ok=True)
    (out / "svg").mkdir(parents=True, exist_ok=True)
    files = {f"png/{file_stem(t)}.png" for t in built} | {f"svg/{file_stem(t)}.svg" for t in built}
    files |= {f"png/{file_stem(t)}~{k + 1}.png" for t, b in built.items() for k in range(len(b.variants))}
    for stale in list((out / "png").glob("*.png")) + list((out / "svg").glob("*.svg")):
        if str(stale.relative_to(out)) not in files:
            stale.unlink()
    for tid, b in built.items():
        stem = file_stem(tid)
        _write_png(out / "png" / f"{stem}.png", b.master)
        for k, image in enumerate(b.variants):
            _write_png(out / "png" / f"{stem}~{k + 1}.png", image)
        marker = svg_text(tid) if tid in SIGNS else picture_svg(tid, b.master)
        (out / "svg" / f"{stem}.svg").write_text(marker, encoding="utf-8")
    (out / "catalogue.json").write_text(catalogue_json_text(built, report.official), encoding="utf-8")
    return report


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", nargs="?", default=str(DEFAULT_CATALOGUE_DIR), help="output folder (templates/ch)")
    parser.add_argument("--svg", default=None, help="folder of the official SVG drawings "
                                                    "(signalo project/images/official/original)")
    args = parser.parse_args(argv)
    try:
        report = build(Path(args.out), args.svg)
    except (ArtworkError, RuntimeError) as exc:
        print(f"error: {exc}")
        return 1
    print(f"wrote {len(report.official) + len(report.own)} templates to {args.out}: {len(report.official)} from "
          f"official drawings, {len(report.own)} own drawings, {len(report.missing)} left out")
    for tid, reason in report.own.items():
        print(f"  own drawing {tid}: {reason}")
    for tid, reason in report.missing.items():
        print(f"  left out {tid}: {reason}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
