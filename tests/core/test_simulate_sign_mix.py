"""Streets of the whole catalogue (issue 44, item 6): every family in the mix's proportions, faces printed from the
masters and their variants, signs without a standard size at the sizes and heights of their part, reproducible."""

from __future__ import annotations

from collections import Counter

import numpy as np
import pytest

from signmapper_core.catalogue import load_catalogue
from signmapper_core.catalogue.model import COLOURS
from signmapper_core.catalogue.text_panels import is_text_panel
from signmapper_core.drive.reader import read_truth
from signmapper_core.geometry import world_to_pixel
from signmapper_core.simulate import SimulationConfig, generate_drive
from signmapper_core.simulate.face_artwork import MASTER, drawing_stems, has_procedural, master_face, pointing
from signmapper_core.simulate.faces import LONGER_SIDE, FaceOptions, SignFace, draw_sign_face, pick_format
from signmapper_core.simulate.generator import make_scene, make_street
from signmapper_core.simulate.layout import CARRIAGEWAY
from signmapper_core.simulate.panels import PanelLook
from signmapper_core.simulate.scene_pieces import KERB_H, Pieces, TextureKeys
from signmapper_core.simulate.sign_mix import BOARD, MIX, POST, MixPart, SignMix, whole_mix
from signmapper_core.simulate.sign_mounts import (
    BOARD_LOWER_EDGE_M,
    KERB_CLEAR_M,
    POST_LOWER_EDGE_M,
    sign_post,
)
from signmapper_core.simulate.street_body import FacadeSpan

LONG = SimulationConfig(pairs=1500, seed=8601, distractor_density=0.0, plate_share=0.0)


class StreetFrame:
    """(s, lateral, height above the road) of world points near a street, from its centreline sampled once."""

    def __init__(self, street, step_m: float = 0.05):
        self.ss = np.arange(0.0, street.length, step_m)
        self.centre, self.forward, self.right = street.point(self.ss), street.forward(self.ss), street.right(self.ss)

    def __call__(self, point) -> tuple[float, float, float]:
        rel = np.asarray(point, float) - self.centre
        along = np.einsum("ij,ij->i", rel[:, :2], self.forward[:, :2])
        near = np.linalg.norm(rel[:, :2], axis=1) < 30
        k = int(np.argmin(np.where(near, np.abs(along), np.inf)))
        return float(self.ss[k]), float(np.dot(rel[k], self.right[k])), float(rel[k][2])


@pytest.fixture(scope="module")
def long_street():
    """A 3 km street of the whole catalogue, laid out only (no pixels): its frame and its signs' truth rows."""
    scene = make_scene(LONG)
    return StreetFrame(scene.street), [t for t in scene.truth if not t.is_plate]


def spots(frame: StreetFrame, truth) -> list[list]:
    """The truth rows grouped by sign spot (spots stand at least 4 m apart along the street), lowest first."""
    placed = sorted(((frame(t.position), t) for t in truth), key=lambda item: item[0][0])
    groups: list[list] = []
    for (s, _lat, _h), t in placed:
        if groups and s - groups[-1][-1][0] < 2.0:
            groups[-1].append((s, t))
        else:
            groups.append([(s, t)])
    return [sorted((t for _, t in group), key=lambda t: t.height - t.height_m / 2) for group in groups]


def test_every_catalogue_id_is_in_one_part_and_is_placed_sometimes():
    mix, catalogue = whole_mix(), load_catalogue()
    assert sorted(k.template_id for k in mix.kinds()) == sorted(catalogue.ids())
    for entry in catalogue:
        first = next(p for p in MIX if p.holds(entry))
        assert mix.part_of(entry.id) is first
        assert mix.probability(entry.id) > 0
    assert sum(mix.probability(i) for i in catalogue.ids()) == pytest.approx(1.0)
    # a measured sign needs a size rule in its part, an id a part at all
    with pytest.raises(ValueError, match="no standard size"):
        SignMix.from_catalogue(catalogue, (MixPart("all", 1, ("*",)),))
    with pytest.raises(ValueError, match="in no part"):
        SignMix.from_catalogue(catalogue, MIX[:3])


def test_picks_follow_the_weights_of_the_parts():
    mix = whole_mix()
    rng = np.random.default_rng(1)
    n = 20000
    counts = Counter(mix.pick_part(rng)[0].name for _ in range(n))
    total = sum(part.weight for part, _ in mix.parts)
    chi2 = sum((counts[part.name] - n * part.weight / total) ** 2 / (n * part.weight / total) for part, _ in mix.parts)
    assert chi2 < 60  # 25 parts: p < 1e-4 beyond 60
    assert counts["speed limits"] > 5 * counts["lane signs"]


def test_a_long_street_shows_every_family_in_the_proportions_of_the_mix(long_street):
    frame, truth = long_street
    colour = {e.id: e.colour for e in load_catalogue()}
    # every family appears, and every kind of mounting
    assert set(COLOURS) <= {colour[t.template_id] for t in truth}
    mix = whole_mix()
    assert {POST, BOARD} <= {mix.part_of(t.template_id).mount for t in truth}
    # the lowest sign of each spot is the one drawn from the mix by weight: its family follows the mix's shares
    firsts = [group[0] for group in spots(frame, truth)]
    assert len(firsts) > 250
    found = Counter(colour[t.template_id] for t in firsts)
    expected = mix.family_shares()
    chi2 = sum((found[c] - len(firsts) * expected[c]) ** 2 / (len(firsts) * expected[c]) for c in COLOURS)
    assert chi2 < 22.5, (found, expected)  # 6 degrees of freedom: p < 0.001 beyond 22.5
    # regulatory and everyday information signs outnumber the rare kinds by far
    parts = Counter(mix.part_of(t.template_id).name for t in firsts)
    rare = parts["lane signs"] + parts["motorway boards"] + parts["level crossings"] + parts["light signals"]
    assert parts["speed limits"] + parts["one-way, dead end, crossings, parking"] > 2.5 * rare  # 4.9 times in the mix


def test_faces_show_the_masters_and_their_variants(long_street):
    _frame, truth = long_street
    printed = [t for t in truth if t.artwork == MASTER]
    assert printed and all(t.drawing in drawing_stems(t.template_id) for t in printed)
    with_variants = [t for t in printed if len(drawing_stems(t.template_id)) > 1]
    assert sum("~" in t.drawing for t in with_variants) > 0.3 * len(with_variants)
    assert sum("~" not in t.drawing for t in with_variants) > 0.3 * len(with_variants)
    # procedural faces only of the signs the drawer knows, and no drawing named for them
    assert all(has_procedural(t.template_id) and not t.drawing for t in truth if t.artwork == "procedural"
               and not is_text_panel(t.template_id))


def test_a_pointer_variant_points_the_other_way_and_is_printed_so():
    assert pointing("4.32-1", 0) == -1 and pointing("4.32-1", 1) == 1
    shown = set()
    for seed in range(12):
        face = SignFace("4.32-1", (200, 50), 1.2, seed, seed, FaceOptions(face_print=False, face_sheeting=False,
                                                                         face_wear=False, face_dirt=False))
        _bgr, alpha = face.clean()
        # the pointed end covers less of its edge column than the blunt end
        left, right = alpha[:, :6].mean(), alpha[:, -6:].mean()
        assert (right < left) == (face.drawing == 1)
        shown.add(face.drawing)
        assert SignFace("4.32-1", (200, 50), 1.2, seed, seed, FaceOptions(face_variants=False)).drawing == 0
    assert shown == {0, 1}


def test_signs_without_a_standard_size_are_sized_and_mounted_as_their_part_says(long_street):
    frame, truth = long_street
    mix, catalogue = whole_mix(), load_catalogue()
    measured = [t for t in truth if catalogue[t.template_id].sizing == "measured"]
    assert len(measured) > 60
    for t in measured:
        part, entry = mix.part_of(t.template_id), catalogue[t.template_id]
        rule = part.size
        nominal_w, nominal_h = next(iter(entry.formats.values()))
        value = max(t.width_m, t.height_m) if rule.rule == LONGER_SIDE else t.width_m / nominal_w
        assert rule.lo - 0.01 <= value <= rule.hi + 0.01, (t.template_id, t.width_m, t.height_m)
        assert t.width_m / t.height_m == pytest.approx(nominal_w / nominal_h, rel=0.01)
        _s, lateral, height = frame(t.position)
        lower = height - t.height_m / 2
        overhead = CARRIAGEWAY[0] < lateral < CARRIAGEWAY[1]
        if overhead:
            assert lower > 4.2
        elif part.mount == BOARD:
            assert BOARD_LOWER_EDGE_M[0] + KERB_H - 0.05 <= lower <= BOARD_LOWER_EDGE_M[1] + KERB_H + 0.05
        elif part.mount == POST:
            assert lower >= POST_LOWER_EDGE_M[0] + KERB_H - 0.05  # the lowest, or one stacked above it
        if not overhead:  # clear of the carriageway (and of the parking lane on the left)
            edge = CARRIAGEWAY[1] if lateral > 0 else CARRIAGEWAY[0] - 2.0
            assert abs(lateral) - t.width_m / 2 >= abs(edge) + KERB_CLEAR_M[0] - 0.05, t.template_id
    widths = {mix.part_of(t.template_id).name: [] for t in measured}
    for t in measured:
        widths[mix.part_of(t.template_id).name].append(max(t.width_m, t.height_m))
    assert 1.0 <= min(widths["direction signs"]) and max(widths["direction signs"]) <= 1.6
    assert max(max(widths.get("motorway boards", [0])), max(widths.get("advance direction boards", [0]))) >= 2.0


def test_a_post_carries_what_fits_before_the_facade():
    street = make_street(SimulationConfig(pairs=10, seed=3))
    frame = StreetFrame(street)
    look = PanelLook(1750.0, FaceOptions(), weathering=False, shadows=False, occlusion=False)
    pointers = [k for k in whole_mix().kinds([POST]) if k.shape == "pointer"]
    narrow = [FacadeSpan(0.0, 60.0, CARRIAGEWAY[1] + 2.2, 1, 0.0, 10.0)]  # 2.2 m from the kerb to the façade
    counts = Counter()
    for seed in range(16):
        placed = sign_post(Pieces(street, TextureKeys(seed)), look, 30.0, pointers, 3, np.random.default_rng(seed),
                           1, narrow)
        counts[len(placed)] += 1
        for p in placed:
            _s, lateral, _h = frame(p.truth.position)
            assert lateral - p.truth.width_m / 2 >= CARRIAGEWAY[1] + KERB_CLEAR_M[0] - 0.01
            assert lateral + p.truth.width_m / 2 <= CARRIAGEWAY[1] + 2.2 + 0.01
        heights = sorted(p.truth.height for p in placed)
        assert all(b - a > 0.1 for a, b in zip(heights, heights[1:]))  # stacked, not side by side
    assert counts[1] and sum(n for k, n in counts.items() if k > 1)  # pointers both ways fit only sometimes


def test_the_same_seed_gives_the_same_drive(tmp_path):
    config = dict(pairs=2, seed=8602, width=320, height=180, fx=1750.0 / 6, sign_density=40.0)
    generate_drive(tmp_path / "a", SimulationConfig(**config))
    generate_drive(tmp_path / "b", SimulationConfig(**config))
    files = sorted(p.relative_to(tmp_path / "a") for p in (tmp_path / "a").rglob("*") if p.is_file())
    assert len(files) >= 6
    for name in files:
        assert (tmp_path / "a" / name).read_bytes() == (tmp_path / "b" / name).read_bytes(), name
    truth = read_truth(tmp_path / "a" / "truth.csv")
    assert truth and all(t.drawing or t.artwork != MASTER for t in truth if not t.is_plate)
    other = make_scene(SimulationConfig(**dict(config, seed=8603)))
    assert [t.template_id for t in other.truth] != [t.template_id for t in truth]


def test_a_face_of_a_sign_the_drawer_does_not_know_is_printed_from_its_drawing():
    face = draw_sign_face("0.1", (120, 30), 1.2, np.random.default_rng(0), FaceOptions())
    assert face.artwork == MASTER
    bgr, alpha = face.pixels()
    assert bgr.shape == (30, 120, 3) and alpha.max() == 255


def test_a_rendered_drive_shows_each_sign_where_its_truth_says(tmp_path):
    """Posts, boards and overhead signs are seen at their truth centre (not hidden in a façade or behind a pole)."""
    config = SimulationConfig(pairs=10, seed=8607, width=640, height=360, fx=1750.0 / 3, sign_density=25.0,
                              write_depth=True)
    summary = generate_drive(tmp_path / "drive", config)
    header = (tmp_path / "drive" / "truth.csv").read_text(encoding="utf-8").splitlines()[0]
    assert header.endswith(",face_artwork,face_drawing")
    drive_truth = read_truth(tmp_path / "drive" / "truth.csv")
    signs = [t for t in drive_truth if not t.is_plate]
    assert len(signs) >= 3 and sum(whole_mix().part_of(t.template_id).mount == POST for t in signs) == 3
    checks = hits = 0
    for k, pose in enumerate(summary.true_poses):
        depth = np.load(tmp_path / "drive" / "depth" / f"{k:06d}.npy")
        for sign in signs:
            u, v, z = (float(np.ravel(x)[0]) for x in world_to_pixel(summary.camera, pose, sign.position))
            if not (4.0 <= z <= 14.0 and 10 <= u < config.width - 10 and 10 <= v < config.height - 10):
                continue
            checks += 1
            hits += abs(float(depth[int(round(v)), int(round(u))]) - z) < 0.05
    assert checks >= 5 and hits >= 0.8 * checks


def test_every_drawing_of_every_entry_prints():
    """Each entry's master and variants print at the size the generator gives it (every id is placed sometimes)."""
    rng = np.random.default_rng(0)
    for kind in whole_mix().kinds():
        if is_text_panel(kind.template_id):
            continue  # set from their wording (test_simulate_text_panels.py)
        _name, w_m, h_m = pick_format(kind, rng)
        size = (64, max(1, round(64 * h_m / w_m))) if w_m >= h_m else (max(1, round(64 * w_m / h_m)), 64)
        for drawing in range(len(drawing_stems(kind.template_id))):
            bgr, alpha = master_face(kind.template_id, size, rng, drawing)
            assert bgr.shape[:2] == alpha.shape == (size[1], size[0]), kind.template_id
            assert alpha.mean() > 60, (kind.template_id, drawing)  # the outline fills a good part of its box
