"""A mapping result as a GeoPackage through GDAL/OGR, without QGIS: what ``python -m signmapper_core.map`` writes.

The same layers, fields and run table as ``mapsigns`` (both derive them from
:mod:`output.schema`, both write through OGR's GPKG driver), written atomically
(:mod:`geopackage_file`). What only QGIS adds is left out: the layer styles
(QGIS applies its defaults when the layers are opened; mapsigns run on the file
embeds them) and the QGIS metadata abstracts.
"""

from __future__ import annotations

from contextlib import contextmanager
from typing import Optional

from ..errors import OutputFileError
from ..progress import CancelCheck, check_cancelled
from . import run_table, schema
from .geopackage_file import PartialGeoPackage
from .partial_output import write_failure

OGR_TYPES = {schema.TEXT: "OFTString", schema.INTEGER: "OFTInteger", schema.REAL: "OFTReal"}


@contextmanager
def _ogr_exceptions():
    """OGR and OSR failures as exceptions while writing (and the caller's setting back afterwards)."""
    from osgeo import ogr, osr

    before = ogr.GetUseExceptions(), osr.GetUseExceptions()
    ogr.UseExceptions()
    osr.UseExceptions()
    try:
        yield
    finally:  # in reverse order: GDAL keeps a stack of error handlers
        if not before[1]:
            osr.DontUseExceptions()
        if not before[0]:
            ogr.DontUseExceptions()


def spatial_reference(crs: str):
    """The OSR spatial reference of a drive's CRS (an authority code or anything PROJ reads)."""
    from osgeo import osr

    srs = osr.SpatialReference()
    srs.SetAxisMappingStrategy(osr.OAMS_TRADITIONAL_GIS_ORDER)
    try:
        failed = srs.SetFromUserInput(crs) != 0
    except RuntimeError:
        failed = True
    if failed:
        raise OutputFileError(f"CRS '{crs}' of the drive is not one GDAL knows")
    return srs


def write_geopackage(target, result, context: Optional[schema.OutputContext] = None,
                     is_cancelled: Optional[CancelCheck] = None) -> str:
    """Write ``result`` (a ``MappingResult``) to the GeoPackage ``target``; returns its path.

    Layers ``signs`` and ``detections`` (PointZ in the drive's CRS) and the run table; an existing GeoPackage
    keeps its other layers. A failure or cancel (``Cancelled``, asked between features) leaves the target as
    it was; a failed write is an ``OutputWriteError`` naming the file (and a full disk).
    """
    from osgeo import ogr

    context = context or schema.OutputContext()
    output = PartialGeoPackage(target)
    try:
        with _ogr_exceptions():
            if output.starts_empty:
                source = ogr.GetDriverByName("GPKG").CreateDataSource(str(output.path))
            else:
                source = ogr.Open(str(output.path), update=1)
            srs = spatial_reference(result.drive.crs)
            for layer_name, items in ((schema.SIGNS, result.signs), (schema.DETECTIONS, result.detections)):
                _write_layer(source, layer_name, items, srs, context, is_cancelled)
            _write_run_table(source, run_table.run_record(result, context))
            source.FlushCache()
            source = None
        check_cancelled(is_cancelled, "writing")
    except BaseException as exc:
        source = None
        output.discard()
        if isinstance(exc, RuntimeError):  # OGR's own error (exceptions on): a full disk, a refused write
            raise write_failure(output.target, "the layers", exc) from exc
        raise
    return output.commit()


def _write_layer(source, name: str, items, srs, context, is_cancelled) -> None:
    from osgeo import ogr

    fields = schema.fields(name)
    layer = source.CreateLayer(name, srs, ogr.wkbPoint25D, ["FID=fid", "GEOMETRY_NAME=geom", "OVERWRITE=YES"])
    for field in fields:
        layer.CreateField(ogr.FieldDefn(field.name, getattr(ogr, OGR_TYPES[field.kind])))
    definition = layer.GetLayerDefn()
    layer.StartTransaction()
    for item in items:
        check_cancelled(is_cancelled, "writing")
        feature = ogr.Feature(definition)
        for field_name, value in schema.values(name, item, context).items():
            if value is None:
                feature.SetFieldNull(field_name)
            else:
                feature.SetField(field_name, value)
        east, north, up = (float(c) for c in item.position)
        point = ogr.Geometry(ogr.wkbPoint25D)
        point.AddPoint(east, north, up)
        feature.SetGeometry(point)
        layer.CreateFeature(feature)
    layer.CommitTransaction()


def _write_run_table(source, values: dict) -> None:
    """A non-spatial key/value table recording the drive folder and the run's parameters."""
    from osgeo import ogr

    table = source.CreateLayer(run_table.RUN_TABLE, None, ogr.wkbNone, ["FID=fid", "OVERWRITE=YES"])
    table.CreateField(ogr.FieldDefn("key", ogr.OFTString))
    table.CreateField(ogr.FieldDefn("value", ogr.OFTString))
    definition = table.GetLayerDefn()
    table.StartTransaction()
    for key, value in values.items():
        feature = ogr.Feature(definition)
        feature.SetField("key", key)
        feature.SetField("value", run_table.encode_run_value(value))
        table.CreateFeature(feature)
    table.CommitTransaction()
