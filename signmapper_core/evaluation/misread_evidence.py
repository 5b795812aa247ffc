"""Why a fused sign carries the wrong id, or is no sign at all: what each of its observations read.

Whether a misread can be mended in fusion (a better vote) or only by the classifier
depends on the observations: a vote can only pick an id some observations saw, and
only if the true id had weight in them. These lines show that per observation: the
id read, its indicators, the face's size and depth, the probability the classifier
gave the true id (or that the colour and shape cut left it out), and its best rivals.
A false positive (a fused sign near no reference sign) gets the same lines without a
true id: the pairs and pixel boxes say where to look at what was taken for a sign.
"""

from __future__ import annotations

from typing import Optional, Sequence

NOT_A_CANDIDATE = "not a candidate"


def observation_line(obs, true_id: Optional[str], top: int = 3) -> str:
    """One observation of a fused sign: pair, reading, indicators, face box, depth, and (``true_id`` given) the
    true id's score."""
    scores = obs.detection.scores or {}
    best = sorted(scores.items(), key=lambda kv: -kv[1])[:top]
    rivals = ", ".join(f"{t} {s:.2f}" for t, s in best)
    x, y, w, h = obs.bbox
    line = (f"    pair {obs.pair_id}: read {obs.template_id} ({obs.classification_indicator:.2f}, {obs.status}), "
            f"detection {obs.detection_indicator:.2f}, {w}x{h} px at ({x}, {y}), {obs.depth_m:.1f} m, "
            f"{obs.colour} {obs.shape} by {obs.source}")
    if true_id is not None:
        line += f"; true id {true_id}: {f'{scores[true_id]:.2f}' if true_id in scores else NOT_A_CANDIDATE}"
    return f"{line}; best: {rivals}"


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


def false_positive_lines(signs: Sequence, match: Sequence[int], top: int = 3) -> list[str]:
    """For every fused sign matching no reference sign (``match`` -1): a heading and a line per observation."""
    lines = []
    for sign, ref in zip(signs, match):
        if ref >= 0:
            continue
        lines.append(f"  sign {sign.sign_id}: no reference sign within reach, mapped {sign.template_id} "
                     f"({sign.status}, vote share {sign.vote_share:.2f}, {sign.n_obs} observations)")
        lines += [observation_line(o, None, top) for o in sorted(sign.observations, key=lambda o: o.pair_index)]
    return lines


def missed_lines(reference: Sequence, match: Sequence[int]) -> list[str]:
    """A line for every reference sign in view that no fused sign was matched to (``match``: per fused sign,
    the index of its reference sign or -1)."""
    found = set(int(m) for m in match if m >= 0)
    return [f"  sign {ref.sign_id}: {ref.template_id} ({ref.width_m:.2f} x {ref.height_m:.2f} m) not detected"
            for k, ref in enumerate(reference) if k not in found]


def position_lines(signs: Sequence, reference: Sequence, match: Sequence[int], differences, min_error_m: float = 0.0,
                   ) -> list[str]:
    """Every fused sign matched to a reference sign whose 3D error is at least ``min_error_m``, largest first:
    true and mapped id, the error across, along and in height, and each observation's depth and face box.

    ``differences``: the (n matched, 5) across/along/height/planimetric/3D rows of ``evaluation.evaluate`` in the
    order of the matched signs. Shows where a position error comes from (one bad view, a depth that is off, a
    face measured around the wrong outline, a sign matched to its neighbour on the pole)."""
    matched = [(sign, ref) for sign, ref in zip(signs, match) if ref >= 0]
    rows = sorted(zip(matched, differences), key=lambda row: -row[1][4])
    lines = []
    for (sign, ref), (across, along, height, _, error) in rows:
        if error < min_error_m:
            break
        truth = reference[ref]
        lines.append(f"  sign {sign.sign_id}: true {truth.template_id}, mapped {sign.template_id} ({sign.status}, "
                     f"{sign.width_m:.2f} x {sign.height_m:.2f} m, {sign.n_obs} observations): 3D {error:.2f} m, "
                     f"across {across:+.2f}, along {along:+.2f}, height {height:+.2f}")
        lines += [observation_line(o, truth.template_id) for o in sorted(sign.observations, key=lambda o: o.pair_index)]
    return lines
