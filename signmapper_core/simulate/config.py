"""Settings and result of a synthetic drive, kept apart so the CLI, the Processing
algorithm and the tests share one definition of every knob and its default."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from ..drive.reader import TruthSign
from ..geometry import Camera, Pose

WHOLE, DRAWABLE = "whole", "drawable"  # the sign sets of SimulationConfig.sign_set
# Settings that reproduce the drives of before the whole catalogue (2026-12-06), e.g. the seeds tests and figures
# were taken on: only the red, blue and yellow signs the procedural drawer knows (white ones by white_sign_share),
# equally likely, each printed from its master only; ``SimulationConfig(**DRAWABLE_SIGNS)``.
DRAWABLE_SIGNS = dict(sign_set=DRAWABLE, face_variants=False)
# Face settings that reproduce the faces of before the artwork mix: procedural drawings only, no physical
# variation (the older weathering still applies), on the signs of before; e.g. ``SimulationConfig(**LEGACY_FACES)``.
LEGACY_FACES = dict(DRAWABLE_SIGNS, face_artwork="procedural", face_print=False, face_sheeting=False,
                    face_wear=False, face_dirt=False, face_marks=False, face_dents=False, back_mounts=False)


@dataclass
class SimulationConfig:
    """Everything that shapes a synthetic drive; the same config and seed give the same files."""

    pairs: int = 100
    seed: int = 0
    write_depth: bool = False
    # Camera of the rectified normal images.
    width: int = 1920
    height: int = 1080
    fx: float = 1750.0
    baseline_m: float = 0.9
    camera_height_m: float = 2.4          # projection centre above the road
    # Vehicle.
    speed_kmh: float = 40.0
    rate_hz: float = 5.0
    # GNSS/INS noise of the recorded poses (true poses are used for rendering).
    position_sigma_m: float = 0.02
    angle_sigma_deg: float = 0.02
    # Scene content, per 100 m of street.
    # Which signs stand along the street: "whole", every family of the whole catalogue in the proportions of a
    # Swiss street (simulate/sign_mix.py), white ones included; "drawable", the drives of before (DRAWABLE_SIGNS).
    sign_set: str = WHOLE
    sign_density: float = 10.0            # sign poles
    distractor_density: float = 8.0       # cars, cones, shop signs, coloured patches, sign backs
    # Realism switches.
    noise: bool = True
    motion_blur: bool = True
    exposure_changes: bool = True
    shadows: bool = True
    weathering: bool = True               # faded and dirty sign faces
    occlusion: bool = True                # branches and poles in front of some signs
    glare: bool = True
    jpeg_quality: int = 90
    # Sign faces (simulate/faces.py): the artwork each face is printed from, and physical variation of the
    # sign in face texture space, each switchable and with a seeded random strength per sign.
    face_artwork: str = "mixed"           # "mixed": master image or procedural variant per sign; "procedural"
    master_share: float = 0.7             # share of faces printed from the catalogue master when "mixed"
    face_variants: bool = True            # a master face shows any of the entry's drawings (languages, directions)
    face_print: bool = True               # print run: ink hue/saturation, line weight, black-layer register
    face_sheeting: bool = True            # reflective film: seal cells, sparkle, sheen, specular hot spot
    face_wear: bool = True                # UV ageing: red to orange/pink, chalky blue, contrast loss, peeling
    face_dirt: bool = True                # grime from the bottom, spots, rain streaks
    face_marks: bool = True               # stickers and graffiti tags
    face_dents: bool = True               # dents and bends (mild non-planar warp)
    back_mounts: bool = True              # mounting rails and pole clamps on the backs of panels
    # Supplementary plates (simulate/plate_layout.py): share of sign poles whose lowest sign carries one, with
    # a text in German, French or Italian; > 0 also puts white text plates on façades as distractors.
    plate_share: float = 0.5
    # With sign_set "drawable": white and grey signs (end-of-restriction discs, end-of-zone panels): share of the
    # sign poles that carry them instead of coloured signs; > 0 also adds white distractors (white shop signs,
    # white vans, white emblems). 0 keeps every drive of before as it was. The whole catalogue has its own share.
    white_sign_share: float = 0.0
    # Wide streets (simulate/wide_street.py): lateral distance [m] of each sign spot's first sign from the vehicle's
    # track, drawn uniformly in this range, the spot moved sideways as a whole and the façades set back behind the
    # farthest; None: the signs stand at the kerb as before. right_sign_share: share of the spots on the right of
    # the street (None: sign_mounts.RIGHT_SIDE_SHARE). Both None, every drive of before stays as it was.
    sign_offset_m: tuple[float, float] | None = None
    right_sign_share: float | None = None
    # Georeference.
    crs: str = "EPSG:2056"
    start_easting: float = 2600000.0
    start_northing: float = 1200000.0
    start_height: float = 400.0

    @property
    def spacing_m(self) -> float:
        """Distance driven between two pairs."""
        return self.speed_kmh / 3.6 / self.rate_hz

    def camera(self) -> Camera:
        return Camera(width=int(self.width), height=int(self.height), fx=float(self.fx), fy=float(self.fx),
                      cx=(self.width - 1) / 2.0, cy=(self.height - 1) / 2.0, baseline_m=float(self.baseline_m))

    def validate(self) -> None:
        """Reject settings that cannot give a drive, with a message naming the setting."""
        checks = [
            (self.pairs >= 1, "pairs must be at least 1"),
            (self.width >= 64 and self.height >= 64, "width and height must be at least 64 pixels"),
            (self.fx > 0, "fx must be positive"),
            (self.baseline_m > 0, "baseline_m must be positive"),
            (self.speed_kmh > 0 and self.rate_hz > 0, "speed_kmh and rate_hz must be positive"),
            (self.position_sigma_m >= 0 and self.angle_sigma_deg >= 0, "pose noise sigmas must not be negative"),
            (self.sign_density >= 0 and self.distractor_density >= 0, "densities must not be negative"),
            (1 <= self.jpeg_quality <= 100, "jpeg_quality must be within 1..100"),
            (self.face_artwork in ("mixed", "procedural"), "face_artwork must be 'mixed' or 'procedural'"),
            (0.0 <= self.master_share <= 1.0, "master_share must be within 0..1"),
            (0.0 <= self.plate_share <= 1.0, "plate_share must be within 0..1"),
            (0.0 <= self.white_sign_share <= 1.0, "white_sign_share must be within 0..1"),
            (self.sign_offset_m is None or 0.0 <= self.sign_offset_m[0] <= self.sign_offset_m[1],
             "sign_offset_m must be (min, max) with 0 <= min <= max"),
            (self.right_sign_share is None or 0.0 <= self.right_sign_share <= 1.0,
             "right_sign_share must be within 0..1"),
            (self.sign_set in (WHOLE, DRAWABLE), f"sign_set must be {WHOLE!r} or {DRAWABLE!r}"),
            (self.sign_set == DRAWABLE or self.white_sign_share == 0.0,
             f"white_sign_share applies to sign_set {DRAWABLE!r}: the whole catalogue places white signs in its "
             "own share"),
        ]
        for ok, message in checks:
            if not ok:
                raise ValueError(message)


@dataclass
class SimulationSummary:
    """What :func:`generate_drive` wrote, with the true poses the images were rendered from."""

    out_dir: Path
    pairs: int
    signs: list[TruthSign]
    true_poses: list[Pose]
    recorded_poses: list[Pose]
    seconds: float
    bytes_written: int
    camera: Camera
    notes: dict = field(default_factory=dict)
