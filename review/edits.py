"""Writing review decisions to a layer through QGIS's edit buffer, saving them, and undoing them.

Each decision is one edit command (so it is on ``layer.undoStack()`` while the
layer is being edited). If the layer was not in edit mode, the decision is
committed to the GeoPackage at once and undone later by a new edit restoring the
recorded previous values. If the user already had the layer in edit mode, the
decision joins that edit session uncommitted and is undone through the undo stack.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import List, Optional

from qgis.core import QgsFeature
from qgis.PyQt.sip import isdeleted


class EditError(RuntimeError):
    """A decision could not be written; the layer was left as it was."""


@dataclass
class Decision:
    layer: object  # QgsVectorLayer
    fid: int
    label: str
    old: dict = field(default_factory=dict)
    new: dict = field(default_factory=dict)
    added: bool = False  # a manual sign: undone by deleting the feature
    committed: bool = True


def _commit(layer) -> None:
    if not layer.commitChanges():
        errors = "; ".join(layer.commitErrors())
        layer.rollBack()
        raise EditError(f"{layer.name()}: could not save: {errors}")


class _EditSession:
    """Starts editing if needed; commits at the end only a session it started itself."""

    def __init__(self, layer, label: str):
        self.layer, self.label = layer, label
        self.own = not layer.isEditable()

    def __enter__(self):
        if self.own and not self.layer.startEditing():
            raise EditError(f"{self.layer.name()}: the layer cannot be edited")
        self.layer.beginEditCommand(self.label)
        return self

    def __exit__(self, exc_type, exc, tb):
        if exc_type is not None:
            self.layer.destroyEditCommand()
            if self.own:
                self.layer.rollBack()
            return False
        self.layer.endEditCommand()
        if self.own:
            _commit(self.layer)
        return False


def change_attributes(layer, fid: int, values: dict, label: str) -> Decision:
    """Set ``values`` (field name -> value) of feature ``fid`` as one undoable edit; returns the decision."""
    feature = layer.getFeature(fid)
    if not feature.isValid():
        raise EditError(f"{layer.name()}: feature {fid} no longer exists")
    fields = layer.fields()
    values = {name: value for name, value in values.items() if fields.indexOf(name) >= 0}
    old = {name: feature[name] for name in values}
    with _EditSession(layer, label) as session:
        for name, value in values.items():
            if not layer.changeAttributeValue(fid, fields.indexOf(name), value, old[name]):
                raise EditError(f"{layer.name()}: cannot change {name} of feature {fid}")
    return Decision(layer, fid, label, old, values, committed=session.own)


def add_feature(layer, feature: QgsFeature, label: str) -> Decision:
    """Add a feature as one undoable edit; the decision holds its id after saving."""
    added: List[int] = []

    def remember(_layer_id, features):
        added.extend(f.id() for f in features)

    layer.committedFeaturesAdded.connect(remember)
    try:
        with _EditSession(layer, label) as session:
            if not layer.addFeature(feature):
                raise EditError(f"{layer.name()}: cannot add the feature")
            temporary = feature.id()
    finally:
        layer.committedFeaturesAdded.disconnect(remember)
    fid = added[0] if session.own and added else temporary
    return Decision(layer, fid, label, added=True, committed=session.own)


class DecisionLog:
    """The decisions of this session, newest last, for "Undo last decision"."""

    def __init__(self):
        self.decisions: List[Decision] = []

    def push(self, decision: Decision) -> Decision:
        self.decisions.append(decision)
        return decision

    def last(self) -> Optional[Decision]:
        while self.decisions and isdeleted(self.decisions[-1].layer):
            self.decisions.pop()  # its layer was removed from the project
        return self.decisions[-1] if self.decisions else None

    def undo(self) -> Optional[Decision]:
        """Revert the newest decision on its layer (and on disk if it was saved); returns it."""
        decision = self.last()
        if decision is None:
            return None
        layer = decision.layer
        if not decision.committed and layer.isEditable() and self._on_top_of_undo_stack(decision):
            layer.undoStack().undo()
        elif decision.added:
            with _EditSession(layer, f"Undo: {decision.label}"):
                if not layer.deleteFeature(decision.fid):
                    raise EditError(f"{layer.name()}: cannot delete feature {decision.fid}")
        else:
            change_attributes(layer, decision.fid, decision.old, f"Undo: {decision.label}")
        self.decisions.pop()
        return decision

    @staticmethod
    def _on_top_of_undo_stack(decision: Decision) -> bool:
        stack = decision.layer.undoStack()
        return stack.index() > 0 and stack.command(stack.index() - 1).text() == decision.label
