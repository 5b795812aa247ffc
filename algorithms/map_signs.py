"""``signmapper:mapsigns``: detect, classify and position the traffic signs of a drive."""

from __future__ import annotations

from qgis.core import (
    QgsCoordinateReferenceSystem,
    QgsFeatureSink,
    QgsProcessing,
    QgsProcessingContext,
    QgsProcessingException,
    QgsProcessingOutputVectorLayer,
    QgsProcessingParameterEnum,
    QgsProcessingParameterFile,
    QgsProcessingParameterFileDestination,
    QgsProcessingParameterNumber,
    QgsProcessingParameterString,
    QgsWkbTypes,
)

from .base import Cancelled, SignMapperAlgorithm, core_progress
from .drive_input import open_drive_or_raise
from .gpkg_output import AtomicGeoPackage, layer_uri
from .layer_styles import embed_default_styles
from .sign_fields import DETECTION_LAYER_FIELDS, SIGN_FIELDS, detection_feature, make_fields, sign_feature

COLOURS = ["red", "blue", "yellow"]


class MapSignsAlgorithm(SignMapperAlgorithm):
    NAME = "mapsigns"
    DISPLAY_NAME = "Map traffic signs"
    GROUP_ID = "mapping"
    HELP = (
        "Detects, classifies and positions the traffic signs of a stereo drive (Cavegn 2011). Per stereo pair: "
        "depth from the given depth map or by semi-global matching, search space cut to the depth range, HSV "
        "colour segmentation, shape, metric size rounded to the catalogue's standard formats, planarity "
        "(detection indicator), template matching (classification indicator) and the 3D position of the sign "
        "centre from the pair's pose. Writes a GeoPackage with the layer 'detections' (one PointZ per sign per "
        "pair, in the drive's CRS), the layer 'signs' (the detections of each physical sign fused into one point with "
        "class by weighted vote, number of observations, position spread and face azimuth) and the table "
        "'signmapper_run' recording the drive folder and parameters. "
        "A pair with a corrupt or missing image is logged and skipped; a failed or cancelled run writes nothing."
    )

    DRIVE = "DRIVE"
    NEAR = "NEAR"
    FAR = "FAR"
    COLOURS = "COLOURS"
    EXCLUDE = "EXCLUDE"
    DETECTION_THRESHOLD = "DETECTION_THRESHOLD"
    CLASSIFICATION_THRESHOLD = "CLASSIFICATION_THRESHOLD"
    CATALOGUE = "CATALOGUE"
    OUTPUT = "OUTPUT"
    DETECTIONS = "DETECTIONS"
    SIGNS = "SIGNS"

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_drive_parameter(self.DRIVE)
        self.add_parameter(
            QgsProcessingParameterNumber(self.NEAR, self.tr("Near limit of the depth range [m]"),
                                         QgsProcessingParameterNumber.Double, 4.0, minValue=0.5, maxValue=100.0),
            "Signs closer than this depth (along the optical axis) are not searched; default 4 m.",
        )
        self.add_parameter(
            QgsProcessingParameterNumber(self.FAR, self.tr("Far limit of the depth range [m]"),
                                         QgsProcessingParameterNumber.Double, 14.0, minValue=1.0, maxValue=200.0),
            "Signs farther than this depth are not searched (they are measured better in a later pair); default "
            "14 m as in Cavegn (2011). On wide streets signs on the far side only come into view beyond 14 m: "
            "about 20 m maps them too, with somewhat larger errors and slower stereo matching.",
        )
        self.add_parameter(
            QgsProcessingParameterEnum(self.COLOURS, self.tr("Sign colours to detect"), options=COLOURS,
                                       allowMultiple=True, defaultValue=[0, 1, 2]),
            "Dominant colours segmented in HSV: red (prohibitions, danger, stop), blue (mandatory, information), "
            "yellow (priority road).",
        )
        self.add_parameter(
            QgsProcessingParameterString(self.EXCLUDE, self.tr("Sign types to exclude"), optional=True),
            "Comma-separated template ids of the catalogue that are never assigned, e.g. '2.30-120, 4.17'.",
        )
        self.add_parameter(
            QgsProcessingParameterNumber(self.DETECTION_THRESHOLD, self.tr("Detection indicator threshold"),
                                         QgsProcessingParameterNumber.Double, 0.5, minValue=0.0, maxValue=1.0),
            "Minimum planar share (0-1) of a colour segment for it to count as a sign face.",
        )
        self.add_parameter(
            QgsProcessingParameterNumber(self.CLASSIFICATION_THRESHOLD, self.tr("Classification indicator threshold"),
                                         QgsProcessingParameterNumber.Double, 0.6, minValue=0.0, maxValue=1.0),
            "Minimum template-matching score (0-1) for status 'accepted'; lower scores get status 'review'.",
        )
        self.add_parameter(
            QgsProcessingParameterFile(self.CATALOGUE, self.tr("Template catalogue folder"),
                                       behavior=QgsProcessingParameterFile.Folder, optional=True),
            "Folder with catalogue.json and template images; empty = the bundled Swiss (SSV) catalogue.",
        )
        self.add_parameter(
            QgsProcessingParameterFileDestination(self.OUTPUT, self.tr("Output GeoPackage"),
                                                  fileFilter="GeoPackage (*.gpkg)"),
            "GeoPackage to write; it is replaced only when the run completes.",
        )
        self.addOutput(QgsProcessingOutputVectorLayer(self.SIGNS, self.tr("Signs"), QgsProcessing.TypeVectorPoint))
        self.addOutput(QgsProcessingOutputVectorLayer(self.DETECTIONS, self.tr("Detections"),
                                                      QgsProcessing.TypeVectorPoint))

    def processAlgorithm(self, parameters, context, feedback):  # noqa: N802
        self.require_dependencies()
        from ..signmapper_core.catalogue import load_catalogue
        from ..signmapper_core.pipeline import PipelineConfig

        folder = self.parameterAsFile(parameters, self.DRIVE, context)
        catalogue_dir = self.parameterAsFile(parameters, self.CATALOGUE, context) or None
        try:
            catalogue = load_catalogue(catalogue_dir)
        except Exception as exc:  # the catalogue's own errors name the file
            raise QgsProcessingException(f"Template catalogue: {exc}") from exc
        exclude = self.excluded_ids(parameters, context, catalogue)
        colours = [COLOURS[i] for i in self.parameterAsEnums(parameters, self.COLOURS, context)]
        if not colours:
            raise QgsProcessingException("Choose at least one sign colour to detect.")
        try:
            config = PipelineConfig(
                near_m=self.parameterAsDouble(parameters, self.NEAR, context),
                far_m=self.parameterAsDouble(parameters, self.FAR, context),
                colours=tuple(colours),
                exclude=tuple(exclude),
                detection_threshold=self.parameterAsDouble(parameters, self.DETECTION_THRESHOLD, context),
                classification_threshold=self.parameterAsDouble(parameters, self.CLASSIFICATION_THRESHOLD, context),
            )
        except ValueError as exc:
            raise QgsProcessingException(str(exc)) from exc

        feedback.pushInfo(f"Validating drive {folder}")
        try:
            drive = open_drive_or_raise(folder, core_progress(feedback, 0, 5))
        except Cancelled:
            raise QgsProcessingException("Cancelled while validating the drive; nothing written.") from None
        feedback.pushInfo(f"{len(drive.pairs)} pairs, CRS {drive.crs}, catalogue {catalogue.folder} "
                          f"({len(catalogue)} templates)")

        output = AtomicGeoPackage(self.parameterAsFileOutput(parameters, self.OUTPUT, context))
        try:
            detections = self.detect(drive, catalogue, config, feedback)
            if feedback.isCanceled():
                raise QgsProcessingException("Cancelled; no output written.")
            signs = self.fuse(detections, feedback)
            self.write_layers(output, drive, detections, signs)
            output.write_run_table(self.run_record(drive, catalogue, config))
            embed_default_styles(str(output.partial), catalogue)
            path = output.commit()
        except BaseException:
            output.discard()
            raise
        feedback.pushInfo(f"{len(detections)} detections fused into {len(signs)} signs, written to {path}")
        results = {self.OUTPUT: path}
        for key, layer, title in ((self.SIGNS, "signs", "Signs"), (self.DETECTIONS, "detections", "Sign detections")):
            results[key] = layer_uri(path, layer)
            context.addLayerToLoadOnCompletion(
                results[key], QgsProcessingContext.LayerDetails(title, context.project(), key)
            )
        return results

    def excluded_ids(self, parameters, context, catalogue) -> list[str]:
        text = self.parameterAsString(parameters, self.EXCLUDE, context) or ""
        ids = [t.strip() for t in text.replace(";", ",").split(",") if t.strip()]
        unknown = [i for i in ids if i not in catalogue]
        if unknown:
            raise QgsProcessingException(f"Sign types to exclude: {', '.join(unknown)} not in the catalogue")
        return ids

    def detect(self, drive, catalogue, config, feedback) -> list:
        """Run the pipeline pair by pair; returns (detection, pair record) in driving order."""
        from ..signmapper_core.mapping import map_drive

        detections, skipped, total = [], 0, len(drive.pairs)
        for done, result in enumerate(map_drive(drive, catalogue, config, feedback.isCanceled), start=1):
            if result.error:
                skipped += 1
                feedback.reportError(f"Skipped pair {result.record.id}: {result.error}", fatalError=False)
            detections.extend((detection, result.record) for detection in result.detections)
            feedback.setProgress(5 + 90 * done / total)
            feedback.setProgressText(
                f"Pair {result.record.id}: {len(result.detections)} signs ({result.seconds:.2f} s)"
            )
        if skipped:
            feedback.pushWarning(f"{skipped} of {total} pairs skipped, see the messages above")
        return detections

    def fuse(self, detections, feedback) -> list:
        from ..signmapper_core.fusion import Observation, fuse_observations

        feedback.setProgressText(f"Fusing {len(detections)} detections into signs")
        signs = fuse_observations([Observation(d, r, i) for i, (d, r) in enumerate(detections)])
        feedback.setProgress(97)
        return signs

    def write_layers(self, output, drive, detections, signs) -> None:
        import numpy as np

        from ..signmapper_core.mounting import camera_height_above_road, mounting_height

        crs = QgsCoordinateReferenceSystem(drive.crs)
        centres = np.array([r.pose.centre for r in drive.pairs])
        camera_height = camera_height_above_road(drive.metadata)
        sign_of = {o.id: s.sign_id for s in signs for o in s.observations}
        fields = make_fields(SIGN_FIELDS)
        writer = output.open_layer("signs", fields, QgsWkbTypes.PointZ, crs,
                                   abstract=f"Sign Mapper: traffic signs of drive {drive.root}")
        for sign in signs:
            mount = mounting_height(sign.position, sign.height_m, centres, camera_height)
            writer.addFeature(sign_feature(fields, sign, mount), QgsFeatureSink.FastInsert)
        del writer
        fields = make_fields(DETECTION_LAYER_FIELDS)
        writer = output.open_layer("detections", fields, QgsWkbTypes.PointZ, crs,
                                   abstract=f"Sign Mapper: per-pair sign detections of drive {drive.root}")
        for i, (detection, record) in enumerate(detections):
            writer.addFeature(detection_feature(fields, detection, record, sign_of.get(i)), QgsFeatureSink.FastInsert)
        del writer

    @staticmethod
    def run_record(drive, catalogue, config) -> dict:
        from ..signmapper_core import __version__

        return {
            "software": f"Sign Mapper {__version__}",
            "drive": str(drive.root.resolve()),
            "crs": drive.crs,
            "catalogue": str(catalogue.folder),
            "near_m": config.near_m,
            "far_m": config.far_m,
            "colours": list(config.colours),
            "exclude": list(config.exclude),
            "detection_threshold": config.detection_threshold,
            "classification_threshold": config.classification_threshold,
        }
