"""``signmapper:changes``: compare a mapping run with the existing inventory (a point layer or Signalo)."""

from __future__ import annotations

import math
from pathlib import Path

from qgis.core import (
    NULL,
    QgsCoordinateReferenceSystem,
    QgsCoordinateTransform,
    QgsFeatureSink,
    QgsGeometry,
    QgsProcessing,
    QgsProcessingContext,
    QgsProcessingException,
    QgsProcessingOutputNumber,
    QgsProcessingOutputVectorLayer,
    QgsProcessingParameterFeatureSource,
    QgsProcessingParameterField,
    QgsProcessingParameterFile,
    QgsProcessingParameterFileDestination,
    QgsProcessingParameterNumber,
    QgsProcessingParameterVectorLayer,
    QgsWkbTypes,
)

from ..gpkg.fields import declared_qgs_fields, line_z, named_feature, point_z
from ..gpkg.output import GeoPackageLayers, layer_uri
from ..signmapper_core.changes import schema as changes_schema
from ..signmapper_core.changes.compare import (
    CHANGED,
    CONFIRMED,
    MOVED,
    VERDICTS,
    ChangeConfig,
    InventorySign,
    MappedSign,
    compare,
    with_height,
)
from ..signmapper_core.changes.report import report_html
from ..signmapper_core.drive.reader import open_drive
from ..signmapper_core.errors import DriveFormatError
from ..signmapper_core.evaluation.reference_rows import exact_duplicates, no_geometry_note, repeats_note
from ..signmapper_core.fusion.mounting import camera_height_above_road
from ..signmapper_core.output.run_settings import recorded_config
from ..signmapper_core.output.run_table import RUN_TABLE
from ..signmapper_core.signalo import SignaloError
from .base import SignMapperAlgorithm
from .drive_input import qgis_crs
from .signalo_connection import HELP as SIGNALO_HELP
from .signalo_connection import open_signalo, signalo_parameter
from .signs_input import read_signs, signs_layer_and_run


class ChangesAlgorithm(SignMapperAlgorithm):
    NAME = "changes"
    OWNED_LAYERS = {"OUTPUT": ("changes", "displacements", RUN_TABLE)}
    DISPLAY_NAME = "Compare with inventory"
    GROUP_ID = "inventory"
    ICON = "changes.svg"
    HELP = (
        "Compares a mapping run with the existing sign inventory, given as a point layer with a sign type field or "
        "as a Signalo database. For every inventory sign the drive could have seen (in some pair its whole face in "
        "the image, within the run's depth range, turned towards the camera within the readable angle, from the "
        "drive's poses and camera) the verdict is confirmed (a mapped sign of the same type within the tolerance), "
        "moved (the same type farther away, within the move radius), changed (another type at the same place and "
        "height), missing (nothing mapped there) or not covered (never in view, or a type the run's catalogue "
        "cannot map). Mapped signs left over are new. Writes a GeoPackage with the point layer 'changes' (verdict, "
        "distances, the pairs that should have shown the sign and where it is or should be in the image, so the "
        "review dock opens a missing sign at that pair), the line layer 'displacements' (inventory to mapped "
        "position of every matched sign) and the run table, and an HTML report with the counts and a plan view. "
        "Mapped signs rejected in the review are left out."
    )

    SIGNS = "SIGNS"
    INVENTORY = "INVENTORY"
    TYPE_FIELD = "TYPE_FIELD"
    FACING_FIELD = "FACING_FIELD"
    HEIGHT_FIELD = "HEIGHT_FIELD"
    SIGNALO = "SIGNALO"
    DRIVE = "DRIVE"
    TOLERANCE = "TOLERANCE"
    MOVE_RADIUS = "MOVE_RADIUS"
    MAX_FACE_ANGLE = "MAX_FACE_ANGLE"
    OUTPUT = "OUTPUT"
    REPORT = "REPORT"
    CHANGES = "CHANGES"
    DISPLACEMENTS = "DISPLACEMENTS"

    def shortHelpString(self):  # noqa: N802

        lines = [super().shortHelpString(), "<b>Fields of 'changes'</b>", "<ul>"]
        lines += [f"<li><b>{f.name}</b>: {self.help_html(f.help)}</li>" for f in changes_schema.FIELDS]
        return "\n".join(lines + ["</ul>"])

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_parameter(
            QgsProcessingParameterVectorLayer(self.SIGNS, self.tr("Mapped signs"), [QgsProcessing.TypeVectorPoint]),
            "The 'signs' layer written by Map traffic signs (its GeoPackage names the drive and the run's settings).",
        )
        self.add_parameter(
            QgsProcessingParameterFeatureSource(self.INVENTORY, self.tr("Inventory point layer"),
                                                [QgsProcessing.TypeVectorPoint], optional=True),
            "The existing inventory as points (PointZ, or 2D). Leave empty when reading a Signalo database.",
        )
        self.add_parameter(
            QgsProcessingParameterField(self.TYPE_FIELD, self.tr("Sign type field"), "template_id", self.INVENTORY,
                                        QgsProcessingParameterField.Any, optional=True),
            "Field of the inventory layer with the sign type as SSV number / catalogue id (2.30-50).",
        )
        self.add_parameter(
            QgsProcessingParameterField(self.FACING_FIELD, self.tr("Facing field"), None, self.INVENTORY,
                                        QgsProcessingParameterField.Numeric, optional=True),
            "Optional azimuth (degrees from grid north) the face looks towards; without it a sign counts as readable "
            "from any direction.",
        )
        self.add_parameter(
            QgsProcessingParameterField(self.HEIGHT_FIELD, self.tr("Height field"), None, self.INVENTORY,
                                        QgsProcessingParameterField.Numeric, optional=True),
            "Optional height of the face centre for a 2D layer; without heights distances are planimetric and a "
            "sign is placed at camera height to decide whether the drive could see it.",
        )
        self.add_parameter(signalo_parameter(self.SIGNALO, self.tr("Signalo database"), optional=True),
                           "Instead of a layer: " + SIGNALO_HELP)
        self.add_parameter(
            QgsProcessingParameterFile(self.DRIVE, self.tr("Drive folder"), behavior=QgsProcessingParameterFile.Folder,
                                       optional=True),
            "Only if the drive moved: the folder the mapped signs were mapped from (default: the one their "
            "GeoPackage records).", advanced=True,
        )
        self.add_parameter(
            QgsProcessingParameterNumber(self.TOLERANCE, self.tr("Tolerance [m]"), QgsProcessingParameterNumber.Double,
                                         ChangeConfig.tolerance_m, minValue=0.01),
            "A mapped sign of the same type planimetrically closer than this confirms an inventory sign; another "
            "type this close means the sign changed.",
        )
        self.add_parameter(
            QgsProcessingParameterNumber(self.MOVE_RADIUS, self.tr("Move radius [m]"),
                                         QgsProcessingParameterNumber.Double, ChangeConfig.move_radius_m,
                                         minValue=0.02),
            "The same type farther than the tolerance but within this: the sign moved.",
        )
        self.add_parameter(
            QgsProcessingParameterNumber(self.MAX_FACE_ANGLE, self.tr("Readable face angle [°]"),
                                         QgsProcessingParameterNumber.Double, ChangeConfig.max_face_angle_deg,
                                         minValue=1.0, maxValue=90.0),
            "A face turned farther than this away from the camera cannot be read.", advanced=True,
        )
        self.add_parameter(
            QgsProcessingParameterFileDestination(self.OUTPUT, self.tr("Output GeoPackage"),
                                                  fileFilter="GeoPackage (*.gpkg)"),
            "GeoPackage with the layers 'changes' and 'displacements'; replaced only when the run completes.",
        )
        self.add_parameter(
            QgsProcessingParameterFileDestination(self.REPORT, self.tr("HTML report"), "HTML files (*.html)",
                                                  optional=True),
            "Counts per verdict, a plan view and the list of signs.",
        )
        self.addOutput(QgsProcessingOutputVectorLayer(self.CHANGES, self.tr("Changes"), QgsProcessing.TypeVectorPoint))
        self.addOutput(QgsProcessingOutputVectorLayer(self.DISPLACEMENTS, self.tr("Displacements"),
                                                      QgsProcessing.TypeVectorLine))

        for verdict in VERDICTS:
            self.addOutput(QgsProcessingOutputNumber(verdict.upper().replace(" ", "_"), self.tr(verdict)))

    # inputs -----------------------------------------------------------------------------------------------
    def open_run_drive(self, parameters, context, run: dict):

        folder = self.parameterAsFile(parameters, self.DRIVE, context) or run.get("drive")
        if not folder:
            raise QgsProcessingException("The mapped signs' GeoPackage records no drive (table signmapper_run): "
                                         "give the drive folder.")
        try:
            return open_drive(folder, check_images=False)
        except DriveFormatError as exc:
            raise QgsProcessingException(f"Drive of the mapped signs: {exc}") from exc

    def inventory_from_layer(self, parameters, context, drive_crs, catalogue, feedback):
        import numpy as np


        source = self.parameterAsSource(parameters, self.INVENTORY, context)
        type_field = self.parameterAsString(parameters, self.TYPE_FIELD, context) or "template_id"
        facing_field = self.parameterAsString(parameters, self.FACING_FIELD, context)
        height_field = self.parameterAsString(parameters, self.HEIGHT_FIELD, context)
        names = source.fields().names()
        for name in (type_field, facing_field, height_field):
            if name and name not in names:
                raise QgsProcessingException(f"{source.sourceName()}: no field '{name}'")
        transform = QgsCoordinateTransform(source.sourceCrs(), drive_crs, context.transformContext())
        signs, no_geometry = [], []
        for feature in source.getFeatures():
            geom = QgsGeometry(feature.geometry())
            if geom.isNull():
                no_geometry.append(f"fid {feature.id()}")
                continue
            if transform.sourceCrs() != transform.destinationCrs():
                geom.transform(transform)
            point = next(geom.vertices())
            z = point.z() if QgsWkbTypes.hasZ(geom.wkbType()) else float("nan")
            if height_field and feature[height_field] not in (None, NULL):
                z = float(feature[height_field])
            type_id = "" if feature[type_field] in (None, NULL) else str(feature[type_field])
            facing = feature[facing_field] if facing_field else None
            size = catalogue[type_id].formats.get("normal") if type_id in catalogue else None
            signs.append(InventorySign(str(feature.id()), type_id, np.array([point.x(), point.y(), z]),
                                       None if facing in (None, NULL) else float(facing),
                                       size[0] if size else None, size[1] if size else None, label=type_id))
        if no_geometry:
            feedback.pushWarning(no_geometry_note(source.sourceName(), no_geometry))
        return signs, f"layer {source.sourceName()}"

    @staticmethod
    def without_repeats(inventory: list, where: str, row: str, feedback) -> list:
        """The inventory with each sign that repeats another exactly left out, with a warning (``row``: what the
        inventory's keys are, "fid" or "sign")."""

        repeats = exact_duplicates([s.template_id for s in inventory], [s.position for s in inventory])
        if repeats:
            feedback.pushWarning(repeats_note(where, repeats, [f"{row} {s.key}" for s in inventory]))
        return [sign for i, sign in enumerate(inventory) if i not in repeats]

    def inventory_from_signalo(self, parameters, context, drive_crs, catalogue, feedback):
        import numpy as np

        from ..signmapper_core.signalo.inventory import read_inventory  # delays OpenCV until used

        connection, where = open_signalo(self.parameterAsString(parameters, self.SIGNALO, context))
        try:
            signs, others, crs = read_inventory(connection, set(catalogue.entries), where)
        except SignaloError as exc:
            raise QgsProcessingException(str(exc)) from exc
        finally:
            connection.close()
        if others:
            feedback.pushInfo(f"{others} signs of {where} are not official signs (markers, mirrors, user signs) and "
                              "are left out")
        transform = QgsCoordinateTransform(QgsCoordinateReferenceSystem(crs), drive_crs, context.transformContext())
        if transform.sourceCrs() != transform.destinationCrs():
            moved = []
            for sign in signs:
                point = transform.transform(sign.position[0], sign.position[1])
                moved.append(InventorySign(sign.key, sign.template_id, np.array([point.x(), point.y(), np.nan]),
                                           sign.facing, sign.width_m, sign.height_m, sign.height_above_road_m,
                                           sign.label))
            signs = moved
        return signs, f"Signalo {where}"

    # run --------------------------------------------------------------------------------------------------
    def process(self, parameters, context, feedback):
        import numpy as np

        from ..signmapper_core.catalogue import load_catalogue  # delays OpenCV until used

        has_layer = parameters.get(self.INVENTORY) not in (None, "")
        has_signalo = bool(self.parameterAsString(parameters, self.SIGNALO, context))
        if has_layer == has_signalo:
            raise QgsProcessingException("Give the inventory either as a point layer or as a Signalo database "
                                         "(exactly one of them).")
        layer, run = signs_layer_and_run(self.parameterAsVectorLayer(parameters, self.SIGNS, context))
        drive = self.open_run_drive(parameters, context, run)
        drive_crs, _note = qgis_crs(drive.crs)
        catalogue_dir = run.get("catalogue")
        catalogue = load_catalogue(catalogue_dir if catalogue_dir and Path(catalogue_dir).is_dir() else None)
        recorded = recorded_config(run)
        excluded = set(recorded.classification.exclude)
        config = ChangeConfig(
            tolerance_m=self.parameterAsDouble(parameters, self.TOLERANCE, context),
            move_radius_m=self.parameterAsDouble(parameters, self.MOVE_RADIUS, context),
            near_m=recorded.depth.near_m, far_m=recorded.depth.far_m,
            max_face_angle_deg=self.parameterAsDouble(parameters, self.MAX_FACE_ANGLE, context),
            camera_height_m=camera_height_above_road(drive.metadata))
        try:
            config.validate()
        except ValueError as exc:
            raise QgsProcessingException(str(exc)) from exc

        if has_layer:
            inventory, where = self.inventory_from_layer(parameters, context, drive_crs, catalogue, feedback)
        else:
            inventory, where = self.inventory_from_signalo(parameters, context, drive_crs, catalogue, feedback)
        inventory = self.without_repeats(inventory, where, "fid" if has_layer else "sign", feedback)
        described = f"{where} ({len(inventory)} signs)"
        mapped = []
        for values, xyz in read_signs(layer, drive_crs, context):
            if values.get("plate_of") is not None:
                continue  # a supplementary plate is compared with its sign, not as a sign of its own
            box = tuple(values[k] for k in ("bbox_x", "bbox_y", "bbox_w", "bbox_h"))
            mapped.append(MappedSign(values["sign_id"], values["template_id"] or "", np.array(xyz, float),
                                     values["status"] or "", values["azimuth"], values["best_pair_id"] or "",
                                     values["u"], values["v"], box if None not in box else None, str(values["fid"])))
        feedback.pushInfo(f"{len(mapped)} mapped signs of {layer.name()} against the inventory {described}; drive "
                          f"{drive.root}, {len(drive.pairs)} pairs, visibility {config.near_m:g}-{config.far_m:g} m")
        report = compare(inventory, mapped, drive.camera, drive.pairs, config,
                         mappable_types={e.id for e in catalogue if e.id not in excluded})
        feedback.pushInfo(report.summary())

        self.write(parameters, context, report, drive, run, layer, described)
        path = self.output_target(parameters, self.OUTPUT, context)
        html_path = self.parameterAsFileOutput(parameters, self.REPORT, context)
        if html_path:
            track = [(r.pose.easting, r.pose.northing) for r in drive.pairs]
            notes = [f"Mapped signs: {layer.source()}", f"Inventory: {described}", f"Drive: {drive.root}"]
            Path(html_path).write_text(report_html(report, track, "Sign Mapper: changes against the inventory",
                                                   notes), encoding="utf-8")
        results = {self.OUTPUT: path, self.REPORT: html_path or None}
        for key, name, title in ((self.CHANGES, "changes", "Changes"),
                                 (self.DISPLACEMENTS, "displacements", "Displacements")):
            results[key] = layer_uri(path, name)
            context.addLayerToLoadOnCompletion(results[key], QgsProcessingContext.LayerDetails(title, context.project(),
                                                                                               key))
        for verdict, count in report.counts().items():
            results[verdict.upper().replace(" ", "_")] = count
        return results

    def write(self, parameters, context, report, drive, run, layer, described) -> None:

        crs, _note = qgis_crs(drive.crs)
        output = GeoPackageLayers(self.run_outputs.partial(self.OUTPUT))
        centres = [r.pose.centre for r in drive.pairs]
        fields = declared_qgs_fields(changes_schema.FIELDS)
        writer = output.open_layer("changes", fields, QgsWkbTypes.PointZ, crs,
                                   abstract=f"Sign Mapper: {layer.source()} against {described}")
        import numpy as np

        for change in report.changes:
            if change.inventory is not None:
                east, north, up = with_height(change.inventory, np.array(centres), report.config)
            else:
                east, north, up = change.mapped.position
            up = up if math.isfinite(up) else 0.0
            writer.addFeature(named_feature(fields, changes_schema.values(change), point_z(east, north, up)),
                              QgsFeatureSink.FastInsert)
        writer.close()
        fields = declared_qgs_fields(changes_schema.LINE_FIELDS)
        writer = output.open_layer("displacements", fields, QgsWkbTypes.LineStringZ, crs,
                                   abstract="Sign Mapper: inventory position to mapped position")
        for change in report.changes:
            if change.verdict not in (CONFIRMED, MOVED, CHANGED):
                continue
            start = with_height(change.inventory, np.array(centres), report.config)
            end = change.mapped.position
            writer.addFeature(named_feature(fields, changes_schema.values(change, changes_schema.DISPLACEMENTS),
                                            line_z([start, end])), QgsFeatureSink.FastInsert)
        writer.close()
        table = dict(run)
        table.update(drive=str(drive.root.resolve()), signs=layer.source(), inventory=described)
        output.write_run_table(table)
