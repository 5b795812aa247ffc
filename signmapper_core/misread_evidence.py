"""Why a fused sign carries the wrong id: what each of its observations read, beside the true id.

Whether a misread can be mended in fusion (a better vote) or only by the classifier
depends on the observations: a vote can only pick an id some observations saw, and
only if the true id had weight in them. These lines show that per observation: the
id read, its indicators, the face's size and depth, the probability the classifier
gave the true id (or that the colour and shape cut left it out), and its best rivals.
"""

from __future__ import annotations

from typing import Sequence

NOT_A_CANDIDATE = "not a candidate"


def observation_line(obs, true_id: str, top: int = 3) -> str:
    """One observation of a misread sign: pair, reading, indicators, face size, depth, the true id's score."""
    scores = obs.detection.scores or {}
    truth = f"{scores[true_id]:.2f}" if true_id in scores else NOT_A_CANDIDATE
    best = sorted(scores.items(), key=lambda kv: -kv[1])[:top]
    rivals = ", ".join(f"{t} {s:.2f}" for t, s in best)
    x, y, w, h = obs.bbox
    return (f"    pair {obs.pair_id}: read {obs.template_id} ({obs.classification_indicator:.2f}, {obs.status}), "
            f"detection {obs.detection_indicator:.2f}, {w}x{h} px at {obs.depth_m:.1f} m, "
            f"{obs.colour} {obs.shape} by {obs.source}; true id {true_id}: {truth}; best: {rivals}")


def misread_lines(signs: Sequence, reference_ids: Sequence[str], match: Sequence[int], top: int = 3) -> list[str]:
    """For every fused sign matched to a reference sign of another id: a heading and a line per observation.

    ``match``: per sign, the index of its reference sign or -1 (``evaluation.EvaluationReport.match``).
    """
    lines = []
    for sign, ref in zip(signs, match):
        if ref < 0 or sign.template_id == reference_ids[ref]:
            continue
        true_id = reference_ids[ref]
        lines.append(f"  sign {sign.sign_id}: true {true_id}, mapped {sign.template_id} ({sign.status}, "
                     f"vote share {sign.vote_share:.2f}, {sign.n_obs} observations)")
        lines += [observation_line(o, true_id, top) for o in sorted(sign.observations, key=lambda o: o.pair_index)]
    return lines
