"""Every file output of a run written whole or not at all: one mechanism for all of Sign Mapper's algorithms.

:class:`~.base.SignMapperAlgorithm` runs each algorithm inside :class:`RunOutputs`.
Every output the user gave as a file (a feature sink, a file destination; drive
folders are the core writers' own, the same mechanism) becomes a partial output
of the core (``signmapper_core.output.partial_output``): locked against a second run,
written beside its target, moved in only when the algorithm has returned, and
dropped, the earlier file as it was, when it fails or is cancelled. A layer
written into an existing GeoPackage keeps the file's other layers
(``PartialGeoPackage``). The algorithm writes as usual through
``parameterAsSink`` and ``parameterAsFileOutput``, which the base class points
here; temporary and memory outputs (models chain them) stay QGIS's own.
"""

from __future__ import annotations

from pathlib import Path

from qgis.core import QgsDataSourceUri, QgsProcessingOutputLayerDefinition, QgsProperty

from ..gpkg.output import CheckedSink, layer_uri
from ..signmapper_core.output.geopackage_file import PartialGeoPackage
from ..signmapper_core.output.partial_output import PartialOutput
from .output_paths import FILE, FOLDER, SINK, destinations


def _with_destination(parameters: dict, name: str, destination: str) -> dict:
    """``parameters`` with the output ``name`` sent to ``destination`` (keeping where QGIS loads it)."""
    value = parameters.get(name)
    if isinstance(value, QgsProcessingOutputLayerDefinition):
        value = QgsProcessingOutputLayerDefinition(value)
        value.sink = QgsProperty.fromValue(destination)
    else:
        value = destination
    return {**parameters, name: value}


class RunOutputs:
    """The partial outputs of one run, by parameter; construction locks them all (``OutputBusyError``)."""

    def __init__(self, alg, parameters: dict, context):
        self.alg, self.context = alg, context
        self.outputs = {d.name: d for d in destinations(alg, parameters, context) if d.kind != FOLDER}
        self.partials: dict[Path, PartialOutput] = {}
        self.sinks: list[CheckedSink] = []
        self.ours: dict[Path, list[str]] = {}  # layers written into a file the user named: marked as ours
        try:
            for output in self.outputs.values():
                if output.path not in self.partials:
                    self.partials[output.path] = self._partial(output)
        except BaseException:
            self.discard()
            raise

    def _partial(self, output) -> PartialOutput:
        if output.path.suffix.lower() != ".gpkg":
            return PartialOutput(output.path)
        if output.kind == SINK:  # the layers of every output written into this file
            owned = [o.layer_name for o in self.outputs.values() if o.path == output.path]
        else:
            owned = self.alg.OWNED_LAYERS.get(output.name, ())
        return PartialGeoPackage(output.path, owned)

    def partial(self, name: str) -> PartialOutput:
        """The partial output of the file output ``name``."""
        return self.partials[self.outputs[name].path]

    def add(self, partial: PartialOutput) -> None:
        """One more output of the run that no parameter names (e.g. the crops beside a GeoPackage)."""
        self.partials[partial.target] = partial

    def target(self, name: str) -> Path | None:
        """The file the output ``name`` becomes (None: temporary, memory or not a file)."""
        output = self.outputs.get(name)
        return None if output is None else output.path

    def unchanged(self) -> str:
        """"; <file> is as it was" for every earlier output a failed run leaves alone."""
        return "".join(f"; {partial.target} is as it was" for partial in self.partials.values() if partial.existed)

    def file_output(self, name: str) -> str | None:
        """Where the file output ``name`` is written (a GeoPackage: a copy keeping the layers not ours)."""
        output = self.outputs.get(name)
        if output is None or output.kind != FILE:
            return None
        return str(self.partials[output.path].path)

    def sink(self, name: str, parameters: dict, create):
        """(sink, id) of the feature-sink output ``name``: ``create(parameters)`` is QGIS's own, pointed at the
        partial output; the sink raises when a write fails, the id is the layer's once committed."""
        output = self.outputs.get(name)
        if output is None or output.kind != SINK:
            return create(parameters)
        partial = self.partials[output.path]
        if output.layered:
            uri = QgsDataSourceUri()
            uri.setDatabase(str(partial.path))
            uri.setDataSource("", output.layer_name, "geom")
            destination, final, layer = f"ogr:{uri.uri()}", layer_uri(str(output.path), output.layer_name), \
                output.layer_name
            self.ours.setdefault(output.path, []).append(layer)
        else:
            destination, final, layer = str(partial.path), str(output.path), None
        sink, _partial_id = create(_with_destination(parameters, name, destination))
        if sink is None:
            return None, final
        what = f"the layer '{layer or output.path.stem}' ({output.label})"
        checked = CheckedSink(sink, output.path, what, (partial.path, layer))
        self.sinks.append(checked)
        return checked, final

    def commit(self, results: dict) -> dict:
        """Close the sinks, move every partial output in; ``results`` and the layers QGIS loads name the
        committed files."""
        for sink in self.sinks:
            sink.close()
        for path, layers in self.ours.items():
            self.partials[path].mark_ours(layers, f"{self.alg.displayName()} ({self.alg.id()})")
        moved = {str(p.path): str(p.target) for p in self.partials.values() if p.partial.exists()}
        for partial in self.partials.values():
            partial.commit()
        self.partials = {}

        def final(value):
            if isinstance(value, str):
                for before, after in moved.items():
                    value = value.replace(before, after)
            return value

        loads = self.context.layersToLoadOnCompletion()
        if any(final(key) != key for key in loads):
            self.context.setLayersToLoadOnCompletion({final(key): details for key, details in loads.items()})
        return {key: final(value) for key, value in results.items()}

    def discard(self) -> None:
        """Drop every partial output (earlier files stay) and release the locks."""
        for sink in self.sinks:
            sink.sink = None
        for partial in self.partials.values():
            partial.discard()
        self.partials = {}
