"""Output paths checked before a run: not a folder, in a folder we can write, never one of the inputs.

Every Sign Mapper algorithm asks this in ``checkParameterValues`` and again when
it starts, so a wrong output costs no mapping time and never destroys an input.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

from qgis.core import (
    QgsProcessing,
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

NOT_FILES = ("memory:", "postgres:", "postgis:", "mssql:", "oracle:", "hana:", "spatialite:", "ogr:")


def _plain_path(text) -> Path | None:
    """The file of a destination or source string, None for layers that are not plain files."""
    text = str(text or "").strip()
    if not text or text.startswith(NOT_FILES) or "://" in text:
        return None
    return Path(text.split("|")[0])


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


def destinations(alg, parameters, context) -> list[tuple[str, Path, bool]]:
    """(dialog label, path, is a folder) of every output given as a plain file or folder."""
    out = []
    for param in alg.destinationParameterDefinitions():
        name = param.name()
        if isinstance(param, QgsProcessingParameterFolderDestination):
            path, folder = _plain_path(alg.parameterAsString(parameters, name, context)), True
        elif isinstance(param, QgsProcessingParameterFileDestination):
            path, folder = _plain_path(alg.parameterAsFileOutput(parameters, name, context)), False
        elif isinstance(param, (QgsProcessingParameterFeatureSink, QgsProcessingParameterVectorDestination)):
            if parameters.get(name) is None:
                continue  # an optional output not asked for
            path, folder = _plain_path(layer_destination(parameters[name], context)), False
        else:
            continue
        if path is not None:
            out.append((param.description(), path, folder))
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
            path = _plain_path(alg.parameterAsFile(parameters, name, context))
        elif isinstance(param, (QgsProcessingParameterFeatureSource, QgsProcessingParameterVectorLayer)):
            layer = alg.parameterAsVectorLayer(parameters, name, context)
            if layer is not None:
                parts = QgsProviderRegistry.instance().decodeUri(layer.providerType(), layer.source())
                path = _plain_path(parts.get("path"))
        if path is not None:
            out.append((param.description(), path))
    return out


def _same(a: Path, b: Path) -> bool:
    try:
        return a.resolve() == b.resolve()
    except OSError:
        return False


def writable_problem(path: Path) -> str | None:
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


def output_problem(alg, parameters, context) -> str | None:
    """The first thing wrong with the outputs, as the message to show, or None."""
    outputs = destinations(alg, parameters, context)
    sources = inputs(alg, parameters, context)
    for i, (label, path, folder) in enumerate(outputs):
        if not folder and path.is_dir():
            return f"{label}: {path} is an existing folder; give a file name"
        if folder and path.exists() and not path.is_dir():
            return f"{label}: {path} is an existing file; give a folder"
        for input_label, input_path in sources:
            if _same(path, input_path):
                return (f"{label}: {path} is also the input '{input_label}'; writing it would destroy that input, "
                        "choose another file")
        for other_label, other_path, _ in outputs[:i]:
            if _same(path, other_path):
                return f"{label} and {other_label} both name {path}; each output needs its own file"
        problem = writable_problem(path)
        if problem:
            return f"{label}: {path}: {problem}"
    return None


def remove_written(destinations) -> None:
    """Delete the files of sink outputs written by a run that then failed or was cancelled (memory layers
    and other non-file outputs are left to QGIS)."""
    for destination in destinations:
        path = _plain_path(destination)
        if path is None or not path.is_file():
            continue
        for suffix in ("", "-journal", "-wal", "-shm"):
            Path(str(path) + suffix).unlink(missing_ok=True)
