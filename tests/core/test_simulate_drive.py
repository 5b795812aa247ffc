"""A small synthetic drive checked against its own ground truth: format, truth, depth, poses."""

from __future__ import annotations

import cv2
import numpy as np
import pytest

from signmapper_core.catalogue import load_catalogue
from signmapper_core.drive.reader import open_drive
from signmapper_core.geometry import world_to_pixel
from signmapper_core.plates.formats import PLATE_FORMATS
from signmapper_core.simulate import DRAWABLE_SIGNS, SimulationConfig, generate_drive, true_poses
from signmapper_core.simulate.generator import right_pose

HUE_RANGES = {"red": [(0, 10), (170, 180)], "blue": [(100, 130)], "yellow": [(18, 35)]}


def small_config(**kw) -> SimulationConfig:
    base = dict(pairs=10, seed=3, width=640, height=360, fx=1750.0 / 3, sign_density=25.0, write_depth=True,
                **DRAWABLE_SIGNS)  # red, blue and yellow signs (the whole catalogue's drive: test_simulate_sign_mix)
    base.update(kw)
    return SimulationConfig(**base)


@pytest.fixture(scope="module")
def drive(tmp_path_factory):
    out = tmp_path_factory.mktemp("sim") / "drive"
    summary = generate_drive(out, small_config())
    return summary, open_drive(out)


def colour_fraction(bgr: np.ndarray, colour: str) -> float:
    hsv = cv2.cvtColor(bgr, cv2.COLOR_BGR2HSV)
    mask = np.zeros(hsv.shape[:2], bool)
    for lo, hi in HUE_RANGES[colour]:
        mask |= (hsv[..., 0] >= lo) & (hsv[..., 0] <= hi)
    mask &= (hsv[..., 1] >= 90) & (hsv[..., 2] >= 50)
    return float(mask.mean())


def test_written_drive_opens_with_truth_right_images_and_depth(drive):
    summary, d = drive
    assert len(d) == 10
    assert d.camera == summary.camera
    assert d.crs == "EPSG:2056"
    assert all(rec.right_path is not None and rec.depth_path is not None for rec in d.pairs)
    assert d.truth and len(d.truth) == len(summary.signs) >= 3
    assert len({t.sign_id for t in d.truth}) == len(d.truth)
    left = d.load_left(d.pairs[0])
    assert left.shape == (360, 640, 3) and left.dtype == np.uint8
    depth = d.load_depth(d.pairs[0])
    assert np.isnan(depth[0]).mean() > 0.2          # sky at the top
    assert np.isfinite(depth[-1]).all()             # road at the bottom
    assert 5.0 < np.nanmin(depth[-1]) < 12.0        # 2.4 m high camera: road from ~8 m


def test_truth_names_the_artwork_each_face_was_printed_from(drive):
    _summary, d = drive
    signs = [t for t in d.truth if not t.is_plate]
    assert signs and all(t.artwork in ("master", "procedural") for t in signs)
    assert all(t.artwork == "" for t in d.truth if t.is_plate)  # a plate is drawn by plate_faces, no artwork mix
    header = (d.root / "truth.csv").read_text(encoding="utf-8").splitlines()[0]
    assert header.endswith(",face_artwork")


def test_truth_uses_catalogue_sizes_and_sign_colours(drive):
    summary, d = drive
    catalogue = load_catalogue()
    for sign in d.truth:
        if sign.is_plate:  # supplementary plates: as wide as a plate format, drawings at their aspect
            assert sign.plate_of and max(sign.width_m, sign.height_m) in {w for w, _ in PLATE_FORMATS.values()}
            continue
        entry = catalogue[sign.template_id]
        assert entry.colour in ("red", "blue", "yellow")
        assert any(abs(w - sign.width_m) < 1e-3 and abs(h - sign.height_m) < 1e-3 for w, h in entry.formats.values())


def test_truth_centres_project_onto_sign_pixels(drive):
    summary, d = drive
    catalogue = load_catalogue()
    checks, hits, depth_hits = 0, 0, 0
    for rec, pose in zip(d.pairs, summary.true_poses):
        img = d.load_left(rec)
        depth = d.load_depth(rec)
        for sign in d.truth:
            u, v, z = world_to_pixel(d.camera, pose, sign.position)
            if not (4.0 <= z <= 14.0 and 10 <= u < d.camera.width - 10 and 10 <= v < d.camera.height - 10):
                continue
            r = max(2, int(0.4 * d.camera.fx * min(sign.width_m, sign.height_m) / z))
            ui, vi = int(round(float(u))), int(round(float(v)))
            window = img[max(0, vi - r):vi + r + 1, max(0, ui - r):ui + r + 1]
            checks += 1
            if sign.is_plate:  # white, with black text
                hits += float(np.median(window)) > 150
            else:
                hits += colour_fraction(window, catalogue[sign.template_id].colour) > 0.1
            depth_hits += abs(float(depth[vi, ui]) - float(z)) < 0.05
    assert checks >= 5
    assert hits >= 0.8 * checks
    assert depth_hits >= 0.8 * checks


def test_depth_agrees_with_right_image_disparity(drive):
    """Block matching of textured patches finds them at d = fx * B / Z in the right image."""
    summary, d = drive
    rng = np.random.default_rng(1)
    errors = []
    for rec in d.pairs[::2]:
        left = cv2.cvtColor(d.load_left(rec), cv2.COLOR_BGR2GRAY).astype(np.float32)
        right = cv2.cvtColor(d.load_right(rec), cv2.COLOR_BGR2GRAY).astype(np.float32)
        depth = d.load_depth(rec)
        grad = np.abs(cv2.Sobel(left, cv2.CV_32F, 1, 0, ksize=3))
        half = 7
        for _ in range(1500):
            u = int(rng.integers(80, d.camera.width - half - 1))
            v = int(rng.integers(half, d.camera.height - half))
            zpatch = depth[v - half:v + half + 1, u - half:u + half + 1]
            if not np.isfinite(zpatch).all() or not (3.0 < depth[v, u] < 40.0):
                continue
            if np.ptp(zpatch) > 0.03 * depth[v, u] or grad[v - half:v + half + 1, u - half:u + half + 1].mean() < 20:
                continue
            disp = d.camera.fx * d.camera.baseline_m / float(depth[v, u])
            patch = left[v - half:v + half + 1, u - half:u + half + 1]
            best, best_cost = None, np.inf
            for shift in np.arange(-4, 5):
                x = int(round(u - disp)) + shift
                if x - half < 0:
                    continue
                cand = right[v - half:v + half + 1, x - half:x + half + 1]
                cost = float(np.abs((cand - cand.mean()) - (patch - patch.mean())).mean())
                if cost < best_cost:
                    best, best_cost = x - (u - disp), cost
            if best is not None:
                errors.append(best)
            if len(errors) >= 200:
                break
    errors = np.abs(np.array(errors))
    assert len(errors) >= 60
    assert np.median(errors) <= 0.6
    assert (errors <= 1.0).mean() >= 0.85


def test_recorded_poses_are_true_poses_plus_small_noise(drive):
    summary, d = drive
    assert [p for p in summary.true_poses] == true_poses(small_config())
    for rec, true in zip(d.pairs, summary.true_poses):
        assert np.linalg.norm(rec.pose.centre - true.centre) < 0.02 * 6
        assert abs((rec.pose.heading - true.heading + 180) % 360 - 180) < 0.02 * 6
        assert rec.pose.centre[2] - true.centre[2] != 0.0


def test_right_camera_sits_baseline_along_left_x_axis():
    pose = true_poses(small_config())[2]
    right = right_pose(pose, 0.9)
    xc = pose.world_to_camera(right.centre)
    assert np.allclose(xc, [0.9, 0.0, 0.0], atol=1e-9)
    assert np.allclose(right.rotation, pose.rotation)
