"""``signmapper:drivetrajectory``: the pose of every stereo pair as a PointZ layer (and a track line)."""

from __future__ import annotations

from qgis.core import (
    QgsFeature,
    QgsFeatureSink,
    QgsFields,
    QgsProcessing,
    QgsProcessingException,
    QgsProcessingParameterFeatureSink,
    QgsWkbTypes,
)
from qgis.PyQt.QtCore import QVariant

from ..gpkg.fields import line_z, new_feature, point_z, qgs_fields
from ..signmapper_core.progress import Cancelled
from .base import CoreFeedback, SignMapperAlgorithm
from .drive_input import open_drive_or_raise, qgis_crs

TRAJECTORY_FIELDS = (("pair_id", QVariant.String), ("pair_index", QVariant.Int), ("time", QVariant.Double),
                     ("heading", QVariant.Double), ("pitch", QVariant.Double), ("roll", QVariant.Double),
                     ("image", QVariant.String))


class DriveTrajectoryAlgorithm(SignMapperAlgorithm):
    NAME = "drivetrajectory"
    DISPLAY_NAME = "Drive trajectory"
    GROUP_ID = "tools"
    ICON = "drive_trajectory.svg"
    HELP = (
        "Reads a drive folder (stereo-drive/1: drive.json, poses.csv, left/, right/ or depth/) and writes one "
        "3D point per stereo pair at the left camera's projection centre, in the drive's CRS, with the pair id, "
        "time, heading, pitch, roll and the path of the left image. Optionally writes the track as a 3D line. "
        "The whole folder is validated first: a missing or malformed file stops the run with a message naming "
        "the file, the line and the field."
    )

    DRIVE = "DRIVE"
    OUTPUT = "OUTPUT"
    TRACK = "TRACK"

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_drive_parameter(self.DRIVE)
        self.add_parameter(
            QgsProcessingParameterFeatureSink(self.OUTPUT, self.tr("Trajectory points"), QgsProcessing.TypeVectorPoint),
            "PointZ layer (GeoPackage by default) with one feature per stereo pair, in the drive's CRS.",
        )
        self.add_parameter(
            QgsProcessingParameterFeatureSink(
                self.TRACK, self.tr("Trajectory line"), QgsProcessing.TypeVectorLine, optional=True,
                createByDefault=False,
            ),
            "Optional LineStringZ layer joining the pairs in driving order.",
        )

    def process(self, parameters, context, feedback):
        self.require_dependencies()
        folder = self.parameterAsFile(parameters, self.DRIVE, context)
        feedback.pushInfo(self.tr(f"Validating drive {folder}"))
        try:
            drive = open_drive_or_raise(folder, CoreFeedback(feedback, 0, 50))
        except Cancelled:
            raise QgsProcessingException(self.tr("Cancelled while validating the drive; nothing written.")) from None
        crs, note = qgis_crs(drive.crs)
        if note:
            feedback.pushInfo(note)
        fields = qgs_fields(TRAJECTORY_FIELDS)
        features, vertices = [], []
        for record in drive.pairs:  # built first: a cancel here leaves no file behind
            if feedback.isCanceled():
                raise QgsProcessingException(self.tr("Cancelled; nothing written."))
            pose = record.pose
            vertices.append((pose.easting, pose.northing, pose.height))
            attributes = [record.id, record.index, record.time, pose.heading, pose.pitch, pose.roll,
                          str(record.left_path)]
            features.append(new_feature(fields, attributes, point_z(*vertices[-1])))
            feedback.setProgress(50 + 40 * (record.index + 1) / len(drive.pairs))
        sink, dest_id = self.parameterAsSink(parameters, self.OUTPUT, context, fields, QgsWkbTypes.PointZ, crs)
        if sink is None:
            raise QgsProcessingException(self.invalidSinkError(parameters, self.OUTPUT))
        sink.addFeatures(features, QgsFeatureSink.FastInsert)
        results = {self.OUTPUT: dest_id}
        track_sink, track_id = self.parameterAsSink(
            parameters, self.TRACK, context, QgsFields(), QgsWkbTypes.LineStringZ, crs
        )
        if track_sink is not None:
            line = QgsFeature()
            line.setGeometry(line_z(vertices))
            track_sink.addFeature(line, QgsFeatureSink.FastInsert)
            results[self.TRACK] = track_id
        if feedback.isCanceled():
            raise QgsProcessingException(self.tr("Cancelled; nothing written."))
        feedback.setProgress(100)
        feedback.pushInfo(self.tr(f"{len(features)} of {len(drive.pairs)} pairs written"))
        return results
