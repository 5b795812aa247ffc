"""Settings of the detection pipeline: one frozen section per step, so a run is reproducible.

Defaults follow Cavegn (2011): a 4-14 m search space in front of the camera and
HSV thresholds for the sign colours (``sign_colours``). Hue is OpenCV's 0-179
scale. Every threshold of a step is a field of that step's section, with its
reason; the step functions take them from the config and declare no defaults
of their own. A setting's name is unique across the sections (a search for it
finds every use, and a record of before the sections maps it back by name). A
run's output records every section (``run_settings``), so the run can be
repeated from its output; fusion's settings are ``fusion.FusionConfig``.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from typing import Any, Dict, Mapping, Optional, Tuple

from ..sign_colours import HOUGH_TINT_HUES, HSV_RANGES, SIGN_COLOURS, WEAK_HUES, HsvRange
from .classifier_names import CLASSIFIERS

DEFAULT_HSV_RANGES = HSV_RANGES  # the name the steps' tests use


@dataclass(frozen=True)
class ColourConfig:
    """Colour segmentation (step 3): which colours, their HSV thresholds, and what a usable segment is."""

    colours: Tuple[str, ...] = SIGN_COLOURS
    hsv_ranges: Dict[str, Tuple[HsvRange, ...]] = field(default_factory=lambda: dict(DEFAULT_HSV_RANGES))
    morph_open_px: int = 3  # removes speckle
    morph_close_px: int = 5  # bridges small gaps in a sign's ring
    min_segment_px: int = 150  # smaller segments cannot be sized or classified reliably
    # ...unless the colour is only a part of its face: a yellow diamond fills a quarter of a German priority
    # road's box (a 30 px face: a 15 px diamond of ~110 px)
    min_part_px: Dict[str, int] = field(default_factory=lambda: {"yellow": 90})
    min_bbox_px: int = 12
    border_margin_px: int = 2  # segments this close to the image border are cut and rejected
    # every sign outline is convex: a less solid one is a face bitten into (an occluder, a pictogram touching the
    # edge), which its convex hull restores
    min_solidity: float = 0.85
    # the field inside a ring is a segment of its own when the ring's outline is spoilt by a neighbour
    # of the same colour; only red faces have rings/borders around a field (blue fields are pictograms)
    hole_colours: Tuple[str, ...] = ("red",)
    min_hole_px: int = 60  # the field of a 30 px triangle is ~200 px; smaller holes are letters and gaps
    # an outer outline at most this x its field's box is just the ring around it (Swiss rings: 1.21 x the field
    # for circles, 1.4-1.56 for triangles), so the field is the segment; a larger outline has a neighbour in it
    max_ring_ratio: float = 1.6
    # morphology scaled to the ring: a round sign's ring is ~9.5 % of its diameter (SSV prohibition signs)
    ring_fraction: float = 0.09
    min_face_px: int = 16  # smallest face to find without depth (GTSDB's smallest signs); sets the small pass
    max_merge_pieces: int = 40  # rejected segments tried in pairs (faces split by an occluder)
    # a red diamond may be the middle of a priority road at dusk, its yellow turned dark orange (hue 5-13): no red
    # sign is a diamond
    red_diamonds_as_yellow: bool = True
    merge_max_gap: float = 0.35  # two pieces of one face are at most this x the merged box's size apart
    merge_max_aspect: float = 2.0  # ...and their merged box is at most this much longer than wide: beyond it the
    # pieces are two faces one above the other (a sign and the one under it), not one face cut by a bar or pole
    # a bar (2.02) or a pole cuts a face into pieces stacked along one axis: they overlap along the other by this
    # share of the shorter one...
    split_min_span_overlap: float = 0.6
    # a bar along the diagonal (3.04, end of the priority road) cuts a diamond's colour into two halves offset
    # along both axes: their boxes overlap by about half along each (a clean 3.04: 0.48 and 0.48)
    split_min_diagonal_overlap: float = 0.3
    split_min_gain: float = 0.05  # ...and their hull fits an ideal outline this much better than either piece
    # a pole in front of a direction board leaves two rectangles side by side, edges level within board_edge_align
    # of their height, at most board_max_gap of it apart, together at least board_min_aspect times as wide as high
    board_edge_align: float = 0.12
    board_max_gap: float = 0.6
    board_min_aspect: float = 2.0

    def __post_init__(self):
        unknown = set(self.colours) - set(self.hsv_ranges)
        if unknown:
            raise ValueError(f"no HSV thresholds for colours {sorted(unknown)}")


@dataclass(frozen=True)
class SceneConfig:
    """The scene pass (scene_colour.py): colour floors read from the image, for faded, dim and cast signs."""

    # scene-adaptive colour: a second pass with saturation/value floors from the image
    # remove the scene's colour cast before the scene pass reads hues. Off by default: on GTSDB's tune split it
    # found 1 more of 127 signs (casts there stay under 6 %), but on synthetic drives, whose exposure model
    # casts 3-7 % in most pairs, it cost ~10 ms of 76 per Full-HD pair (given depth)
    white_balance: bool = False
    neutral_max_saturation: int = 40  # below this saturation (0-255) a pixel is grey seen in a cast (10 % cast: ~25);
    # higher lets beige façades pass for grey and tints the road blue (synthetic drives)
    max_white_balance_gain: float = 1.2  # a scene of mostly one colour (hedge, sky) must not be over-corrected
    white_balance_min_change: float = 0.03  # gains all within this of 1 leave the image as it is: so slight a cast
    # moves no hue across a class border, and skipping it saves two full-frame passes
    neutral_value_range: Tuple[int, int] = (41, 239)  # a neutral pixel is neither dark (noise) nor clipped
    neutral_min_share: float = 0.02  # with fewer neutral pixels (of the sampled image) the scene is left as it is
    weak_colour: bool = True
    # colours the scene pass looks for: faded red rings and dim or orange-yellow priority roads (3.03) were
    # misses on GTSDB's tune split (weak yellow: +11 of 382 signs >= 30 px, +2.3 candidates per image);
    # weak blue finds dark and overexposed blue discs (GTSRB tune crops: 2.34-2.41 face found 78 % -> 83 %; GTSDB
    # tune split: +6 of 158 signs < 30 px, none >= 30 px) kept only as sharp discs (weak_shapes, weak_min_fit; any
    # weak blue outline was sky and tinted asphalt: 16 segments per synthetic image, +2.3 candidates per GTSDB
    # image); not looked for by default: +0.4 candidates and ~7 ms per full GTSDB image
    weak_colours: Tuple[str, ...] = ("red", "yellow")
    weak_hues: Dict[str, Tuple[Tuple[int, int], ...]] = field(default_factory=lambda: dict(WEAK_HUES))
    # outlines the scene pass keeps per colour (others: any ideal outline): the catalogue's yellow faces are
    # diamonds (3.03, 3.04); weak yellow of other outlines is beige façade (synthetic drives: +60 % stereo rows)
    weak_shapes: Dict[str, Tuple[str, ...]] = field(default_factory=lambda: {"yellow": ("diamond",),
                                                                             "blue": ("circle",)})
    # the scene pass's segments of these colours need at least this outline fit (others: min_shape_fit); blue at
    # 0.8 instead: +0.6 candidates per GTSDB image for no more signs
    weak_min_fit: Dict[str, float] = field(default_factory=lambda: {"blue": 0.86})
    weak_sat_factor: float = 1.0  # weak saturation floor = factor * the scene's median saturation + offset
    weak_sat_offset: float = 30.0  # GTSDB tune split: at 20, one more of 127 signs but 40 % more candidates
    weak_sat_min: int = 25  # below this, grey road and sky noise turns red/blue; Hough takes paler rims
    weak_min_chroma: int = 16  # max-min of B, G, R: a dark pixel's saturation is mostly noise (tune: 10 -> 16
    # same signs found, 18 % fewer candidates)
    weak_val_factor: float = 0.35  # weak value floor from the scene's median brightness: a dim sign in a dark
    # scene keeps about a third of the scene's brightness (GTSDB dusk scenes: rings at V 35-80, median ~110)
    weak_val_min: int = 30  # darker pixels carry no reliable hue (JPEG steps of 5 are already 40 saturation)
    weak_max_surround: float = 0.03  # a weak segment whose surrounding band is this coloured is background
    weak_surround_px: float = 0.2  # that band follows the outline, this x the segment's size wide: within the
    # white rim of a priority road (0.5 x its yellow), whose autumn trees are yellow too (a band around the
    # box reached them). GTSDB tune split, signs >= 30 px: 0.1 -> 0.03 found 2 more (fewer false segments
    # displaced true ones), 18.9 -> 15.6 candidates per image; 0.01 lost 4, 0 lost 14
    pass_duplicate_iou: float = 0.5  # a later pass's segment overlapping an earlier one this much is the same
    scene_sample_step: int = 4  # the scene's statistics (white balance, medians) are read on every this-th pixel of
    # every this-th row: 1/16 of the cost at 4, the same percentiles


@dataclass(frozen=True)
class BrightFieldConfig:
    """White fields inside red rings found by brightness (bright_fields.py).

    In dim light a ring keeps no usable saturation, but its field is still
    brighter than it and the ring still redder than the field.
    """

    field_pass: bool = True
    field_scale: float = 0.5  # fields are sought on the grey image at this scale at most...
    field_min_side_px: float = 8.0  # ...or less, where the smallest field sought stays this wide: a 4-14 m
    # search space's smallest face (50 px at Full HD, field 30 px) is read at 1/3, half the cost at 0.5
    field_first_level: int = 12  # darkest grey threshold: dusk fields on GTSDB are 30-60 with rings of 15-25
    field_level_ratio: float = 1.25  # next threshold = this x the last: a ring darker than its field by this
    # ratio separates them at some level (GTSDB tune split: ring/field brightness 0.3-0.6 for 90 % of signs)
    # smallest field side (px): the field of a 30 px triangle is ~20 x 17; smaller components (leaves, windows,
    # JPEG blocks) were 80 % of all (GTSDB tune split) and hardly a sign among them
    field_min_px: int = 16
    field_of_face: float = 0.6  # a ring's field is at least this share of its face's side (Swiss triangles 0.64,
    # circles 0.83): the smallest field sought for the smallest face
    field_min_fill: float = 0.35  # component area / box: a field's fill is 0.5 (triangle) to 0.79 (disc)
    field_max_fill: float = 0.95
    # a pictogram reaching the ring (a curve arrow, a worker) bites into the field: a component that is no field is
    # judged by its convex hull when it fills at least this share of it (1.0: never)
    field_min_solidity: float = 0.7
    # ...and only when the hull is one of these shapes: danger triangles carry pictograms up to their ring; the
    # hull of a bright blot in a reddish surround fits a circle or an octagon all too often (GTSDB tune split:
    # 790 circle and octagon hulls in 434 photographs, 2 % on signs; 21 triangles, 9 on signs)
    field_hull_shapes: Tuple[str, ...] = ("triangle",)
    # a bitten component fills less of its box than a field does: down to this share it is judged by its hull
    field_min_bitten_fill: float = 0.28
    field_max_aspect: float = 1.6  # longer / shorter box side: a disc turned 50 deg; no field on a sign of the
    # tune split was longer (a fifth of all components are)
    field_same_iou: float = 0.85  # a component whose box overlaps one of a lower level this much is that one
    # ... unless it lost this share of its pixels: then the level split off the ring's lighter pixels that a
    # lower level joined to the field (GTSDB tune split: thin dusk rings, a field's fill 0.82 -> 0.68)
    field_same_area_drop: float = 0.1
    field_ring_fraction: float = 0.12  # band around a field read as its ring, x the field's size (SSV: 0.11)
    # the ring's colour relative to its field (per channel band / field): GTSDB tune split, components
    # with a field's box and fill: red rings R/G, R/B 1.2-2.2 (10th-75th percentile), other
    # components 1.0-1.25 (25th-90th); the band is darker than the field on signs (median 0.49)
    field_ring_min_red_green: float = 1.15
    field_ring_min_red_blue: float = 1.05
    field_ring_max_brightness: float = 0.85
    # a component is first judged on the reduced image by means, asking this share of each margin above
    # (GTSDB tune split: 15 % of the components pass, every field later kept on a sign among them)
    field_coarse_share: float = 0.5
    # a ring in the dark loses its colour in the camera (GTSDB tune split: dusk danger triangles, ring/field R/G
    # 1.00-1.08, brightness 0.47-0.63): a ring this much darker than its field and of no other colour (R/G, R/B at
    # least dark_ring_min_ratio) still counts when the field is a triangle fitting its ideal outline this well
    dark_ring_max_brightness: float = 0.7
    dark_ring_min_ratio: float = 0.97
    dark_ring_min_fit: float = 0.88
    # ...or this well when the field itself is dim (mean of B, G, R at most dark_field_max_brightness): at dusk a
    # field of 20-40 keeps a blurred outline (GTSDB tune split: dusk triangles fit 0.69-0.78), while a field this
    # dim is rare in daylight scenes, so the looser floor adds few outlines there (1.0: never looser)
    dark_field_min_fit: float = 0.69
    dark_field_max_brightness: float = 45.0
    dark_ring_max_level: int = 57  # ...on grey levels up to this (tune split: dusk fields separate at 15-46)
    field_min_inside_share: float = 0.5  # the pass reads the whole image: a field counts with this share inside
    # the search space (one mostly outside it is another depth's)
    # a field whose box lies inside a colour segment's box (give or take this many pixels) and fills at least this
    # share of it is the field of a ring the colour passes outlined already (a disc's field fills ~70 % of its
    # box, a triangle's ~50 %)
    field_in_outline_slack_px: int = 2
    field_in_outline_min_share: float = 0.3
    # priority roads by their white frame (framed_diamonds.py): on GTSDB's tune split 7 of 382 signs >= 30 px
    # were priority roads with no yellow segment (dusk orange below the hue band, washed out, joined to yellow
    # leaves); on the same ladder of grey levels their sign or frame is a bright diamond
    diamond_pass: bool = True
    diamond_max_aspect: float = 1.25  # longer / shorter box side: a diamond seen at up to ~35 deg
    # component area / box: the whole sign fills 0.5 of its box, its frame alone (the middle darker than the
    # level) ~0.3
    diamond_min_fill: float = 0.25
    diamond_max_fill: float = 0.7
    diamond_min_fit: float = 0.85  # the filled outline's fit to the ideal diamond (tune split: 0.87-0.94)
    diamond_core_scale: float = 0.45  # the middle read for its colour: the outline shrunk to this (yellow: ~0.6)
    diamond_frame_scale: float = 0.8  # the frame read for its colour: outside the outline shrunk to this
    # middle / frame per channel: blue / red at most this (tune split, priority roads: 0.29-0.76; white: ~1) and
    # green / red at least this (yellow keeps its green; a red or orange middle loses it)
    diamond_max_blue_red: float = 0.8
    diamond_min_green_red: float = 0.55


@dataclass(frozen=True)
class RimConfig:
    """Face boxes measured in the image around a coloured part (face_extent.rim_face_bboxes).

    A coloured part inside a white rim (yellow diamond, blue panel): the face box
    is also measured as the white rim and as the face's outer edge; rim widths
    differ between designs (Germany's priority road: face = 2.0 x its yellow,
    the Swiss template 1.28 x).
    """

    rim_max_saturation: int = 70  # a white rim read as bright pixels joined to the part: white and grey in shade
    rim_min_value: int = 60  # ...at least this bright...
    rim_value_ratio: float = 0.9  # ...and at least this x the part's median brightness (both in the same light)
    rim_window_margin: float = 0.3  # the window read around the part: twice the template's rim plus this x the
    # part (designs with wider rims than the template's)
    # the face so measured spans this range x the part; narrower is the part itself, wider a wall or the sky
    rim_measured_scales: Tuple[float, float] = (1.08, 2.6)
    rim_outline_min_inside: float = 0.8  # an outline laid at a scale counts with this share of it in the image
    rim_max_scale: float = 2.4  # widest rim sought: face / coloured part (GTSDB tune split: 1.9-2.3 for 3.03)
    rim_inner_scale: float = 1.12  # the part's own edge lies within this of its colour segment's box
    rim_edge_contrast: float = 3.0  # the outer edge is this x stronger than the plain rim inside it
    rim_edge_noise: float = 8.0  # Sobel units (~2 grey levels) added to the rim's strength: a spotless rim
    rim_border_scale: float = 1.15  # a dark border line's outer edge within this of its inner one (up to 7 %
    # of the face wide) ends the face; GTSDB's boxes end there
    rim_border_min_strength: float = 0.6  # that outer edge is at least this x as strong as the inner one
    rim_blur_px: float = 1.5  # a part's colour segment misses this much of its blurred edge on each side
    # (GTSDB: a 15 px priority-road diamond's face is 2.3-2.6 x its segment, not 2.0)
    ring_edge_max_scale: float = 1.8  # widest ring sought around a field: face / field (Swiss circles 1.21,
    # triangles 1.4-1.56; GTSDB tune split: 1.4-1.9 to the annotated box)
    rim_same_iou: float = 0.8  # a measured face box overlapping an earlier reading this much is that reading
    rim_scale_step: float = 1.03  # the outline is laid at scales this factor apart (3 %: a pixel at 33 px)
    rim_outline_samples: int = 96  # points along the outline at each scale; their median edge strength counts


@dataclass(frozen=True)
class ShapeConfig:
    """Shape (step 4): how well a segment must fit an ideal outline."""

    min_shape_fit: float = 0.68  # IoU with the best ideal outline; real triangles with rounded corners
    # and perspective fit 0.69-0.72 (GTSDB tune split: 0.72 -> 0.68 found 2.3 % more faces)
    confident_shape_fit: float = 0.72  # below it (or off the usual fill window) an outline is marginal...
    confident_fill_window: float = 0.15  # (that window: this close to the ideal fill ratio of its shape)
    marginal_shape_min_score: Optional[float] = None  # ...and is reported only with this indicator (None = the
    # classifier's own: NCC 0.5 instead of 0.35, the network its acceptance threshold);
    # so is a round face sized by its larger axis: a search-space cut of two stacked triangles (41 x 62 px)
    # read as an oblique 0.37 round sign on synthetic drive 1002
    # other shapes fitting within this of the best stay candidates: a 30 px disc and octagon differ by
    # a few corner pixels (GTSDB tune split: ~1 in 20 round signs of 30-40 px read as octagons)
    shape_ambiguity: float = 0.04
    # ...widened by this many pixels of blur over the segment's shorter side: a 15 px priority-road diamond's
    # corners are rounded off into an octagon (GTSDB tune split: diamond 0.76-0.81, octagon 0.81-0.84)
    shape_ambiguity_px: float = 1.2
    # shapes whose ideal fill ratio is this close to the measured one are tried on a segment; the templates'
    # own parts keep 0.15. Small real triangles (blur, rounded corners) fill 0.63-0.69 of their box, beyond
    # a triangle's 0.5 + 0.15 (GTSDB tune split: 0.15 -> 0.2 found 3 more of 127 signs, +2 candidates/image)
    shape_fill_window: float = 0.2
    # where outlines are compared with each other (split pieces with their merged hull, a coloured part with part
    # and white rim) rather than one read alone, they use the window these comparisons were tuned with, before
    # shape_fill_window was widened for small real triangles
    compare_fill_window: float = 0.15
    # a round face of which only one half kept its colour (a no-entry disc whose lower half joined the sign
    # below, a ring in shade: GTSDB tune split, 3 of 382 signs >= 30 px) is a segment this many times as wide as
    # high (a half disc: 2; seen at an angle or with a bit of the other half: less)...
    half_disc_aspect: Tuple[float, float] = (1.5, 2.6)
    half_disc_min_fit: float = 0.88  # ...whose hull fits the ideal half disc this well (IoU; a rectangle: 0.79)
    # ...unless a segment of the same colour outlines that disc already: its box overlaps the disc's this much
    # (IoU; a half overlaps it by ~0.5, so the pass's duplicate IoU would take the half itself for one)
    half_disc_same_iou: float = 0.7
    # ...or unless the depth range cut the other half off: with depth, that half must lie in the search space by
    # this share (a disc at the far end of the range halved by the cut was a false sign 5 m off, synthetic drive
    # 1024)
    half_disc_min_search_share: float = 0.5


@dataclass(frozen=True)
class SizeConfig:
    """Size (step 5): a segment's metric size rounded to a standard format."""

    size_tolerance: float = 0.15  # relative deviation from a standard format
    # a face fitting no standard format but within this factor of one (old and custom-made signs) is still read,
    # and mapped where its reading is clear (at the acceptance threshold), in review with its measured size
    off_format_factor: float = 1.6
    # a round face seen at an angle is an ellipse: sized by its larger axis, down to this axis ratio
    # (~60 deg off the optical axis; beyond it the face is unreadable anyway)
    min_round_axis_ratio: float = 0.5
    # ...its diameter the fitted ellipse's larger axis, at most this x the larger box side (an ellipse fitted to a
    # cut outline overshoots) and never below that side (a disc cut by an occluder keeps its extent on one axis)
    round_face_max_axis_scale: float = 1.15
    # a danger triangle whose top is hidden (a branch, a hedge) is read from its base (hidden_apex.py) when at least
    # apex_min_hidden of where its apex should be is coloured (saturation above apex_min_saturation) but not red
    apex_completion: bool = True
    apex_min_saturation: int = 60
    apex_min_hidden: float = 0.5
    # smallest and largest face side assumed where the catalogue (after exclusions) has no format at all: the
    # smallest face worth finding and the stereo bands need one
    fallback_face_sides_m: Tuple[float, float] = (0.4, 1.5)


@dataclass(frozen=True)
class DepthConfig:
    """The search space (near..far in front of the camera) and depth from stereo when no depth map is given."""

    near_m: float = 4.0
    far_m: float = 14.0
    search_close_px: int = 15  # holes of a given depth's search space this small are closed before it cuts colours
    search_grow_px: int = 31  # with SGBM depth the search space is grown by this much instead
    face_depth_slack: float = 0.2  # a face centre's plane depth is used within near x (1 - this) .. far x (1 + this)
    # (a face reaching past the range's limits); beyond, the segment's measured depth is used
    sgbm_scale: float = 0.5  # SGBM on a downscaled pair: ~8x faster, disparity still sub-pixel
    sgbm_block_size: int = 5
    sgbm_rows_only: bool = True  # match only the row bands holding colour candidates
    sgbm_columns_only: bool = True  # within those rows, only windows around the candidates (their columns,
    # and the largest disparity to their left): 40 % of the rows' width on synthetic drives, same detections
    # windows are the candidates' own boxes (grown by the margin), joined only where they overlap: the row bands
    # gave a small candidate the whole height of a tall one's band beside it (seed 2001: 925k -> 517k pixels
    # matched a pair, 44 % fewer); off: the bands' windows (sgbm_columns_only)
    sgbm_box_windows: bool = True
    sgbm_row_margin_px: int = 24  # margin around candidates, rows and columns
    sgbm_far_factor: float = 2.0  # search disparities down to far*2: far points then match outside the range
    sgbm_uniqueness: int = 15
    # OpenCV's smoothness penalties per pixel of the block (x block size^2): small disparity steps (P1) and larger
    # jumps (P2) along a path; the ratio 1:4 and these values are OpenCV's documented choice for SGBM
    sgbm_p1: int = 8
    sgbm_p2: int = 32
    sgbm_disp12_max_diff: int = 2  # left-right check: disparities of both views differing more are invalid
    sgbm_speckle_window: int = 60  # disparity blobs smaller than this (pixels at the matcher's scale) are noise...
    sgbm_speckle_range: int = 2  # ...where their disparities vary at most this much within
    sgbm_prefilter_cap: int = 31  # clip of the x-derivative prefilter: limits the weight of strong texture
    sgbm_warm_up_px: int = 64  # full-resolution columns matched left of a window before its own, so the matcher's
    # left-to-right pass enters the window settled (sgbm_depth)
    # colour candidates whose box height cannot be a face (or a coloured part of one) anywhere in the depth range
    # get no stereo rows: taller than this x the tallest format at the near limit (perspective, rims)...
    sgbm_band_max_height: float = 1.3
    sgbm_band_min_height: float = 0.5  # ...or shorter than this x the lowest format at the far limit (a half face)

    def __post_init__(self):
        if not 0 < self.near_m < self.far_m:
            raise ValueError(f"need 0 < near_m < far_m, got {self.near_m}, {self.far_m}")


@dataclass(frozen=True)
class PlanarityConfig:
    """Planarity (step 6): the share of a segment lying on one plane, the detection indicator."""

    detection_threshold: float = 0.5  # planar share of a segment needed to keep it
    planarity_window_px: int = 7
    # a window's local plane is fitted only where at least this share of its pixels have a depth, and at least
    # planarity_window_min_px of them: fewer fit a plane to noise (any three points lie on one)
    planarity_window_min_share: float = 1 / 3
    planarity_window_min_px: int = 6
    planarity_tolerance_px: float = 0.6  # residual in full-resolution disparity pixels, given depth
    sgbm_planarity_tolerance_px: float = 1.0  # the same for half-scale SGBM depth (noisier: 17% of true
    # signs fell below 0.5 at 0.6 px on a synthetic drive, 3% at 1.0 px)
    max_slant_deg: float = 45.0  # signs face the road, roughly along the optical axis
    planarity_refit_band: float = 3.0  # the dominant plane is refitted on the pixels within this x the tolerance
    # of it (twice): robust to a few outliers, wide enough to keep a first fit's slightly tilted plane
    min_depth_coverage: float = 0.3  # share of a segment's pixels needing a valid depth
    # depths farther than this share from the segment's median are matching artefacts (SGBM gives a sign's left
    # edge the background's depth) or background through the outline; a slanted face stays within a few per cent.
    # None: all depths count
    max_depth_deviation: Optional[float] = 0.25


@dataclass(frozen=True)
class ClassificationConfig:
    """Classification (step 7): which classifier, which templates, and when its reading is accepted."""

    classifier: str = "auto"  # "cnn" (learned network of the catalogue), "ncc" (template matching), "auto" (cnn if
    # the catalogue has a network)
    classification_threshold: Optional[float] = None  # indicator needed for "accepted"; None = the classifier's own
    exclude: Tuple[str, ...] = ()  # template ids never assigned
    min_surround_score: float = 0.3  # a panel reading needs its part outside the colour segment to match
    min_face_part: float = 0.6  # a board (no standard size) whose colour segment is less of its face than this is
    # read as a panel, its surround to match, though face and segment share their shape (a red piece of a ring
    # grown into a blue board with a red symbol)
    # (and the classifier's reading at its acceptance threshold to win): dirty 2.59.1 zone panels matched 0.43-0.50
    # and were read as their 30 disc at 0.5; at 0.3 none of 3 on drives 809, 1050-1061 was, and drives 801-810,
    # 1040-1049 mapped exactly as at 0.5
    min_classification_score: Optional[float] = None  # below this the segment is not reported; None = classifier's
    scales: Tuple[float, ...] = (0.92, 1.0, 1.08)
    shift_fraction: float = 0.08  # shift search, as a fraction of the segment size
    max_template_px: int = 96  # larger segments are compared downscaled
    coarse_template_px: int = 32  # with many candidates, all are first compared at this size without search...
    coarse_keep: int = 6  # ...and only this many best go on to the full scale and shift search
    tie_margin: float = 0.04  # candidates this close to the best score are decided on the pictogram field alone:
    # speed limits differing in one digit score alike on the whole face, where the rim dominates
    inner_fraction: float = 0.14  # that field is the face without this outer share (the rim)
    surround_grow: float = 0.04  # a panel's part outside its colour part is read without this margin of the face
    # around the colour part (its blurred edge would count as surround)
    # a disc with white at its own depth above it and beside it sits on a zone panel (zone_panel_surround): a panel
    # reading wins there though its surround fails min_surround_score (a design unlike the official one), and a
    # reading of the disc alone (a speed limit, 2.61) is held for review. White: at most white_max_saturation and at
    # least this value, on this share of a strip...
    panel_white_min_value: int = 130
    panel_white_share: float = 0.5
    panel_depth_tolerance: Tuple[float, float] = (0.15, 0.03)  # ...within this of the disc's depth (metres, or
    # that share of it, the larger)...
    panel_at_depth: Tuple[float, float] = (0.9, 0.6)  # ...for this share of its depths above the disc, and beside
    # it (a shadowed procedural panel's margins kept 0.6; set on looked-at drives 801-805, 1150-1179: all 11 views
    # of a zone panel read as its disc held; of the 167 other speed-limit and 2.61 views, two had such white around
    # them, both already in review)
    # the open set: a face that passed colour, outline, size and planarity but whose best candidate's logit is below its
    # network's unknown_logit (model card) is mapped as unknown, in review, unless the network gives it at least
    # this probability of being no sign at all
    open_set: bool = True
    unknown_max_background: float = 0.5
    unknown_min_print: float = 0.01  # ...and whose colour segment's inner part (unknown_print_inset cut off each
    # side) has at least this share of its pixels on an edge (unknown_print_canny): a plain patch carries no sign
    unknown_print_inset: float = 0.1
    unknown_print_canny: Tuple[int, int] = (50, 150)
    # direction signs that differ by their lines of text get the count the face shows (pipeline.text_lines):
    # faces at least text_lines_min_px high; text_lines_inset (of the width, of the height) cut off each side
    # (border, a pointer's tip); text is a Lab distance above text_lines_contrast from the field; a row with
    # text_lines_row_share of text pixels is text (a gap between lines holds none); a line is a band of text rows
    # text_lines_min_height high
    text_lines_min_px: int = 18
    text_lines_inset: Tuple[float, float] = (0.2, 0.06)
    text_lines_contrast: float = 60.0
    text_lines_max_column_ink: float = 0.8  # a column this full of "text" is a pole or post in front
    text_lines_row_share: float = 0.03
    text_lines_min_height: float = 0.08
    same_sign_max_iou: float = 0.3  # detections of one pair overlapping more (or holding the other's centre) are
    # one sign found twice, or a part of it found as a sign: the best (detection x classification) is kept
    part_max_area_share: float = 0.7  # ...but a detection inside an accepted one's face covering at most this share
    # of it is that sign's part whatever its indicators: the plain blue field of a no-parking disc (2.50, ~40 % of
    # its face) was read as a blue disc (2.34) and kept for its flatter patch (tune drives 801-810: 2 of 7 accepted
    # signs with a wrong id); a face found twice (about the same box) is not a part

    def __post_init__(self):
        if self.classifier not in CLASSIFIERS:
            raise ValueError(f"unknown classifier {self.classifier!r}; choose one of {', '.join(CLASSIFIERS)}")


@dataclass(frozen=True)
class HoughConfig:
    """Hough fallback for faded or white/grey round signs (hough.py), and the faces it seeks without depth."""

    hough_enabled: bool = True
    hough_scale: float = 0.5  # at most; less where the smallest radius sought allows (hough_min_radius_px)
    # smallest radius sought, in pixels of the Hough image: a 4-14 m search space's smallest disc (r 20 px)
    # is read at 1/3 (half the cost at 0.5); the colour step without depth (r 14 px) stays at 0.5
    hough_min_radius_px: float = 6.0
    hough_circularity: float = 0.85  # param2 of HOUGH_GRADIENT_ALT
    hough_dp: float = 1.5  # accumulator resolution of HOUGH_GRADIENT_ALT: 1.5 x coarser than the image (OpenCV's
    # advice for that method); finer finds no more signs and costs more
    hough_edge_threshold: float = 150.0  # param1 of HOUGH_GRADIENT_ALT
    hough_mask_median_px: int = 5  # the search space's outline is smoothed by a median of this (odd) size first:
    # speckle in a matched depth map would feed the transform many short edges (slow, and false circles)
    hough_ring_share: float = 0.1  # a circle's colour is read in its outer ring this share of its diameter deep,
    # where a round sign carries it (an SSV prohibition ring: ~9.5 %)
    hough_max_status: str = "review"  # status cap of Hough finds whose ring is not in full colour
    hough_max_diameter_m: float = 0.6  # larger round formats only by colour: the radius range sets the cost
    hough_fallback_diameters_m: Tuple[float, ...] = (0.4, 0.6)  # where the catalogue has no round format up to it
    hough_radius_slack: float = 0.2  # the radius range of those formats in near..far, widened by this share both
    # ways (a face at the range's limits, format tolerance, a disc seen at an angle)
    max_face_px: int = 200  # largest round face the Hough route (and the bright-field pass) looks for without
    # depth (radius range = cost)
    hough_min_face_px: int = 28  # smallest one: circles under ~28 px double its time and are mostly clutter
    hough_covered_iou: float = 0.5  # a circle whose box matches a face candidate's this much is that candidate
    # (a colour segment that swallowed the disc with a neighbour matches less and does not cover it)
    # a Hough ring is named by the hue of its pixels at least this saturated: below the colour step's weak
    # floor (weak_sat_min) so a rim too pale for it is still read as red/blue, above grey noise (~10)
    hough_tint_min_saturation: int = 22
    hough_tint_hues: Dict[str, Tuple[Tuple[int, int], ...]] = field(default_factory=lambda: dict(HOUGH_TINT_HUES))
    hough_tint_min_share: float = 0.25  # share of the ring's pixels a tint needs to name it; else white
    hough_strong_ring_share: float = 0.5  # a Hough find whose ring is this much in full colour is a colour find
    # the colour step lost (an attachment spoiled its outline) and may be accepted; others stay at hough_max_status
    # a white circle with a red annulus just outside it (hough_field_ring_band x its radius, of which at least half in
    # the image) this much in full colour is the field of a red ring the colour step lost (a pole in front, the
    # image border through it): it is read as that ring's field (a "hole" segment), not as a white sign
    hough_field_ring_share: float = 0.5
    hough_field_ring_band: Tuple[float, float] = (1.08, 1.25)


@dataclass(frozen=True)
class WhiteConfig:
    """White and grey signs (white_outlines.py, white_signs.py): fields enclosed by strong edges, achromatic and
    bright, read as discs and upright rectangles over the whole image; then depth, format, planarity, standing
    free, a support below and NCC among the white entries."""

    # on by default: a surveyor's inventory holds the white and grey signs too; the scan and the Hough transform
    # still cover the whole image, so a run without them is faster (docs/measurements.md)
    white_signs: bool = True
    white_max_side_m: float = 0.9  # formats up to this: the 1.2 m discs (motorways) would set the cost
    white_min_side_m: float = 0.35  # shorter sides below this (text bands, 0.2 m hint squares) count as this: they
    # are found where they are that large in the image, nearer, and the scan keeps its reduction
    white_scan_side_px: float = 20.0  # the image is scanned reduced by a whole factor so that the smallest face
    # sought keeps at least this side (Full HD, 4-14 m: by 2, the smallest 21 px)
    white_canny_low: int = 40  # Canny thresholds of the outline edges (grey levels of the reduced image)
    white_canny_high: int = 110
    white_max_saturation: int = 60  # an achromatic pixel (white, grey, black print); faded red rims stay above
    white_min_achromatic: float = 0.8  # share of a cell's pixels that are achromatic
    white_min_brightness: float = 0.6  # a cell's mean value is at least this x the scene's median: a grey ring in
    # shade stays above, a dark window pane (~0.3) falls below
    white_part_share: float = 0.35  # a cell may be this part of the smallest face (a field cut by a stripe band)
    white_min_cell_fill: float = 0.12  # cell pixels / its box: thinner cells are gaps between edges, not fields
    # (tune drives 1700-1705: these three let candidates cover 41 of 50 faces in view, 36 at 0.85 / 0.8 / 0.2)
    white_join_reach: float = 0.35  # cells within this x their size of a face's cells are read with them...
    white_join_gap: float = 0.25  # ...or within this x the smallest face side (a zone panel's ring and stripe)
    white_join_steps: int = 12  # cells joined one at a time from each, every face-like union a reading
    white_min_shape_fit: float = 0.8  # IoU with the ideal rectangle (façade patches and leaves fit loosely)
    white_max_aspect: float = 1.6  # longer / shorter side of a rectangle: zone panels are 1.4
    white_min_panel_cover: float = 0.2  # the cells fill this share of a rectangle (a zone panel's field around
    # its ring, stripes and lettering: 0.2-0.4)
    white_min_panel_support: float = 0.8  # a rectangle whose cells' hull fits no rectangle (stripes cut off its
    # corners) is a panel when this share of its sides lies on strong edges (a disc's box: ~0.3)
    white_panel_grow: float = 0.2  # a panel's outline is sought up to this x its size beyond its cells
    white_min_disc_cover: float = 0.2  # the cells fill this share of their smallest circle (a field cut by digits
    # and a stripe band: 0.35-0.45 on end-of-limit discs)
    white_support_samples: int = 48  # points on that circle (or the rectangle's sides)...
    white_min_edge_support: float = 0.65  # ...this share of them on a strong gradient across the outline
    white_refine_margin: float = 0.25  # circles this far below it are moved and resized to their best outline...
    white_circle_search: float = 0.12  # ...within this x the radius (centre and radius)
    white_circle_search_steps: int = 5  # ...on a grid of this many steps along each of the three
    white_rim_saturation_step: float = 10.0  # a disc's ring is a faded coloured rim when it is this much more
    # saturated than its field (tune drives 1700-1705: tinted white faces -8..+6; without it 12 of 56 views lost)
    white_rim_field_depth: float = 0.25  # its field: the disc without this share of its diameter all round
    white_ring_band: Tuple[float, float] = (1.06, 1.2)  # a disc whose band this many times its radius out is
    # mostly (white_min_ring_share) red or blue by the colour step's ranges, while the band beyond
    # (white_beyond_band) is not, is the white field of a red or blue ring: the colour step's sign (tune drive
    # 1708: a 2.30-60 cut by the image edge, its field read as 2.53-60 at 1.00)
    white_beyond_band: Tuple[float, float] = (1.5, 1.75)
    white_min_ring_share: float = 0.6
    white_hough: bool = True  # round outlines are also sought by the Hough transform (HOUGH_GRADIENT_ALT) on the
    # scanned image: tune drives 1700-1705, 12 of 38 disc views had no candidate from the cells (fields cut by
    # digits and stripes into cells below a part of a face, pale rings before pale walls); Hough found 6 of them
    white_hough_dp: float = 1.5  # its accumulator's resolution (1.5 x coarser than the scanned image)
    white_hough_min_dist: float = 2.0  # circles' centres at least this x the smallest radius apart: the transform
    # costs less than half of what it does at 1.0 (a face's concentric outlines are one circle anyway)
    white_hough_edge: float = 300.0  # its edge threshold on Scharr gradients (~ Canny 110 on Sobel)...
    white_hough_roundness: float = 0.75  # ...and how round an outline must be (0-1): 4 circles per pair
    white_hough_min_radius: float = 0.85  # x half the smallest face side: its radius estimate runs short of a
    # faint outline's (tune drives: at 1.0 a 0.6 m disc at 12.8 m was not found, its radius 1.3 x the floor)
    white_format_fit: bool = True  # a face whose measured size fits no white format is sought again as the
    # outline of each format at its depth (format_outline): tune drives 1700-1705, 9 of 58 views fell between
    # formats (a pale disc read with a white board behind it, 0.73-0.76 m; panels cut short by their stripes)
    white_format_min_iou: float = 0.5  # the format's outline overlaps the candidate's box at least this much
    white_disc_in_panel: float = 0.8  # a disc found with this share of its box inside a white panel found too is
    # the panel's zone disc, not a sign (tune drives 1700-1705: a 2.59.2 panel's ring read as 2.53.1 in 3 views)
    white_panel_around: bool = True  # a disc read as a sign is sought once more as the zone disc of a white
    # panel around it, the panel's four sides on strong edges (white_min_panel_support): a 2.59.2 before a pale
    # wall was found as its disc alone and read as 2.53.1 (tune drive 1706)
    white_ring_ratios: Tuple[float, float] = (1.25, 1.75)  # a disc is also judged as the outer outline of an
    # achromatic ring around it, this many times its radius (2.53.1's grey ring: 1.5): held-out drives confused
    # 2.53.1 with 2.53-60 three times, the candidate its inner field, the ring's outline lost before pale walls
    white_ring_steps: int = 11  # radii tried between the two
    white_ring_min_support: float = 0.45  # share of the ring's outline on radial gradients (a face's: 0.65)
    white_max_coloured_share: float = 0.3  # a panel with more of its pixels coloured is a coloured zone panel
    # (tune drives: white panels 0.07-0.18 in tinted light; a red-ringed 2.59.5 read by the format refit 0.40)
    white_min_gradient: float = 80.0  # Sobel magnitude of that gradient (about 20 grey levels across the outline)
    white_max_candidates: int = 40  # per pair, largest first: bounds the stereo matching they ask for
    white_same_iou: float = 0.6  # a face overlapping a kept one this much is the same
    # standing free: bands beside the face (after a gap, both x its width) hold few pixels at its depth
    white_side_gap: float = 0.15
    white_side_band: float = 0.5
    white_min_side_valid: float = 0.2  # share of the bands needing a depth to judge (else: sky, no verdict)
    white_max_side_share: float = 0.35  # a façade or a van's body around a window or a panel: most at its depth
    white_same_depth_m: float = 0.4  # "at the face's depth": within this (or this share of the depth)
    white_same_depth_share: float = 0.05
    # a support below: rows of a strip under the face (after a gap, x its height; the strip x its width wide)
    # holding a pixel at its depth: the pole, or the sign under it on the same pole
    white_support_gap: float = 0.05
    white_support_length: float = 0.4
    white_support_width: float = 0.3
    white_min_support: float = 0.5
    white_pole_edge: float = 60.0  # Sobel x response of a pole's edge (about 15 grey levels across it)...
    white_min_pole_rows: float = 0.7  # ...in this share of the strip's rows, in one column: a pole in the image
    white_min_score: float = 0.5  # NCC among the white entries: below it no template resembles the face...
    white_unsupported_min_score: float = 0.65  # ...or below this without a support seen below it
    white_accept_score: float = 0.65  # and from this on it is "accepted"
    white_network_gate: bool = True  # below white_min_score a supported face is still a sign where the network
    # (knowing every white candidate) reads it at its acceptance threshold: a 2.59.2 in greenish light, 0.46
    white_radial_cos: float = 0.8  # an outline point's gradient points across the outline (along the radius, or
    # across a panel's side) within this cosine (37 deg): a pixel step of a slanted outline stays within,
    # texture's gradients point anywhere
    white_edge_band_px: float = 1.5  # cells end where the outline's edge band (Canny, a pixel wider) begins: the
    # outline is sought this far outside them, in the band's middle (reduced image's pixels)
    white_pole_blur_rows: int = 7  # the strip below a face is averaged over this many rows along the pole before
    # its edges are measured: a pole's edges stay, pixel noise averages out (white_pole_edge is measured after it)
    # white text panels (text_panels.py: 4.29, 4.30, 4.33), sought with the white step: the field inside the frame
    text_panels: bool = True
    panel_canny: Tuple[int, int] = (40, 110)  # Canny thresholds of the fields' edges (grey levels, full image)
    panel_frame_margin: float = 0.045  # the frame and the white margin outside it, share of the face's height
    panel_frame_reach: float = 0.1  # the frame's dark line lies within this x the field's height outside it...
    panel_frame_contrast: float = 0.8  # ...darker than this x the field's median brightness (a blurred 2 px line:
    # ~0.65)
    panel_min_frame: float = 0.6  # share of the field's outline with dark beside it: a candidate...
    panel_margin_brightness: float = 0.75  # ...and where that dark is a line, bright again (the panel's margin)...
    panel_line_reach_px: int = 6  # (the line and the margin are sought at least this far: ~2 px each far away)
    panel_min_line: float = 0.35  # ...on this share of its top and bottom edges (a white board: < 0.25)...
    panel_full_line: float = 0.6  # ...the indicator (frame_indicator) falls below this share of the better edge
    panel_accept_frame: float = 0.85  # ...accepted from this indicator on (with a support below)...
    panel_unsupported_frame: float = 0.8  # ...and without a support seen below only from this on
    panel_min_aspect: float = 0.9  # field width / height (a two-line place name: ~1.2; one destination: ~6)
    panel_max_aspect: float = 10.0
    panel_min_cell_fill: float = 0.25  # the field's cell (lettering cut out) fills this share of its box...
    panel_min_fill: float = 0.75  # ...and, its lettering's holes filled, this share (a pointer: ~0.9)
    panel_min_ink: float = 0.03  # lettering: share of the filled field that is holes (a blank board has none)
    panel_max_ink: float = 0.6
    panel_max_candidates: int = 12  # per pair, largest first
    panel_end_share: float = 0.25  # a field's end columns (as many as this x its height: a rounded corner is
    # less, a pointer's point, 0.5-0.7 x the panel's height, more)...
    panel_point_ratio: float = 0.6  # ...at most this x its middle's height: it ends in a point (4.33)
    panel_stack_align: float = 0.04  # two fields stacked on a bar (4.30) share their sides within this x width
    panel_bar_max_share: float = 0.3  # and the bar between them is at most this share of their height
    panel_bar_rows: Tuple[float, float] = (0.1, 0.45)  # a 4.30's bar over its lower field, x that field's height
    panel_plate_gap: float = 0.3  # a field this x a sign's height or less below or above it is its plate
    panel_size_step_m: float = 0.05  # a panel's measured size is given to this step (it has no standard format)


@dataclass(frozen=True)
class PlateConfig:
    """Supplementary plates (plates.py): white rectangles of a plate format right below or above a sign."""

    find_plates: bool = True
    plate_min_cover: float = 0.6  # a white-step rectangle reading this much covered by a plate of another sign is
    # that plate (the smaller box's share inside the other)
    plate_max_gap_m: float = 0.12  # between the sign's edge and the plate (both clamped to one pole)
    plate_min_gap_m: float = 0.03  # a white region reaching further into the sign's box is part of its panel
    plate_box_overshoot: float = 0.1  # ...or further than this share of the sign's box height: a face box grown
    # from its coloured part (a zone panel from its ring) may reach past the face's edge over its plate's top
    # (tune drive 1807: a 2.59.1's box 12 px of 190 over its 5.22 plate, which was lost in 2 of 4 pairs)
    plate_max_saturation: int = 60  # white and grey: a plate in shade is grey, never coloured
    plate_min_value: int = 100  # floor of its brightness (Otsu's split of the window raises it in the sun)
    plate_value_steps: Tuple[int, ...] = (0, 25, 50)  # further floors above that: a plate before a pale wall
    # ...and the lowest floor cut along brightness edges (Canny of the value, these thresholds): a plate before a
    # pale façade that no floor parts from it
    plate_edge_cut: bool = True
    plate_edge_thresholds: Tuple[int, int] = (20, 60)
    plate_depth_tolerance_m: float = 0.3  # where depth is known, the plate lies in the sign's depth (or 5 %)
    plate_close_m: float = 0.0  # closing before the holes are filled (0: none; a plate's thin frame must stay)
    plate_frame_share: float = 0.075  # of a plate's height: its white margin and black frame line (inset)
    plate_min_fill: float = 0.85  # of its box: a rectangle
    plate_notch_m: float = 0.02  # thin dark lines across a plate (a wire, a pole's edge) do not count against it
    plate_neck_m: float = 0.12  # a pale pole joins a plate to its sign above or runs on below it, one region
    # with it: runs of a region narrower than this (a pole, 6-8 cm) are cut off before it is read (tune drives
    # 1800-1809: 5 of the 12 views of a plate missed under a sign found)
    plate_neck_end_share: float = 0.15  # a region left by the cut whose source goes on past its far edge within
    # this share of its width at both ends is the top of a larger white frame (a zone panel under a sign), no plate
    plate_max_offset: float = 0.35  # centre off the sign's axis, share of the wider of the two
    plate_size_tolerance: float = 0.2  # relative deviation from a plate format (PLATE_FORMATS)
    plate_ink_darkness: float = 0.6  # a plate pixel darker than this x the plate's median is ink (text, pictogram,
    # frame): printed black on white stays below half of the paper's brightness even in shade
    plate_min_seen: float = 0.3  # at least this share of a plate's box seen (not hidden in front) to judge its ink
    plate_edge_px: int = 1  # a plate box within this of the image's edge may be cut by it: not seen whole
    plate_depth_tolerance_share: float = 0.05  # ...the depth tolerance grows to this share of the depth (SGBM's
    # depth error grows with distance)
    plate_min_ink: float = 0.02  # share of dark pixels (text, pictogram, frame): a blank white region is no plate
    plate_max_ink: float = 0.5
    plate_accept_score: float = 0.8  # fill and fit to its format: above, the plate is "accepted"
    # a plate cut into pieces by something in front (a branch, a lamp post): the box around its pieces, its
    # hidden pixels counted as the plate's, is a plate when this share of it is seen ...
    plate_min_visible: float = 0.4
    plate_hidden_weight: float = 0.9  # ... and scores this much less than a plate seen whole
    # a lamp post or trunk in front crosses the sign and its plate from top to bottom: a dark vertical run over
    # this share of the window's height within the sign's columns, at most plate_occluder_max_width x the sign's
    # width wide, hides what lies behind it (the sign's own pole is behind both, so its run stops at them)
    plate_occluder_span: float = 0.9
    plate_occluder_max_width: float = 0.3
    plate_occluder_contrast: float = 0.8  # within a plate's crop, such a post is darker than this x its paper
    plate_split_min_overlap: float = 0.8  # two pieces of a plate cut by such a post are level: rows this shared
    plate_pictogram_min_score: float = 0.7  # correlation with a pictogram plate's drawing: below, a text plate
    plate_min_size_px: Tuple[int, int] = (6, 4)  # (width, height) of the smallest region read as a plate: smaller
    # ones are specks (the smallest format, 0.40 x 0.15 m, is ~50 x 19 px at 14 m with fy 1750)
    plate_notched_min_fill: float = 0.6  # a region filling at least this share of its box (but less than
    # plate_min_fill) is measured again with its thin notches closed (plate_notch_m); one filling less lacks more
    # than thin lines across it explain, and is spared the second measurement
    plate_max_value_floor: int = 250  # brightness floors (plate_value_steps) from this up are not tried: they keep
    # only clipped highlights, no plate's paper
    plate_min_widening: float = 0.1  # a hidden plate's seen pieces are completed to a format's width only where
    # that adds more than this share of their width: a piece nearly that wide is read as a region already
    plate_misfit_weight: float = 0.5  # a plate at the edge of plate_size_tolerance scores this much less than one
    # of exactly a format's size (its score falls linearly in the log size error between)
    # a pictogram plate (plate_classify.py): the crop, grey, and each drawing are compared at this height (the
    # drawing's aspect), enough for the strokes of its pictogram and words without enlarging a far plate much
    plate_compare_height_px: int = 36
    plate_compare_min_px: int = 8  # a crop (after its inset) or a drawing narrower or lower than this shows no
    # pictogram to compare: no score
    plate_compare_blur_px: float = 0.9  # both blurred by this Gaussian sigma at that size (tuned on synthetic
    # crops of all 59 drawings and of text plates: from none, 438 -> 460 of 464 views >= 20 px told and 13 -> 5 of
    # 150 text plates taken for a drawing, with the threshold raised from 0.6 to 0.7)
    plate_compare_shift_px: int = 3  # the best correlation over shifts up to this: a plate's box is found to a
    # pixel or two
    plate_compare_insets: Tuple[float, ...] = (0.0, 0.06, 0.12)  # share of the crop's height cut from each side
    # before comparing (the best counts): a box taken for the inside of a frame is that much larger than the plate
    plate_inset_candidates: int = 2  # the insets beyond the first are tried on only this many drawings the crop is
    # most like uncut (each inset costs a correlation per drawing)
    plate_aspect_tolerance: float = 0.25  # a plate's crop is compared only with drawings of its aspect within this
    # share (log): its box is found to a pixel or two, a frame's margin at most (plate_compare_insets)
    plate_pictogram_min_seen: float = 0.4  # share of a plate's crop seen (not hidden in front) to compare it with
    # the drawings at all: less leaves too little of a pictogram to tell it from the others


@dataclass(frozen=True)
class TemplateGeometry:
    """How the catalogue's own drawings are read: the outline of a template's coloured part or enclosed field.

    Not a run setting: the templates are clean drawings without blur or perspective, measured once per
    catalogue (``face_extent``) whatever the run's settings; a run's segments use ``ShapeConfig``.
    """

    template_min_fit: float = 0.72  # a drawn part fits its ideal outline closely (a segment needs 0.68)
    template_fill_window: float = 0.15  # and fills its box as that outline does (a segment: 0.2)
    template_min_part_share: float = 0.02  # a colour covering less of the face is a detail (letters, a thin line)
    template_full_snap: float = 0.03  # a part this close to the face's edges on every side is the whole face
    # (rendering's rounding, no rim to correct for)
    template_min_field_share: float = 0.05  # an enclosed field smaller than this share of the face is a letter's hole
    # a panel's inset part of another shape covers between these shares of the panel (a zone sign's disc);
    # smaller is a detail, larger is the panel's own colour
    template_panel_part_area: Tuple[float, float] = (0.1, 0.8)
    # a face's bright part (white and light colours: a priority road's white frame with its yellow) is its pixels
    # at least this grey (0-255): the frame's edge line is black, its yellow ~190 grey
    template_bright_grey: int = 128
    # an entry of another colour whose own colour falls in a segment colour's range over the same part (within
    # this share of the face) looks like that colour to the segmentation: tourist brown is dark red
    template_same_part_tolerance: float = 0.03


TEMPLATE_GEOMETRY = TemplateGeometry()


@dataclass(frozen=True)
class PipelineConfig:
    """All settings of the detection steps, one section per step.

    The documented contract (``mapsigns``' main parameters) is ``depth.near_m``,
    ``depth.far_m``, ``colour.colours``, ``classification.exclude``,
    ``planarity.detection_threshold``, ``classification.classification_threshold``
    and ``classification.classifier``.
    """

    colour: ColourConfig = field(default_factory=ColourConfig)
    scene: SceneConfig = field(default_factory=SceneConfig)
    bright_fields: BrightFieldConfig = field(default_factory=BrightFieldConfig)
    rims: RimConfig = field(default_factory=RimConfig)
    shape: ShapeConfig = field(default_factory=ShapeConfig)
    size: SizeConfig = field(default_factory=SizeConfig)
    depth: DepthConfig = field(default_factory=DepthConfig)
    planarity: PlanarityConfig = field(default_factory=PlanarityConfig)
    classification: ClassificationConfig = field(default_factory=ClassificationConfig)
    hough: HoughConfig = field(default_factory=HoughConfig)
    white: WhiteConfig = field(default_factory=WhiteConfig)
    plates: PlateConfig = field(default_factory=PlateConfig)


SECTIONS: Dict[str, type] = {f.name: f.default_factory for f in dataclasses.fields(PipelineConfig)}
# setting name -> its section (names are unique across the sections; tests/core/test_run_settings.py checks it)
SECTION_OF: Dict[str, str] = {f.name: section for section, cls in SECTIONS.items() for f in dataclasses.fields(cls)}


def with_settings(config: PipelineConfig, changes: Mapping[str, Mapping[str, Any]]) -> PipelineConfig:
    """``config`` with the settings ``{section: {name: value}}`` changed; each section checks its own values."""
    return dataclasses.replace(config, **{section: dataclasses.replace(getattr(config, section), **values)
                                          for section, values in changes.items()})


def default(section: str, name: str):
    """The default of setting ``name`` of ``section``, without building a config (front ends offer it as theirs)."""
    cls = SECTIONS.get(section)
    for f in dataclasses.fields(cls) if cls is not None else ():
        if f.name == name:
            return f.default_factory() if f.default is dataclasses.MISSING else f.default
    raise KeyError(f"PipelineConfig has no setting '{section}.{name}'")
