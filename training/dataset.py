"""Labelled synthetic patches, generated in parallel and reproducibly: sample i depends only on (seed, i)."""

from __future__ import annotations

import multiprocessing as mp

import numpy as np

from .backgrounds import BackgroundPool, procedural_backgrounds, skimage_photos
from .compose import SampleMaker

_maker: SampleMaker | None = None


def _init(catalogue_dir, class_ids, input_px, margin, design_variants=False):
    global _maker
    from signmapper_core.catalogue import load_catalogue

    pool = BackgroundPool(skimage_photos() + procedural_backgrounds(np.random.default_rng(12345)))
    _maker = SampleMaker(load_catalogue(catalogue_dir), class_ids, pool, input_px, margin,
                         design_variants=design_variants)


def _make(job):
    seed, index, label = job
    rng = np.random.default_rng([seed, index])
    if label < 0:
        return _maker.background_sample(rng)
    return _maker.sign_sample(_maker.class_ids[label], rng)


# Signs that differ from a common one only by small lettering are rarer on the road than it: 2.30.1 (the
# general 50 at town entries, "GENERELL" on the ring) is seen far less often than 2.30-50. Sampled at this
# share of the others, a ring whose lettering the camera cannot resolve reads as the common sign.
CLASS_SHARE = {"2.30.1": 0.35}


def class_shares(class_ids) -> list:
    return [CLASS_SHARE.get(t, 1.0) for t in class_ids]


def labels_for(n_classes: int, per_class: int, background: int, seed: int, shares=None) -> np.ndarray:
    """Labels in a seeded order, ``per_class`` of each class times its share; -1 is the background class."""
    shares = [1.0] * n_classes if shares is None else list(shares)
    counts = [max(1, int(round(per_class * s))) for s in shares]
    labels = np.concatenate([np.repeat(np.arange(n_classes), counts), np.full(background, -1)])
    return np.random.default_rng(seed).permutation(labels)


def generate(catalogue_dir, class_ids, labels: np.ndarray, seed: int, input_px: int, margin: float,
             workers: int = 2, progress=None, design_variants: bool = False) -> np.ndarray:
    """uint8 patches (n, input_px, input_px, 3) for ``labels`` (index into ``class_ids``, -1 = background)."""
    jobs = [(seed, i, int(label)) for i, label in enumerate(labels)]
    out = np.empty((len(jobs), input_px, input_px, 3), np.uint8)
    args = (str(catalogue_dir) if catalogue_dir else None, list(class_ids), input_px, margin, design_variants)
    with mp.get_context("fork").Pool(workers, initializer=_init, initargs=args) as pool:
        for i, patch in enumerate(pool.imap(_make, jobs, chunksize=256)):
            out[i] = patch
            if progress and i % 5000 == 0:
                progress(i, len(jobs))
    return out
