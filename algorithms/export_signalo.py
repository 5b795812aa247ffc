"""``signmapper:exporttosignalo``: write a mapping run's accepted signs into a Signalo database."""

from __future__ import annotations

from qgis.core import (
    QgsCoordinateReferenceSystem,
    QgsProcessing,
    QgsProcessingException,
    QgsProcessingOutputNumber,
    QgsProcessingOutputString,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterNumber,
    QgsProcessingParameterVectorLayer,
)

from ..signmapper_core.signalo import AZIMUTH_GAP_DEG, POLE_RADIUS_M, SignaloError
from ..signmapper_core.signalo.schema import check_database
from ..signmapper_core.statuses import ACCEPTED, MANUAL, REVIEW
from .base import SignMapperAlgorithm
from .signalo_connection import HELP as SIGNALO_HELP
from .signalo_connection import open_signalo, signalo_parameter
from .signs_input import read_signs, signs_layer_and_run


class ExportToSignaloAlgorithm(SignMapperAlgorithm):
    NAME = "exporttosignalo"
    DISPLAY_NAME = "Export to Signalo"
    GROUP_ID = "inventory"
    ICON = "export_signalo.svg"
    HELP = (
        "Writes the accepted signs of a mapping run (and those a person added; optionally also those still awaiting "
        "review, marked 'needs validation') into a Signalo database (opengisch/signalo, data model 1.2 to 1.x). "
        "Signs within the pole radius of each other are one support (pole) at their mean position, with the free "
        "height under its lowest sign; faces looking the same way share an azimut (the direction the face looks "
        "towards); each sign gets a frame ranked from the top and a sign referencing the official sign type by its "
        "SSV number (a sign with a number, e.g. 2.30-50, as 2.30 with inscription 50), its dimensions "
        "(radius for round faces, else height and width, in metres) and a comment with the run id, the sign id, "
        "format and indicators. Types Signalo does not list are reported and not written. One transaction: all or "
        "nothing. Running it again with the same run adds nothing. With a 'changes' layer comparing this run "
        "with the same Signalo database, signs found confirmed or moved update their Signalo sign instead (a "
        "moved pole carrying only that sign is moved; otherwise the support is marked for validation)."
    )

    SIGNS = "SIGNS"
    SIGNALO = "SIGNALO"
    INCLUDE_REVIEW = "INCLUDE_REVIEW"
    CHANGES = "CHANGES"
    POLE_RADIUS = "POLE_RADIUS"
    AZIMUTH_GAP = "AZIMUTH_GAP"

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_parameter(
            QgsProcessingParameterVectorLayer(self.SIGNS, self.tr("Mapped signs"), [QgsProcessing.TypeVectorPoint]),
            "The 'signs' layer written by Map traffic signs (its run id makes the export repeatable).",
        )
        self.add_parameter(signalo_parameter(self.SIGNALO, self.tr("Signalo database")), SIGNALO_HELP)
        self.add_parameter(
            QgsProcessingParameterBoolean(self.INCLUDE_REVIEW, self.tr("Also signs awaiting review"), False),
            "Also write signs whose status is still 'review', with Signalo's 'needs validation' set.",
        )
        self.add_parameter(
            QgsProcessingParameterVectorLayer(self.CHANGES, self.tr("Changes against this database (update)"),
                                              [QgsProcessing.TypeVectorPoint], optional=True),
            "The 'changes' layer of Compare with inventory run against this Signalo database: its confirmed and "
            "moved signs update their Signalo sign instead of adding one.",
        )
        self.add_parameter(
            QgsProcessingParameterNumber(self.POLE_RADIUS, self.tr("Pole radius [m]"),
                                         QgsProcessingParameterNumber.Double, POLE_RADIUS_M, minValue=0.0),
            "Signs planimetrically this close to each other are on one support.", advanced=True,
        )
        self.add_parameter(
            QgsProcessingParameterNumber(self.AZIMUTH_GAP, self.tr("Azimuth grouping [°]"),
                                         QgsProcessingParameterNumber.Double, AZIMUTH_GAP_DEG, minValue=0.0,
                                         maxValue=180.0),
            "Faces of one support whose directions differ by at most this share an azimut.", advanced=True,
        )
        for name, title in (("ADDED", "Signs added"), ("UPDATED", "Signs updated"), ("ALREADY", "Already exported"),
                            ("UNKNOWN", "Types not in Signalo"), ("SUPPORTS", "Supports added")):
            self.addOutput(QgsProcessingOutputNumber(name, self.tr(title)))
        self.addOutput(QgsProcessingOutputString("SIGNALO_VERSION", self.tr("Signalo data model version")))

    def updates(self, parameters, context) -> dict:
        """Our sign id -> (Signalo sign id, moved) from a changes layer."""
        layer = self.parameterAsVectorLayer(parameters, self.CHANGES, context)
        if layer is None:
            return {}
        names = set(layer.fields().names())
        if not {"verdict", "inventory_id", "sign_id"} <= names:
            raise QgsProcessingException(f"{layer.source()}: not a 'changes' layer of Compare with inventory")
        found = {}
        for feature in layer.getFeatures():
            if feature["verdict"] in ("confirmed", "moved") and feature["sign_id"] and feature["inventory_id"]:
                found[int(feature["sign_id"])] = (str(feature["inventory_id"]), feature["verdict"] == "moved")
        return found

    def process(self, parameters, context, feedback):
        import numpy as np

        from ..signmapper_core.signalo.export import ExportSign, export_signs  # delays OpenCV until used

        layer, run = signs_layer_and_run(self.parameterAsVectorLayer(parameters, self.SIGNS, context))
        run_id = run.get("run_id")
        if not run_id:
            raise QgsProcessingException(f"{layer.source()}: the run table records no run_id (written by an older "
                                         "Sign Mapper): map the drive again so the export can recognise the run.")
        statuses = {ACCEPTED, MANUAL} | ({REVIEW} if self.parameterAsBoolean(parameters, self.INCLUDE_REVIEW, context)
                                         else set())
        updates = self.updates(parameters, context)
        connection, where = open_signalo(self.parameterAsString(parameters, self.SIGNALO, context))
        try:
            try:
                with connection, connection.cursor() as cursor:
                    srid = check_database(cursor, where).srid
            except SignaloError as exc:
                raise QgsProcessingException(str(exc)) from exc
            signs, left_out = [], 0
            for values, xyz in read_signs(layer, QgsCoordinateReferenceSystem(f"EPSG:{srid}"), context):
                if values["status"] not in statuses:
                    left_out += 1
                    continue
                update_id, moved = updates.get(values["sign_id"], (None, False))
                signs.append(ExportSign(
                    values["sign_id"], values["template_id"] or "", np.array(xyz, float), values["azimuth"],
                    values["width_m"] or 0.0, values["height_m"] or 0.0, values["format"] or "",
                    values["shape"] or "", values["status"] or "", values["detection_indicator"],
                    values["classification_indicator"], values["n_obs"], values["sigma_m"],
                    values["mount_height_m"], update_id, moved, values["plate_of"], values["text"],
                    values["review_reason"]))
            feedback.pushInfo(f"{len(signs)} signs of run {run_id} to write into {where}; {left_out} left out by "
                              f"status (writing {', '.join(sorted(statuses))})")
            try:
                result = export_signs(connection, run_id, signs, self.parameterAsDouble(parameters, self.POLE_RADIUS,
                                                                                        context),
                                      self.parameterAsDouble(parameters, self.AZIMUTH_GAP, context), where)
            except SignaloError as exc:
                raise QgsProcessingException(str(exc)) from exc
        finally:
            connection.close()
        feedback.pushInfo(f"Signalo {result.version or '(version not recorded)'}: {result.summary()}")
        for sign_id, type_id in result.unknown:
            feedback.pushWarning(f"Sign {sign_id}: type {type_id} has no official sign in Signalo; not written")
        for plate_id, sign_id in result.plates_without_sign:
            feedback.pushWarning(f"Plate {plate_id}: its sign {sign_id} is not written by this export (left out by "
                                 "status, unknown type, already exported or updated); the plate is not written")
        return {"ADDED": len(result.added), "UPDATED": len(result.updated), "ALREADY": len(result.already),
                "UNKNOWN": len(result.unknown), "SUPPORTS": result.supports,
                "SIGNALO_VERSION": result.version or ""}
