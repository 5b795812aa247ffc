"""``signmapper:mapsigns``: detect, classify and position the traffic signs of a drive."""

from __future__ import annotations

from pathlib import Path

from qgis.core import (
    QgsFeatureSink,
    QgsProcessing,
    QgsProcessingContext,
    QgsProcessingException,
    QgsProcessingOutputVectorLayer,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterFile,
    QgsProcessingParameterFileDestination,
    QgsProcessingParameterNumber,
    QgsProcessingParameterString,
    QgsWkbTypes,
)

from ..gpkg.fields import layer_feature, layer_fields
from ..gpkg.language import qgis_language
from ..gpkg.output import GeoPackageLayers, layer_uri
from ..gpkg.styles import OutputStyler, embed_default_styles
from ..signmapper_core.drive.clock import drive_start, first_time
from ..signmapper_core.errors import ClusterError, DriveFormatError, MappingError
from ..signmapper_core.fusion.signs import FusionConfig
from ..signmapper_core.output import run_table, schema
from ..signmapper_core.output.geopackage_file import OUR_TABLES
from ..signmapper_core.output.schema import DETECTIONS, SIGNS, OutputContext
from ..signmapper_core.output.sign_crops import CropFolder
from ..signmapper_core.pipeline.classifier_names import CLASSIFIER_CHOICES, CLASSIFIERS
from ..signmapper_core.pipeline.classifiers import NccClassifier, accept_threshold, classifier_for
from ..signmapper_core.pipeline.config import DepthConfig, default
from ..signmapper_core.pipeline.depth_range import camera_reach
from ..signmapper_core.progress import Cancelled, check_cancelled
from ..signmapper_core.run import MAX_SKIPPED_PERCENT
from ..signmapper_core.run.dask_pairs import scheduler_address
from ..signmapper_core.run.mapping import map_drive
from ..signmapper_core.run.setup import RunSetupError, assemble_run
from ..signmapper_core.sign_colours import SIGN_COLOURS
from ..signmapper_core.simulate.config import SimulationConfig
from .base import CoreFeedback, SignMapperAlgorithm
from .drive_input import open_drive_or_raise, qgis_crs

COLOURS = list(SIGN_COLOURS)
_FUSION = FusionConfig()  # the defaults the help states
NEAR_SETTING, FAR_SETTING = ("depth", "near_m"), ("depth", "far_m")  # the settings the depth range parameters set
# the reach the synthetic drives' camera gets, as the help's example
PAPER_REACH = camera_reach(SimulationConfig().camera(), DepthConfig(), default("colour", "min_face_px"))


class MapSignsAlgorithm(SignMapperAlgorithm):
    NAME = "mapsigns"
    OWNED_LAYERS = {"OUTPUT": OUR_TABLES}
    DISPLAY_NAME = "Map traffic signs"
    GROUP_ID = "mapping"
    ICON = "map_signs.svg"
    HELP = (
        "Detects, classifies and positions the traffic signs of a stereo drive (Cavegn 2011). Per stereo pair: "
        "depth from the given depth map or by semi-global matching, search space cut to the depth range, HSV "
        "colour segmentation, shape, metric size rounded to the catalogue's standard formats, planarity "
        "(detection indicator), classification by the learned network or by template matching (classification "
        "indicator: the network's calibrated probability, or the correlation score) and the 3D position of the "
        "sign centre from the pair's pose. Writes a GeoPackage with the layer 'detections' (one PointZ per sign per "
        "pair, in the drive's CRS), the layer 'signs' (the detections of each physical sign fused into one point with "
        "class by weighted vote, number of observations, position σ and face azimuth) and the table "
        "'signmapper_run' recording the drive folder and parameters. "
        "A sign's position comes from all the pairs it was seen in, each weighted by how precisely stereo places it "
        "(depth error Z²·σ_d/(f·B) along the line of sight, Z·σ_px/f across, with the drive's focal length f and "
        f"baseline B, σ_d = {_FUSION.disparity_sigma_px:g} px and σ_px = {_FUSION.image_sigma_px:g} px), and it "
        "reports its estimated σ along the line of sight and across it (sigma_along_m, sigma_across_m); views of "
        "one far sign whose depths scatter along their line of sight are fused as one sign. "
        "Plausibility: a sign that would be accepted but is mapped where or as no sign can be goes to review with "
        "its reason: its face centre less than "
        f"{_FUSION.min_centre_above_road_m:g} m above the road beside it (a deliberately loose bound below the "
        "lowest mounted signs, the keep-left/right signs on traffic-island bollards; the road is the camera's path "
        "less the camera height, so this applies only where drive.json states vehicle.camera_height_m), its face "
        f"looking more than {_FUSION.max_face_turn_deg:g}° away from the direction to the vehicle's path (a sign "
        "beside the road or on the back of its pole is ~90°), or it stands more than "
        f"{_FUSION.max_lateral_m:g} m beside the path (a deliberately loose bound beyond the far side of a "
        "four-lane street). Nothing is dropped: a person decides. "
        "A pair with a corrupt or missing image is logged and skipped; when more than a set share of the pairs "
        "(or all of them) cannot be mapped, the run fails. A failed or cancelled run writes nothing and leaves an "
        "earlier output as it was. Written into an existing GeoPackage, only the layers above are replaced: the "
        "file's other layers stay. The table 'signmapper_run' records every setting of the run, so 'Settings from "
        "an earlier output' can map a drive again exactly as then."
    )

    DRIVE = "DRIVE"
    SETTINGS_FROM = "SETTINGS_FROM"
    NEAR = "NEAR"
    FAR = "FAR"
    COLOURS = "COLOURS"
    WHITE_SIGNS = "WHITE_SIGNS"
    EXCLUDE = "EXCLUDE"
    DETECTION_THRESHOLD = "DETECTION_THRESHOLD"
    CLASSIFICATION_THRESHOLD = "CLASSIFICATION_THRESHOLD"
    CLASSIFIER = "CLASSIFIER"
    CATALOGUE = "CATALOGUE"
    LANGUAGE = "LANGUAGE"
    CROPS = "CROPS"
    MAX_SKIPPED = "MAX_SKIPPED"
    WORKERS = "WORKERS"
    SCHEDULER = "SCHEDULER"
    OUTPUT = "OUTPUT"
    DETECTIONS = "DETECTIONS"
    SIGNS = "SIGNS"

    def shortHelpString(self):  # noqa: N802
        """The help, the parameters, and every output field with its layers (from output_schema)."""
        lines = [super().shortHelpString(), "<b>Output fields</b>", "<ul>"]
        for field in schema.FIELDS:
            layers = " and ".join(layer for layer in schema.LAYERS if field.reader(layer) is not None)
            lines.append(f"<li><b>{field.name}</b> ({layers}): {self.help_html(field.help)}</li>")
        lines.append("</ul>")
        return "\n".join(lines)

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_drive_parameter(self.DRIVE)
        self.add_parameter(
            QgsProcessingParameterFile(self.SETTINGS_FROM, self.tr("Settings from an earlier output"),
                                       extension="gpkg", optional=True),
            "A GeoPackage this algorithm wrote: the drive is mapped with the settings its table signmapper_run "
            "records (every pipeline and fusion setting, classifier, catalogue folder) instead of the defaults. "
            "A parameter below that you set to something other than its default wins over the record; one left "
            "at its default (or empty) takes the record's value. Language, crops and the share of unreadable pairs "
            "are not taken from it.",
        )
        self.add_parameter(
            QgsProcessingParameterNumber(self.NEAR, self.tr("Near limit of the depth range [m]"),
                                         QgsProcessingParameterNumber.Double, None, optional=True, minValue=0.5,
                                         maxValue=100.0),
            "Signs closer than this depth (along the optical axis) are not searched: they are cut by the frame. Empty "
            f"(the default): {default(*NEAR_SETTING):g} m as in Cavegn (2011). Setting either limit fixes the range to "
            "the two limits (the other keeps its default) and turns off the reach beyond the far limit.",
        )
        self.add_parameter(
            QgsProcessingParameterNumber(self.FAR, self.tr("Far limit of the depth range [m]"),
                                         QgsProcessingParameterNumber.Double, None, optional=True, minValue=1.0,
                                         maxValue=200.0),
            "Signs farther than this depth are searched in a later pair, where they are measured better. Empty (the "
            f"default): {default(*FAR_SETTING):g} m as in Cavegn (2011), and a sign never seen that close (it leaves "
            "the view first, far to the side on a wide street or high over the road; or the drive ends or turns off "
            "before it) is searched beyond it, where it is seen best: out to the reach the drive's camera gives, "
            f"where a normal 60 cm disc still spans {default('colour', 'min_face_px')} px and one view's depth is "
            f"known to {default('depth', 'placing_sigma_m'):g} m ({PAPER_REACH.reach_m:g} m for the synthetic drives' "
            "Full-HD camera, about 27 m for KITTI's 1242 x 375 one); such a sign needs two views. The log and the run "
            "table state the range used.",
        )
        self.add_parameter(
            self.named_enum(self.COLOURS, "Sign colours to detect", COLOURS, allowMultiple=True,
                            defaultValue=[COLOURS.index(c) for c in default("colour", "colours")]),
            "Dominant colours segmented in HSV: red (prohibitions, danger, stop), blue (mandatory, information), "
            "yellow (priority road).",
        )
        self.add_parameter(
            # optional: models saved before this parameter existed stay valid (QGIS asks for every mandatory one)
            QgsProcessingParameterBoolean(self.WHITE_SIGNS, self.tr("Look for white and grey signs"),
                                          defaultValue=default("white", "white_signs"), optional=True),
            "End-of-restriction discs and panels (2.53-2.59) have no sign colour: they are found by their outlines "
            "and the depth map over the whole image and classified by the classifier. White place-name and direction "
            "panels of secondary roads (4.29, 4.30, 4.33) are found by their framed white field, told apart by "
            "their layout (a pointer, a bar), sized as measured and their text read by Tesseract like a plate's. "
            f"{'On' if default('white', 'white_signs') else 'Off'} by default; switched off, a run maps only the "
            "coloured signs and is somewhat faster (see the README for the figures).",
        )
        self.add_parameter(
            QgsProcessingParameterString(self.EXCLUDE, self.tr("Sign types to exclude"), optional=True),
            "Comma-separated template ids of the catalogue that are never assigned, e.g. '2.30-120, 4.17'.",
            advanced=True,
        )
        self.add_parameter(
            QgsProcessingParameterNumber(self.DETECTION_THRESHOLD, self.tr("Detection indicator threshold"),
                                         QgsProcessingParameterNumber.Double,
                                         default("planarity", "detection_threshold"), minValue=0.0, maxValue=1.0),
            "Minimum planar share (0-1) of a colour segment for it to count as a sign face.",
            advanced=True,
        )
        self.add_parameter(
            self.named_enum(self.CLASSIFIER, "Classifier", list(CLASSIFIER_CHOICES.items()),
                            defaultValue=CLASSIFIERS.index(default("classification", "classifier")),
                            optional=True),  # models saved before it still run
            "How a face gets its sign type among the candidates its colour and shape leave. The learned network "
            "is trained on synthetic faces of the official SSV drawings; its indicator is a calibrated probability "
            "that the type is right. Template matching is the paper's method; its indicator is the correlation "
            "score. A catalogue folder of your own has no network unless you train one (make train-classifier).",
            advanced=True,
        )
        self.add_parameter(
            QgsProcessingParameterNumber(self.CLASSIFICATION_THRESHOLD, self.tr("Classification indicator threshold"),
                                         QgsProcessingParameterNumber.Double,
                                         default("classification", "classification_threshold"), optional=True,
                                         minValue=0.0, maxValue=1.0),
            "Minimum classification indicator (0-1) for status 'accepted'; lower ones get status 'review'. Empty = "
            f"the classifier's own: the network's calibrated threshold, {NccClassifier.accept_threshold:g} for "
            "template matching.",
            advanced=True,
        )
        self.add_parameter(
            QgsProcessingParameterFile(self.CATALOGUE, self.tr("Template catalogue folder"),
                                       behavior=QgsProcessingParameterFile.Folder, optional=True),
            "Folder with catalogue.json and template images; empty = the bundled Swiss (SSV) catalogue.",
            advanced=True,
        )
        self.add_language_parameter(
            self.LANGUAGE, "The language QGIS runs in",
            "Sign names, field titles and the words shown for coded values (status, format, colour, shape) in "
            "English, German, French or Italian; by default the language QGIS runs in. The file keeps the codes "
            "themselves, so expressions and other tools read the same values whatever the language.",
            advanced=True,
        )
        self.add_parameter(
            QgsProcessingParameterBoolean(self.CROPS, self.tr("Write an image crop per sign"), defaultValue=True),
            "A JPEG of each sign from its best pair, in a folder '<output name>_crops' beside the GeoPackage, its "
            "path in the field crop_path: signs can be checked without the drive, the identify panel's form and "
            "map tip show the photo, the inventory atlas prints it. Off: no crops (a little faster).",
        )
        self.add_parameter(
            QgsProcessingParameterNumber(self.MAX_SKIPPED, self.tr("Largest share of unreadable pairs [%]"),
                                         QgsProcessingParameterNumber.Double, MAX_SKIPPED_PERCENT, minValue=0.0,
                                         maxValue=100.0),
            "Pairs whose files cannot be read (or whose detection fails) are skipped and logged. When more than "
            "this share of the drive is skipped the run fails (as soon as that is certain) and writes nothing, "
            "since the output would lack their signs without a word. A run where no pair can be mapped always "
            "fails.",
            advanced=True,
        )
        self.add_parameter(
            QgsProcessingParameterNumber(self.WORKERS, self.tr("Worker processes"),
                                         QgsProcessingParameterNumber.Integer, 0, optional=True, minValue=0,
                                         maxValue=256),  # optional: models saved before it still run
            "Processes mapping the stereo pairs side by side, each on its own core; 0 = all cores of this "
            "computer, 1 = in the QGIS process. The output is the same whatever the number; fewer leave cores "
            "free for other work while a long drive maps. Each process holds its own pair images and "
            "classifier (about 270 MB at Full HD).",
            advanced=True,
        )
        self.add_parameter(
            QgsProcessingParameterString(self.SCHEDULER, self.tr("Dask scheduler address"), optional=True),
            "Map the stereo pairs on a Dask cluster instead of this computer: the address of its scheduler, "
            "tcp://HOST:PORT as 'dask scheduler' prints it (Worker processes is then not used). Every worker must "
            "read the drive folder at the same path as here, import the plugin's signmapper_core (the plugin folder "
            "on its PYTHONPATH) with OpenCV, and run the same plugin version; only the detections come back and the "
            "signs are fused here, so the output is the same as on this computer. Cancel cancels the cluster's "
            "tasks. Needs the Python packages dask and distributed (requirements-dask.txt) here and on the "
            "workers. Empty: this computer's worker processes. See docs/scale-out.md.",
            advanced=True,
        )
        self.add_parameter(
            QgsProcessingParameterFileDestination(self.OUTPUT, self.tr("Output GeoPackage"),
                                                  fileFilter="GeoPackage (*.gpkg)"),
            "GeoPackage to write. Its layers signs and detections and the table signmapper_run are replaced only "
            "when the run completes; other layers of an existing GeoPackage are kept.",
        )
        self.addOutput(QgsProcessingOutputVectorLayer(self.SIGNS, self.tr("Signs"), QgsProcessing.TypeVectorPoint))
        self.addOutput(QgsProcessingOutputVectorLayer(self.DETECTIONS, self.tr("Detections"),
                                                      QgsProcessing.TypeVectorPoint))

    def check_inputs(self, parameters, context) -> None:
        """Catch wrong inputs before the run: drive folder, outputs, depth range, colours, catalogue, exclusions."""
        self.settings(parameters, context)

    def settings(self, parameters, context, notes=None):
        """(drive folder, catalogue, PipelineConfig, FusionConfig) of the parameters and, when given, the settings
        of an earlier output; QgsProcessingException says what is wrong. Notes on the record go to ``notes``."""
        self.require_dependencies()

        folder = self.parameterAsFile(parameters, self.DRIVE, context)
        if not folder or not (Path(folder) / "drive.json").is_file():
            raise QgsProcessingException(f"Drive folder {folder or '(none)'}: no drive.json, not a stereo-drive/1 "
                                         "folder")
        output = self.output_target(parameters, self.OUTPUT, context)
        if not output.lower().endswith(".gpkg"):
            label = self.parameterDefinition(self.OUTPUT).description()
            raise QgsProcessingException(f"{label}: {output}: the output must be a GeoPackage file ending in .gpkg")
        self.check_outputs(parameters, context)  # an existing file that is no GeoPackage is refused, not replaced
        self.scheduler(parameters, context)  # a malformed address is said before the run
        colours = [COLOURS[i] for i in self.parameterAsEnums(parameters, self.COLOURS, context)]
        chosen = {  # (section, setting) -> the dialog's value
            NEAR_SETTING: self.optional_number(parameters, self.NEAR, context),
            FAR_SETTING: self.optional_number(parameters, self.FAR, context),
            ("colour", "colours"): tuple(colours),
            ("white", "white_signs"): self.parameterAsBool(parameters, self.WHITE_SIGNS, context),
            ("classification", "exclude"): tuple(self.excluded_ids(parameters, context)),
            ("planarity", "detection_threshold"): self.parameterAsDouble(parameters, self.DETECTION_THRESHOLD,
                                                                         context),
            ("classification", "classification_threshold"): self.optional_number(
                parameters, self.CLASSIFICATION_THRESHOLD, context),
            ("classification", "classifier"): CLASSIFIERS[self.parameterAsEnum(parameters, self.CLASSIFIER, context)],
        }
        labels = {key: self.parameterDefinition(name).description() for key, name in (
            ("settings_from", self.SETTINGS_FROM), ("near_m", self.NEAR), ("far_m", self.FAR))}
        try:
            run = assemble_run(chosen, self.parameterAsFile(parameters, self.SETTINGS_FROM, context) or None,
                               self.parameterAsFile(parameters, self.CATALOGUE, context) or None,
                               defaults_yield=True, warn=notes.append if notes is not None else None, labels=labels)
        except RunSetupError as exc:
            raise QgsProcessingException(str(exc)) from None
        return folder, run.catalogue, run.config, run.fusion

    def scheduler(self, parameters, context):
        """The Dask scheduler address given (``tcp://HOST:PORT``), or None: map on this computer."""
        text = (self.parameterAsString(parameters, self.SCHEDULER, context) or "").strip()
        if not text:
            return None

        try:
            return scheduler_address(text)
        except ClusterError as exc:
            raise QgsProcessingException(f"{self.parameterDefinition(self.SCHEDULER).description()}: {exc}") \
                from None

    @staticmethod
    def report_classifier(catalogue, config, feedback) -> None:

        classifier = classifier_for(catalogue, config)
        feedback.pushInfo(f"Classifier: {classifier.name}; status 'accepted' from a classification indicator of "
                          f"{accept_threshold(classifier, config):.2f}")

    def optional_number(self, parameters, name, context):
        """The number given for an optional parameter, or None when it was left empty."""
        value = parameters.get(name)
        if value is None or (isinstance(value, str) and not value.strip()):
            return None
        return self.parameterAsDouble(parameters, name, context)

    def process(self, parameters, context, feedback):
        notes = []
        folder, catalogue, config, fusion = self.settings(parameters, context, notes)
        for note in notes:
            feedback.pushWarning(note)
        if self.parameterAsFile(parameters, self.SETTINGS_FROM, context):
            feedback.pushInfo(f"Settings from {self.parameterAsFile(parameters, self.SETTINGS_FROM, context)}, "
                              "with the parameters set to something other than their defaults")
        feedback.pushInfo(f"Validating drive {folder}")
        try:
            drive = open_drive_or_raise(folder, CoreFeedback(feedback, 0, 5))
        except Cancelled:
            raise QgsProcessingException("Cancelled while validating the drive; nothing written.") from None
        feedback.pushInfo(f"{len(drive.pairs)} pairs, CRS {drive.crs}, catalogue {catalogue.folder} "
                          f"({len(catalogue)} templates)")
        self.report_classifier(catalogue, config, feedback)

        language = self.language(parameters, context)
        path = self.output_target(parameters, self.OUTPUT, context)
        output = self.run_outputs.partial(self.OUTPUT)
        unchanged = self.run_outputs.unchanged()
        crops = None
        if self.parameterAsBoolean(parameters, self.CROPS, context):
            crops = CropFolder(path)
            self.run_outputs.add(crops.output)
        max_skipped = self.parameterAsDouble(parameters, self.MAX_SKIPPED, context) / 100.0
        workers = self.parameterAsInt(parameters, self.WORKERS, context) if parameters.get(self.WORKERS) else 0
        scheduler = self.scheduler(parameters, context)
        if scheduler:
            feedback.pushInfo(f"Mapping the pairs on the Dask cluster of the scheduler {scheduler}")
        try:
            result = self.map(drive, catalogue, config, feedback, max_skipped, fusion, workers, scheduler)
            out = self.output_context(drive, catalogue, language, result, crops, feedback)
            layers = GeoPackageLayers(output)
            self.write_layers(layers, result, out, feedback)
            layers.write_run_table(run_table.run_record(result, out))
            without_svg = embed_default_styles(str(output.path), catalogue, language, output.target)
            check_cancelled(feedback.isCanceled, "writing")
        except Cancelled:
            raise QgsProcessingException(f"Cancelled; no output written{unchanged}.") from None
        except MappingError as exc:
            label = self.parameterDefinition(self.MAX_SKIPPED).description()
            remedy = f", or raise '{label}'" if exc.limit_exceeded else ""  # no share helps when none maps
            raise QgsProcessingException(f"Mapping failed: {exc}. Nothing written{unchanged}. Repair or remove "
                                         f"the unreadable files{remedy}.") from None
        except ClusterError as exc:
            label = self.parameterDefinition(self.SCHEDULER).description()
            raise QgsProcessingException(f"{label}: {exc}. Nothing written{unchanged}.") from None
        if without_svg:
            feedback.pushWarning(f"{len(without_svg)} of {len(catalogue)} templates have no SVG pictogram (e.g. "
                                 f"{without_svg[0]}): their signs are drawn with a plain marker of their shape and "
                                 "colour")
        if output.kept:
            feedback.pushInfo(f"Kept the other layers of {path}: {', '.join(output.kept)}")
        feedback.pushInfo(f"{len(result.detections)} detections fused into {len(result.signs)} signs, "
                          f"written to {path}" + (f", {len(out.crops)} crops in {crops.folder}" if crops else ""))
        results = {self.OUTPUT: path}
        for key, layer, title in ((self.SIGNS, SIGNS, "Signs"), (self.DETECTIONS, DETECTIONS, "Sign detections")):
            results[key] = layer_uri(path, layer)
            details = QgsProcessingContext.LayerDetails(title, context.project(), key)
            details.setPostProcessor(OutputStyler.create(layer, catalogue, language))
            context.addLayerToLoadOnCompletion(results[key], details)
        return results

    def language(self, parameters, context) -> str:
        return self.chosen_language(parameters, self.LANGUAGE, context) or qgis_language()

    @staticmethod
    def output_context(drive, catalogue, language, result, crops, feedback) -> OutputContext:
        """Language, the drive's clock and, when asked for, the crops written (in the partial folder)."""

        try:
            start = drive_start(drive)
        except DriveFormatError as exc:
            feedback.pushWarning(f"{exc}; timestamps left empty")
            start = None
        written = {}
        if crops is not None:
            feedback.setProgressText(f"Writing {len(result.signs)} sign crops")
            written = crops.write(drive, result.signs, feedback.isCanceled,
                                  feedback.pushWarning)
        return OutputContext(language=language, catalogue=catalogue, start=start, first_time=first_time(drive),
                             crops=written)

    def excluded_ids(self, parameters, context) -> list[str]:
        text = self.parameterAsString(parameters, self.EXCLUDE, context) or ""
        return [t.strip() for t in text.replace(";", ",").split(",") if t.strip()]

    @staticmethod
    def map(drive, catalogue, config, feedback, max_skipped: float = 1.0, fusion=None, workers: int = 0,
            scheduler=None):
        """The core's map_drive with the algorithm's progress bar, cancel button and log.

        ``Cancelled``, ``MappingError`` (too many pairs skipped) and ``ClusterError`` reach the caller, which
        discards its output. ``workers``: processes mapping the pairs (0 = all cores); ``scheduler``: a Dask
        scheduler address instead (the cancel button cancels the cluster's tasks).
        """

        steps = CoreFeedback(feedback, 5, 92)
        result = map_drive(drive, catalogue, config, steps.progress, steps.is_cancelled, steps.warn,
                           fusion=fusion, max_skipped_share=max_skipped, workers=workers, scheduler=scheduler)
        if result.skipped:
            feedback.pushWarning(f"{result.failure_summary()}; see the messages above")
        return result

    @staticmethod
    def write_layers(output: GeoPackageLayers, result, out: OutputContext, feedback=None) -> None:
        """The layers signs (fused signs) and detections (observations), fields as output_schema declares.

        A cancel while writing raises ``Cancelled``, a failed write ``OutputWriteError``; the run's partial
        output is then discarded.
        """
        crs, note = qgis_crs(result.drive.crs)
        if note and feedback is not None:
            feedback.pushInfo(note)
        for layer, items, what in ((SIGNS, result.signs, "traffic signs"),
                                   (DETECTIONS, result.detections, "per-pair sign detections")):
            fields = layer_fields(layer)
            writer = output.open_layer(layer, fields, QgsWkbTypes.PointZ, crs,
                                       abstract=f"Sign Mapper: {what} of drive {result.drive.root}")
            for item in items:
                check_cancelled(feedback.isCanceled if feedback is not None else None, "writing")
                writer.addFeature(layer_feature(fields, layer, item, out), QgsFeatureSink.FastInsert)
            writer.close()
