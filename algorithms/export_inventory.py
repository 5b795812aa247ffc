"""``signmapper:exportinventory``: the reviewed signs as a deliverable (GeoPackage, CSV or shapefile)."""

from __future__ import annotations

from pathlib import Path

from qgis.core import (
    NULL,
    QgsFeatureSink,
    QgsProcessingContext,
    QgsProcessingException,
    QgsProcessingOutputNumber,
    QgsProcessingParameterFileDestination,
    QgsVectorFileWriter,
    QgsWkbTypes,
)

from ..gpkg.fields import QT_TYPES, new_feature, point_z, qgs_fields
from ..gpkg.output import CheckedSink, GeoPackageLayers, layer_uri
from ..review.layers import gpkg_source
from ..signmapper_core.output import inventory_export as inventory
from ..signmapper_core.output.partial_output import write_failure
from .deliverable import DeliverableAlgorithm
from .signs_input import read_signs

INVENTORY_LAYER = "inventory"  # the layer written into a GeoPackage (its other layers are kept)
# file suffix -> (OGR driver, layer creation options); CSV in the separator spreadsheets of the language expect
FORMATS = {".gpkg": ("GPKG", []), ".csv": ("CSV", ["WRITE_BOM=YES"]), ".shp": ("ESRI Shapefile", [])}
CSV_SEPARATORS = {"en": "COMMA", "de": "SEMICOLON", "fr": "SEMICOLON", "it": "SEMICOLON"}


class ExportInventoryAlgorithm(DeliverableAlgorithm):
    NAME = "exportinventory"
    DISPLAY_NAME = "Export inventory"
    ICON = "export_inventory.svg"
    HELP = (
        "Writes the reviewed signs of a 'signs' layer as a deliverable: the accepted signs and those a person added "
        "(optionally also those still to review), in sign number order, each supplementary plate right after its "
        "sign. The columns are what a surveyor hands over (sign number, SSV type and name, plate of, text, status, "
        "reviewed, E/N/H, face azimuth, mounting height, size and format, date, image crop), titled and worded in "
        "the output language. The format follows the file name: a GeoPackage (layer 'inventory', the file's other "
        "layers kept), a CSV for spreadsheets (UTF-8; separated by semicolons in German, French and Italian, by "
        "commas in English; E/N/H as columns) or a shapefile (PointZ; its column names are at most 10 characters, "
        "so they are shortened from the titles and the log lists them). A plate whose sign is not delivered is "
        "left out and named in the log. A failed or cancelled run leaves an earlier file as it was."
    )

    OUTPUT = "OUTPUT"
    OWNED_LAYERS = {OUTPUT: (INVENTORY_LAYER,)}  # in an existing GeoPackage only this layer is replaced
    REVIEW_HELP = "Also deliver signs whose status is still 'review' (their status column says so)."
    LANGUAGE_HELP = ("Column titles, sign names and coded values (status, format) in this language; by default the "
                     "language the signs were mapped in.")

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_deliverable_inputs()
        self.add_parameter(
            QgsProcessingParameterFileDestination(
                self.OUTPUT, self.tr("Inventory file"),
                fileFilter="GeoPackage (*.gpkg);;CSV for spreadsheets (*.csv);;ESRI Shapefile (*.shp)"),
            "GeoPackage (.gpkg), CSV (.csv) or shapefile (.shp), by its suffix. Written only when the run "
            "completes; in an existing GeoPackage only the layer 'inventory' is replaced.",
        )
        self.addOutput(QgsProcessingOutputNumber("SIGNS_WRITTEN", self.tr("Signs written")))

    def check_outputs(self, parameters, context) -> None:
        self.output_format(parameters, context)  # first: a wrong suffix is said before any file is locked
        super().check_outputs(parameters, context)

    def output_format(self, parameters, context) -> str:
        """The output's suffix (.gpkg, .csv, .shp); QgsProcessingException naming the file otherwise. (An
        existing .gpkg that is no GeoPackage is refused by the output check, not replaced.)"""
        path = Path(self.output_target(parameters, self.OUTPUT, context))
        suffix = path.suffix.lower()
        if suffix not in FORMATS:
            label = self.parameterDefinition(self.OUTPUT).description()
            raise QgsProcessingException(f"{label}: {path}: give a file ending in .gpkg, .csv or .shp")
        return suffix

    def process(self, parameters, context, feedback):

        suffix = self.output_format(parameters, context)
        layer, _run, statuses, language = self.deliverable_inputs(parameters, context)
        signs = []
        for values, (east, north, height) in read_signs(layer, layer.crs(), context):
            values.update(easting=east, northing=north, elevation=height)  # where the sign is now, as drawn
            signs.append(values)
        chosen = inventory.select(signs, statuses)
        target = Path(self.output_target(parameters, self.OUTPUT, context))
        gpkg_folder = Path(gpkg_source(layer)[0] or target).parent
        for sign in chosen.signs:
            sign["crop_path"] = inventory.rebased(sign.get("crop_path"), gpkg_folder, target.parent)
        columns = inventory.columns(language)
        names = inventory.short_names([c.title for c in columns]) if suffix == ".shp" else [c.title for c in columns]
        fields = qgs_fields((name, QT_TYPES[column.kind]) for column, name in zip(columns, names))

        writer = self.open_output(parameters, target, suffix, fields, layer, language, context)
        for k, sign in enumerate(chosen.signs):
            if feedback.isCanceled():
                raise QgsProcessingException(f"Cancelled; {target} not written.")
            point = None if suffix == ".csv" else point_z(sign["easting"], sign["northing"], sign["elevation"])
            feature = new_feature(fields, [NULL if v is None else v for v in inventory.row(sign, language)], point)
            writer.addFeature(feature, QgsFeatureSink.FastInsert)  # a failed write raises, naming the file
            feedback.setProgress(100.0 * (k + 1) / max(len(chosen.signs), 1))
        writer.close()
        path = str(target)  # the partial output becomes it when the run returns
        feedback.pushInfo(f"{len(chosen.signs)} signs written to {path} ({', '.join(statuses)}); {chosen.left_out} "
                          "left out by status")
        for plate, host in chosen.orphan_plates:
            feedback.pushWarning(f"Plate {plate}: its sign {host} is not delivered (its status); the plate is left "
                                 "out too")
        if suffix == ".shp":
            feedback.pushInfo("Shapefile columns: " + ", ".join(f"{n} = {c.title}" for n, c in zip(names, columns)))
        source = layer_uri(path, INVENTORY_LAYER) if suffix == ".gpkg" else path
        context.addLayerToLoadOnCompletion(source, QgsProcessingContext.LayerDetails(
            f"Inventory {target.stem}", context.project(), self.OUTPUT))
        return {self.OUTPUT: path, "SIGNS_WRITTEN": len(chosen.signs)}

    def open_output(self, parameters, target: Path, suffix: str, fields, layer, language, context) -> CheckedSink:
        """The writer of the inventory in the run's partial output (``RunOutputs``: committed when the run
        succeeds, dropped when it fails); a failed write raises ``OutputWriteError``."""
        if suffix == ".gpkg":  # a copy of an existing file keeping its other layers
            return GeoPackageLayers(self.run_outputs.partial(self.OUTPUT)).open_layer(
                INVENTORY_LAYER, fields, QgsWkbTypes.PointZ, layer.crs(),
                abstract=f"Sign Mapper: inventory of {layer.source()}")
        path = self.parameterAsFileOutput(parameters, self.OUTPUT, context)  # the partial file; side files beside
        driver, layer_options = FORMATS[suffix]
        options = QgsVectorFileWriter.SaveVectorOptions()
        options.driverName = driver
        options.fileEncoding = "UTF-8"
        options.layerOptions = layer_options + ([f"SEPARATOR={CSV_SEPARATORS[language]}"] if suffix == ".csv" else [])
        geometry = QgsWkbTypes.NoGeometry if suffix == ".csv" else QgsWkbTypes.PointZ
        writer = QgsVectorFileWriter.create(path, fields, geometry, layer.crs(), context.transformContext(), options)
        what = f"the inventory ({self.parameterDefinition(self.OUTPUT).description()})"
        if writer.hasError() != QgsVectorFileWriter.NoError:
            raise write_failure(target, what, writer.errorMessage())
        return CheckedSink(writer, target, what, (path, None))
