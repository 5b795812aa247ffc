"""Decisions on the shown feature: accept, reject, reclassify, undo, and adding a sign a person clicked.

Values follow the output schema (``values``); each decision is one undoable
edit (``edits``). Finding a clicked sign runs the core's ``detect_at`` in a
worker thread.
"""

from __future__ import annotations

from qgis.PyQt.sip import isdeleted

from ..gpkg.fields import feature_values
from ..signmapper_core.catalogue.model import UNKNOWN_ID
from ..signmapper_core.changes.schema import CHANGES
from ..signmapper_core.output.schema import SIGNS
from ..signmapper_core.run.mapping import detect_at, manual_sign
from ..signmapper_core.statuses import MANUAL
from .edits import DecisionLog, EditError, add_feature, change_attributes
from .layers import features_where
from .values import accept_values, manual_feature, plate_text_values, reclassify_values, reject_values

DUPLICATE_RADIUS_M = 0.5  # an added sign this close to one of the same type is probably that sign


class DecisionTaker:
    def __init__(self, session, dock, jobs, navigator, show_feature, show_selection):
        self.session, self.dock, self.jobs, self.navigator = session, dock, jobs, navigator
        self.show_feature, self.show_selection = show_feature, show_selection  # the controller's
        self.log = DecisionLog()

    def _decide(self, values: dict, what: str) -> None:
        """Write ``values`` to the shown feature; ``what`` describes the decision, "{fid}" is the feature id."""
        layer, fid = self.session.layer, self.session.fid
        if layer is None or fid is None:
            return
        label = what.format(fid=fid)
        try:
            decision = change_attributes(layer, fid, values, f"Sign Mapper: {label}")
        except EditError as exc:
            self.dock.show_message(str(exc), error=True)
            return
        self._taken(decision)
        saved = "saved" if decision.committed else "in your edit session, not saved yet"
        self.dock.show_message(f"{label[0].upper()}{label[1:]} ({saved})")
        if not (self.dock.advance_after_decision() and self.navigator.next_review()):
            self.show_feature(fid)

    def _taken(self, decision) -> None:
        self.log.push(decision)
        self.dock.set_undo_enabled(True, decision.label)
        decision.layer.triggerRepaint()

    def accept(self) -> None:
        self._decide(accept_values(), "accept feature {fid}")

    def reject(self) -> None:
        self._decide(reject_values(), "reject feature {fid}")

    def reclassify(self, template_id: str) -> None:
        session = self.session
        if session.layer is None or session.fid is None or session.catalogue is None:
            return
        if template_id not in session.catalogue:
            self.dock.show_message(f"Template {template_id} is not in the catalogue", error=True)
            return
        if session.kind == CHANGES:
            self.dock.show_picker(False)
            self.dock.show_message("A verdict has no type to change: reclassify the mapped sign in its 'signs' "
                                   "layer and compare again", error=True)
            return
        current = feature_values(session.layer.getFeature(session.fid), session.kind)
        values = reclassify_values(session.kind, session.catalogue[template_id], current["format"],
                                   current["status"] or "", session.language)
        self.dock.show_picker(False)
        self._decide(values, "reclassify feature {fid} as " + template_id)

    def set_text(self, text: str) -> None:
        """A person corrected (or confirmed) the text of the shown plate."""
        session = self.session
        if session.layer is None or session.fid is None or session.kind != SIGNS:
            return
        current = feature_values(session.layer.getFeature(session.fid), session.kind)
        if current["plate_of"] is None:
            self.dock.show_message("Only a supplementary plate has a text to set", error=True)
            return
        values = plate_text_values(text, current["status"] or "", current["template_id"] or "",
                                   session.output_context())
        self._decide(values, f"set the text of plate {{fid}} to \"{values['text'] or ''}\"")

    def undo_last(self) -> None:
        try:
            decision = self.log.undo()
        except EditError as exc:
            self.dock.show_message(str(exc), error=True)
            return
        last = self.log.last()
        self.dock.set_undo_enabled(last is not None, last.label if last else "")
        if decision is None:
            return
        self.dock.show_message(f"Undone: {decision.label}")
        decision.layer.triggerRepaint()
        layer = self.session.layer
        if decision.layer is not layer:
            return
        if decision.added:
            layer.removeSelection()
            self.session.fid = None
            self.show_selection()
        else:
            self.navigator.select(decision.fid)
            self.show_feature(decision.fid)

    def add_sign(self, pair_id: str, u: float, v: float) -> None:
        """Run the detection steps in a window around a click on the sign's centre; add what they find."""
        session = self.session
        record = session.record(pair_id)
        if session.layer is None or record is None or session.catalogue is None:
            self.dock.show_message("Adding a sign needs a Sign Mapper layer and its drive's images", error=True)
            return

        drive, catalogue, config, layer = session.drive, session.catalogue, session.pipeline_config(), session.layer

        def found(observation):
            if isdeleted(layer) or layer is not session.layer:
                return
            if observation is None:
                self.dock.show_message(f"No sign found around ({u:.0f}, {v:.0f}) in pair {pair_id}: click the "
                                       "centre of a sign face inside the search range", error=True)
                return
            self._add(observation)

        self.dock.show_message(f"Looking for a sign around ({u:.0f}, {v:.0f}) in pair {pair_id}…")
        self.jobs.submit("add", lambda: detect_at(drive, record, catalogue, config, u, v), found)

    def _same_sign_nearby(self, layer, observation):
        """(fid, distance) of the nearest feature of the same type within DUPLICATE_RADIUS_M (3D), else None.

        In a detections layer only the same pair counts: other pairs' detections of one sign are expected.
        """
        east, north, up = (float(c) for c in observation.position)
        best = None
        for feature in features_where(layer, "template_id", observation.template_id):
            if self.session.kind != SIGNS and feature["pair_id"] != observation.pair_id:
                continue
            if not feature.hasGeometry():
                continue
            point = feature.geometry().constGet()
            dz = (point.z() - up) if point.is3D() else 0.0
            distance = ((point.x() - east) ** 2 + (point.y() - north) ** 2 + dz ** 2) ** 0.5
            if distance <= DUPLICATE_RADIUS_M and (best is None or distance < best[1]):
                best = (feature.id(), distance)
        return best

    def _add(self, observation) -> None:
        """A feature for the clicked sign: the observation itself, or in a signs layer a new sign numbered last."""

        layer, kind = self.session.layer, self.session.kind
        if kind == CHANGES:
            self._found_in_change(observation)
            return
        twin = self._same_sign_nearby(layer, observation)
        if twin is not None and not self.dock.confirm(
                "Sign Mapper: add a second sign?",
                f"{layer.name()} already has a {observation.template_id} {twin[1]:.2f} m from the clicked sign "
                f"(feature {twin[0]}). Add another one anyway?"):
            self.dock.show_message(f"Not added: {observation.template_id} is already mapped {twin[1]:.2f} m away "
                                   f"(feature {twin[0]})")
            self.navigator.select(twin[0])
            return
        item = observation
        if kind == SIGNS:
            ids = [feature_values(f, SIGNS)["sign_id"] for f in layer.getFeatures()]
            item = manual_sign(observation, max([i for i in ids if i is not None], default=0) + 1)
        label = f"Sign Mapper: add {observation.template_id} in pair {observation.pair_id}"
        try:
            decision = add_feature(layer, manual_feature(layer, kind, item, self.session.output_context()), label)
        except EditError as exc:
            self.dock.show_message(str(exc), error=True)
            return
        self._taken(decision)
        name = self.session.output_context().name(observation.template_id, observation.name)  # the layer's language
        self.dock.show_message(f"Added {observation.template_id} {name} at {observation.depth_m:.1f} m "
                               f"(pair {observation.pair_id})")
        self.navigator.select(decision.fid)

    def _found_in_change(self, observation) -> None:
        """A person found the sign of a change (e.g. a 'missing' one) in the image: the verdict becomes what the
        found sign says against the inventory type. A sign the network reads as no catalogue sign is the
        inventory's: the person pointed at it, and "unknown" says nothing against its type."""
        current = feature_values(self.session.layer.getFeature(self.session.fid), CHANGES)
        read = observation.template_id
        found = current["inventory_type"] if read == UNKNOWN_ID and current["inventory_type"] else read
        verdict = "confirmed" if found == current["inventory_type"] else "changed"
        x, y, w, h = observation.bbox
        reason = f"found by a person in pair {observation.pair_id}: {read}"
        if found != read:
            reason += f", the inventory's {found}"
        values = {"verdict": verdict, "template_id": found, "status": MANUAL, "reviewed": 1,
                  "pair_id": observation.pair_id, "u": float(observation.u), "v": float(observation.v),
                  "bbox_x": int(x), "bbox_y": int(y), "bbox_w": int(w), "bbox_h": int(h), "reason": reason}
        self._decide(values, f"{verdict}: {found} found in pair {observation.pair_id} for feature {{fid}}")
