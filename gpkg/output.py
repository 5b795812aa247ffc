"""Writing Sign Mapper's GeoPackages from QGIS without ever leaving a half-written file.

The partial file, its commit and the layers of an existing file that are kept
are the core's (``signmapper_core.geopackage_file``, shared with the QGIS-free
writer ``signmapper_core.gpkg_writer``); QGIS writes the layers into it.
"""

from __future__ import annotations

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
    QgsWkbTypes,
)
from qgis.PyQt.QtCore import QVariant

from ..signmapper_core import geopackage_file
from ..signmapper_core.geopackage_file import OutputFileError, PartialGeoPackage
from ..signmapper_core.output_schema import RUN_TABLE, encode_run_value


def geopackage_tables(path) -> list[str] | None:
    """Tables (layers) of an existing GeoPackage; None where there is no file or an empty one.

    Raises QgsProcessingException when the file exists but is no GeoPackage: it is not ours to replace.
    """
    try:
        return geopackage_file.geopackage_tables(path)
    except OutputFileError as exc:
        raise QgsProcessingException(str(exc)) from exc


class AtomicGeoPackage(PartialGeoPackage):
    """A GeoPackage built layer by layer by QGIS in a partial file, committed at the end.

    ``kept`` lists the layers of an existing target that are not ``ours``: they are
    carried over unchanged.
    """

    def __init__(self, target: str, ours=geopackage_file.OUR_TABLES):
        try:
            super().__init__(target, ours)
        except OutputFileError as exc:
            raise QgsProcessingException(str(exc)) from exc
        self._layers = 0

    def open_layer(self, name: str, fields: QgsFields, wkb_type, crs: QgsCoordinateReferenceSystem,
                   abstract: str = "") -> QgsVectorFileWriter:
        """A writer for a new layer; call ``del writer`` (or let it go) to flush before the next layer."""
        options = QgsVectorFileWriter.SaveVectorOptions()
        options.driverName = "GPKG"
        options.layerName = name
        options.fileEncoding = "UTF-8"
        first = self._layers == 0 and self.starts_empty
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


def layer_uri(path: str, layer: str) -> str:
    return f"{path}|layername={layer}"


def read_run_table(path: str) -> dict:
    """The run table of the GeoPackage ``path`` as written (``output_schema.RUN_KEYS``); {} where there is none."""
    from ..signmapper_core.run_settings import RunRecordError, read_run_record

    if not path:
        return {}
    try:
        return read_run_record(path)
    except RunRecordError:
        return {}
