"""Which signs a street of the whole catalogue carries: how often, how large and how mounted, in one table.

``MIX`` splits the catalogue into parts, each a kind of street sign: its weight
(the share of the sign poles whose first sign is of that part; a part's ids are
equally likely), the ids it holds (patterns, the first part that matches an id
takes it, so every id the generator places belongs to exactly one part), how its
signs are mounted, and the size of those of its signs that have no standard
size (``sizing: measured``; the others get their standard formats).

The weights are an estimate for a Swiss town street, not a count: regulatory
signs (speed limits, no stopping or parking, priority), information signs
(one-way, dead end, pedestrian crossings, parking) and direction signs most
often; motorway boards, lane signs, level crossings and light signals rarely.
Tourist and diversion signs (the only brown and nearly the only orange ones)
and the green motorway direction signs come a little more often than on most
streets, so that every colour family has some 5 % of the signs in view and a
set of 40 to 50 drives of 100 pairs shows each family at least 30 times.

Sizes without a standard (estimates, per part; the aspect is always the drawing's):
direction and tourist pointers, diversion pointers 1.0-1.6 m wide; place-name
signs of main roads 1.2-2.0 m; advance direction boards 1.5-3.0 m and motorway
boards 2-4 m on their longer side; lane signs 1.8-3.0 m; St Andrew's crosses and
distance beacons 0.9-1.4 m; zone panels 0.95-1.05 and panels of information
signs with a text, route and number markers 1.0-1.3 times, light signals 1.0-1.5
times their drawing's nominal size (the drawing at 1:20, life size for these).

Mountings (``sign_mounts``): ``pole``, the standing poles of before (single,
stacked, back to back, overhead); ``post``, up to ``stack`` signs of the part on
one post, a direction sign at its blunt end; ``board``, two posts at the roadside
or a gantry arm overhead; ``text panel``, the white panels set from their wording
(``text_panel_poles``).
"""

from __future__ import annotations

from dataclasses import dataclass
from fnmatch import fnmatchcase
from functools import lru_cache
from typing import Sequence

import numpy as np

from ..catalogue import load_catalogue
from ..catalogue.model import COLOURS
from ..catalogue.model import MEASURED as MEASURED_SIZING
from ..catalogue.text_panels import TEXT_PANELS
from .faces import LONGER_SIDE, SCALE, MeasuredSize, SignKind, sign_kind

POLE, POST, BOARD, TEXT_PANEL = "pole", "post", "board", "text panel"
MOUNTS = (POLE, POST, BOARD, TEXT_PANEL)


@dataclass(frozen=True)
class MixPart:
    """One kind of street sign in the mix."""

    name: str
    weight: float  # relative share of the sign poles whose first sign is of this part
    ids: tuple[str, ...]  # id patterns (fnmatch), of ``colours`` only when given
    mount: str = POLE
    size: MeasuredSize | None = None  # the size of the part's signs without a standard size
    colours: tuple[str, ...] = ()
    stack: int = 1  # POST: at most this many signs on one post

    def holds(self, entry) -> bool:
        return (not self.colours or entry.colour in self.colours) and any(fnmatchcase(entry.id, p) for p in self.ids)


def _longer(lo: float, hi: float) -> MeasuredSize:
    return MeasuredSize(LONGER_SIDE, lo, hi)


def _scale(lo: float, hi: float) -> MeasuredSize:
    return MeasuredSize(SCALE, lo, hi)


POINTER_M = _longer(1.0, 1.6)  # direction, tourist and diversion pointers: their width
MIX = (
    MixPart("speed limits", 11, ("2.30-*", "2.30.1")),
    MixPart("no stopping or parking", 6, ("2.49", "2.50")),
    MixPart("end of restrictions", 3, ("2.53*", "2.55", "2.56", "2.56.1", "2.58")),
    MixPart("zone signs", 4, ("2.59.*",), size=_scale(0.95, 1.05)),
    MixPart("priority road", 8, ("3.03", "3.04")),
    MixPart("stop and give way", 5, ("3.01", "3.02")),
    MixPart("level crossings", 1, ("1.15", "1.16", "1.17", "3.22", "3.23", "3.24", "3.25"), size=_longer(0.9, 1.4)),
    MixPart("light signals", 0.5, ("3.20", "3.21", "2.65"), size=_scale(1.0, 1.5)),
    MixPart("danger and junction signs", 7, ("1.*", "3.05", "3.06", "3.07", "3.08", "3.09")),
    MixPart("information signs with a text", 2, ("2.41.2*", "4.07a", "4.10", "4.22", "4.23", "4.75", "4.76",
                                                 "4.90", "4.91", "4.93"), size=_scale(1.0, 1.3)),
    MixPart("prohibitions", 8, ("2.*",), colours=("red",)),
    MixPart("mandatory signs", 7, ("2.*",), colours=("blue",)),
    MixPart("one-way, dead end, crossings, parking", 11, ("3.10", "4.08", "4.08.1", "4.09", "4.09.1", "4.11",
                                                          "4.11a", "4.17", "4.18", "4.19", "4.20", "4.21*")),
    MixPart("white text panels", 4, tuple(sorted(TEXT_PANELS)), TEXT_PANEL),
    MixPart("place names of main roads", 2, ("4.27-*", "4.28"), POST, _longer(1.2, 2.0)),
    MixPart("direction signs", 6, ("4.32-*", "4.45", "4.46", "4.46.1", "4.47", "4.48", "4.49", "4.50.1", "4.50.3"),
            POST, POINTER_M, stack=3),
    MixPart("motorway direction signs", 3, ("4.31-*",), POST, POINTER_M, stack=2),
    MixPart("motorway and expressway signs", 2, ("4.01", "4.02", "4.03", "4.04")),
    MixPart("diversions", 6, ("4.34*",), POST, POINTER_M, stack=2),
    MixPart("tourist signs", 7, ("0.*",), POST, POINTER_M, stack=2),
    MixPart("advance direction boards", 3, ("4.35", "4.36", "4.37", "4.38", "4.39", "4.40", "4.41", "4.42*", "4.52",
                                            "4.53", "4.54", "4.55", "4.60", "4.61", "4.62"), BOARD, _longer(1.5, 3.0)),
    MixPart("motorway boards", 2, ("4.64", "4.65", "4.66", "4.67", "4.68", "4.69", "4.94"), BOARD, _longer(2.0, 4.0)),
    MixPart("lane signs", 1, ("4.77*",), BOARD, _longer(1.8, 3.0)),
    MixPart("route and number markers", 2, ("4.50.*", "4.51*", "4.56", "4.57", "4.58", "4.59*", "4.63", "4.70",
                                            "4.71", "4.72", "4.73"), size=_scale(1.0, 1.3)),
    MixPart("other information signs", 5, ("4.*",)),
)


class SignMix:
    """The parts of a mix with the catalogue's kinds each holds; picks a part by weight, then one of its kinds."""

    def __init__(self, parts: Sequence[tuple[MixPart, list[SignKind]]]):
        self.parts = [(part, kinds) for part, kinds in parts if kinds]
        weights = np.array([part.weight for part, _ in self.parts], float)
        self._cumulative = np.cumsum(weights) / weights.sum()
        self._part_of = {k.template_id: part for part, kinds in self.parts for k in kinds}

    @classmethod
    def from_catalogue(cls, catalogue, table: Sequence[MixPart] = MIX) -> SignMix:
        """Each entry of ``catalogue`` in the first part of ``table`` that holds it; raises when an entry is in
        none, or has no standard size and its part no size rule."""
        members: dict[str, list[SignKind]] = {part.name: [] for part in table}
        for entry in sorted(catalogue, key=lambda e: e.id):
            part = next((p for p in table if p.holds(entry)), None)
            if part is None:
                raise ValueError(f"catalogue entry {entry.id!r} is in no part of the sign mix")
            measured = entry.sizing == MEASURED_SIZING
            if measured and part.size is None:
                raise ValueError(f"catalogue entry {entry.id!r} has no standard size and the sign mix's part "
                                 f"{part.name!r} no size rule")
            kind = sign_kind(entry, measured=part.size if measured else None, mount=part.mount)
            if kind is not None:
                members[part.name].append(kind)
        return cls([(part, members[part.name]) for part in table])

    def part_of(self, template_id: str) -> MixPart:
        return self._part_of[template_id]

    def kinds(self, mounts: Sequence[str] = MOUNTS) -> list[SignKind]:
        return [k for part, kinds in self.parts if part.mount in mounts for k in kinds]

    def only(self, *mounts: str) -> SignMix:
        """The mix of the parts mounted one of these ways (the second sign of a stacked pole: ``only(POLE)``)."""
        return SignMix([(part, kinds) for part, kinds in self.parts if part.mount in mounts])

    def pick_part(self, rng: np.random.Generator) -> tuple[MixPart, list[SignKind]]:
        """A part by weight (one draw)."""
        k = int(np.searchsorted(self._cumulative, rng.random(), side="right"))
        return self.parts[min(k, len(self.parts) - 1)]

    def pick(self, rng: np.random.Generator) -> SignKind:
        """A kind: its part by weight, then one of the part's kinds (two draws)."""
        _, kinds = self.pick_part(rng)
        return kinds[int(rng.integers(len(kinds)))]

    def probability(self, template_id: str) -> float:
        """How likely the first sign of a pole is this id."""
        part = self.part_of(template_id)
        members = dict((p.name, kinds) for p, kinds in self.parts)[part.name]
        return part.weight / sum(p.weight for p, _ in self.parts) / len(members)

    def family_shares(self) -> dict[str, float]:
        """Share of the poles whose first sign is of each colour family (text panels: white)."""
        total = sum(part.weight for part, _ in self.parts)
        shares = dict.fromkeys(COLOURS, 0.0)
        for part, kinds in self.parts:
            for kind in kinds:
                shares[kind.colour] += part.weight / total / len(kinds)
        return shares


def pick_kind(kinds: SignMix | Sequence[SignKind], rng: np.random.Generator) -> SignKind:
    """A kind of a mix by its weights, or of a list of kinds, each equally likely (the drives of before)."""
    if isinstance(kinds, SignMix):
        return kinds.pick(rng)
    return kinds[int(rng.integers(len(kinds)))]


@lru_cache(maxsize=1)
def whole_mix() -> SignMix:
    """The mix of the bundled catalogue."""

    return SignMix.from_catalogue(load_catalogue())
