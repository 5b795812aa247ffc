"""``signmapper:syntheticdrive``: a realistic stereo drive with ground truth, for trying and testing Sign Mapper."""

from __future__ import annotations

from qgis.core import (
    QgsCoordinateReferenceSystem,
    QgsFeatureSink,
    QgsFields,
    QgsProcessing,
    QgsProcessingException,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterFeatureSink,
    QgsProcessingParameterFolderDestination,
    QgsProcessingParameterNumber,
    QgsWkbTypes,
)
from qgis.PyQt.QtCore import QVariant

from ..gpkg.fields import new_feature, point_z, qgs_fields
from ..signmapper_core.progress import Cancelled
from ..signmapper_core.simulate.config import SimulationConfig
from .base import CoreFeedback, SignMapperAlgorithm

DEFAULTS = SimulationConfig()  # the camera and noise a drive gets unless the dialog says otherwise


class SyntheticDriveAlgorithm(SignMapperAlgorithm):
    NAME = "syntheticdrive"
    DISPLAY_NAME = "Synthetic drive"
    GROUP_ID = "tools"
    ICON = "synthetic_drive.svg"
    HELP = (
        "Generates a synthetic stereo mobile-mapping drive in the stereo-drive/1 layout: a street with façades, "
        "vegetation, cars and other sign-coloured distractors, and poles carrying Swiss traffic signs, rendered "
        "as rectified stereo pairs with sensor noise, blur, JPEG compression, exposure changes, shadows and "
        "occlusions. Each sign face is printed from the catalogue's master image or a procedural variant and "
        "gets its own print, reflective sheeting, wear, dirt, stickers or dents. poses.csv holds the poses with "
        "GNSS/INS noise; truth.csv the true sign positions, ids and sizes. The same seed always gives the same "
        "files. Use it to try the mapping or to measure its accuracy."
    )

    OUTPUT = "OUTPUT"
    TRUTH = "TRUTH"
    PAIRS = "PAIRS"
    SEED = "SEED"
    WRITE_DEPTH = "WRITE_DEPTH"
    WIDTH = "WIDTH"
    HEIGHT = "HEIGHT"
    FX = "FX"
    BASELINE = "BASELINE"
    POSITION_SIGMA = "POSITION_SIGMA"
    ANGLE_SIGMA = "ANGLE_SIGMA"

    def initAlgorithm(self, config=None):  # noqa: N802
        number = QgsProcessingParameterNumber
        self.add_parameter(number(self.PAIRS, self.tr("Number of stereo pairs"), number.Integer, 50, minValue=1,
                                  maxValue=100000),
                           "Pairs to record; at 40 km/h and 5 pairs/s consecutive pairs are about 2.2 m apart.")
        self.add_parameter(number(self.SEED, self.tr("Random seed"), number.Integer, 1, minValue=0),
                           "Seed of the scene, the rendering effects and the pose noise; same seed, same drive.")
        self.add_parameter(QgsProcessingParameterBoolean(self.WRITE_DEPTH, self.tr("Write true depth maps"), False),
                           "Also write depth/<id>.npy with the exact depth; off = depth is computed from the "
                           "stereo pair, as with real data.")
        for name, title, kind, value, low, high, help_text in (
                (self.WIDTH, "Image width [px]", number.Integer, DEFAULTS.width, 64, 8192,
                 "Width of the rectified normal images."),
                (self.HEIGHT, "Image height [px]", number.Integer, DEFAULTS.height, 64, 8192,
                 "Height of the rectified normal images."),
                (self.FX, "Focal length [px]", number.Double, DEFAULTS.fx, 10.0, None,
                 "Focal length of the normal images in pixels (fx = fy)."),
                (self.BASELINE, "Stereo baseline [m]", number.Double, DEFAULTS.baseline_m, 0.05, 5.0,
                 "Distance of the right camera along the left camera's x axis."),
                (self.POSITION_SIGMA, "GNSS position noise σ [m]", number.Double, DEFAULTS.position_sigma_m, 0.0, 10.0,
                 "Standard deviation of the noise added per axis to the recorded positions."),
                (self.ANGLE_SIGMA, "INS attitude noise σ [°]", number.Double, DEFAULTS.angle_sigma_deg, 0.0, 5.0,
                 "Standard deviation of the noise added to the recorded heading, pitch and roll.")):
            limits = {"minValue": low} if high is None else {"minValue": low, "maxValue": high}
            self.add_parameter(number(name, self.tr(title), kind, value, **limits), help_text)
        self.add_parameter(QgsProcessingParameterFolderDestination(self.OUTPUT, self.tr("Drive folder")),
                           "Folder to write the drive into; it must not exist yet or be empty.")
        self.add_parameter(QgsProcessingParameterFeatureSink(self.TRUTH, self.tr("Ground truth signs"),
                                                             QgsProcessing.TypeVectorPoint, optional=True),
                           "The signs of truth.csv as a PointZ layer (sign face centres), e.g. as the reference "
                           "of Evaluate against reference.")

    def process(self, parameters, context, feedback):
        self.require_dependencies()
        from ..signmapper_core.simulate import SimulationConfig, generate_drive  # delays OpenCV and numpy until used

        out_dir = self.parameterAsString(parameters, self.OUTPUT, context)
        config = SimulationConfig(
            pairs=self.parameterAsInt(parameters, self.PAIRS, context),
            seed=self.parameterAsInt(parameters, self.SEED, context),
            write_depth=self.parameterAsBool(parameters, self.WRITE_DEPTH, context),
            width=self.parameterAsInt(parameters, self.WIDTH, context),
            height=self.parameterAsInt(parameters, self.HEIGHT, context),
            fx=self.parameterAsDouble(parameters, self.FX, context),
            baseline_m=self.parameterAsDouble(parameters, self.BASELINE, context),
            position_sigma_m=self.parameterAsDouble(parameters, self.POSITION_SIGMA, context),
            angle_sigma_deg=self.parameterAsDouble(parameters, self.ANGLE_SIGMA, context),
        )
        # The truth layer is opened first (a bad destination fails before any rendering) and written before
        # the drive takes its name: all outputs or none (the truth's file is committed after the drive).
        truth = self.truth_sink(parameters, context, config.crs)
        steps = CoreFeedback(feedback)
        try:
            summary = generate_drive(out_dir, config, progress=steps.progress, is_cancelled=steps.is_cancelled,
                                     before_commit=None if truth is None else truth.write)
        except Cancelled:
            raise QgsProcessingException("Cancelled; no drive written.") from None
        except (ValueError, OSError) as exc:
            raise QgsProcessingException(f"Synthetic drive: {exc}") from exc
        feedback.pushInfo(f"{summary.pairs} pairs and {len(summary.signs)} signs written to {out_dir} "
                          f"in {summary.seconds:.1f} s")
        results = {self.OUTPUT: out_dir}
        if truth is not None:
            results[self.TRUTH] = truth.dest
        return results

    def truth_sink(self, parameters, context, crs) -> TruthLayer | None:
        fields = qgs_fields((("sign_id", QVariant.String), ("template_id", QVariant.String),
                             ("width_m", QVariant.Double), ("height_m", QVariant.Double), ("facing", QVariant.Double),
                             ("plate_of", QVariant.String), ("text", QVariant.String)))
        sink, dest = self.parameterAsSink(parameters, self.TRUTH, context, fields, QgsWkbTypes.PointZ,
                                          QgsCoordinateReferenceSystem(crs))
        if sink is None:
            if parameters.get(self.TRUTH) is not None and self.parameterAsOutputLayer(parameters, self.TRUTH, context):
                raise QgsProcessingException(self.invalidSinkError(parameters, self.TRUTH))
            return None
        return TruthLayer(sink, dest, fields)


class TruthLayer:
    """The truth sink of a run, written once the drive's signs are known."""

    def __init__(self, sink, dest: str, fields: QgsFields):
        self.sink, self.dest, self.fields = sink, dest, fields

    def write(self, signs) -> None:
        for sign in signs:
            feature = new_feature(self.fields, [sign.sign_id, sign.template_id, sign.width_m, sign.height_m,
                                                sign.facing, sign.plate_of or None, sign.text or None],
                                  point_z(sign.easting, sign.northing, sign.height))
            if not self.sink.addFeature(feature, QgsFeatureSink.FastInsert):
                raise QgsProcessingException(f"{self.dest}: cannot write the ground truth signs")
