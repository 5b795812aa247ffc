"""``signmapper:evaluate``: the paper's Tables 1 and 2 for a signs layer against a surveyed reference."""

from __future__ import annotations

import math
from pathlib import Path

from qgis.core import (
    NULL,
    QgsCoordinateTransform,
    QgsFeatureRequest,
    QgsFeatureSink,
    QgsGeometry,
    QgsProcessing,
    QgsProcessingException,
    QgsProcessingOutputNumber,
    QgsProcessingParameterDistance,
    QgsProcessingParameterFeatureSink,
    QgsProcessingParameterFeatureSource,
    QgsProcessingParameterField,
    QgsProcessingParameterFileDestination,
    QgsWkbTypes,
)
from qgis.PyQt.QtCore import QVariant

from ..gpkg.fields import line_z, new_feature, qgs_fields
from ..gpkg.output import read_run_table
from ..signmapper_core.errors import DriveFormatError
from ..signmapper_core.evaluation.reference_rows import (
    exact_duplicates,
    ids_from_numbers,
    no_geometry_note,
    numeric_ids_note,
    repeats_note,
)
from ..signmapper_core.statuses import REJECTED
from .base import SignMapperAlgorithm


def facing_value(source, feature, field: str):
    """A facing azimuth from a numeric or text field (None when empty); a clear error names the feature."""
    value = feature[field]
    if value is None or value == NULL or str(value).strip() == "":
        return None
    try:
        number = float(str(value).strip().replace(",", "."))
    except ValueError:
        number = math.nan
    if math.isfinite(number):
        return number % 360.0
    raise QgsProcessingException(f"{source.sourceName()}: feature {feature.id()}: facing field '{field}' holds "
                                     f"{value!r}, not an azimuth in degrees")


def defined(value):
    """A figure as a number, or None (NULL, no value) where it is undefined: a rate of nothing, σ of nothing."""
    value = float(value)
    return value if math.isfinite(value) else None


class EvaluateAlgorithm(SignMapperAlgorithm):
    NAME = "evaluate"
    DISPLAY_NAME = "Evaluate against reference"
    GROUP_ID = "quality"
    ICON = "evaluate.svg"
    HELP = (
        "Compares mapped signs with a reference inventory (surveyed signs, or a drive's truth.csv loaded as a "
        "point layer) as in Cavegn (2011). Each mapped sign is matched to the nearest reference sign within the "
        "matching radius (3D). Table 1: reference signs, detection rate, correct-classification rate (share of "
        "detected signs whose id equals the reference id), false positives and duplicates (reference signs "
        "matched by more than one mapped sign). Table 2: mean, empirical standard deviation, RMS and maximum "
        "of the coordinate differences across track, along track, in height, planimetric and 3D, in the frame "
        "of the trajectory at each sign. Signs with status 'rejected' are left out. Writes an HTML report with "
        "a plot of the error vectors, a statistics table and a line layer joining each matched pair. "
        "Sign types are catalogue ids compared as text: '1.30' is not '1.3'. Load a reference such as truth.csv "
        "with its id field as text; where the field is numeric (delimited-text type detection turns '1.30' into "
        "1.3) a warning says so and each number is read back as the catalogue id it stands for where that is "
        "unambiguous. No output may name an input file: the run is refused before any work."
    )

    SIGNS = "SIGNS"
    SIGNS_ID_FIELD = "SIGNS_ID_FIELD"
    REFERENCE = "REFERENCE"
    REFERENCE_ID_FIELD = "REFERENCE_ID_FIELD"
    REFERENCE_HEIGHT_FIELD = "REFERENCE_HEIGHT_FIELD"
    REFERENCE_FACING_FIELD = "REFERENCE_FACING_FIELD"
    RADIUS = "RADIUS"
    TRAJECTORY = "TRAJECTORY"
    REPORT = "REPORT"
    STATISTICS = "STATISTICS"
    MATCHES = "MATCHES"

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_parameter(
            QgsProcessingParameterFeatureSource(self.SIGNS, self.tr("Mapped signs"), [QgsProcessing.TypeVectorPoint]),
            "Point layer of mapped signs, e.g. the 'signs' layer written by Map traffic signs.",
        )
        self.add_parameter(
            QgsProcessingParameterField(self.SIGNS_ID_FIELD, self.tr("Sign type field of the mapped signs"),
                                        "template_id", self.SIGNS, QgsProcessingParameterField.String, optional=True),
            "Field holding the catalogue id (SSV number) of each mapped sign; empty = template_id.",
        )
        self.add_parameter(
            QgsProcessingParameterFeatureSource(self.REFERENCE, self.tr("Reference signs"),
                                                [QgsProcessing.TypeVectorPoint]),
            "Surveyed reference inventory as a point layer (PointZ, or a height field below).",
        )
        self.add_parameter(
            QgsProcessingParameterField(self.REFERENCE_ID_FIELD, self.tr("Sign type field of the reference"),
                                        "template_id", self.REFERENCE, QgsProcessingParameterField.Any),
            "Field of the reference holding the catalogue id of each sign.",
        )
        self.add_parameter(
            QgsProcessingParameterField(self.REFERENCE_HEIGHT_FIELD, self.tr("Height field of the reference"),
                                        None, self.REFERENCE, QgsProcessingParameterField.Numeric, optional=True),
            "Only for a reference without Z values: the field holding the height of each sign centre.",
        )
        self.add_parameter(
            QgsProcessingParameterField(self.REFERENCE_FACING_FIELD, self.tr("Facing field of the reference"),
                                        None, self.REFERENCE, QgsProcessingParameterField.Any, optional=True),
            "Optional azimuth (degrees from grid north, a number or text holding one) the sign face looks "
            "towards. When given, reference signs "
            "whose face never looks towards the vehicle within 20 m ahead (e.g. the far sign of a back-to-back "
            "pair on a one-way drive) are left out, since no forward-looking camera could map them.",
        )
        self.add_parameter(
            QgsProcessingParameterDistance(self.RADIUS, self.tr("Matching radius"), 0.75, self.SIGNS, minValue=0.01),
            "A mapped sign farther than this (3D) from every reference sign is a false positive; 0.75 m as in the "
            "README's figures.",
        )
        self.add_parameter(
            QgsProcessingParameterFeatureSource(self.TRAJECTORY, self.tr("Trajectory"), [
                QgsProcessing.TypeVectorPoint, QgsProcessing.TypeVectorLine], optional=True),
            "Trajectory points (in driving order) or line defining along and across track. Empty: taken from the "
            "drive recorded in the mapped signs' GeoPackage.",
        )
        self.add_parameter(
            QgsProcessingParameterFileDestination(self.REPORT, self.tr("HTML report"), "HTML files (*.html)"),
            "Tables 1 and 2 and the error-vector plot as one HTML page.",
        )
        self.add_parameter(
            QgsProcessingParameterFeatureSink(self.STATISTICS, self.tr("Statistics"), QgsProcessing.TypeVector),
            "Table with one row per figure of Tables 1 and 2.",
        )
        self.add_parameter(
            QgsProcessingParameterFeatureSink(self.MATCHES, self.tr("Matches"), QgsProcessing.TypeVectorLine),
            "Line from each mapped sign to its reference sign, with the ids and the error components.",
        )
        for name, title in (("DETECTION_RATE", "Detection rate"), ("CLASSIFICATION_RATE", "Classification rate"),
                            ("FALSE_POSITIVES", "False positives"), ("DUPLICATES", "Duplicates"),
                            ("SIGMA_3D", "Empirical σ 3D [m]")):
            self.addOutput(QgsProcessingOutputNumber(name, self.tr(title)))

    def process(self, parameters, context, feedback):
        import numpy as np

        from ..signmapper_core.evaluation.accuracy import COMPONENTS, evaluate, format_report  # delays numpy until used
        from ..signmapper_core.evaluation.report import missed_rows, report_html, sign_rows  # delays numpy until used

        signs = self.parameterAsSource(parameters, self.SIGNS, context)
        reference = self.parameterAsSource(parameters, self.REFERENCE, context)
        if signs is None or reference is None:
            raise QgsProcessingException("Mapped signs and reference layer are required.")
        sign_field = self.parameterAsString(parameters, self.SIGNS_ID_FIELD, context) or "template_id"
        ref_field = self.parameterAsString(parameters, self.REFERENCE_ID_FIELD, context)
        height_field = self.parameterAsString(parameters, self.REFERENCE_HEIGHT_FIELD, context)
        radius = self.parameterAsDouble(parameters, self.RADIUS, context)

        mapped = self.read_points(signs, sign_field, None, None, context, skip_rejected=True, feedback=feedback)
        to_signs = QgsCoordinateTransform(reference.sourceCrs(), signs.sourceCrs(), context.transformContext())
        facing_field = self.parameterAsString(parameters, self.REFERENCE_FACING_FIELD, context)
        refs = self.read_points(reference, ref_field, height_field, to_signs, context, facing_field=facing_field,
                                feedback=feedback)
        if reference.fields().field(ref_field).isNumeric():
            refs["ids"] = self.read_numbers_as_ids(refs["ids"], mapped["ids"], parameters, context, feedback,
                                                reference, ref_field)
        refs = self.without_repeats(refs, reference, feedback)
        if not refs["xyz"]:
            raise QgsProcessingException("The reference layer has no points.")
        trajectory = self.trajectory_xy(parameters, context, signs, to_signs)
        if facing_field:
            refs = self.keep_facing_trajectory(refs, trajectory, feedback)
        feedback.pushInfo(f"{len(mapped['xyz'])} mapped signs, {len(refs['xyz'])} reference signs, "
                          f"radius {radius} m, trajectory of {len(trajectory)} vertices")
        report = evaluate(np.array(mapped["xyz"]).reshape(-1, 3), mapped["ids"], np.array(refs["xyz"]),
                          refs["ids"], trajectory, radius)
        feedback.pushInfo(format_report(report, aligned=False))
        if feedback.isCanceled():
            raise QgsProcessingException("Cancelled; nothing written.")

        html_path = self.parameterAsFileOutput(parameters, self.REPORT, context)
        notes = [f"Matching radius {radius} m (3D). Signs with status 'rejected' left out."]
        recorded = self.recorded_run(parameters, context)
        about = self.report_about(recorded, signs, reference, radius, facing_field)
        sign_list = sign_rows(report, mapped["ids"], mapped["labels"], mapped["statuses"])
        missed = missed_rows(report, refs["xyz"], [f"fid {f}" for f in refs["fids"]])
        drive = Path(recorded["drive"]).name if recorded.get("drive") else ""
        title = f"Sign Mapper: evaluation of drive {drive}" if drive else "Sign Mapper: evaluation against reference"
        Path(html_path).write_text(report_html(report, title, notes, self.report_settings(recorded), sign_list,
                                               missed, about), encoding="utf-8")
        stats_id = self.write_statistics(parameters, context, report, COMPONENTS)
        matches_id = self.write_matches(parameters, context, signs, report, mapped, refs)
        if feedback.isCanceled():
            raise QgsProcessingException("Cancelled; nothing written.")
        t1 = report.table1
        return {
            self.REPORT: html_path, self.STATISTICS: stats_id, self.MATCHES: matches_id,
            "DETECTION_RATE": defined(t1.detection_rate), "CLASSIFICATION_RATE": defined(t1.classification_rate),
            "FALSE_POSITIVES": t1.false_positive_detections, "DUPLICATES": t1.duplicates,
            "SIGMA_3D": defined(report.table2["3d"].std),
        }

    def read_numbers_as_ids(self, numbers, mapped_ids, parameters, context, feedback, reference, field_name):
        """Catalogue ids (text) for a reference id field that QGIS typed as a number, with a warning: read back
        among the mapped ids and the ids of the catalogue the signs were mapped with (``ids_from_numbers``)."""
        from ..signmapper_core.catalogue import load_catalogue  # delays OpenCV and numpy until used

        kind = reference.fields().field(field_name).typeName()
        known = set(mapped_ids)
        try:
            known |= set(load_catalogue(self.recorded_run(parameters, context).get("catalogue")).ids())
        except Exception:  # noqa: BLE001 - the catalogue only helps to read numbers back; its loss is logged
            feedback.pushInfo("The catalogue of the mapped signs could not be loaded; only their own ids are "
                              "used to read the reference's numbers back as ids")
        ids, unresolved, example = ids_from_numbers(numbers, known)
        feedback.pushWarning(numeric_ids_note(field_name, kind, unresolved, example))
        return ids

    @staticmethod
    def keep_facing_trajectory(refs: dict, trajectory, feedback) -> dict:
        from ..signmapper_core.evaluation.visibility import faces_trajectory  # delays numpy until used

        keep = [i for i, (xyz, facing) in enumerate(zip(refs["xyz"], refs["facing"]))
                if facing is None or faces_trajectory(xyz, facing, trajectory)]  # unknown facing: kept
        feedback.pushInfo(f"{len(refs['xyz']) - len(keep)} reference signs never face the drive and are left out")
        return {key: [values[i] for i in keep] for key, values in refs.items()}

    @staticmethod
    def read_points(source, id_field, height_field, transform, context, skip_rejected=False,
                    facing_field=None, feedback=None) -> dict:
        """Position, id, fid and facing of every feature; those without geometry are left out with a warning."""

        names = source.fields().names()
        if id_field not in names:
            raise QgsProcessingException(f"{source.sourceName()}: no field '{id_field}'")
        has_status = "status" in names
        has_number = "sign_id" in names
        out = {"xyz": [], "ids": [], "fids": [], "facing": [], "labels": [], "statuses": []}
        no_geometry = []
        for feature in source.getFeatures(QgsFeatureRequest()):
            if skip_rejected and has_status and feature["status"] == REJECTED:
                continue
            geom = QgsGeometry(feature.geometry())
            if geom.isNull():
                no_geometry.append(f"fid {feature.id()}")
                continue
            if transform is not None and transform.sourceCrs() != transform.destinationCrs():
                geom.transform(transform)
            point = next(geom.vertices())
            z = point.z() if QgsWkbTypes.hasZ(geom.wkbType()) else None
            if height_field:
                z = feature[height_field]
            if z is None or z != z:
                raise QgsProcessingException(
                    f"{source.sourceName()}: feature {feature.id()} has no height; use a PointZ layer or choose "
                    "the height field")
            out["xyz"].append((point.x(), point.y(), float(z)))
            out["ids"].append(str(feature[id_field]))
            out["fids"].append(feature.id())
            number = feature["sign_id"] if has_number else None
            out["labels"].append(f"sign {number}" if number not in (None, NULL) else f"fid {feature.id()}")
            out["statuses"].append(str(feature["status"]) if has_status and feature["status"] != NULL else "")
            out["facing"].append(facing_value(source, feature, facing_field) if facing_field else None)
        if no_geometry and feedback is not None:
            feedback.pushWarning(no_geometry_note(source.sourceName(), no_geometry))
        return out

    @staticmethod
    def without_repeats(points: dict, source, feedback) -> dict:
        """``points`` (:meth:`read_points`) with each row that repeats another exactly left out, with a warning."""

        repeats = exact_duplicates(points["ids"], points["xyz"])
        if not repeats:
            return points
        feedback.pushWarning(repeats_note(source.sourceName(), repeats, [f"fid {f}" for f in points["fids"]]))
        return {key: [v for i, v in enumerate(values) if i not in repeats] for key, values in points.items()}

    @staticmethod
    def report_about(recorded: dict, signs, reference, radius, facing_field) -> dict:
        """What the report compared, at its head: the drive by its own folder (a model's temporary output path
        says nothing), the layers, the radius, the date."""
        from datetime import datetime

        about = {}
        if recorded.get("drive"):
            about["drive"] = f"{Path(recorded['drive']).name} ({recorded['drive']})"
        about.update({"mapped signs": signs.sourceName(), "reference": reference.sourceName(),
                      "matching radius [m]": radius, "facing field": facing_field or "(none)",
                      "date of this evaluation": datetime.now().astimezone().isoformat(timespec="seconds")})
        return about

    @staticmethod
    def report_settings(recorded: dict) -> dict:
        """The mapping's recorded settings for the report's folded last section."""
        return {f"mapping: {key}": ", ".join(map(str, value)) if isinstance(value, list) else value
                for key, value in recorded.items()}

    def trajectory_xy(self, parameters, context, signs, to_signs):
        import numpy as np

        source = self.parameterAsSource(parameters, self.TRAJECTORY, context)
        if source is not None:
            transform = QgsCoordinateTransform(source.sourceCrs(), signs.sourceCrs(), context.transformContext())
            xy = []
            for feature in source.getFeatures():
                geom = QgsGeometry(feature.geometry())
                geom.transform(transform)
                xy.extend((v.x(), v.y()) for v in geom.vertices())
            if len(xy) < 2:
                raise QgsProcessingException("The trajectory needs at least two vertices.")
            return np.array(xy)
        drive = self.recorded_drive(parameters, context)
        if drive is None:
            raise QgsProcessingException(
                "No trajectory given and the mapped signs do not name their drive (table signmapper_run); "
                "give the trajectory, e.g. from Drive trajectory.")
        return np.array([[r.pose.easting, r.pose.northing] for r in drive.pairs])

    def recorded_run(self, parameters, context) -> dict:
        """The run table of the mapped signs' GeoPackage ({} for other layers)."""
        layer = self.parameterAsVectorLayer(parameters, self.SIGNS, context)
        return {} if layer is None else read_run_table(layer.source().split("|")[0])

    def recorded_drive(self, parameters, context):
        from ..signmapper_core.drive.reader import open_drive  # delays numpy until used

        values = self.recorded_run(parameters, context)
        if "drive" not in values:
            return None
        path = self.parameterAsVectorLayer(parameters, self.SIGNS, context).source().split("|")[0]
        try:
            return open_drive(values["drive"], check_images=False)
        except DriveFormatError as exc:
            raise QgsProcessingException(f"Drive recorded in {path}: {exc}") from exc

    def write_statistics(self, parameters, context, report, components):
        fields = qgs_fields((("table", QVariant.String), ("figure", QVariant.String), ("value", QVariant.Double)))
        sink, dest = self.parameterAsSink(parameters, self.STATISTICS, context, fields, QgsWkbTypes.NoGeometry)
        t1 = report.table1
        rows = [("1", "reference_signs", t1.reference_signs), ("1", "detected_signs", t1.detected_signs),
                ("1", "detection_rate", t1.detection_rate),
                ("1", "correctly_classified_signs", t1.correctly_classified_signs),
                ("1", "classification_rate", t1.classification_rate), ("1", "mapped_features", t1.detections),
                ("1", "false_positives", t1.false_positive_detections), ("1", "duplicates", t1.duplicates)]
        for c in components:
            s = report.table2[c]
            rows += [("2", f"{c}_mean", s.mean), ("2", f"{c}_std", s.std), ("2", f"{c}_rms", s.rms),
                     ("2", f"{c}_max", s.max_abs)]
        for table, figure, value in rows:
            sink.addFeature(new_feature(fields, [table, figure, defined(value)]), QgsFeatureSink.FastInsert)
        return dest

    def write_matches(self, parameters, context, signs, report, mapped, refs):
        fields = qgs_fields((("mapped_fid", QVariant.LongLong), ("mapped_id", QVariant.String),
                             ("reference_id", QVariant.String), ("correct", QVariant.Bool),
                             ("across", QVariant.Double), ("along", QVariant.Double), ("height", QVariant.Double),
                             ("planimetric", QVariant.Double), ("d3", QVariant.Double)))
        sink, dest = self.parameterAsSink(parameters, self.MATCHES, context, fields, QgsWkbTypes.LineStringZ,
                                          signs.sourceCrs())
        k = 0
        for i, ref in enumerate(report.match):
            if ref < 0:
                continue
            comps = [round(float(c), 4) for c in report.differences[k]]
            attributes = [mapped["fids"][i], mapped["ids"][i], refs["ids"][ref],
                          mapped["ids"][i] == refs["ids"][ref]] + comps
            sink.addFeature(new_feature(fields, attributes, line_z([mapped["xyz"][i], refs["xyz"][ref]])),
                            QgsFeatureSink.FastInsert)
            k += 1
        return dest
