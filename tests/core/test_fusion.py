"""Fusion of per-pair detections into physical signs, on constructed observations."""

from dataclasses import replace

import numpy as np
import pytest

from signmapper_core.drive.reader import PairRecord
from signmapper_core.fusion.signs import FusionConfig, Observation, fuse_observations
from signmapper_core.geometry import Camera, Pose
from signmapper_core.pipeline.detection import Detection

WEST = np.array([-1.0, 0.0, 0.0])  # face looking west, towards a vehicle driving east
EAST = np.array([1.0, 0.0, 0.0])
CAMERA = Camera(1920, 1080, 1750.0, 1750.0, 959.5, 539.5, 0.9)  # the synthetic drives' Full-HD camera


def camera_at(pair_index: int) -> np.ndarray:
    return np.array([2.0 * pair_index, 0.0, 2.4])  # driving east, 2 m per pair


def observe(pos, pair_index, template_id="2.30-50", colour="red", shape="circle", noise=0.0, rng=None,
            normal=WEST, cls=0.9, det=0.95, fmt=("normal", 0.6, 0.6)):
    pos = np.asarray(pos, float)
    if noise and rng is not None:
        pos = pos + rng.normal(0, noise, 3)
    depth = float(np.linalg.norm(pos[:2] - camera_at(pair_index)[:2]))
    detection = Detection(template_id, "", colour, shape, fmt[1], fmt[2], fmt[0], det, cls, "accepted", 500.0, 400.0,
                          (10, 10, 40, 40), depth, pos, normal_world=normal)
    record = PairRecord(pair_index, f"{pair_index:06d}", 0.2 * pair_index, Pose(*camera_at(pair_index), 90.0, 0.0, 0.0),
                        None, None, None)
    return Observation(detection, record)


def seen_from(pos, pairs, **kwargs):
    pairs = list(pairs)
    rng = np.random.default_rng([int(1000 * c) % 2**31 for c in pos] + [pairs[0]])
    return [observe(pos, k, rng=rng, **kwargs) for k in pairs]


def test_one_sign_in_five_pairs_is_one_feature():
    truth = np.array([20.0, 3.0, 2.5])
    signs = fuse_observations(seen_from(truth, range(3, 8), noise=0.03), CAMERA)
    assert len(signs) == 1
    sign = signs[0]
    assert sign.n_obs == 5 and sign.template_id == "2.30-50" and sign.vote_share == pytest.approx(1.0)
    assert np.linalg.norm(sign.position - truth) < 0.04
    assert 0.0 < sign.sigma_m < 0.1
    assert sign.status == "accepted"
    assert sign.azimuth == pytest.approx(270.0)
    assert (sign.format, sign.width_m, sign.height_m) == ("normal", 0.6, 0.6)


def test_stacked_signs_on_one_pole_stay_apart():
    upper, lower = np.array([20.0, 3.0, 3.2]), np.array([20.0, 3.0, 2.5])
    obs = seen_from(upper, range(3, 8), noise=0.03) + seen_from(lower, range(3, 8), template_id="2.01", noise=0.03)
    signs = fuse_observations(obs, CAMERA)
    assert sorted(s.template_id for s in signs) == ["2.01", "2.30-50"]
    assert {s.n_obs for s in signs} == {5}


def test_stacked_identical_signs_stay_apart():
    upper, lower = np.array([20.0, 3.0, 3.2]), np.array([20.0, 3.0, 2.5])
    signs = fuse_observations(seen_from(upper, range(3, 8), noise=0.02) + seen_from(lower, range(3, 8), noise=0.02),
                              CAMERA)
    assert len(signs) == 2
    assert sorted(round(s.position[2], 1) for s in signs) == [2.5, 3.2]


def test_back_to_back_signs_stay_apart():
    pole = np.array([20.0, 3.0, 2.5])
    front = seen_from(pole + [-0.03, 0, 0], range(3, 8), normal=WEST, noise=0.02)
    # The back-facing sign is seen on the way back (pairs 40-44), facing east.
    back = [observe(pole + [0.03, 0, 0], k, normal=EAST, template_id="2.30-50") for k in range(40, 45)]
    signs = fuse_observations(front + back, CAMERA)
    assert len(signs) == 2
    assert sorted(round(s.azimuth) for s in signs) == [90, 270]


def test_identical_signs_a_few_metres_apart_stay_apart():
    a, b = np.array([20.0, 3.0, 2.5]), np.array([23.0, 3.0, 2.5])
    signs = fuse_observations(seen_from(a, range(3, 8), noise=0.03) + seen_from(b, range(4, 9), noise=0.03), CAMERA)
    assert len(signs) == 2
    assert all(s.n_obs == 5 for s in signs)


def test_outlier_observation_does_not_pull_the_position():
    truth = np.array([20.0, 3.0, 2.5])
    obs = seen_from(truth, range(3, 8), noise=0.01)
    obs[2].detection.position = truth + [0.25, 0.0, 0.1]  # a bad depth in one pair, still inside the gate
    sign = fuse_observations(obs, CAMERA)[0]
    assert sign.n_obs == 5
    assert np.linalg.norm(sign.position - truth) < 0.02


def test_weighted_vote_and_share():
    truth = np.array([20.0, 3.0, 2.5])
    obs = seen_from(truth, range(3, 8), noise=0.01)
    obs[1].detection.template_id = "2.30-60"
    sign = fuse_observations(obs, CAMERA)[0]
    assert sign.template_id == "2.30-50"
    assert sign.vote_share == pytest.approx(0.8)


def test_a_sign_whose_views_disagree_waits_for_review_and_says_so():
    truth = np.array([20.0, 3.0, 2.5])
    views = seen_from(truth, [3, 4, 5], cls=0.99) + seen_from(truth, [6, 7], template_id="2.30-60", cls=0.99)
    (sign,) = fuse_observations(views, CAMERA, FusionConfig(accept_classification=0.9, accept_vote_share=0.7))
    assert sign.template_id == "2.30-50" and sign.vote_share == pytest.approx(0.6)
    assert sign.status == "review" and sign.review_reason == "views disagree on the id"


def test_single_weak_observation_goes_to_review_not_dropped():
    signs = fuse_observations([observe([20.0, 3.0, 2.5], 4, cls=0.55, det=0.6)], CAMERA)
    assert len(signs) == 1 and signs[0].status == "review" and signs[0].n_obs == 1


@pytest.mark.parametrize("cls, status", [(0.95, "review"), (0.96, "review"), (0.975, "accepted")])
def test_a_sign_seen_twice_needs_two_thirds_of_the_way_from_the_classifiers_threshold(cls, status):
    """With a calibrated threshold of 0.9, the voters' mean must reach 0.9 + 2/3 x 0.1 = 0.967: a design misread
    in every view is misread with about 0.95 in each; with accept_margin 0 the threshold itself is enough."""
    seen_twice = [observe([20.0, 3.0, 2.5], k, cls=c) for k, c in ((5, cls - 0.01), (6, cls + 0.01))]
    (sign,) = fuse_observations(seen_twice, CAMERA, FusionConfig(accept_classification=0.9))
    assert sign.status == status and sign.n_obs == 2
    assert sign.review_reason == (None if status == "accepted" else "views' mean indicator below the sign's threshold")
    (sign,) = fuse_observations(seen_twice, CAMERA, FusionConfig(accept_classification=0.9, accept_margin=0.0))
    assert sign.status == "accepted"


@pytest.mark.parametrize("cls, status", [(0.975, "review"), (0.985, "accepted")])
def test_a_sign_seen_once_needs_more_than_one_seen_twice(cls, status):
    """One observation must close 40 % of the rest of the way from the threshold of a sign seen twice (0.967 with
    the classifier's 0.9) to 1: 0.98."""
    config = FusionConfig(accept_classification=0.9, accept_single_observation=True)
    signs = fuse_observations([observe([20.0, 3.0, 2.5], 6, cls=cls)], CAMERA, config)  # 8.5 m away
    assert [s.status for s in signs] == [status]


def test_by_default_a_sign_seen_once_waits_for_review_however_clear():
    (sign,) = fuse_observations([observe([20.0, 3.0, 2.5], 6, cls=0.99)], CAMERA,
                                FusionConfig(accept_classification=0.9))
    assert sign.status == "review" and sign.n_obs == 1 and sign.review_reason == "seen in one pair only"
    seen_twice = fuse_observations([observe([20.0, 3.0, 2.5], k, cls=0.99) for k in (5, 6)], CAMERA,
                                   FusionConfig(accept_classification=0.9))
    assert [s.status for s in seen_twice] == ["accepted"]


@pytest.mark.parametrize("pair, far_m, status", [(6, 14.0, "accepted"), (4, 14.0, "review"), (4, 20.0, "accepted")])
def test_a_sign_seen_once_near_the_far_limit_stays_for_review(pair, far_m, status):
    """Seen once 12.4 m away (pair 4), with the range ending at 14 m: beyond 0.85 of it, where a sign further away
    can be measured into the range, even a very clear reading waits for review; 8.5 m away (pair 6) it does not,
    nor at 12.4 m when the range reaches 20 m."""
    config = FusionConfig(accept_classification=0.9, far_m=far_m, accept_single_observation=True)
    (sign,) = fuse_observations([observe([20.0, 3.0, 2.5], pair, cls=0.99)], CAMERA, config)
    assert sign.status == status
    seen_twice = fuse_observations([observe([20.0, 3.0, 2.5], k, cls=0.99) for k in (3, 4)], CAMERA, config)
    assert [s.status for s in seen_twice] == ["accepted"]  # two observations: the rule for one does not apply


def test_same_sign_on_a_second_pass_is_merged():
    truth = np.array([20.0, 3.0, 2.5])
    first = seen_from(truth, range(3, 8), noise=0.02)
    second = seen_from(truth, range(60, 64), noise=0.02)
    signs = fuse_observations(first + second, CAMERA)
    assert len(signs) == 1 and signs[0].n_obs == 9


def test_long_gap_without_merge_gate_gives_two_tracks():
    truth = np.array([20.0, 3.0, 2.5])
    config = FusionConfig(merge_gate_m=0.0, gate_sigmas=0.0)  # no merge gate, however precise the tracks
    signs = fuse_observations(seen_from(truth, range(3, 6), noise=0.02) + seen_from(truth, range(30, 33), noise=0.02),
                              CAMERA, config)
    assert len(signs) == 2


def test_sign_read_as_two_shapes_is_one_sign_with_the_majority_class():
    """A zone panel read as its inner speed ring in some pairs: one sign, classed by the vote."""
    panel_centre = np.array([20.0, 3.0, 2.5])
    ring_centre = panel_centre + [0.0, 0.0, 0.12]
    panel = seen_from(panel_centre, [3, 4, 6], template_id="2.59.1-30", shape="rectangle", noise=0.01,
                      fmt=("normal", 0.5, 0.7))
    ring = seen_from(ring_centre, [5, 7], template_id="2.30-80", noise=0.01)
    signs = fuse_observations(panel + ring, CAMERA)
    assert len(signs) == 1
    assert signs[0].template_id == "2.59.1-30" and signs[0].n_obs == 5
    assert signs[0].vote_share == pytest.approx(0.6)
    assert np.linalg.norm(signs[0].position - panel_centre) < 0.03


def test_noisy_vertical_tilt_of_the_normals_does_not_split_a_sign():
    """An overhead sign whose fitted planes tilt up and down by 40 degrees from pair to pair."""
    truth = np.array([20.0, 3.0, 5.2])
    obs = seen_from(truth, range(3, 8), noise=0.01)
    for k, o in enumerate(obs):
        tilt = np.radians(40.0 if k % 2 else -40.0)
        o.detection.normal_world = np.array([-np.cos(tilt), 0.0, np.sin(tilt)])  # looking west, tilted
    signs = fuse_observations(obs, CAMERA)
    assert len(signs) == 1 and signs[0].n_obs == 5
    assert signs[0].azimuth == pytest.approx(270.0)


def test_two_coloured_sign_found_by_either_colour_is_one_sign():
    truth = np.array([20.0, 3.0, 5.2])
    obs = seen_from(truth, range(3, 8), template_id="4.09", shape="square", noise=0.01, fmt=("normal", 0.6, 0.6))
    for k, o in enumerate(obs):
        o.detection.colour = "red" if k % 2 else "blue"
    signs = fuse_observations(obs, CAMERA)
    assert len(signs) == 1 and signs[0].n_obs == 5 and signs[0].template_id == "4.09"


def test_observations_wrap_their_detection_and_are_linked_to_their_sign_by_id():
    truth = np.array([20.0, 3.0, 2.5])
    obs = seen_from(truth, range(3, 8), noise=0.01) + [observe([60.0, 3.0, 2.5], 25, template_id="1.01",
                                                               shape="triangle")]
    for i, o in enumerate(obs, start=1):
        o.id = i
    obs[0].detection.template_id = "2.30-60"  # the observation reads its detection, it keeps no copy
    assert obs[0].template_id == "2.30-60" and obs[0].pair_id == "000003" and obs[0].time == pytest.approx(0.6)
    signs = fuse_observations(obs, CAMERA)
    assert [s.sign_id for s in signs] == [1, 2]
    assert [o.sign_id for o in obs] == [1] * 5 + [2]
    assert {o.id for o in signs[0].observations} == {1, 2, 3, 4, 5}
    assert signs[1].colour == "red" and signs[1].shape == "triangle" and signs[1].best is obs[5]


def _merged_by_definition(tracks, config):
    """The merge rule read literally: the first pair of tracks (earlier, then later) that is one sign joins, the
    later into the earlier, and the search starts again from the beginning."""
    from signmapper_core.fusion.precision import StereoPrecision
    from signmapper_core.fusion.signs import _one_sign, _TrackSummary

    precision = StereoPrecision.of(CAMERA, config)
    summaries = {}  # a track's summary by its observations: the same track is summarised once

    def summary(track):
        key = tuple(id(o) for o in track)
        if key not in summaries:
            summaries[key] = _TrackSummary.of(track, precision)
        return summaries[key]

    tracks = [list(t) for t in tracks]
    merged = True
    while merged:
        merged = False
        for i in range(len(tracks)):
            for j in range(i + 1, len(tracks)):
                if _one_sign(summary(tracks[i]), summary(tracks[j]), config):
                    tracks[i] = sorted(tracks[i] + tracks[j], key=lambda o: o.pair_index)
                    del tracks[j]
                    merged = True
                    break
            if merged:
                break
    return tracks


@pytest.mark.parametrize("seed", range(6))
def test_track_merging_compares_neighbours_only_and_joins_in_the_order_of_its_rule(seed):
    from signmapper_core.fusion.precision import StereoPrecision
    from signmapper_core.fusion.signs import _merge_tracks

    rng = np.random.default_rng(seed)
    config = FusionConfig()
    sites = rng.uniform(0, 40, (6, 3)) * np.array([1.0, 1.0, 0.05]) + np.array([0.0, 0.0, 2.0])
    tracks = []
    for _ in range(80):  # fragments of signs at a few sites: passes, occlusions, readings of two ways
        site = sites[rng.integers(len(sites))] + rng.normal(0, 0.5 * config.merge_gate_m, 3)
        start = int(rng.integers(0, 200))
        kwargs = dict(template_id=str(rng.choice(["2.01", "2.30-50", "4.17"])),
                      colour=str(rng.choice(["red", "blue", "yellow"])),
                      normal=WEST if rng.random() < 0.8 else EAST)
        tracks.append([observe(site, k, **kwargs) for k in range(start, start + int(rng.integers(1, 4)))])
    expected = _merged_by_definition(tracks, config)
    got = _merge_tracks(tracks, config, StereoPrecision.of(CAMERA, config))
    assert len(expected) < len(tracks)  # the scene does merge
    assert [[id(o) for o in t] for t in got] == [[id(o) for o in t] for t in expected]


def doubtful(observations):
    for o in observations:
        o.detection.status = "review"
    return observations


ZONES = {"2.59.1-30": "2.30-30", "2.59.3": "2.61"}


def test_doubtful_disc_readings_of_a_zone_panel_count_for_the_panel_but_do_not_accept_it():
    truth = np.array([20.0, 3.0, 2.5])
    # the panel's white missed: its "30" disc read alone, unsure (fresh drive 1100-1109's 2.59.1 and 2.59.3)
    discs = doubtful(seen_from(truth, [3, 4, 6], template_id="2.30-80", cls=0.85))
    panel = seen_from(truth, [5], template_id="2.59.1-30", shape="rectangle", cls=0.93, fmt=("normal", 0.5, 0.7))
    (alone,) = fuse_observations(discs + panel, CAMERA)
    assert alone.template_id == "2.30-80"  # without the catalogue's zone panels
    (sign,) = fuse_observations(discs + panel, CAMERA, carried_discs=ZONES)
    assert sign.template_id == "2.59.1-30" and sign.vote_share == pytest.approx(1.0) and sign.n_obs == 4
    assert (sign.format, sign.width_m, sign.height_m) == ("normal", 0.5, 0.7)  # from the panel's own reading
    assert sign.status == "review"  # one view read the panel: a person confirms it
    more = seen_from(truth, [7], template_id="2.59.1-30", shape="rectangle", cls=0.95, fmt=("normal", 0.5, 0.7))
    (seen_twice,) = fuse_observations(discs + panel + more, CAMERA, carried_discs=ZONES)
    assert seen_twice.template_id == "2.59.1-30" and seen_twice.status == "accepted"


def test_only_a_confident_panel_reading_claims_discs_and_only_its_own_disc():
    truth = np.array([20.0, 3.0, 2.5])
    discs = doubtful(seen_from(truth, [3, 4, 6], template_id="2.30-80", cls=0.85))
    unsure_panel = doubtful(seen_from(truth, [5], template_id="2.59.1-30", shape="rectangle", cls=0.7))
    (sign,) = fuse_observations(discs + unsure_panel, CAMERA, carried_discs=ZONES)
    assert sign.template_id == "2.30-80"  # a doubtful panel reading does not outvote three discs
    blue = seen_from(truth, [5], template_id="2.59.3", shape="rectangle", colour="blue", cls=0.95)
    signs = fuse_observations(discs + blue, CAMERA, carried_discs=ZONES)
    assert "2.30-80" in {s.template_id for s in signs}  # a pedestrian-zone panel does not claim speed limits


def test_a_disc_sign_read_clearly_stays_itself_though_read_as_a_zone_panel_from_afar():
    truth = np.array([20.0, 3.0, 2.5])
    # drive 1107: a 2.30-100 over a plate read as 2.59.1 at 13.6 m (0.98), then as itself at 1.00 three times
    afar = seen_from(truth, [3], template_id="2.59.1-30", shape="rectangle", cls=0.98)
    near = seen_from(truth, [4, 5, 6], template_id="2.30-100", cls=1.0)
    (sign,) = fuse_observations(afar + near, CAMERA, carried_discs=ZONES)
    assert sign.template_id == "2.30-100" and sign.status == "accepted"
    # drive 1088: a 2.14 over a plate read as 2.59.1 at 13 and 11 m, as 2.14 at 9 and 7 m (no speed limit)
    afar = seen_from(truth, [3, 4], template_id="2.59.1-30", shape="rectangle", cls=0.99, det=0.97)
    near = doubtful(seen_from(truth, [5, 6], template_id="2.14", cls=1.0, det=0.99))
    (sign,) = fuse_observations(afar + near, CAMERA, carried_discs=ZONES)
    assert sign.template_id == "2.14"


def test_a_plate_is_accepted_on_the_classifiers_threshold_without_the_signs_margin():
    """The plate step's score is no probability of the network: the margin set on the network's misreadings of
    signs (accept_margin) must not send clear plates to review."""
    from signmapper_core.plates.fusion import fuse_plates

    config = FusionConfig(accept_classification=0.9)
    signs_seen = [observe([20.0, 3.0, 2.5], k, cls=0.99) for k in (5, 6)]
    plates_seen = [observe([20.0, 3.0, 2.0], k, template_id="5.xx", cls=0.93) for k in (5, 6)]
    for plate, sign in zip(plates_seen, signs_seen):
        plate.detection.plate_of = sign.detection
    (sign,) = fuse_observations(signs_seen, CAMERA, config)
    (plate,) = fuse_plates(signs_seen + plates_seen, [sign], CAMERA, config)
    assert sign.status == "accepted" and plate.plate_of == sign.sign_id
    assert plate.status == "accepted" and plate.classification_indicator == pytest.approx(0.93)


def test_views_held_for_review_make_no_accepted_sign_on_their_own():
    """Detection holds some readings for review whatever their score (a disc inside a white panel, a Hough circle
    without a full-colour ring): four such views at 0.99 give a sign for review; one accepted view among them is
    enough."""
    truth = np.array([20.0, 3.0, 2.5])
    held = doubtful(seen_from(truth, [3, 4, 5, 6], template_id="2.30-30", cls=0.99))
    held[0].detection.review_reason = "a zone panel's disc read alone"
    (sign,) = fuse_observations(held, CAMERA, FusionConfig(accept_classification=0.9))
    assert sign.template_id == "2.30-30" and sign.status == "review"
    # the reason names what held the views: a rule, or for views without one their indicator
    assert sign.review_reason == ("no view accepted: a zone panel's disc read alone; "
                                  "indicator below the acceptance threshold")
    held[2].detection.status = "accepted"
    (sign,) = fuse_observations(held, CAMERA, FusionConfig(accept_classification=0.9))
    assert sign.status == "accepted"


def test_a_zone_panels_disc_held_for_review_counts_for_the_panel_read_once():
    """Drive 1172: a 2.59.3 panel read as its disc (2.61) at 12.9 and 6.0 m, confidently, and as the panel at
    8.3 m. Held for review (inside white at its own depth), the disc views count for the panel."""
    truth = np.array([20.0, 3.0, 2.5])
    panel = seen_from(truth, [5], template_id="2.59.3", shape="rectangle", colour="blue", cls=1.0,
                      fmt=("normal", 0.6, 0.9))
    discs = seen_from(truth, [3, 7], template_id="2.61", colour="blue", cls=0.97, det=0.98)
    (sign,) = fuse_observations(discs + panel, CAMERA, carried_discs=ZONES)
    assert sign.template_id == "2.61"  # confident disc readings outvote the panel
    (sign,) = fuse_observations(doubtful(discs) + panel, CAMERA, carried_discs=ZONES)
    assert sign.template_id == "2.59.3" and sign.n_obs == 3 and sign.vote_share == pytest.approx(1.0)


def _held(observations, reason):
    for o in observations:
        o.detection.status, o.detection.review_reason = "review", reason
    return observations


def test_a_sign_read_only_off_format_or_as_unknown_is_mapped_when_seen_twice():
    from signmapper_core.output.review_reasons import NO_ENTRY_MATCHES, OFF_FORMAT

    near, cone, other = np.array([20.0, 3.0, 2.5]), np.array([40.0, -3.0, 0.3]), np.array([60.0, 3.0, 2.5])
    obs = (_held(seen_from(near, [3], fmt=("measured", 0.3, 0.3)), OFF_FORMAT)
           + _held(seen_from(cone, [12], template_id="unknown", colour="orange"), NO_ENTRY_MATCHES)
           + _held(seen_from(other, [22, 23], fmt=("measured", 0.3, 0.3)), OFF_FORMAT)
           + _held(seen_from(near + [0, 40, 0], [30]), ""))  # another reading held once: mapped, in review
    within = FusionConfig(far_m=60.0)  # these views are 14-58 m away: a range fixed to 60 m holds them
    signs = fuse_observations(obs, CAMERA, within)
    assert [(s.n_obs, s.status) for s in signs] == [(2, "review"), (1, "review")]
    assert np.linalg.norm(signs[0].position - other) < 0.01
    assert [o.sign_id for o in obs] == [None, None, 1, 1, 2]  # the views of no sign belong to none
    assert len(fuse_observations(obs, CAMERA, replace(within, doubtful_min_views=1))) == 4


def test_a_sign_seen_only_beyond_far_is_mapped_when_seen_twice():
    """Issue 45: beyond far (the reach) one view places a face to a metre at best; a car's rear lights ahead of a
    drive's last pair were read as boards once each."""
    config = FusionConfig(far_m=14.0)
    once_far, twice_far, once_near = np.array([40.0, 3.0, 2.5]), np.array([80.0, 3.0, 2.5]), np.array([120.0, 3.0, 2.5])
    obs = (seen_from(once_far, [10])  # 20 m away, seen once
           + seen_from(twice_far, [29, 30])  # 22 and 20 m away
           + seen_from(once_near, [55]))  # 10 m away, seen once
    assert [round(o.depth_m) for o in obs] == [20, 22, 20, 10]
    signs = fuse_observations(obs, CAMERA, config)
    assert [s.n_obs for s in signs] == [2, 1]
    assert np.linalg.norm(signs[0].position - twice_far) < 0.05 and np.linalg.norm(signs[1].position - once_near) < 0.05
    assert len(fuse_observations(obs, CAMERA, FusionConfig(far_m=14.0, far_min_views=1))) == 3
    assert len(fuse_observations(obs, CAMERA, FusionConfig(far_m=30.0))) == 3  # a range fixed to 30 m: all within


def test_views_reading_no_catalogue_sign_do_not_outvote_one_that_reads_an_id():
    from signmapper_core.output.review_reasons import NO_ENTRY_MATCHES

    truth = np.array([20.0, 3.0, 2.5])
    unknown = _held(seen_from(truth, [3, 6], template_id="unknown", cls=0.94), NO_ENTRY_MATCHES)
    named = seen_from(truth, [4, 5], template_id="3.07", colour="red", cls=0.8)
    (sign,) = fuse_observations(unknown + named, CAMERA)
    assert sign.template_id == "3.07" and sign.status == "review"
    assert sign.vote_share == pytest.approx(0.8 / (0.8 + 0.94))  # the unknown views' weight kept in the share
    (alone,) = fuse_observations(_held(seen_from(truth, [3, 6], template_id="unknown", cls=0.94),
                                       NO_ENTRY_MATCHES), CAMERA)
    assert alone.template_id == "unknown"
