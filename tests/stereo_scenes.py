"""Raw stereo pairs of a known scene, rendered through real camera models (distortion, toe-in), for import tests.

The scene is a set of textured planes given in a world frame; each camera is a
pinhole with OpenCV distortion at a centre with a camera -> world rotation
(camera x right, y down, z forward). A pixel sees the nearest plane hit by its
ray; its ray is found by undoing the distortion with ``cv2.undistortPoints``,
so the images are exactly what a camera with that calibration would record.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import cv2
import numpy as np


@dataclass(frozen=True)
class Plane:
    """Points X with ``normal . X = offset``; texture coordinates are X's components along ``u_axis``/``v_axis``."""

    normal: tuple[float, float, float]
    offset: float
    u_axis: tuple[float, float, float]
    v_axis: tuple[float, float, float]
    seed: int = 0
    limits: tuple[float, float, float, float] | None = None   # u_min, u_max, v_min, v_max (m); None = endless

    def contains(self, points: np.ndarray) -> np.ndarray:
        if self.limits is None:
            return np.ones(len(points), bool)
        u, v = points @ np.asarray(self.u_axis, float), points @ np.asarray(self.v_axis, float)
        u0, u1, v0, v1 = self.limits
        return (u > u0) & (u < u1) & (v > v0) & (v < v1)


@dataclass(frozen=True)
class RawCamera:
    k: np.ndarray
    d: np.ndarray
    centre: np.ndarray                 # world
    rotation: np.ndarray               # camera -> world
    size: tuple[int, int]              # (width, height)


def texture(seed: int, size: int = 1024) -> np.ndarray:
    """Smooth random colour texture (features at several scales, no repeats), BGR uint8."""
    rng = np.random.default_rng(seed)
    out = np.zeros((size, size, 3), np.float32)
    for sigma, weight in ((1.5, 0.5), (4.0, 0.8), (12.0, 1.0)):
        noise = rng.normal(0, 1, (size, size, 3)).astype(np.float32)
        noise = cv2.GaussianBlur(noise, (0, 0), sigma)
        out += weight * noise / (noise.std() + 1e-9)
    out = (out - out.min()) / (out.max() - out.min())
    return (out * 255).astype(np.uint8)


def sample(image: np.ndarray, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Bilinear samples (n, 3) of ``image`` at float positions (remap wants maps under 32767 rows)."""
    n, columns = len(x), 1024
    rows = -(-n // columns)
    pad = rows * columns - n
    mx = np.concatenate([x, np.zeros(pad)]).astype(np.float32).reshape(rows, columns)
    my = np.concatenate([y, np.zeros(pad)]).astype(np.float32).reshape(rows, columns)
    out = cv2.remap(image, mx, my, cv2.INTER_LINEAR, borderMode=cv2.BORDER_REFLECT)
    return out.reshape(-1, 3)[:n]


@dataclass
class Scene:
    planes: list[Plane]
    texture_m_per_px: float = 0.01      # 1 cm per texture pixel
    textures: dict = field(default_factory=dict)

    def hits(self, origin: np.ndarray, rays: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Nearest hit point (n, 3) and plane index (n,) of world rays (-1 where nothing is hit)."""
        best_t = np.full(len(rays), np.inf)
        best_i = np.full(len(rays), -1)
        for i, plane in enumerate(self.planes):
            n = np.asarray(plane.normal, float)
            denom = rays @ n
            with np.errstate(divide="ignore", invalid="ignore"):
                t = (plane.offset - origin @ n) / denom
            better = (t > 0) & (t < best_t)
            better[better] &= plane.contains(origin + rays[better] * t[better, None])
            best_t[better], best_i[better] = t[better], i
        points = origin + rays * np.where(np.isfinite(best_t), best_t, 0)[:, None]
        return points, best_i

    def render(self, camera: RawCamera) -> np.ndarray:
        w, h = camera.size
        u, v = np.meshgrid(np.arange(w, dtype=np.float32), np.arange(h, dtype=np.float32))
        pixels = np.stack([u.ravel(), v.ravel()], axis=1).reshape(-1, 1, 2)
        normalised = cv2.undistortPoints(pixels, camera.k, camera.d).reshape(-1, 2)
        rays = np.column_stack([normalised, np.ones(len(normalised))]) @ camera.rotation.T
        points, index = self.hits(camera.centre, rays)
        image = np.zeros((h * w, 3), np.uint8)
        for i, plane in enumerate(self.planes):
            sel = index == i
            if not sel.any():
                continue
            tex = self.textures.setdefault(plane.seed, texture(plane.seed))
            tu = points[sel] @ np.asarray(plane.u_axis, float) / self.texture_m_per_px + tex.shape[1] / 2
            tv = points[sel] @ np.asarray(plane.v_axis, float) / self.texture_m_per_px + tex.shape[0] / 2
            image[sel] = sample(tex, tu, tv)
        return image.reshape(h, w, 3)


def rot_y(deg: float) -> np.ndarray:
    a = np.radians(deg)
    return np.array([[np.cos(a), 0, np.sin(a)], [0, 1, 0], [-np.sin(a), 0, np.cos(a)]])


def rot_z(deg: float) -> np.ndarray:
    a = np.radians(deg)
    return np.array([[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1]])


def convergent_rig(size=(640, 480), baseline=0.5, toe_in_deg=1.5):
    """Left and right raw cameras, toed in by ``toe_in_deg`` each, with different lenses and distortions.

    World frame = the rig: x right, y down, z forward, left camera at the origin.
    """
    w, h = size
    k_left = np.array([[0.85 * w, 0, w / 2 - 3.2], [0, 0.85 * w + 1.5, h / 2 + 2.1], [0, 0, 1]])
    k_right = np.array([[0.87 * w, 0, w / 2 + 4.5], [0, 0.87 * w - 1.0, h / 2 - 1.7], [0, 0, 1]])
    left = RawCamera(k_left, np.array([-0.28, 0.09, 0.0012, -0.0007, 0.0]), np.zeros(3),
                     rot_y(toe_in_deg) @ rot_z(0.3), size)
    right = RawCamera(k_right, np.array([-0.21, 0.05, -0.0009, 0.0006, 0.0]), np.array([baseline, 0.01, -0.005]),
                      rot_y(-toe_in_deg) @ rot_z(-0.2), size)
    return left, right


def relative_pose(left: RawCamera, right: RawCamera) -> tuple[np.ndarray, np.ndarray]:
    """R, T with X_right = R X_left + T (cv2.stereoCalibrate's convention)."""
    r = right.rotation.T @ left.rotation
    t = right.rotation.T @ (left.centre - right.centre)
    return r, t


def wall_scene() -> Scene:
    """A slanted textured wall 6-12 m ahead and a nearer panel, in the rig frame (z forward)."""
    slant = np.array([-0.35, 0.0, 1.0]) / np.linalg.norm([-0.35, 0.0, 1.0])
    return Scene([
        Plane(tuple(slant), 9.0 * slant[2], (float(slant[2]), 0.0, float(-slant[0])), (0.0, 1.0, 0.0), seed=1),
        Plane((0.0, 0.0, 1.0), 5.5, (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), seed=2, limits=(-1.2, 0.4, -0.8, 0.5)),
    ])
