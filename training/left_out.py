"""The ids a classifier is trained without, to measure how signs it never saw come out (the open set).

The ids are drawn by a seed written down before the training (``docs/measurements.md``), from every catalogue
entry the network is asked about (not the generic text panels, which are told by their layout), so that nobody
picks them after seeing results.
"""

from __future__ import annotations

import numpy as np

from signmapper_core.catalogue.text_panels import is_text_panel

LEFT_OUT_SHARE = 0.1


def left_out_ids(catalogue_ids, seed: int, share: float = LEFT_OUT_SHARE) -> list:
    """A ``share`` of the ids, drawn with ``seed``, in id order."""
    pool = sorted(t for t in catalogue_ids if not is_text_panel(t))
    n = int(round(share * len(pool)))
    picked = np.random.default_rng(seed).choice(len(pool), size=n, replace=False)
    return sorted(pool[i] for i in picked)
