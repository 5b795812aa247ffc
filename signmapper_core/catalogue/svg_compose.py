"""Read official SVG drawings as lists of drawable elements, measure them, and compose new drawings from them.

A sign carrying a value (``2.30-20``) is drawn by taking the official drawing of
the same sign with another value and replacing its digit glyphs by the glyphs
of another official drawing: elements are addressed by their index among the
drawable elements in document order, and placed by their rendered bounding
boxes, so no path geometry is parsed here. Build-time only (needs the renderer).
"""

from __future__ import annotations

import copy
import io
import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .svg_render import render_svg

SVG_NS = "http://www.w3.org/2000/svg"
XLINK_NS = "http://www.w3.org/1999/xlink"
DRAWABLE = {"path", "rect", "circle", "ellipse", "polygon", "polyline", "line", "use", "text", "image"}
NOT_RENDERED = {"defs", "metadata", "namedview", "clipPath", "mask", "symbol", "title", "desc", "style",
                "linearGradient", "radialGradient", "pattern", "marker", "filter"}
CSS_PX = {"px": 1.0, "": 1.0, "pt": 96 / 72, "pc": 16.0, "mm": 96 / 25.4, "cm": 96 / 2.54, "in": 96.0}
MEASURE_PX = 2000  # longer side of the rendering used to measure element boxes

ET.register_namespace("", SVG_NS)
ET.register_namespace("xlink", XLINK_NS)

Box = tuple  # (x0, y0, x1, y1) in user units


def _local(tag) -> str:
    return tag.split("}")[-1] if isinstance(tag, str) else ""


def _length_px(value: str | None, source: str) -> float | None:
    if value is None:
        return None
    m = re.fullmatch(r"\s*([0-9.]+(?:[eE][-+]?\d+)?)\s*([a-z]*)\s*", value)
    if not m or m.group(2) not in CSS_PX:
        raise ValueError(f"{source}: unsupported SVG length {value!r}")
    return float(m.group(1)) * CSS_PX[m.group(2)]


def _drawables(root: ET.Element) -> list[tuple[ET.Element, list[ET.Element]]]:
    """(element, ancestors from the root down) of every drawable element, in document order."""
    out = []

    def walk(el, ancestors):
        for child in el:
            name = _local(child.tag)
            if name in NOT_RENDERED:
                continue
            if name in DRAWABLE:
                out.append((child, ancestors))
            else:
                walk(child, ancestors + [child])

    walk(root, [root])
    return out


@dataclass
class SvgDocument:
    """One SVG drawing: its tree, page size and drawable elements (by document-order index)."""

    source: str
    data: bytes
    root: ET.Element
    _boxes: dict = field(default_factory=dict, repr=False)

    @classmethod
    def load(cls, path: Path) -> SvgDocument:
        data = Path(path).read_bytes()
        try:
            root = ET.fromstring(data)
        except ET.ParseError as exc:
            raise ValueError(f"{path}: not a readable SVG file ({exc})") from None
        if _local(root.tag) != "svg":
            raise ValueError(f"{path}: root element is <{_local(root.tag)}>, not <svg>")
        return cls(str(path), data, root)

    @property
    def elements(self) -> list[ET.Element]:
        return [el for el, _ in _drawables(self.root)]

    def view_box(self) -> tuple[float, float, float, float]:
        """(x, y, w, h) of the user coordinate system shown on the page."""
        vb = self.root.get("viewBox")
        if vb:
            values = [float(v) for v in re.split(r"[\s,]+", vb.strip())]
            if len(values) != 4 or values[2] <= 0 or values[3] <= 0:
                raise ValueError(f"{self.source}: malformed viewBox {vb!r}")
            return tuple(values)
        w, h = self.page_px()
        return 0.0, 0.0, w, h

    def page_px(self) -> tuple[float, float]:
        """Page size in CSS pixels, as the renderer sizes it at zoom 1."""
        w = _length_px(self.root.get("width"), self.source)
        h = _length_px(self.root.get("height"), self.source)
        vb = self.root.get("viewBox")
        if (w is None or h is None) and vb:
            _, _, vw, vh = (float(v) for v in re.split(r"[\s,]+", vb.strip()))
            w, h = (w or vw), (h or vh)
        if not w or not h:
            raise ValueError(f"{self.source}: the SVG has neither width/height nor a viewBox")
        return w, h

    def px_per_unit(self) -> float:
        return self.page_px()[0] / self.view_box()[2]

    def element(self, index: int) -> ET.Element:
        els = self.elements
        if not 0 <= index < len(els):
            raise ValueError(f"{self.source}: no drawable element {index} (it has {len(els)})")
        return els[index]

    def fill(self, index: int) -> str | None:
        el = self.element(index)
        m = re.search(r"(?:^|;)\s*fill\s*:\s*([^;]+)", el.get("style", ""))
        return m.group(1).strip() if m else el.get("fill")

    def box(self, indices) -> Box:
        """Rendered bounding box of the union of the given elements, in user units."""
        key = tuple(sorted(indices))
        if key not in self._boxes:
            keep = set(key)
            root = copy.deepcopy(self.root)
            for i, (el, ancestors) in enumerate(_drawables(root)):
                if i not in keep:
                    ancestors[-1].remove(el)
            w, h = self.page_px()
            zoom = MEASURE_PX / max(w, h)
            alpha = render_svg(ET.tostring(root), zoom, self.source)[:, :, 3]
            ys, xs = np.nonzero(alpha)
            if xs.size == 0:
                raise ValueError(f"{self.source}: elements {list(key)} draw nothing")
            scale = zoom * self.px_per_unit()
            vx, vy, _, _ = self.view_box()
            self._boxes[key] = (vx + xs.min() / scale, vy + ys.min() / scale,
                                vx + (xs.max() + 1) / scale, vy + (ys.max() + 1) / scale)
        return self._boxes[key]


def _set_fill(el: ET.Element, colour: str) -> None:
    style = el.get("style")
    if style is not None and re.search(r"(?:^|;)\s*fill\s*:", style):
        el.set("style", re.sub(r"((?:^|;)\s*fill\s*:\s*)[^;]+", lambda m: m.group(1) + colour, style))
    else:
        el.set("fill", colour)


@dataclass(frozen=True)
class Placement:
    """Elements of ``doc`` mapped into another drawing by x' = s * x + tx, y' = s * y + ty."""

    doc: SvgDocument
    elements: tuple  # drawable indices; the first is the outline, the rest its counters
    scale: float
    tx: float
    ty: float
    recolour: tuple | None = None  # (outline fill, counter fill)


def _placed_group(p: Placement) -> ET.Element:
    matrix = f"matrix({p.scale:.6f},0,0,{p.scale:.6f},{p.tx:.6f},{p.ty:.6f})"
    group = ET.Element(f"{{{SVG_NS}}}g", {"transform": matrix})
    drawables = _drawables(p.doc.root)
    for k, index in enumerate(p.elements):
        el, ancestors = drawables[index]
        if "url(" in ET.tostring(el, encoding="unicode"):
            raise ValueError(f"{p.doc.source}: element {index} references other elements; it cannot be moved")
        parent = group
        for anc in ancestors[1:]:  # keep the transforms and styles of enclosing groups
            attrs = {k2: v for k2, v in anc.attrib.items() if _local(k2) != "id"}
            parent = ET.SubElement(parent, anc.tag, attrs)
        clone = copy.deepcopy(el)
        clone.attrib.pop("id", None)
        if p.recolour is not None:
            _set_fill(clone, p.recolour[0] if k == 0 else p.recolour[1])
        parent.append(clone)
    return group


def compose(base: SvgDocument, drop, placements) -> bytes:
    """The base drawing without the ``drop`` elements, with ``placements`` drawn on top."""
    root = copy.deepcopy(base.root)
    dropped = set(drop)
    for i, (el, ancestors) in enumerate(_drawables(root)):
        if i in dropped:
            ancestors[-1].remove(el)
    for p in placements:
        root.append(_placed_group(p))
    buf = io.BytesIO()
    ET.ElementTree(root).write(buf, encoding="utf-8", xml_declaration=True)
    return buf.getvalue()


def region(doc: SvgDocument, box: Box) -> bytes:
    """The drawing with its page cut down to ``box`` (user units): renders only that part."""
    root = copy.deepcopy(doc.root)
    x0, y0, x1, y1 = box
    k = doc.px_per_unit()
    root.set("viewBox", f"{x0:.4f} {y0:.4f} {x1 - x0:.4f} {y1 - y0:.4f}")
    root.set("width", f"{(x1 - x0) * k:.4f}")
    root.set("height", f"{(y1 - y0) * k:.4f}")
    root.attrib.pop("preserveAspectRatio", None)
    return ET.tostring(root, encoding="utf-8", xml_declaration=True)
