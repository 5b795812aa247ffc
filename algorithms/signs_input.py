"""Reading a mapping run's ``signs`` layer and its run table, for ``changes`` and the Signalo export."""

from __future__ import annotations

from qgis.core import QgsCoordinateTransform, QgsGeometry, QgsProcessingException, QgsWkbTypes

from ..gpkg.fields import feature_values
from ..gpkg.output import read_run_table
from ..review.layers import gpkg_source
from ..signmapper_core.output.schema import SIGNS, required_names


def signs_layer_and_run(layer) -> tuple:
    """(layer, run table) of a signs layer written by Map traffic signs; QgsProcessingException if it is not one."""
    if layer is None or not layer.isValid():
        raise QgsProcessingException("No mapped signs layer given.")
    missing = required_names(SIGNS) - set(layer.fields().names())
    if missing:
        raise QgsProcessingException(f"{layer.source()}: not a 'signs' layer of Map traffic signs (no field "
                                     f"{', '.join(sorted(missing))})")
    path, _name = gpkg_source(layer)
    return layer, read_run_table(path)


def read_signs(layer, target_crs, context, skip_rejected: bool = True) -> list:
    """(values of every feature as output_schema reads them, (E, N, H) in ``target_crs``), rejected left out."""
    transform = QgsCoordinateTransform(layer.crs(), target_crs, context.transformContext())
    out = []
    for feature in layer.getFeatures():
        values = feature_values(feature, SIGNS)
        if skip_rejected and values["status"] == "rejected":
            continue
        geom = QgsGeometry(feature.geometry())
        if geom.isNull():
            raise QgsProcessingException(f"{layer.name()}: sign {values['sign_id']} has no geometry")
        if transform.sourceCrs() != transform.destinationCrs():
            geom.transform(transform)
        point = next(geom.vertices())
        z = point.z() if QgsWkbTypes.hasZ(geom.wkbType()) else float("nan")
        values["fid"] = feature.id()
        out.append((values, (point.x(), point.y(), z)))
    return out
