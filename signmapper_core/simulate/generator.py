"""Driver of a synthetic drive: poses along the street, pair-by-pair rendering, files.

The drive is written as a partial output (``atomic_folder``): moved in when
complete, so a cancelled or failed run leaves no half-written drive; what a
killed run left is removed by the next run writing into the same folder.
Memory stays flat with the length of the drive: only textures near the
vehicle are kept.
"""

from __future__ import annotations

import time
from pathlib import Path
from typing import Callable

import numpy as np

from ..drive.atomic_folder import writing_folder
from ..drive.writer import write_drive_json, write_pair, write_poses_csv, write_truth_csv
from ..geometry import Pose
from ..progress import CancelCheck, ProgressCallback, check_cancelled, report
from . import textures as tx
from .config import WHOLE, SimulationConfig, SimulationSummary
from .faces import FaceOptions, sign_kinds, white_sign_kinds
from .layout import Scene, build_scene
from .rasterizer import Rasterizer, TextureCache
from .realism import apply_effects, draw_effects
from .scene_pieces import LANE_CENTRE
from .sign_mix import POLE, whole_mix
from .street import Street

S_FIRST = 10.0          # street position of the first pair (objects exist behind it)
LOOK_AHEAD_M = 160.0
LOOK_BEHIND_M = 5.0


def _vehicle_positions(config: SimulationConfig) -> np.ndarray:
    """Street position of each pair: the nominal spacing with a slowly varying speed."""
    rng = np.random.default_rng([config.seed, 4])
    n = config.pairs
    wobble = 1.0 + 0.04 * np.sin(np.arange(n) / rng.uniform(8, 15) + rng.uniform(0, 2 * np.pi))
    steps = config.spacing_m * wobble
    return S_FIRST + np.concatenate([[0.0], np.cumsum(steps[:-1])])


def true_poses(config: SimulationConfig, street: Street | None = None) -> list[Pose]:
    """Poses the images are rendered from (the truth behind poses.csv)."""
    street = street or make_street(config)
    s_cam = _vehicle_positions(config)
    rng = np.random.default_rng([config.seed, 5])
    n = len(s_cam)
    t = np.arange(n, dtype=float)
    # slow vehicle attitude wander (degrees) and lane keeping (metres)
    def wander(amp):
        return amp * np.sin(t / rng.uniform(5, 9) + rng.uniform(0, 6.3)) + amp * 0.4 * rng.standard_normal(n)
    yaw, pitch, roll, lateral = wander(0.4), wander(0.25), wander(0.3), wander(0.12)
    poses = []
    for i, s in enumerate(s_cam):
        p = street.point(s, LANE_CENTRE + lateral[i], config.camera_height_m)
        heading = np.degrees(street.heading(s)) + yaw[i]
        pit = np.degrees(np.arctan(street.grade(s))) + pitch[i]
        poses.append(Pose(float(p[0]), float(p[1]), float(p[2]), float(heading % 360.0), float(pit), float(roll[i])))
    return poses


def recorded_poses(config: SimulationConfig, poses: list[Pose]) -> list[Pose]:
    """True poses plus independent GNSS/INS noise per pair with the configured sigmas."""
    rng = np.random.default_rng([config.seed, 6])
    out = []
    for p in poses:
        dp = rng.normal(0.0, config.position_sigma_m, 3) if config.position_sigma_m > 0 else np.zeros(3)
        da = rng.normal(0.0, config.angle_sigma_deg, 3) if config.angle_sigma_deg > 0 else np.zeros(3)
        out.append(Pose(p.easting + dp[0], p.northing + dp[1], p.height + dp[2], (p.heading + da[0]) % 360.0,
                        p.pitch + da[1], p.roll + da[2]))
    return out


def make_street(config: SimulationConfig) -> Street:
    length = S_FIRST + config.spacing_m * 1.05 * config.pairs + LOOK_AHEAD_M + 20.0
    return Street(length, (config.start_easting, config.start_northing, config.start_height),
                  np.random.default_rng([config.seed, 0]))


def make_scene(config: SimulationConfig, street: Street | None = None) -> Scene:
    street = street or make_street(config)
    s_cam = _vehicle_positions(config)
    realism = {"weathering": config.weathering, "shadows": config.shadows, "occlusion": config.occlusion}
    mix = whole_mix() if config.sign_set == WHOLE else None
    kinds = mix.kinds([POLE]) if mix is not None else sign_kinds()
    return build_scene(street, config.seed, float(s_cam[0]), float(s_cam[-1]), config.fx, config.sign_density,
                       config.distractor_density, kinds, realism,
                       FaceOptions.from_config(config), config.plate_share,
                       white_sign_kinds() if config.white_sign_share > 0 else [], config.white_sign_share, mix,
                       config.sign_offset_m, config.right_sign_share)


def right_pose(pose: Pose, baseline_m: float) -> Pose:
    """The right camera: ``baseline_m`` along the left camera's x axis, same orientation."""
    c = pose.centre + pose.rotation[:, 0] * baseline_m
    return Pose(float(c[0]), float(c[1]), float(c[2]), pose.heading, pose.pitch, pose.roll)


def render_pair(config: SimulationConfig, scene: Scene, rasterizer: Rasterizer, pose: Pose, s_cam: float,
                index: int):
    """(left, right, depth) of one pair, effects applied; depth is the left camera's true Z."""
    cam = rasterizer.camera
    surfaces = scene.surfaces_between(s_cam - LOOK_BEHIND_M, s_cam + LOOK_AHEAD_M)
    horizon_v = cam.cy + cam.fy * np.tan(np.radians(pose.pitch))
    # the same clouds all drive long: they are far away and should not flicker from pair to pair
    sky = tx.sky(cam.height, cam.width, horizon_v, cam.fy, np.random.default_rng([config.seed, 8]))
    left, depth = rasterizer.render(surfaces, pose, sky)
    right, _ = rasterizer.render(surfaces, right_pose(pose, config.baseline_m), sky)
    switches = {"exposure_changes": config.exposure_changes, "motion_blur": config.motion_blur,
                "noise": config.noise, "glare": config.glare}
    fx = draw_effects(np.random.default_rng([config.seed, 7, index]), cam.width, cam.height, switches)
    return apply_effects(left, fx, right=False), apply_effects(right, fx, right=True), depth


def generate_drive(out_dir, config: SimulationConfig | None = None,
                   progress: ProgressCallback | None = None,
                   is_cancelled: CancelCheck | None = None,
                   before_commit: Callable[[list], None] | None = None) -> SimulationSummary:
    """Write a synthetic drive (drive-format v1 with truth.csv) into ``out_dir``.

    ``out_dir`` must not exist or be an empty folder. Returns a summary with the
    true poses the images were rendered from. Raises :class:`~signmapper_core.progress.Cancelled` when
    ``is_cancelled()`` turns true; nothing is left behind then.
    ``before_commit(truth)`` is called with the truth signs once every file is
    written, before the drive takes its name: a caller's own outputs (the truth
    layer) are written there, so that when they fail no drive is left either.
    """
    config = config or SimulationConfig()
    config.validate()
    out_dir = Path(out_dir)
    started = time.perf_counter()
    with writing_folder(out_dir) as tmp:
        report(progress, 0.0, "laying out the street")
        street = make_street(config)
        scene = make_scene(config, street)
        camera = config.camera()
        poses = true_poses(config, street)
        noisy = recorded_poses(config, poses)
        s_cam = _vehicle_positions(config)
        write_drive_json(tmp, config.crs, camera, software="Sign Mapper synthetic drive generator",
                         seed=config.seed, vehicle={"speed_kmh": config.speed_kmh, "rate_hz": config.rate_hz,
                                  "camera_height_m": config.camera_height_m})
        cache = TextureCache()
        rasterizer = Rasterizer(camera, cache)
        ids = [f"{i:06d}" for i in range(config.pairs)]
        for i, pose in enumerate(poses):
            check_cancelled(is_cancelled, "synthetic drive")
            left, right, depth = render_pair(config, scene, rasterizer, pose, float(s_cam[i]), i)
            write_pair(tmp, ids[i], left, right, depth if config.write_depth else None,
                       jpeg_quality=config.jpeg_quality)
            cache.evict_before(float(s_cam[i]) - LOOK_BEHIND_M)
            report(progress, (i + 1) / config.pairs, f"pair {i + 1} of {config.pairs}")
        times = [i / config.rate_hz for i in range(config.pairs)]
        write_poses_csv(tmp, zip(ids, times, noisy))
        truth = scene.truth
        write_truth_csv(tmp, truth)
        check_cancelled(is_cancelled, "synthetic drive")
        if before_commit is not None:
            before_commit(truth)
    size = sum(f.stat().st_size for f in out_dir.rglob("*") if f.is_file())
    return SimulationSummary(out_dir=out_dir, pairs=config.pairs, signs=truth, true_poses=poses,
                             recorded_poses=noisy, seconds=time.perf_counter() - started, bytes_written=size,
                             camera=camera, notes={"textures_cached_at_end": len(cache)})
