"""Generator runs: determinism, cancellation, pose noise statistics, the command line."""

from __future__ import annotations

import hashlib

import numpy as np
import pytest

from signmapper_core.drive.reader import open_drive
from signmapper_core.simulate import Cancelled, SimulationConfig, generate_drive, recorded_poses, true_poses
from signmapper_core.simulate.__main__ import main


def tiny(**kw) -> SimulationConfig:
    base = dict(pairs=3, seed=11, width=320, height=180, fx=1750.0 / 6)
    base.update(kw)
    return SimulationConfig(**base)


def file_hashes(root) -> dict[str, str]:
    return {str(p.relative_to(root)): hashlib.sha256(p.read_bytes()).hexdigest()
            for p in sorted(root.rglob("*")) if p.is_file()}


def test_same_seed_gives_identical_files_and_another_seed_does_not(tmp_path):
    generate_drive(tmp_path / "a", tiny(write_depth=True))
    generate_drive(tmp_path / "b", tiny(write_depth=True))
    generate_drive(tmp_path / "c", tiny(write_depth=True, seed=12))
    a, b, c = (file_hashes(tmp_path / n) for n in "abc")
    assert a == b
    assert sorted(a) == sorted(c)
    assert a["left/000000.jpg"] != c["left/000000.jpg"]
    assert a["poses.csv"] != c["poses.csv"]


def test_cancel_leaves_no_output_and_no_partial_folder(tmp_path):
    calls = []

    def cancel_after_two():
        calls.append(1)
        return len(calls) > 2

    with pytest.raises(Cancelled):
        generate_drive(tmp_path / "drive", tiny(pairs=5), is_cancelled=cancel_after_two)
    assert list(tmp_path.iterdir()) == []


def test_refuses_to_overwrite_a_non_empty_folder(tmp_path):
    (tmp_path / "drive").mkdir()
    (tmp_path / "drive" / "keep.txt").write_text("x")
    with pytest.raises(FileExistsError):
        generate_drive(tmp_path / "drive", tiny())
    assert (tmp_path / "drive" / "keep.txt").exists()


def test_progress_reaches_one(tmp_path):
    seen = []
    generate_drive(tmp_path / "drive", tiny(), progress=lambda f, m: seen.append((f, m)))
    fractions = [f for f, _m in seen]
    assert fractions == sorted(fractions) and fractions[-1] == 1.0


@pytest.mark.parametrize("pos_sigma, ang_sigma", [(0.02, 0.02), (0.1, 0.05)])
def test_recorded_pose_noise_has_the_configured_sigma(pos_sigma, ang_sigma):
    cfg = SimulationConfig(pairs=1500, seed=5, position_sigma_m=pos_sigma, angle_sigma_deg=ang_sigma)
    truth = true_poses(cfg)
    noisy = recorded_poses(cfg, truth)
    dp = np.array([n.centre - t.centre for n, t in zip(noisy, truth)])
    da = np.array([[(n.heading - t.heading + 180) % 360 - 180, n.pitch - t.pitch, n.roll - t.roll]
                   for n, t in zip(noisy, truth)])
    assert np.allclose(dp.std(axis=0), pos_sigma, rtol=0.12)
    assert np.allclose(da.std(axis=0), ang_sigma, rtol=0.12)
    assert np.all(np.abs(dp.mean(axis=0)) < 4 * pos_sigma / np.sqrt(len(dp)))
    # independent per pair: no correlation between consecutive pairs
    assert abs(np.corrcoef(dp[:-1, 0], dp[1:, 0])[0, 1]) < 0.1


def test_true_poses_follow_the_drive_spacing():
    cfg = SimulationConfig(pairs=50, seed=2)
    poses = true_poses(cfg)
    steps = np.linalg.norm(np.diff([p.centre for p in poses], axis=0), axis=1)
    assert np.all(np.abs(steps - cfg.spacing_m) < 0.15 * cfg.spacing_m)
    assert abs(cfg.spacing_m - 40 / 3.6 / 5) < 1e-9
    assert np.all(np.abs([p.pitch for p in poses]) < 5) and np.all(np.abs([p.roll for p in poses]) < 2)


def test_command_line_writes_a_drive(tmp_path, capsys):
    out = tmp_path / "cli"
    rc = main([str(out), "--pairs", "2", "--seed", "4", "--width", "320", "--height", "180", "--depth", "--quiet",
               "--plain"])
    assert rc == 0
    d = open_drive(out)
    assert len(d) == 2 and d.camera.width == 320
    assert abs(d.camera.fx - 1750.0 / 6) < 1e-9          # fx follows --width by default
    assert d.pairs[0].depth_path is not None
    assert "2 pairs" in capsys.readouterr().out
    assert main([str(out), "--pairs", "2"]) == 2           # refuses a non-empty folder
