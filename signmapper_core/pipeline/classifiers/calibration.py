"""How the model card's acceptance threshold is fitted (``classifier/model.json``, ``accept_threshold``).

Two programs fit it: the training on its synthetic validation faces (``training.train``) and the calibration on
real photographs (``scripts.calibrate_classifier``), which overwrites the training's figure. They share this rule
so that the threshold means the same whichever wrote it. Not used while mapping: the pipeline only reads the card.
"""

from __future__ import annotations

import numpy as np


def acceptance_threshold(best_p: np.ndarray, correct: np.ndarray, max_wrong: float) -> float:
    """Lowest probability above which at most ``max_wrong`` of the accepted picks are wrong.

    ``best_p``: each face's probability of its best candidate; ``correct``: whether that candidate is the true id.
    Faces sorted from the surest down, the threshold is the probability of the last face at which the wrong share
    so far is still within ``max_wrong``; kept within 0.5..0.99, and 0.99 where even the surest face is wrong too
    often.
    """
    order = np.argsort(-best_p)
    wrong = np.cumsum(~correct[order]) / np.arange(1, len(order) + 1)
    ok = np.nonzero(wrong <= max_wrong)[0]
    if ok.size == 0:
        return 0.99
    return float(np.clip(best_p[order][ok[-1]], 0.5, 0.99))
