"""Writing Sign Mapper's layers from QGIS: into a partial output, every failed write said where it happens.

The partial file, its commit and the layers of an existing file that are kept
are the core's (``signmapper_core.output.geopackage_file``, shared with the QGIS-free
writer ``signmapper_core.output.gpkg_writer``); QGIS writes the layers into it.
QGIS's writers answer a failed write (a full disk) with ``False``, or not at
all when the last features are committed as the file closes: :class:`CheckedSink`
raises instead, and counts the features in the file once it is closed.
"""

from __future__ import annotations

from pathlib import Path

from qgis.core import (
    QgsCoordinateReferenceSystem,
    QgsCoordinateTransformContext,
    QgsFeatureSink,
    QgsFields,
    QgsLayerMetadata,
    QgsVectorFileWriter,
    QgsWkbTypes,
)
from qgis.PyQt.QtCore import QVariant

from ..signmapper_core.output.partial_output import write_failure
from ..signmapper_core.output.run_table import RUN_TABLE, RunRecordError, encode_run_value, read_run_record
from .fields import new_feature, qgs_fields


class CheckedSink:
    """A feature sink (a file writer, a Processing sink) that raises ``OutputWriteError`` when a write fails.

    ``target`` and ``what`` name the output in the message; ``written`` is (file, layer) of what the sink
    writes: :meth:`close` closes the sink and counts that layer's features against those added.
    """

    def __init__(self, sink, target, what: str, written: tuple | None = None):
        self.sink, self.target, self.what, self.written = sink, Path(target), what, written
        self.added = 0

    def addFeature(self, feature, flags=QgsFeatureSink.FastInsert) -> bool:  # noqa: N802 - QgsFeatureSink's
        if not self.sink.addFeature(feature, flags):
            raise self._failure()
        self.added += 1
        return True

    def addFeatures(self, features, flags=QgsFeatureSink.FastInsert) -> bool:  # noqa: N802 - QgsFeatureSink's
        features = list(features)
        if not self.sink.addFeatures(features, flags):
            raise self._failure()
        self.added += len(features)
        return True

    def close(self) -> None:
        """Flush and close the file (the writer is deleted); a short layer raises."""
        if self.sink is None:
            return
        try:
            if not self.sink.flushBuffer():
                raise self._failure()
        finally:
            self.sink = None  # the last reference: the writer closes its file
        if self.written is not None:
            found = feature_count(*self.written)
            if found != self.added:
                raise write_failure(self.target, self.what, f"{self.added} features written, {found} in the file "
                                    "once it was closed")

    def _failure(self):
        return write_failure(self.target, self.what, self.sink.lastError() or "the file system refused the write")


def feature_count(path, layer: str | None = None) -> int:
    """Features of ``layer`` (None: the only one) in the file at ``path`` as GDAL reads them (-1: unreadable)."""
    from osgeo import ogr

    dataset = ogr.Open(str(path))
    if dataset is None:
        return -1
    found = dataset.GetLayerByName(layer) if layer is not None else dataset.GetLayer(0)
    return -1 if found is None else found.GetFeatureCount()


class GeoPackageLayers:
    """QGIS writing layers into the partial file of a ``PartialGeoPackage``: the first creates the file
    unless it is a copy of the target holding layers to keep."""

    def __init__(self, output):
        self.output = output

    def open_layer(self, name: str, fields: QgsFields, wkb_type, crs: QgsCoordinateReferenceSystem,
                   abstract: str = "") -> CheckedSink:
        """A writer for a new layer; ``close()`` it before the next layer."""
        path = self.output.path
        options = QgsVectorFileWriter.SaveVectorOptions()
        options.driverName = "GPKG"
        options.layerName = name
        options.fileEncoding = "UTF-8"
        options.actionOnExistingFile = (QgsVectorFileWriter.CreateOrOverwriteLayer if path.exists()
                                        else QgsVectorFileWriter.CreateOrOverwriteFile)
        if abstract:
            metadata = QgsLayerMetadata()
            metadata.setTitle(name)
            metadata.setAbstract(abstract)
            options.layerMetadata = metadata
            options.saveMetadata = True
        writer = QgsVectorFileWriter.create(str(path), fields, wkb_type, crs, QgsCoordinateTransformContext(), options)
        what = f"the layer '{name}'"
        if writer.hasError() != QgsVectorFileWriter.NoError:
            raise write_failure(self.output.target, what, writer.errorMessage())
        return CheckedSink(writer, self.output.target, what, (path, name))

    def write_run_table(self, values: dict) -> None:
        """A non-spatial key/value table recording the drive folder and the run's parameters."""
        fields = qgs_fields((("key", QVariant.String), ("value", QVariant.String)))
        writer = self.open_layer(RUN_TABLE, fields, QgsWkbTypes.NoGeometry, QgsCoordinateReferenceSystem())
        for key, value in values.items():
            writer.addFeature(new_feature(fields, [key, encode_run_value(value)]))
        writer.close()


def layer_uri(path: str, layer: str) -> str:
    return f"{path}|layername={layer}"


def read_run_table(path: str) -> dict:
    """The run table of the GeoPackage ``path`` as written (``output.run_table.RUN_KEYS``); {} where there is none."""

    if not path:
        return {}
    try:
        return read_run_record(path)
    except RunRecordError:
        return {}
