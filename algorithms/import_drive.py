"""``signmapper:importdrive``: a survey's stereo images, calibration and poses as a drive folder."""

from __future__ import annotations

from pathlib import Path

from qgis.core import (
    QgsProcessingException,
    QgsProcessingOutputNumber,
    QgsProcessingParameterFile,
    QgsProcessingParameterFileDestination,
    QgsProcessingParameterFolderDestination,
    QgsProcessingParameterNumber,
    QgsProcessingParameterString,
)

from ..signmapper_core.errors import DriveFormatError, ImportInputError
from ..signmapper_core.progress import Cancelled
from .base import CoreFeedback, SignMapperAlgorithm

PRESETS = (("generic", "Generic: image folders, calibration file, pose CSV"), ("kitti", "KITTI raw drive folder"))
KITTI_CAMERAS = (("colour", "Colour cameras (image_02 left, image_03 right)"),
                 ("grey", "Grey cameras (image_00 left, image_01 right)"))
POSE_KINDS = (("per_image", "One row per image (exterior orientation, matched by image id)"),
              ("trajectory", "Trajectory (time-stamped, interpolated to the image times)"))
CONVENTION_NAMES = ("ned_ypr", "enu_ypr", "opk", "camera_hpr")
UNITS = (("deg", "Degrees"), ("rad", "Radians"))
NORTHS = (("auto", "Automatic (navigation angles: true north; a camera's angles: the grid of a projected input CRS)"),
          ("true", "True north"), ("grid", "Grid north of the input CRS"))
IMAGE_FORMATS = (("auto", "Automatic (normal images kept as they are, rectified ones as JPEG)"), ("jpg", "JPEG"),
                 ("png", "PNG"))


class ImportDriveAlgorithm(SignMapperAlgorithm):
    NAME = "importdrive"
    DISPLAY_NAME = "Import drive"
    GROUP_ID = "tools"
    ICON = "import_drive.svg"
    HELP = (
        "Builds a drive folder (stereo-drive/1) from what a survey vehicle records: left and right images (raw, "
        "i.e. distorted and slightly convergent, or already rectified), a stereo calibration and the poses of the "
        "navigation system or a photogrammetric exterior orientation. Raw pairs are undistorted and rectified into "
        "normal images with OpenCV (stereoRectify, initUndistortRectifyMap, remap); the poses are turned into the "
        "left normal image's heading, pitch and roll in the output CRS: angle convention, lever arm and boresight "
        "to the left camera, grid convergence and heights by pyproj. Before any image is written, the inputs are "
        "checked (image size against the calibration, poses against the image times, a CRS without metres, and the "
        "angles against the direction of travel: radians given as degrees, or a wrong angle convention, stop the "
        "import naming the unit or convention that fits; a vehicle standing still is a warning) and the first pair "
        "is rectified and its rows checked: the mean vertical disparity of matched features must stay below the "
        "limit ('Largest mean vertical disparity'). "
        "A failed or cancelled import leaves no folder behind. Preview the result with Drive trajectory, then map it "
        "with Map traffic signs. The KITTI preset reads a KITTI raw drive folder (images, OXTS poses, calibration "
        "files) by itself; given a date or download folder instead of a drive folder, it names the drive folders "
        "inside. In qgis_process every choice takes its number or its name, e.g. PRESET=kitti ANGLES=enu_ypr."
    )

    PRESET = "PRESET"
    KITTI_FOLDER = "KITTI_FOLDER"
    KITTI_CAMERAS = "KITTI_CAMERAS"
    LEFT = "LEFT"
    RIGHT = "RIGHT"
    LEFT_PATTERN = "LEFT_PATTERN"
    RIGHT_PATTERN = "RIGHT_PATTERN"
    CALIBRATION = "CALIBRATION"
    POSES = "POSES"
    POSES_KIND = "POSES_KIND"
    IMAGE_TIMES = "IMAGE_TIMES"
    ANGLES = "ANGLES"
    ANGLE_UNIT = "ANGLE_UNIT"
    NORTH = "NORTH"
    INPUT_CRS = "INPUT_CRS"
    OUTPUT_CRS = "OUTPUT_CRS"
    LEVER = ("LEVER_X", "LEVER_Y", "LEVER_Z")
    BORESIGHT = ("BORESIGHT_HEADING", "BORESIGHT_PITCH", "BORESIGHT_ROLL")
    IMAGE_FORMAT = "IMAGE_FORMAT"
    JPEG_QUALITY = "JPEG_QUALITY"
    MAX_VERTICAL_DISPARITY = "MAX_VERTICAL_DISPARITY"
    OUTPUT = "OUTPUT"
    CHECK_IMAGE = "CHECK_IMAGE"
    PAIRS = "PAIRS"
    VERTICAL_DISPARITY = "VERTICAL_DISPARITY"

    def initAlgorithm(self, config=None):  # noqa: N802
        from ..signmapper_core.importdrive import GenericInputs, ImportOptions  # delays numpy until used
        from ..signmapper_core.importdrive.attitude import CONVENTIONS  # delays numpy until used

        folder, file = QgsProcessingParameterFile.Folder, QgsProcessingParameterFile.File
        number = QgsProcessingParameterNumber
        self.add_parameter(self.named_enum(self.PRESET, "What to import", PRESETS, defaultValue=0),
                           "Generic: name the image folders, the calibration file and the pose CSV below. KITTI: "
                           "name a KITTI raw drive folder; images, poses and calibration are found in it.")
        self.add_parameter(QgsProcessingParameterFile(self.KITTI_FOLDER, self.tr("KITTI drive folder"), folder,
                                                      optional=True),
                           "KITTI preset only: a KITTI raw drive folder such as 2011_09_26_drive_0001_sync (rectified "
                           "images) or ..._extract (raw images), with image_02/, image_03/, oxts/; the calib_*.txt "
                           "files in it or in the date folder above.")
        self.add_parameter(self.named_enum(self.KITTI_CAMERAS, "KITTI cameras", KITTI_CAMERAS, defaultValue=0),
                           "KITTI preset only: the colour or the grey stereo pair.", advanced=True)
        self.add_parameter(QgsProcessingParameterFile(self.LEFT, self.tr("Left images folder"), folder,
                                                      optional=True),
                           "Folder of the left camera's images (JPEG, PNG, TIFF, BMP). Without a pattern every image "
                           "is taken and its id is its file name without suffix.")
        self.add_parameter(QgsProcessingParameterFile(self.RIGHT, self.tr("Right images folder"), folder,
                                                      optional=True),
                           "Folder of the right images with the same ids. Leave empty when both are in the left "
                           "folder and the patterns tell them apart.")
        self.add_parameter(QgsProcessingParameterString(self.LEFT_PATTERN, self.tr("Left file name pattern"), "",
                                                        optional=True),
                           "Optional: file names of the left images with one '*' standing for the image id, e.g. "
                           "*_L.jpg (then 0001_L.jpg is image 0001).", advanced=True)
        self.add_parameter(QgsProcessingParameterString(self.RIGHT_PATTERN, self.tr("Right file name pattern"), "",
                                                        optional=True),
                           "Optional: file names of the right images, e.g. *_R.jpg.", advanced=True)
        self.add_parameter(QgsProcessingParameterFile(
            self.CALIBRATION, self.tr("Stereo calibration"), file, optional=True,
            fileFilter="Calibration (*.yml *.yaml *.xml *.json *.txt);;All files (*)"),
            "OpenCV YAML/XML/JSON with K1, D1, K2, D2, R, T as cv2.stereoCalibrate gives them (X_right = R X_left + "
            "T, T in metres) and the image size (image_width/image_height); KITTI's calib_cam_to_cam.txt; or, for "
            "pairs that are rectified already, a JSON/YAML pinhole: fx, fy, cx, cy, baseline_m, width, height.")
        self.add_parameter(QgsProcessingParameterFile(self.POSES, self.tr("Poses (CSV)"), file, optional=True,
                                                      fileFilter="Text tables (*.csv *.txt);;All files (*)"),
                           "Delimited text with a header (comma, semicolon, tab or spaces). Columns by name: id (or "
                           "image, name; per-image tables), time (trajectories), x/easting/lon/longitude, "
                           "y/northing/lat/latitude, z/height/alt, and the three angles of the convention "
                           "(yaw/heading, pitch, roll or omega, phi, kappa).")
        self.add_parameter(self.named_enum(self.POSES_KIND, "Poses are", POSE_KINDS, defaultValue=0),
                           "One row per image, whose id column names the image (id, file name or file name without "
                           "suffix); or a trajectory whose rows are interpolated to each image's time (positions "
                           "linearly, orientations along the shortest turn; epochs at most 1 s apart).")
        self.add_parameter(QgsProcessingParameterFile(self.IMAGE_TIMES, self.tr("Image times (CSV)"), file,
                                                      optional=True,
                                                      fileFilter="Text tables (*.csv *.txt);;All files (*)"),
                           "For a trajectory: a table with id and time of every image, on the trajectory's clock. "
                           "Every image time must lie within the trajectory.")
        self.add_parameter(self.named_enum(self.ANGLES, "Angle convention",
                                           [(n, CONVENTIONS[n].title) for n in CONVENTION_NAMES], defaultValue=0),
                           "How the three angles are defined. Navigation NED: heading clockwise from north, pitch "
                           "nose up, roll right side down (body x forward, y right, z down). Navigation ENU (KITTI, "
                           "ROS): yaw counter-clockwise from east, pitch nose down, roll left side up (x forward, y "
                           "left, z up). Omega/phi/kappa: R = Rx(omega) Ry(phi) Rz(kappa), camera looking along -z "
                           "(omega 90 = looking north, level). Camera heading/pitch/roll: as in poses.csv of a drive. "
                           "The body's forward direction must follow the direction of travel (median over the moving "
                           "epochs): when it misses it and another convention follows it, the import stops naming that "
                           "one; a vehicle standing still cannot be checked (a warning).")
        self.add_parameter(self.named_enum(self.ANGLE_UNIT, "Angle unit", UNITS, defaultValue=0),
                           "Unit of the angles in the pose table. Degrees that behave like radians (the forward "
                           "direction misses the direction of travel) stop the import with a message.")
        self.add_parameter(self.named_enum(self.NORTH, "Angles are against", NORTHS, defaultValue=0),
                           "True north (what an INS gives) or the grid north of a projected input CRS (what "
                           "photogrammetric software gives in a projected CRS). The output grid's convergence is "
                           "applied either way.", advanced=True)
        self.add_parameter(QgsProcessingParameterString(self.INPUT_CRS, self.tr("CRS of the poses"),
                                                        GenericInputs.input_crs),
                           "Any CRS PROJ knows, geographic (x = longitude) or projected. Say what the heights are: "
                           "EPSG:4979 = WGS 84 with ellipsoidal heights, EPSG:4326+5773 = with EGM96 heights, "
                           "EPSG:2056+5728 = LV95 with LN02 heights. A CRS without heights keeps them as given.")
        self.add_parameter(QgsProcessingParameterString(self.OUTPUT_CRS, self.tr("CRS of the drive"), "",
                                                        optional=True),
                           "Projected CRS in metres for the drive, e.g. EPSG:2056 (LV95) or EPSG:2056+5728 (LV95 with "
                           "LN02 heights; needs swisstopo's geoid grid in PROJ). "
                           f"Empty: {ImportOptions.output_crs}, or for KITTI the UTM zone with EGM96 heights.")
        for name, axis in zip(self.LEVER, ("x", "y", "z")):
            self.add_parameter(number(name, self.tr(f"Lever arm {axis} [m]"), number.Double, 0.0),
                               f"Position of the left camera's projection centre relative to the body whose poses "
                               f"are given, along the body's {axis} axis (the axes of the angle convention: NED "
                               f"x forward, y right, z down; ENU x forward, y left, z up; camera conventions the "
                               f"camera's axes).")
        for name, angle, text in zip(self.BORESIGHT, ("heading", "pitch", "roll"),
                                     ("positive turns the camera to the right", "positive tilts it up",
                                      "positive turns it clockwise as seen from behind")):
            self.add_parameter(number(name, self.tr(f"Boresight {angle} [°]"), number.Double, 0.0,
                                      minValue=-360.0, maxValue=360.0),
                               f"Camera {angle} relative to the body ({text}); 0, 0, 0 = the camera looks along the "
                               f"body's forward axis (for camera conventions: along the recorded camera's axis).")
        self.add_parameter(self.named_enum(self.IMAGE_FORMAT, "Image format of the drive", IMAGE_FORMATS,
                                           defaultValue=0),
                           "Automatic keeps normal images (already rectified JPEG/PNG/TIFF) byte for byte and writes "
                           "rectified ones as JPEG.", advanced=True)
        self.add_parameter(number(self.JPEG_QUALITY, self.tr("JPEG quality"), number.Integer,
                                  ImportOptions.jpeg_quality, minValue=50, maxValue=100),
                           "Quality of JPEG images written by the import.", advanced=True)
        self.add_parameter(number(self.MAX_VERTICAL_DISPARITY, self.tr("Largest mean vertical disparity [px]"),
                                  number.Double, ImportOptions.max_vertical_disparity_px, minValue=0.01,
                                  maxValue=50.0),
                           "The rows of the first pair must line up after rectification: the mean absolute vertical "
                           "disparity of its matched features must stay below this, or the import stops.",
                           advanced=True)
        self.add_parameter(QgsProcessingParameterFolderDestination(self.OUTPUT, self.tr("Drive folder")),
                           "Folder to write the drive into; it must not exist yet or be empty.")
        self.add_parameter(QgsProcessingParameterFileDestination(self.CHECK_IMAGE, self.tr("Epipolar check image"),
                                                                 "PNG image (*.png)", optional=True,
                                                                 createByDefault=False),
                           "Optional PNG of the first pair side by side with rows through matched features: both "
                           "ends of each line must sit on the same feature.")
        self.addOutput(QgsProcessingOutputNumber(self.PAIRS, self.tr("Stereo pairs written")))
        self.addOutput(QgsProcessingOutputNumber(self.VERTICAL_DISPARITY,
                                                 self.tr("Mean vertical disparity of the first pair [px]")))

    def check_inputs(self, parameters, context) -> None:
        """Every input read and checked before the run: folders, calibration, poses, CRSs, outputs."""
        self.settings(parameters, context)

    def settings(self, parameters, context, check: bool = True):
        """(DriveSource, ImportOptions, output folder) of the parameters; QgsProcessingException says what is wrong.

        ``check``: also compute the poses (quick, no pixels) so that their errors show before the run.
        """
        self.require_dependencies()
        # delays numpy until used
        from ..signmapper_core.importdrive import GenericInputs, ImportOptions, Orientation, generic_source
        from ..signmapper_core.importdrive.importer import plan_import  # delays numpy until used
        from ..signmapper_core.importdrive.kitti import is_kitti_drive, kitti_source, utm_crs  # delays numpy

        self.check_outputs(parameters, context)
        kitti = self.chosen_name(parameters, self.PRESET, context) == "kitti"
        string = self.parameterAsString
        try:
            if kitti:
                folder = self.parameterAsFile(parameters, self.KITTI_FOLDER, context)
                if not folder:
                    raise QgsProcessingException("The KITTI preset needs the KITTI drive folder.")
                cameras = self.chosen_name(parameters, self.KITTI_CAMERAS, context)
                source = kitti_source(folder, cameras)
                output_crs = string(parameters, self.OUTPUT_CRS, context).strip() or utm_crs(source)
            else:
                needed = {self.LEFT: "the left images folder", self.CALIBRATION: "the stereo calibration",
                          self.POSES: "the poses"}
                missing = [text for name, text in needed.items() if not self.parameterAsFile(parameters, name, context)]
                left = self.parameterAsFile(parameters, self.LEFT, context)
                given = [f for f in (left, self.parameterAsFile(parameters, self.KITTI_FOLDER, context)) if f]
                kitti_folder = next((f for f in given if is_kitti_drive(f)), None)
                if kitti_folder and (missing or kitti_folder == left):
                    raise QgsProcessingException(self.kitti_preset_hint(kitti_folder))
                if missing:
                    raise QgsProcessingException(f"A generic import needs {', '.join(missing)}.")
                trajectory = self.chosen_name(parameters, self.POSES_KIND, context) == "trajectory"
                times = self.parameterAsFile(parameters, self.IMAGE_TIMES, context)
                if trajectory and not times:
                    raise QgsProcessingException("A trajectory is interpolated to the image times: give the image "
                                                 "times (a CSV with id and time).")
                source = generic_source(GenericInputs(
                    left=Path(self.parameterAsFile(parameters, self.LEFT, context)),
                    right=Path(r) if (r := self.parameterAsFile(parameters, self.RIGHT, context)) else None,
                    left_pattern=string(parameters, self.LEFT_PATTERN, context).strip(),
                    right_pattern=string(parameters, self.RIGHT_PATTERN, context).strip(),
                    calibration=Path(self.parameterAsFile(parameters, self.CALIBRATION, context)),
                    poses=Path(self.parameterAsFile(parameters, self.POSES, context)),
                    trajectory=trajectory, image_times=Path(times) if times else None,
                    orientation=Orientation(
                        self.chosen_name(parameters, self.ANGLES, context),
                        self.chosen_name(parameters, self.ANGLE_UNIT, context),
                        self.chosen_name(parameters, self.NORTH, context)),
                    input_crs=string(parameters, self.INPUT_CRS, context).strip(),
                    lever_arm_m=tuple(self.parameterAsDouble(parameters, n, context) for n in self.LEVER),
                    boresight_deg=tuple(self.parameterAsDouble(parameters, n, context) for n in self.BORESIGHT)))
                output_crs = string(parameters, self.OUTPUT_CRS, context).strip() or ImportOptions.output_crs
            check_image = self.parameterAsFileOutput(parameters, self.CHECK_IMAGE, context)
            options = ImportOptions(
                output_crs=output_crs,
                image_format=self.chosen_name(parameters, self.IMAGE_FORMAT, context),
                jpeg_quality=self.parameterAsInt(parameters, self.JPEG_QUALITY, context),
                max_vertical_disparity_px=self.parameterAsDouble(parameters, self.MAX_VERTICAL_DISPARITY, context),
                check_image=Path(check_image) if check_image else None)
            if check:  # the poses against the images, the CRSs, the calibration against the first image's size
                plan_import(source, options, all_headers=False)
        except (ImportInputError, ValueError, OSError) as exc:
            raise QgsProcessingException(f"Import drive: {exc}") from exc
        return source, options, self.parameterAsString(parameters, self.OUTPUT, context)

    def kitti_preset_hint(self, folder: str) -> str:
        """What to do with a KITTI drive folder given to the generic import, in the dialog's and qgis_process's
        words."""
        preset, kitti_folder = (self.parameterDefinition(n).description() for n in (self.PRESET, self.KITTI_FOLDER))
        name, title = PRESETS[1]
        return (f"{folder} is a KITTI raw drive folder, which the generic import does not read: set '{preset}' to "
                f"'{title}' ({self.PRESET}={name} in qgis_process) and give the folder as '{kitti_folder}' "
                f"({self.KITTI_FOLDER}).")

    def process(self, parameters, context, feedback):
        source, options, out_dir = self.settings(parameters, context, check=False)
        from ..signmapper_core.importdrive import import_drive  # delays numpy until used

        feedback.pushInfo(f"Importing {source.label}: {len(source.pairs)} pairs into {out_dir} ({options.output_crs})")
        steps = CoreFeedback(feedback)
        try:
            summary = import_drive(out_dir, source, options, progress=steps.progress,
                                   is_cancelled=steps.is_cancelled, warn=steps.warn)
        except Cancelled:
            raise QgsProcessingException("Cancelled; no drive written.") from None
        except (ImportInputError, DriveFormatError, ValueError, OSError) as exc:
            raise QgsProcessingException(f"Import drive: {exc}") from exc
        camera = summary.camera
        feedback.pushInfo(
            f"{summary.pairs} pairs written in {summary.seconds:.1f} s "
            f"({'rectified by the import' if summary.resampled else 'normal images kept'}); camera "
            f"{camera.width}x{camera.height}, fx {camera.fx:.2f} px, principal point ({camera.cx:.2f}, "
            f"{camera.cy:.2f}), baseline {camera.baseline_m:.4f} m. First pair: {summary.check.text()}.")
        results = {self.OUTPUT: out_dir, self.PAIRS: summary.pairs,
                   self.VERTICAL_DISPARITY: summary.check.mean_abs_dy}
        if options.check_image is not None:
            results[self.CHECK_IMAGE] = str(options.check_image)
        return results
