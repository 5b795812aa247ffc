"""Reading features of our layers into what the dock shows (``ReviewItem``), and their driving order.

Attributes are read through the output schema (``gpkg/fields.feature_values``):
a name that is not a field of the layer kind fails here, not silently in the dock.
"""

from __future__ import annotations

import math
from typing import List, Optional, Tuple

from qgis.core import QgsFeatureRequest

from ..gpkg.fields import feature_values
from ..signmapper_core.changes.schema import CHANGES
from ..signmapper_core.output.classifier_alternatives import parse_alternatives
from ..signmapper_core.output.schema import DETECTIONS, SIGNS
from ..signmapper_core.plates.catalogue import pictogram_png
from ..signmapper_core.statuses import REVIEW
from ..ui.review_item import ObservationView, ReviewItem
from .imaging import crop_rect
from .layers import detections_layer_for, features_where

BBOX = ("bbox_x", "bbox_y", "bbox_w", "bbox_h")
SIGN_FIGURES = (("n_obs", "observations", "{}"), ("vote_share", "vote share", "{:.2f}"), ("sigma_m", "σ", "{:.2f} m"))


def driving_order(layer, kind: str) -> List[Tuple[int, str]]:
    """(fid, status) of all features in driving order (time, then fid)."""
    request = QgsFeatureRequest().setFlags(QgsFeatureRequest.NoGeometry)
    request.setSubsetOfAttributes(["time", "status"], layer.fields())
    rows = []
    for feature in layer.getFeatures(request):
        values = feature_values(feature, kind)
        time = values["time"]
        rows.append((time if time is not None else math.inf, feature.id(), values["status"] or ""))
    return [(fid, status) for _, fid, status in sorted(rows)]


def _bbox(values: dict) -> Optional[Tuple[int, int, int, int]]:
    box = tuple(values[k] for k in BBOX)
    return box if all(c is not None for c in box) else None


def read_item(session, feature) -> ReviewItem:
    """Everything the dock shows of ``feature`` of the session's layer, except the images (loaded later)."""
    layer, kind = session.layer, session.kind
    values = feature_values(feature, kind)
    order = driving_order(layer, kind)
    position = next((i for i, (fid, _) in enumerate(order) if fid == feature.id()), 0) + 1
    to_review = sum(status == REVIEW for _, status in order)
    if kind == CHANGES:
        return change_item(session, feature, values, f"{position} of {len(order)} · {to_review} to review")
    if kind == SIGNS:
        what, pair_id = f"sign {values['sign_id']}", values["best_pair_id"]
    else:
        what, pair_id = f"feature {feature.id()}", values["pair_id"]
    u, v = values["u"], values["v"]
    point = feature.geometry().constGet() if feature.hasGeometry() else None
    item = ReviewItem(
        kind, feature.id(), f"{layer.name()} · {what} · {position} of {len(order)} · {to_review} to review",
        template_id=values["template_id"] or "", name=values["name"] or "", colour=values["colour"] or "",
        shape=values["shape"] or "", format=values["format"] or "",
        size_m=(values["width_m"] or 0.0, values["height_m"] or 0.0),
        status=values["status"] or "", reviewed=bool(values["reviewed"]),
        detection_indicator=values["detection_indicator"],
        classification_indicator=values["classification_indicator"],
        pair_id=pair_id or "", time=values["time"], depth_m=values["depth_m"], bbox=_bbox(values),
        centroid=(u, v) if u is not None and v is not None else None,
        position=(point.x(), point.y(), point.z()) if point is not None else None,
        alternatives=parse_alternatives(values["alternatives"]), review_reason=values["review_reason"] or "",
    )
    catalogue = session.catalogue
    if catalogue is not None and (kind == SIGNS or item.template_id in catalogue):
        item.pictogram_path = pictogram_png(catalogue, item.template_id)
    if kind == SIGNS:
        item.extra = [(label, fmt.format(values[key])) for key, label, fmt in SIGN_FIGURES if values[key] is not None]
        item.observations = observations_of(layer, values["sign_id"]) or own_observation(values)
        item.plate_of, item.text, item.text_confidence = values["plate_of"], values["text"], values["text_confidence"]
    if item.bbox is not None and session.drive is not None:
        item.crop = crop_rect(item.bbox, session.drive.image_size)
    return item


def own_observation(values: dict) -> List[ObservationView]:
    """A sign without linked detections (added by hand, or a copied layer): its own best observation."""
    box, pair_id = _bbox(values), values["best_pair_id"]
    if box is None or not pair_id:
        return []
    score = values["classification_indicator"]
    label = f"{pair_id}\n{score:.2f}" if score is not None else str(pair_id)
    return [ObservationView(str(pair_id), label, None, values["template_id"] or "", box)]


def review_progress(layer, kind: str) -> Tuple[int, int, int]:
    """(to review, reviewed, total) of a layer: what the dock and the map show of the review's progress."""
    request = QgsFeatureRequest().setFlags(QgsFeatureRequest.NoGeometry)
    request.setSubsetOfAttributes(["status", "reviewed"], layer.fields())
    to_review = reviewed = total = 0
    for feature in layer.getFeatures(request):
        values = feature_values(feature, kind)
        total += 1
        to_review += values["status"] == REVIEW
        reviewed += bool(values["reviewed"])
    return to_review, reviewed, total


def observations_of(signs_layer, sign_id) -> List[ObservationView]:
    """The detections fused into sign ``sign_id``, in driving order, from the same GeoPackage."""
    detections = detections_layer_for(signs_layer) if sign_id is not None else None
    if detections is None:
        return []
    rows = [(feature_values(f, DETECTIONS), f.id()) for f in features_where(detections, "sign_id", sign_id)]
    rows.sort(key=lambda row: (row[0]["time"] or 0, row[1]))
    views = []
    for values, _fid in rows:
        pair_id, score = str(values["pair_id"]), values["classification_indicator"]
        views.append(ObservationView(pair_id, f"{pair_id}\n{score:.2f}" if score is not None else pair_id, None,
                                     values["template_id"] or "", tuple(c or 0 for c in (values[k] for k in BBOX))))
    return views


def change_item(session, feature, values: dict, place: str) -> ReviewItem:
    """A verdict of ``changes``: the pair where the mapped sign was seen, or where a missing sign should be,
    with the sign's box; the template is the mapped sign's, or for a missing sign the inventory's."""
    verdict, inventory_id = values["verdict"] or "", values["inventory_id"]
    what = f"{verdict}: inventory {inventory_id} ({values['inventory_label'] or values['inventory_type']})" \
        if inventory_id else f"{verdict}: mapped sign {values['sign_id']}"
    template_id = values["template_id"] or values["inventory_type"] or ""
    catalogue = session.catalogue
    entry = catalogue[template_id] if catalogue is not None and template_id in catalogue else None
    u, v = values["u"], values["v"]
    point = feature.geometry().constGet() if feature.hasGeometry() else None
    size = entry.formats.get("normal", next(iter(entry.formats.values()))) if entry is not None else (0.0, 0.0)
    item = ReviewItem(
        CHANGES, feature.id(), f"{session.layer.name()} · {what} · {place}", template_id=template_id,
        name=entry.name("de") if entry else "", colour=entry.colour if entry else "",
        shape=entry.shape if entry else "",
        format="normal" if entry else "", size_m=size, status=values["status"] or "",
        reviewed=bool(values["reviewed"]), pair_id=values["pair_id"] or "", time=values["time"],
        depth_m=values["depth_m"], bbox=_bbox(values), centroid=(u, v) if u is not None and v is not None else None,
        position=(point.x(), point.y(), point.z()) if point is not None else None,
    )
    if entry is not None:
        item.pictogram_path = str(catalogue.pictogram_path(template_id, "png"))
    item.extra = [("verdict", verdict)] + [(label, fmt.format(values[key])) for key, label, fmt in (
        ("inventory_type", "inventory", "{}"), ("distance_m", "distance", "{:.2f} m"), ("n_pairs", "pairs", "{}"))
        if values[key] is not None]
    if item.bbox is not None and session.drive is not None:
        item.crop = crop_rect(item.bbox, session.drive.image_size)
    return item
