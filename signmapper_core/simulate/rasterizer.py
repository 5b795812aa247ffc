"""Pinhole rasteriser for planar surfaces with an exact per-pixel depth buffer.

Each surface is clipped against the near plane in its own texture coordinates,
warped into the image with the plane's exact homography (``K [U V O]`` in camera
coordinates), and z-tested against an inverse-depth buffer. Inverse depth of a
plane is affine in (u, v), so the depth map is exact for the rendered scene,
which makes the right image and the depth map agree to the pixel. Surfaces are
drawn back to front so anti-aliased edges blend over what lies behind them.
"""

from __future__ import annotations

import cv2
import numpy as np

from ..geometry import Camera, Pose
from .surfaces import Surface, Texture

CLIP_NEAR_M = 0.3  # the camera's clipping planes: a triangle is cut at the near one, one wholly beyond the far
CLIP_FAR_M = 250.0  # one is not drawn
SUBPIXEL_BITS = 4


class TextureCache:
    """Textures by key, made on first use and dropped once the vehicle has passed them."""

    def __init__(self):
        self._store: dict[str, tuple[Texture, float]] = {}

    def get(self, surface: Surface) -> Texture:
        src = surface.texture
        hit = self._store.get(src.key)
        if hit is None:
            tex = src.make()
            if tex.bgr.shape[:2] != (src.height, src.width):
                raise ValueError(f"texture {src.key}: made {tex.bgr.shape[:2]}, declared {(src.height, src.width)}")
            hit = (tex, surface.s_max)
            self._store[src.key] = hit
        elif surface.s_max > hit[1]:
            self._store[src.key] = (hit[0], surface.s_max)
        return hit[0]

    def evict_before(self, s: float) -> None:
        for key in [k for k, (_t, s_max) in self._store.items() if s_max < s]:
            del self._store[key]

    def __len__(self) -> int:
        return len(self._store)


def _clip_near(st: np.ndarray, z: np.ndarray, near: float) -> np.ndarray:
    """Sutherland-Hodgman clip of a polygon (texture coords) to z >= near; z is linear in st."""
    out = []
    n = len(st)
    for i in range(n):
        a, b = st[i], st[(i + 1) % n]
        za, zb = z[i], z[(i + 1) % n]
        if za >= near:
            out.append(a)
        if (za >= near) != (zb >= near):
            t = (near - za) / (zb - za)
            out.append(a + t * (b - a))
    return np.array(out) if out else np.empty((0, 2))


class Rasterizer:
    """Renders a list of surfaces for one camera pose into a BGR image and a depth map."""

    def __init__(self, camera: Camera, textures: TextureCache):
        self.camera = camera
        self.textures = textures
        self.k = np.array([[camera.fx, 0, camera.cx], [0, camera.fy, camera.cy], [0, 0, 1.0]])

    def render(self, surfaces: list[Surface], pose: Pose, background: np.ndarray
               ) -> tuple[np.ndarray, np.ndarray]:
        """(image BGR uint8, depth float32 with NaN where only background is seen)."""
        cam = self.camera
        image = background.copy()
        inv_depth = np.zeros((cam.height, cam.width), np.float32)
        rot = pose.rotation
        centre = pose.centre
        jobs = []
        for k in self._candidates(surfaces, rot, centre):
            job = self._prepare(surfaces[k], rot, centre)
            if job is not None:
                jobs.append(job)
        jobs.sort(key=lambda j: -j[0])
        for job in jobs:
            self._draw(image, inv_depth, *job[1:])
        with np.errstate(divide="ignore"):
            depth = np.where(inv_depth > 0, 1.0 / inv_depth, np.nan).astype(np.float32)
        return image, depth

    def _candidates(self, surfaces: list[Surface], rot: np.ndarray, centre: np.ndarray) -> np.ndarray:
        """Indices of surfaces that may be seen: vectorised near/far, back-face and frustum culling."""
        if not surfaces:
            return np.empty(0, int)
        packed = np.stack([s.packed for s in surfaces])
        o_c = (packed[:, 0:3] - centre) @ rot
        u_c = packed[:, 3:6] @ rot
        v_c = packed[:, 6:9] @ rot
        poly = packed[:, 12:20].reshape(-1, 4, 2)
        pts = o_c[:, None, :] + poly[..., 0:1] * u_c[:, None, :] + poly[..., 1:2] * v_c[:, None, :]
        z = pts[..., 2]
        keep = (z.max(axis=1) >= CLIP_NEAR_M) & (z.min(axis=1) <= CLIP_FAR_M)
        one_sided = packed[:, 20] > 0
        facing = np.einsum("ij,ij->i", packed[:, 9:12], centre - packed[:, 0:3]) > 0
        keep &= ~one_sided | facing
        # frustum test for surfaces entirely in front of the near plane
        front = keep & (z.min(axis=1) >= CLIP_NEAR_M)
        with np.errstate(divide="ignore", invalid="ignore"):
            u = self.camera.fx * pts[..., 0] / z + self.camera.cx
            v = self.camera.fy * pts[..., 1] / z + self.camera.cy
        outside = ((u.max(axis=1) < -1) | (u.min(axis=1) > self.camera.width) | (v.max(axis=1) < -1)
                   | (v.min(axis=1) > self.camera.height))
        keep &= ~(front & outside)
        return np.flatnonzero(keep)

    def _prepare(self, surf: Surface, rot: np.ndarray, centre: np.ndarray):
        o_c = (surf.origin - centre) @ rot
        u_c = surf.axis_u @ rot
        v_c = surf.axis_v @ rot
        st = surf.polygon
        z = o_c[2] + st[:, 0] * u_c[2] + st[:, 1] * v_c[2]
        if z.max() < CLIP_NEAR_M or z.min() > CLIP_FAR_M:
            return None
        if z.min() < CLIP_NEAR_M:
            st = _clip_near(st, z, CLIP_NEAR_M)
            if len(st) < 3:
                return None
        pts_c = o_c + st[:, :1] * u_c + st[:, 1:2] * v_c
        zc = pts_c[:, 2]
        uv = self.k[:2, :2] @ (pts_c[:, :2] / zc[:, None]).T + self.k[:2, 2:3]
        uv = uv.T
        cam = self.camera
        x0 = max(int(np.floor(uv[:, 0].min())) - 1, 0)
        y0 = max(int(np.floor(uv[:, 1].min())) - 1, 0)
        x1 = min(int(np.ceil(uv[:, 0].max())) + 2, cam.width)
        y1 = min(int(np.ceil(uv[:, 1].max())) + 2, cam.height)
        if x1 <= x0 or y1 <= y0:
            return None
        h = self.k @ np.array([u_c, v_c, o_c]).T
        # Plane n.X = d in camera coordinates; inverse depth is affine in the pixel.
        normal = surf.front_normal @ rot
        d = float(np.dot(normal, o_c))
        if abs(d) < 1e-12:
            return None  # seen edge-on
        plane = (normal[0] / cam.fx / d, normal[1] / cam.fy / d,
                 (normal[2] - normal[0] * cam.cx / cam.fx - normal[1] * cam.cy / cam.fy) / d)
        mean_z = float(zc.mean())
        texel_px = float(np.sqrt(u_c @ u_c)) * cam.fx / max(mean_z, CLIP_NEAR_M)
        return mean_z, surf, uv, (x0, y0, x1, y1), h, plane, texel_px

    def _draw(self, image, inv_depth, surf: Surface, uv, box, h, plane, texel_px):
        x0, y0, x1, y1 = box
        bw, bh = x1 - x0, y1 - y0
        cover = np.zeros((bh, bw), np.uint8)
        # Grown by ~0.6 px and filled without anti-aliasing, so neighbouring surfaces overlap
        # instead of leaving seams; soft outlines come from alpha textures and the camera blur.
        centre = uv.mean(axis=0)
        away = uv - centre
        grown = uv + 0.6 * away / np.maximum(np.linalg.norm(away, axis=1, keepdims=True), 1e-9)
        pts = np.round((grown - [x0, y0]) * (1 << SUBPIXEL_BITS)).astype(np.int32)
        cv2.fillConvexPoly(cover, pts, 255, cv2.LINE_8, SUBPIXEL_BITS)
        us = np.arange(x0, x1, dtype=np.float32)
        vs = np.arange(y0, y1, dtype=np.float32)
        inv_z = (plane[0] * us)[None, :] + (plane[1] * vs + plane[2])[:, None]
        inv_z = inv_z.astype(np.float32, copy=False)
        zb = inv_depth[y0:y1, x0:x1]
        if surf.texture is None:
            colour = np.empty((bh, bw, 3), np.uint8)
            colour[:] = surf.colour
            alpha = cover
        else:
            tex = self.textures.get(surf)
            level = 0
            if texel_px < 0.7:
                level = int(np.floor(np.log2(1.0 / texel_px)))
            bgr, a_tex = tex.level(level)
            sx = tex.bgr.shape[1] / bgr.shape[1]
            sy = tex.bgr.shape[0] / bgr.shape[0]
            # texel centres of level L sit at (s + 0.5) / 2^L - 0.5 in level-0 texel coordinates
            to_level0 = np.array([[sx, 0, 0.5 * sx - 0.5], [0, sy, 0.5 * sy - 0.5], [0, 0, 1.0]])
            shift = np.array([[1.0, 0, -x0], [0, 1.0, -y0], [0, 0, 1.0]])
            m = shift @ h @ to_level0
            colour = cv2.warpPerspective(bgr, m, (bw, bh), flags=cv2.INTER_LINEAR, borderMode=cv2.BORDER_REPLICATE)
            if a_tex is not None:
                a_warp = cv2.warpPerspective(a_tex, m, (bw, bh), flags=cv2.INTER_LINEAR,
                                             borderMode=cv2.BORDER_CONSTANT, borderValue=0)
                alpha = cv2.multiply(cover, a_warp, scale=1.0 / 255)
            else:
                alpha = cover
        visible = inv_z >= zb
        weight = alpha.astype(np.float32) * (1.0 / 255)
        weight *= visible
        region = image[y0:y1, x0:x1]
        blended = cv2.blendLinear(colour, region, weight, 1.0 - weight)
        region[...] = blended
        np.copyto(zb, inv_z, where=visible & (alpha >= 128))
