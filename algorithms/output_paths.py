"""Inputs and outputs checked before a run: paths that can exist, outputs that destroy nothing.

Every Sign Mapper algorithm asks :func:`path_problems` in ``checkParameterValues``
and again when it starts, so a wrong output costs no mapping time and never
destroys an input, a user's layer or another run's output.
"""

from __future__ import annotations

import os
import re
import tempfile
from dataclasses import dataclass
from pathlib import Path
from typing import Optional

from qgis.core import (
    QgsDataSourceUri,
    QgsProcessing,
    QgsProcessingAlgorithm,
    QgsProcessingOutputLayerDefinition,
    QgsProcessingParameterFeatureSink,
    QgsProcessingParameterFeatureSource,
    QgsProcessingParameterFile,
    QgsProcessingParameterFileDestination,
    QgsProcessingParameterFolderDestination,
    QgsProcessingParameterVectorDestination,
    QgsProcessingParameterVectorLayer,
    QgsProperty,
    QgsProviderRegistry,
)

from ..signmapper_core.errors import OutputBusyError, OutputFileError
from ..signmapper_core.output.file_paths import path_problem
from ..signmapper_core.output.geopackage_file import geopackage_contents, is_ours
from ..signmapper_core.output.target_lock import TargetLock

NOT_FILES = ("memory:", "postgres:", "postgis:", "mssql:", "oracle:", "hana:", "spatialite:")
SINK, FILE, FOLDER = "layer", "file", "folder"  # what a destination parameter writes
LAYER_NAME = re.compile(r"^(?P<path>[^|]+)\|layername=(?P<layer>.+)$")


def file_and_layer(text) -> tuple[Path, Optional[str]] | None:
    """(file, layer name or None) of a destination or source string; None for what is no plain file.

    Besides a path: ``path|layername=name`` and ``ogr:dbname='path' table="name"``, the two ways QGIS names a
    layer in a file.
    """
    text = str(text or "").strip()
    if text.startswith("ogr:"):
        uri = QgsDataSourceUri(text[len("ogr:"):])
        return (Path(uri.database()), uri.table() or None) if uri.database() else None
    if not text or text.startswith(NOT_FILES) or "://" in text or text == QgsProcessing.TEMPORARY_OUTPUT:
        return None
    named = LAYER_NAME.match(text)
    if named:
        return Path(named["path"]), named["layer"]
    return Path(text.split("|")[0]), None


def layer_destination(value, context) -> str:
    """The file or URI a layer output is given as, read without ``parameterAsOutputLayer``: that one also asks
    Processing to load the output when the run completes, under a name no layer will have for a temporary one
    ('memory:Matches'), which ended dialog and model runs with "layers were not correctly generated"."""
    if isinstance(value, QgsProcessingOutputLayerDefinition):
        value = value.sink
    if isinstance(value, QgsProperty):
        value, _ok = value.valueAsString(context.expressionContext())
    text = str(value or "")
    return "" if text == QgsProcessing.TEMPORARY_OUTPUT else text


def default_layer_name(path: Path) -> str:
    """The layer name QGIS gives a new file: its name up to the first dot."""
    return path.name.split(".", 1)[0]


@dataclass(frozen=True)
class Destination:
    """One output given as a file or folder: parameter, dialog label, path, kind, layer name given."""

    name: str
    label: str
    path: Path
    kind: str  # SINK, FILE or FOLDER
    layer: Optional[str] = None

    @property
    def layered(self) -> bool:
        """A layer written into a GeoPackage, which may hold other layers."""
        return self.kind == SINK and self.path.suffix.lower() == ".gpkg"

    @property
    def layer_name(self) -> str:
        return self.layer or default_layer_name(self.path)


def destinations(alg, parameters, context) -> list[Destination]:
    """Every output given as a plain file or folder (not temporary, memory or database outputs).

    QGIS's own resolution (QgsProcessingAlgorithm's, not an algorithm's redirect to a partial output).
    """
    out = []
    for param in alg.destinationParameterDefinitions():
        name = param.name()
        raw = layer_destination(parameters.get(name), context)
        if not raw:
            continue  # an optional output not asked for, or a new temporary file
        if isinstance(param, QgsProcessingParameterFolderDestination):
            parsed, kind = file_and_layer(QgsProcessingAlgorithm.parameterAsString(alg, parameters, name, context)), \
                FOLDER
        elif isinstance(param, QgsProcessingParameterFileDestination):
            parsed, kind = file_and_layer(QgsProcessingAlgorithm.parameterAsFileOutput(alg, parameters, name,
                                                                                       context)), FILE
        elif isinstance(param, (QgsProcessingParameterFeatureSink, QgsProcessingParameterVectorDestination)):
            parsed, kind = file_and_layer(raw), SINK  # not parameterAsOutputLayer: see layer_destination
        else:
            continue
        if parsed is not None:
            out.append(Destination(name, param.description(), parsed[0], kind, parsed[1]))
    return out


def inputs(alg, parameters, context) -> list[tuple[str, Path]]:
    """(dialog label, path) of every input that is a file or folder on disk."""
    out = []
    for param in alg.parameterDefinitions():
        name = param.name()
        if parameters.get(name) is None or param.isDestination():
            continue
        path = None
        if isinstance(param, QgsProcessingParameterFile):
            path = file_and_layer(alg.parameterAsFile(parameters, name, context))
        elif isinstance(param, (QgsProcessingParameterFeatureSource, QgsProcessingParameterVectorLayer)):
            layer = alg.parameterAsVectorLayer(parameters, name, context)
            if layer is not None:
                parts = QgsProviderRegistry.instance().decodeUri(layer.providerType(), layer.source())
                path = file_and_layer(parts.get("path"))
        if path is not None:
            out.append((param.description(), path[0]))
    return out


def _same(a: Path, b: Path) -> bool:
    try:
        return a.resolve() == b.resolve()
    except OSError:
        return False


def path_problems(alg, parameters, context) -> Optional[str]:
    """The first input or output path that cannot exist on this system (too long), as the message, or None."""
    for param in alg.parameterDefinitions():
        if isinstance(param, QgsProcessingParameterFile) and parameters.get(param.name()) is not None:
            parsed = file_and_layer(alg.parameterAsFile(parameters, param.name(), context))
            problem = parsed and path_problem(parsed[0])
            if problem:
                return f"{param.description()}: {problem}"
    for output in destinations(alg, parameters, context):
        problem = path_problem(output.path)
        if problem:
            return f"{output.label}: {problem}"
    return None


def output_problem(alg, parameters, context) -> Optional[str]:
    """The first thing wrong with the paths, as the message to show, or None."""
    problem = path_problems(alg, parameters, context)
    if problem:
        return problem
    outputs = destinations(alg, parameters, context)
    sources = inputs(alg, parameters, context)
    for i, output in enumerate(outputs):
        label, path = output.label, output.path
        if output.kind != FOLDER and path.is_dir():
            return f"{label}: {path} is an existing folder; give a file name"
        if output.kind == FOLDER and path.exists() and not path.is_dir():
            return f"{label}: {path} is an existing file; give a folder"
        for input_label, input_path in sources:
            if _same(path, input_path):
                return (f"{label}: {path} is also the input '{input_label}'; writing it would destroy that input, "
                        "choose another file")
        for other in outputs[:i]:
            if _same(path, other.path) and not (output.layered and other.layered
                                                and output.layer_name != other.layer_name):
                return f"{label} and {other.label} both name {path}; each output needs its own file"
        problem = writable_problem(path)
        if problem:
            return f"{label}: {path}: {problem}"
        problem = busy_problem(path) or layer_problem(output)
        if problem:
            return f"{label}: {problem}"
    return None


def writable_problem(path: Path) -> Optional[str]:
    """Why ``path`` cannot be created (its nearest existing folder is read-only or a file), or None."""
    folder = path.parent
    while not folder.exists() and folder != folder.parent:
        folder = folder.parent
    if not folder.is_dir():
        return f"{folder} is a file, not a folder"
    try:
        handle, probe = tempfile.mkstemp(prefix=".signmapper-write-test-", dir=folder)
    except OSError as exc:
        return f"cannot write into the folder {folder} ({exc.strerror or exc})"
    os.close(handle)
    os.unlink(probe)
    return None


def busy_problem(path: Path) -> Optional[str]:
    """Why another run stands in the way of writing ``path`` (it writes it now), or None."""
    if not TargetLock(path).path.exists():
        return None
    try:
        with TargetLock(path):
            return None
    except OutputBusyError as exc:
        return str(exc)
    except OSError:
        return None  # cannot even open the lock file: the write itself will say why


def layer_problem(output: Destination) -> Optional[str]:
    """Why ``output`` cannot be written into its existing GeoPackage (it is none, or a user's layer of the same
    name is in the way), or None. The file's other layers are kept; a layer of the same name is replaced only
    when Sign Mapper wrote it.
    """
    if output.path.suffix.lower() != ".gpkg":
        return None
    try:
        contents = geopackage_contents(output.path)
    except OutputFileError as exc:
        return str(exc)
    name = output.layer_name
    if not output.layered or contents is None or name not in contents or is_ours(contents[name]):
        return None
    suggestion = re.sub(r"\W+", "_", output.label.lower()).strip("_")
    return (f"{output.path} already holds a layer '{name}' that Sign Mapper did not write; it is left as it is. "
            f"To add this output as a layer of its own, give the layer a name: in the dialog 'Save to "
            f"GeoPackage…' and a new layer name, on the command line {output.name}=\"ogr:dbname='{output.path}' "
            f"table=\\\"{suggestion}\\\" (geom)\" or {output.name}=\"{output.path}|layername={suggestion}\"; or "
            "choose another file")
