"""Writing Sign Mapper's GeoPackages without ever leaving a half-written file.

Layers go into a hidden ``.<name>.partial.gpkg`` beside the target; only a
completed run moves it over the target (an atomic rename on one file system).
A failed or cancelled run deletes the partial file and leaves any earlier
output untouched.
"""

from __future__ import annotations

import os
from pathlib import Path

from qgis.core import (
    QgsCoordinateReferenceSystem,
    QgsCoordinateTransformContext,
    QgsFeature,
    QgsFeatureSink,
    QgsField,
    QgsFields,
    QgsLayerMetadata,
    QgsProcessingException,
    QgsVectorFileWriter,
    QgsVectorLayer,
    QgsWkbTypes,
)
from qgis.PyQt.QtCore import QVariant

from ..signmapper_core.output_schema import RUN_TABLE, decode_run_value, encode_run_value


class AtomicGeoPackage:
    """A GeoPackage built layer by layer in a partial file, committed at the end."""

    def __init__(self, target: str):
        self.target = Path(target)
        if self.target.suffix.lower() != ".gpkg":
            raise QgsProcessingException(f"{self.target}: the output must be a GeoPackage file ending in .gpkg")
        self.partial = self.target.with_name(f".{self.target.stem}.partial.gpkg")
        self._layers = 0
        self.discard()

    def open_layer(self, name: str, fields: QgsFields, wkb_type, crs: QgsCoordinateReferenceSystem,
                   abstract: str = "") -> QgsVectorFileWriter:
        """A writer for a new layer; call ``del writer`` (or let it go) to flush before the next layer."""
        options = QgsVectorFileWriter.SaveVectorOptions()
        options.driverName = "GPKG"
        options.layerName = name
        options.fileEncoding = "UTF-8"
        first = self._layers == 0
        options.actionOnExistingFile = (
            QgsVectorFileWriter.CreateOrOverwriteFile if first else QgsVectorFileWriter.CreateOrOverwriteLayer
        )
        if abstract:
            metadata = QgsLayerMetadata()
            metadata.setTitle(name)
            metadata.setAbstract(abstract)
            options.layerMetadata = metadata
            options.saveMetadata = True
        self.partial.parent.mkdir(parents=True, exist_ok=True)
        writer = QgsVectorFileWriter.create(
            str(self.partial), fields, wkb_type, crs, QgsCoordinateTransformContext(), options
        )
        if writer.hasError() != QgsVectorFileWriter.NoError:
            raise QgsProcessingException(f"{self.target}: cannot create layer '{name}': {writer.errorMessage()}")
        self._layers += 1
        return writer

    def write_run_table(self, values: dict) -> None:
        """A non-spatial key/value table recording the drive folder and the run's parameters."""
        fields = QgsFields()
        fields.append(QgsField("key", QVariant.String))
        fields.append(QgsField("value", QVariant.String))
        writer = self.open_layer(RUN_TABLE, fields, QgsWkbTypes.NoGeometry, QgsCoordinateReferenceSystem())
        for key, value in values.items():
            feature = QgsFeature(fields)
            feature.setAttributes([key, encode_run_value(value)])
            writer.addFeature(feature, QgsFeatureSink.FastInsert)
        del writer

    def commit(self) -> str:
        os.replace(self.partial, self.target)
        return str(self.target)

    def discard(self) -> None:
        for suffix in ("", "-journal", "-wal", "-shm"):
            path = Path(str(self.partial) + suffix)
            if path.exists():
                path.unlink()


def layer_uri(path: str, layer: str) -> str:
    return f"{path}|layername={layer}"


def read_run_table(path: str) -> dict:
    """The run table of the GeoPackage ``path`` as written (``output_schema.RUN_KEYS``); {} where there is none."""
    if not path:
        return {}
    table = QgsVectorLayer(layer_uri(path, RUN_TABLE), RUN_TABLE, "ogr")
    if not table.isValid():
        return {}
    values = {}
    for feature in table.getFeatures():
        key, text = feature["key"], feature["value"]
        if isinstance(key, str) and isinstance(text, str):
            values[key] = decode_run_value(key, text)
    return values
