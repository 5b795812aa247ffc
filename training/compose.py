"""One training sample: a worn face seen in perspective on a pole in a real background, as the camera saw it.

The sample is cut with the same :func:`face_patch` the mapping uses, around a
jittered box, because at mapping time the box comes from colour segmentation
and is never exact.
"""

from __future__ import annotations

import math

import cv2
import numpy as np

from signmapper_core.pipeline.classifiers.face_patch import face_patch
from signmapper_core.plates.printed_numbers import speed_limit_number

from .backgrounds import BackgroundPool
from .camera_effects import blur, lighting, resolution_loss, sensor_noise_and_jpeg
from .face_variants import (
    MIRROR_SAFE,
    mirrored,
    pictogram_scaled,
    pictogram_variant,
    speed_limit_face,
)
from .face_wear import wear_face

WORK_PX = 192  # faces are worn at this size, then shrunk by pyramid steps to about twice the target size


def _rotation(yaw: float, pitch: float, roll: float) -> np.ndarray:
    cy, sy = math.cos(yaw), math.sin(yaw)
    cp, sp = math.cos(pitch), math.sin(pitch)
    cr, sr = math.cos(roll), math.sin(roll)
    ry = np.array([[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]])
    rx = np.array([[1, 0, 0], [0, cp, -sp], [0, sp, cp]])
    rz = np.array([[cr, -sr, 0], [sr, cr, 0], [0, 0, 1]])
    return ry @ rx @ rz


def view_homography(face_w: int, face_h: int, size_px: float, centre, rng: np.random.Generator) -> np.ndarray:
    """Homography from face pixels to the canvas: the face turned (yaw up to ±40°) and seen from a distance."""
    yaw = math.radians(40.0 * rng.beta(1.3, 2.2) * rng.choice((-1, 1)))
    pitch = math.radians(float(np.clip(rng.normal(0, 6), -15, 15)))
    roll = math.radians(float(np.clip(rng.normal(0, 3), -10, 10)))
    k = size_px / max(face_w, face_h)
    corners = np.array([[0, 0], [face_w, 0], [face_w, face_h], [0, face_h]], np.float64)
    xyz = np.column_stack([(corners[:, 0] - face_w / 2) * k, (corners[:, 1] - face_h / 2) * k, np.zeros(4)])
    xyz = xyz @ _rotation(yaw, pitch, roll).T
    distance = size_px * rng.uniform(4, 30)  # perspective: camera distance over sign size
    uv = xyz[:, :2] * (distance / (distance + xyz[:, 2:3])) + np.asarray(centre, np.float64)
    return cv2.getPerspectiveTransform(corners.astype(np.float32), uv.astype(np.float32))


def _shrink(face: np.ndarray, alpha: np.ndarray, target: float) -> tuple[np.ndarray, np.ndarray]:
    """Pyramid-halve the face while it stays above twice the target size (warping then does not alias)."""
    while max(face.shape[:2]) > 2.5 * target and min(face.shape[:2]) > 8:
        face, alpha = cv2.pyrDown(face), cv2.pyrDown(alpha)
    return face, alpha


def paste(canvas: np.ndarray, face: np.ndarray, alpha: np.ndarray, hom: np.ndarray) -> np.ndarray:
    """Warp a face into the canvas and blend it by its anti-aliased outline; returns the warped alpha."""
    size = (canvas.shape[1], canvas.shape[0])
    warped = cv2.warpPerspective(face, hom, size, flags=cv2.INTER_LINEAR, borderMode=cv2.BORDER_REPLICATE)
    a = cv2.warpPerspective(alpha, hom, size, flags=cv2.INTER_LINEAR, borderValue=0).astype(np.float32) / 255.0
    canvas[:] = canvas * (1 - a[..., None]) + warped.astype(np.float32) * a[..., None]
    return a


def draw_pole(canvas: np.ndarray, centre, size_px: float, rng: np.random.Generator) -> None:
    """A grey pole behind the sign, from its centre down (or up) out of the crop."""
    width = max(1, int(size_px * rng.uniform(0.06, 0.14)))
    grey = float(rng.uniform(90, 200))
    x = int(centre[0] + rng.normal(0, 0.03 * size_px))
    y1 = canvas.shape[0] if rng.random() < 0.8 else 0
    cv2.rectangle(canvas, (x - width // 2, int(centre[1])), (x + width // 2, y1), (grey, grey, grey * 0.97), -1)


def occlude(canvas: np.ndarray, bbox, backgrounds: BackgroundPool, rng: np.random.Generator) -> None:
    """A branch, leaves or a pole in front of part of the face (at most about a third of it)."""
    x, y, w, h = bbox
    patch = backgrounds.crop(rng, canvas.shape[0], canvas.shape[1]).astype(np.float32)
    mask = np.zeros(canvas.shape[:2], np.uint8)
    if rng.random() < 0.5:  # a pole or trunk crossing vertically
        cx = int(x + rng.uniform(0, w))
        cv2.rectangle(mask, (cx - max(1, int(w * rng.uniform(0.05, 0.15))), 0), (cx + max(1, int(w * 0.08)),
                                                                                 canvas.shape[0]), 255, -1)
    else:  # a leafy blob coming in from one side
        side = rng.integers(4)
        cx = x + (0 if side == 0 else w if side == 1 else rng.uniform(0, w))
        cy = y + (0 if side == 2 else h if side == 3 else rng.uniform(0, h))
        axes = (max(1, int(w * rng.uniform(0.15, 0.45))), max(1, int(h * rng.uniform(0.15, 0.45))))
        cv2.ellipse(mask, (int(cx), int(cy)), axes, float(rng.uniform(0, 180)), 0, 360, 255, -1)
    m = cv2.GaussianBlur(mask, (3, 3), 0).astype(np.float32)[..., None] / 255.0
    canvas[:] = canvas * (1 - m) + patch * m


def distractor_shapes(canvas: np.ndarray, rng: np.random.Generator) -> None:
    """Sign-coloured blobs, bars and letters that are not signs (shop fronts, cars, posters); BGR red, blue, yellow,
    green, brown, orange or any."""
    h, w = canvas.shape[:2]
    for _ in range(int(rng.integers(1, 4))):
        colour = tuple(float(c) for c in rng.choice([(40, 40, 200), (170, 80, 20), (20, 190, 235),
                                                     (64, 127, 0), (40, 50, 122), (30, 130, 245),
                                                     tuple(rng.uniform(0, 255, 3))]))
        cx, cy = int(rng.uniform(0, w)), int(rng.uniform(0, h))
        if rng.random() < 0.5:
            cv2.rectangle(canvas, (cx, cy), (cx + int(rng.uniform(0.1, 0.6) * w), cy + int(rng.uniform(0.1, 0.6) * h)),
                          colour, -1)
        else:
            cv2.putText(canvas, "".join(rng.choice(list("ABCDEFGHKLMNOPRSTUZ0123456789"), 3)), (cx - w // 4, cy),
                        cv2.FONT_HERSHEY_SIMPLEX, rng.uniform(0.3, 1.5) * w / 60, colour, max(1, w // 30))


def jitter_box(bbox, rng: np.random.Generator, amount: float = 1.0) -> tuple[float, float, float, float]:
    """The true face box moved and resized as colour segmentation would get it wrong."""
    x, y, w, h = bbox
    sw, sh = np.clip(rng.normal(1.0, 0.07 * amount, 2), 0.8, 1.25)
    nw, nh = w * sw, h * sh
    cx = x + w / 2 + rng.normal(0, 0.05 * amount) * w
    cy = y + h / 2 + rng.normal(0, 0.05 * amount) * h
    return cx - nw / 2, cy - nh / 2, nw, nh


def _working_size(bgr: np.ndarray, alpha: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    scale = WORK_PX / max(bgr.shape[:2])
    size = (max(4, round(bgr.shape[1] * scale)), max(4, round(bgr.shape[0] * scale)))
    return cv2.resize(bgr, size, interpolation=cv2.INTER_AREA), cv2.resize(alpha, size, interpolation=cv2.INTER_AREA)


class SampleMaker:
    """Makes labelled training patches from a catalogue's master images."""

    def __init__(self, catalogue, class_ids, backgrounds: BackgroundPool, input_px: int, margin: float,
                 min_px: float = 14.0, max_px: float = 170.0, design_variants: bool = False):
        self.class_ids = list(class_ids)
        # False: the shipped model's faces (30 % pictograms scaled); True: 50 % pictograms redrawn and wider rims too
        self.design_variants = design_variants
        self.backgrounds = backgrounds
        self.input_px = input_px
        self.margin = margin
        self.min_px, self.max_px = min_px, max_px
        self.masters = {}  # id -> (bgr, alpha) of each of its drawings, the master first
        for tid in self.class_ids:
            self.masters[tid] = [_working_size(bgr, alpha)
                                 for bgr, alpha in [catalogue.master(tid)] + catalogue.variant_masters(tid)]

    def _canvas(self, rng, size_px):
        side = int(size_px * (1 + 2 * rng.uniform(0.35, 0.8))) + 8
        canvas = self.backgrounds.crop(rng, side, side).astype(np.float32)
        if rng.random() < 0.5:  # recolour the background a little: grey photos, other seasons
            canvas = canvas * np.clip(rng.normal(1, 0.12, 3), 0.7, 1.3)
        return canvas

    def _design(self, tid, rng):
        """The official drawing of ``tid`` (any of its language versions or directions) or, as often, another
        design of the same sign (face_variants)."""
        drawings = self.masters[tid]
        face, alpha = drawings[int(rng.integers(len(drawings)))] if len(drawings) > 1 else drawings[0]
        number = speed_limit_number(tid)
        if number is not None and "2.01" in self.masters and rng.random() < 0.4:
            ring, alpha = self.masters["2.01"][0]
            face = speed_limit_face(ring, alpha, number, rng)
        elif tid in MIRROR_SAFE and rng.random() < 0.5:
            face, alpha = mirrored(face, alpha)
        if not self.design_variants:
            if rng.random() < 0.3:
                face = pictogram_scaled(face, alpha, rng)
        elif rng.random() < 0.5:  # the pictogram moved, resized, warped, restroked or simplified
            face = pictogram_variant(face, alpha, rng)
        return face, alpha

    def _place_sign(self, canvas, tid, size_px, centre, rng, worn=True):
        face, alpha = _shrink(*self._design(tid, rng), size_px)
        if worn:
            face = wear_face(face, alpha, rng, wider_rims=self.design_variants)
        hom = view_homography(face.shape[1], face.shape[0], size_px, centre, rng)
        return paste(canvas, face, alpha, hom)

    def sign_sample(self, tid: str, rng: np.random.Generator) -> np.ndarray:
        size_px = float(np.exp(rng.uniform(np.log(self.min_px), np.log(self.max_px))))
        canvas = self._canvas(rng, size_px)
        centre = (canvas.shape[1] / 2 + rng.normal(0, 2), canvas.shape[0] / 2 + rng.normal(0, 2))
        if rng.random() < 0.1:
            distractor_shapes(canvas, rng)
        if rng.random() < 0.5:
            draw_pole(canvas, centre, size_px, rng)
        if rng.random() < 0.25:  # a neighbouring sign or plate above or below on the same pole
            other = self.class_ids[int(rng.integers(len(self.class_ids)))]
            dy = size_px * rng.uniform(1.02, 1.25) * rng.choice((-1, 1))
            self._place_sign(canvas, other, size_px * rng.uniform(0.6, 1.1), (centre[0], centre[1] + dy), rng)
        a = self._place_sign(canvas, tid, size_px, centre, rng)
        x, y, w, h = cv2.boundingRect((a > 0.5).astype(np.uint8))
        if w == 0 or h == 0:
            x, y, w, h = int(centre[0] - size_px / 2), int(centre[1] - size_px / 2), int(size_px), int(size_px)
        if rng.random() < 0.15:
            occlude(canvas, (x, y, w, h), self.backgrounds, rng)
        return self._photograph(canvas, (x, y, w, h), size_px, rng)

    def background_sample(self, rng: np.random.Generator) -> np.ndarray:
        size_px = float(np.exp(rng.uniform(np.log(self.min_px), np.log(self.max_px))))
        canvas = self._canvas(rng, size_px)
        if rng.random() < 0.5:
            distractor_shapes(canvas, rng)
        if rng.random() < 0.3:
            draw_pole(canvas, (canvas.shape[1] / 2, canvas.shape[0] / 2), size_px, rng)
        c = canvas.shape[0] / 2
        box = (c - size_px / 2, c - size_px * rng.uniform(0.3, 0.7), size_px, size_px * rng.uniform(0.6, 1.4))
        return self._photograph(canvas, box, size_px, rng)

    def _photograph(self, canvas, bbox, size_px, rng) -> np.ndarray:
        img = lighting(canvas, rng)
        img = blur(img, size_px, rng)
        img = resolution_loss(img, rng)
        img = sensor_noise_and_jpeg(img, rng)
        return face_patch(img, jitter_box(bbox, rng), self.input_px, self.margin)
