"""Settings of the detection pipeline: one frozen section per step, so a run is reproducible.

Defaults follow Cavegn (2011): a 4-14 m search space in front of the camera and
HSV thresholds for the sign colours (``sign_colours``). Hue is OpenCV's 0-179
scale. Every threshold of a step is a field of that step's section, with its
rule on one line (units in brackets); the step functions take them from the
config and declare no defaults of their own. How the values were found is in
docs/measurements.md ("How the pipeline settings were found"). A setting's name
is unique across the sections (a search for it finds every use, and a record of
before the sections maps it back by name). A run's output records every section
(``run_settings``), so the run can be repeated from its output; fusion's
settings are ``fusion.FusionConfig``.
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

    colours: Tuple[str, ...] = SIGN_COLOURS  # the colours segmented: every colour with HSV thresholds
    # HSV thresholds per colour [hue 0-179, saturation and value 0-255]
    hsv_ranges: Dict[str, Tuple[HsvRange, ...]] = field(default_factory=lambda: dict(DEFAULT_HSV_RANGES))
    morph_open_px: int = 3  # opening of a colour mask [px]: removes speckle
    morph_close_px: int = 5  # closing of a colour mask [px]: bridges small gaps in a sign's ring
    min_segment_px: int = 150  # smallest segment [px²]: smaller ones cannot be sized or classified reliably
    # smallest segment of a colour that is only a part of its face [px²]: a 30 px priority road's diamond is ~110
    min_part_px: Dict[str, int] = field(default_factory=lambda: {"yellow": 90})
    min_bbox_px: int = 12  # shortest box side of a segment [px]: shorter outlines are speckle
    border_margin_px: int = 2  # segments this close to the image border [px] are cut and rejected
    min_solidity: float = 0.85  # every sign outline is convex: a less solid one is bitten into, its hull restores it
    hole_colours: Tuple[str, ...] = ("red",)  # colours whose ring's field is a segment too (red rings around fields)
    min_hole_px: int = 60  # smallest such field [px²]: smaller holes are letters and gaps (a 30 px triangle's: ~200)
    max_ring_ratio: float = 1.6  # an outline at most this x its field's box is just the ring: the field is the segment
    ring_fraction: float = 0.09  # morphology scaled to a ring this share of the diameter (SSV prohibition ring: 9.5 %)
    min_face_px: int = 16  # smallest face found without depth [px] (GTSDB's smallest signs); sets the small pass
    max_merge_pieces: int = 40  # most rejected segments tried in pairs as one face split by an occluder
    red_diamonds_as_yellow: bool = True  # a red diamond is a dusk priority road's darkened yellow: no red sign is one
    # a segment of a key colour is also offered the entries of these colours: orange in shade reads as yellow...
    also_offered: Dict[str, Tuple[str, ...]] = field(default_factory=lambda: {"yellow": ("orange",)})
    offered_hue_drift: int = 2  # ...where its median hue is this close to theirs [0-179] (shaded orange 16, a bus 23)
    merge_max_gap: float = 0.35  # two pieces of one face are at most this x the merged box's size apart...
    merge_max_aspect: float = 2.0  # ...their merged box at most this x longer than wide (else two stacked faces)
    split_min_span_overlap: float = 0.6  # pieces a bar or pole cut apart overlap along the other axis by this share
    split_min_diagonal_overlap: float = 0.3  # pieces a diagonal bar cut (3.04) overlap this much along both axes...
    split_min_gain: float = 0.05  # ...and their hull fits an ideal outline this much better than either piece
    board_edge_align: float = 0.12  # two rectangles a pole cut from one board: edges level within this x their height
    board_max_gap: float = 0.6  # ...at most this x their height apart...
    board_min_aspect: float = 1.3  # ...and together at least this many times as wide as high (place names: 1.4)

    def __post_init__(self):
        unknown = set(self.colours) - set(self.hsv_ranges)
        if unknown:
            raise ValueError(f"no HSV thresholds for colours {sorted(unknown)}")


@dataclass(frozen=True)
class SceneConfig:
    """The scene pass (scene_colour.py): colour floors read from the image, for faded, dim and cast signs."""

    white_balance: bool = False  # remove the scene's colour cast before the scene pass reads hues (off: costly)
    neutral_max_saturation: int = 40  # a pixel below this saturation [0-255] is grey seen in a cast (10 % cast: ~25)
    max_white_balance_gain: float = 1.2  # a scene of mostly one colour (hedge, sky) must not be over-corrected
    white_balance_min_change: float = 0.03  # gains all within this of 1 leave the image as it is: no hue moves class
    neutral_value_range: Tuple[int, int] = (41, 239)  # a neutral pixel's value [0-255]: neither dark nor clipped
    neutral_min_share: float = 0.02  # with fewer neutral pixels (of the sampled image) the scene is left as it is
    weak_colour: bool = True  # run the scene pass: colour floors from the image find faded, dim and cast faces
    weak_colours: Tuple[str, ...] = ("red", "yellow")  # colours it seeks: faded red rings, dim or orange priority roads
    # its hue ranges per colour [hue 0-179]; a colour without one takes its HSV ranges' hues
    weak_hues: Dict[str, Tuple[Tuple[int, int], ...]] = field(default_factory=lambda: dict(WEAK_HUES))
    # outlines it keeps per colour (others: any ideal outline): yellow faces are diamonds (3.03, 3.04), blue discs
    weak_shapes: Dict[str, Tuple[str, ...]] = field(default_factory=lambda: {"yellow": ("diamond",),
                                                                             "blue": ("circle",)})
    # outline fit [IoU] its segments of these colours need (others: min_shape_fit): weak blue is mostly sky and road
    weak_min_fit: Dict[str, float] = field(default_factory=lambda: {"blue": 0.86})
    weak_sat_factor: float = 1.0  # weak saturation floor = this x the scene's median saturation + weak_sat_offset
    weak_sat_offset: float = 30.0  # ...plus this [saturation 0-255]
    weak_sat_min: int = 25  # lowest weak saturation floor [0-255]: below, grey road and sky noise turns red/blue
    weak_min_chroma: int = 16  # max - min of B, G, R a weak pixel needs [0-255]: a dark pixel's saturation is noise
    weak_val_factor: float = 0.35  # weak value floor = this x the scene's median brightness: a dim sign keeps ~1/3
    weak_val_min: int = 30  # lowest weak value floor [0-255]: darker pixels carry no reliable hue
    weak_max_surround: float = 0.03  # a weak segment whose surrounding band is more coloured than this is background
    weak_surround_px: float = 0.2  # that band's width [x the segment's size]: within a priority road's white rim
    pass_duplicate_iou: float = 0.5  # a later pass's segment overlapping an earlier one this much [IoU] is the same
    scene_sample_step: int = 4  # scene statistics read on every this-th pixel and row: 1/16 the cost, same percentiles


@dataclass(frozen=True)
class BrightFieldConfig:
    """White fields inside red rings found by brightness (bright_fields.py).

    In dim light a ring keeps no usable saturation, but its field is still
    brighter than it and the ring still redder than the field.
    """

    field_pass: bool = True  # seek the white fields of red rings by brightness on a ladder of grey levels
    field_scale: float = 0.5  # fields are sought on the grey image at this scale at most...
    field_min_side_px: float = 8.0  # ...or less, where the smallest field sought stays this wide [px]
    field_first_level: int = 12  # darkest grey level [0-255]: below the darkest dusk rings
    field_level_ratio: float = 1.25  # next level = this x the last: a ring this much darker than its field parts
    field_min_px: int = 16  # shortest field side [px]: a 30 px triangle's field is ~20 x 17, smaller is clutter
    field_of_face: float = 0.6  # a ring's field is at least this share of its face's side (Swiss triangles 0.64)
    field_min_fill: float = 0.35  # least component area / box: a field fills 0.5 (triangle) to 0.79 (disc)
    field_max_fill: float = 0.95  # most component area / box
    field_min_solidity: float = 0.7  # a component bitten by a pictogram is judged by its hull if it fills this of it
    field_hull_shapes: Tuple[str, ...] = ("triangle",)  # ...of these shapes: danger triangles carry pictograms
    field_min_bitten_fill: float = 0.28  # a bitten component is judged by its hull down to this area / box
    field_max_aspect: float = 1.6  # longer / shorter box side of a field: a disc turned 50 deg
    field_same_iou: float = 0.85  # a component whose box overlaps one of a lower level this much [IoU] is that one...
    field_same_area_drop: float = 0.1  # ...unless it lost this share of its pixels: that level parted ring and field
    field_ring_fraction: float = 0.12  # band around a field read as its ring, x the field's size (SSV ring: 0.11)
    field_ring_min_red_green: float = 1.15  # the ring's R/G is at least this x the field's (a red ring)...
    field_ring_min_red_blue: float = 1.05  # ...its R/B at least this x the field's...
    field_ring_max_brightness: float = 0.85  # ...and its brightness at most this x the field's
    field_coarse_share: float = 0.5  # the first check on the reduced image asks this share of each margin above
    dark_ring_max_brightness: float = 0.7  # a colourless dusk ring counts at most this x as bright as its field...
    dark_ring_min_ratio: float = 0.97  # ...of no other colour (R/G and R/B over its field's at least this)...
    dark_ring_min_fit: float = 0.88  # ...around a triangle field fitting its ideal outline this well [IoU]...
    dark_field_min_fit: float = 0.69  # ...or this well when the field itself is dim: dusk blurs it (1.0: never)
    dark_field_max_brightness: float = 45.0  # a dim field: mean of B, G, R at most this [0-255], rare in daylight
    dark_ring_max_level: int = 57  # ...on grey levels up to this [0-255]
    field_min_inside_share: float = 0.5  # the pass reads the whole image: a field counts with this share in the search
    field_in_outline_slack_px: int = 2  # a field inside a colour segment's box (give or take this [px])...
    field_in_outline_min_share: float = 0.3  # ...filling this share of it is a ring the colour passes outlined already
    diamond_pass: bool = True  # seek priority roads by their white frame: a bright diamond on the grey levels
    diamond_max_aspect: float = 1.25  # longer / shorter box side: a diamond seen at up to ~35 deg
    diamond_min_fill: float = 0.25  # least component area / box: the frame alone (middle darker) fills ~0.3
    diamond_max_fill: float = 0.7  # most component area / box: the whole sign fills 0.5
    diamond_min_fit: float = 0.85  # the filled outline's fit to the ideal diamond [IoU]
    diamond_core_scale: float = 0.45  # the middle read for its colour: the outline shrunk to this (yellow: ~0.6)
    diamond_frame_scale: float = 0.8  # the frame read for its colour: outside the outline shrunk to this
    diamond_max_blue_red: float = 0.8  # middle / frame blue/red at most this: a yellow middle (a white one: ~1)
    diamond_min_green_red: float = 0.55  # middle / frame green/red at least this: yellow keeps its green, red loses it


@dataclass(frozen=True)
class RimConfig:
    """Face boxes measured in the image around a coloured part (face_extent.rim_face_bboxes).

    A coloured part inside a white rim (yellow diamond, blue panel): the face box
    is also measured as the white rim and as the face's outer edge; rim widths
    differ between designs (Germany's priority road: face = 2.0 x its yellow,
    the Swiss template 1.28 x).
    """

    rim_max_saturation: int = 70  # a white rim: bright pixels joined to the part, at most this saturated [0-255]...
    rim_min_value: int = 60  # ...at least this bright [0-255]...
    rim_value_ratio: float = 0.9  # ...and at least this x the part's median brightness (both in the same light)
    rim_window_margin: float = 0.3  # window read: twice the template's rim plus this x the part (wider rims)
    rim_measured_scales: Tuple[float, float] = (1.08, 2.6)  # a measured face spans this x the part (else part, wall)
    rim_outline_min_inside: float = 0.8  # an outline laid at a scale counts with this share of it in the image
    rim_max_scale: float = 2.4  # widest rim sought: face / coloured part
    rim_inner_scale: float = 1.12  # the part's own edge lies within this of its colour segment's box
    rim_edge_contrast: float = 3.0  # the outer edge is this x stronger than the plain rim inside it
    rim_edge_noise: float = 8.0  # added to the rim's strength [Sobel units, ~2 grey levels]: a spotless rim
    rim_border_scale: float = 1.15  # a dark border's outer edge within this of its inner one ends the face (GTSDB's)
    rim_border_min_strength: float = 0.6  # that outer edge is at least this x as strong as the inner one
    rim_blur_px: float = 1.5  # a part's colour segment misses this much of its blurred edge on each side [px]
    ring_edge_max_scale: float = 1.8  # widest ring sought around a field: face / field (Swiss triangles: 1.4-1.56)
    rim_same_iou: float = 0.8  # a measured face box overlapping an earlier reading this much [IoU] is that reading
    rim_scale_step: float = 1.03  # the outline is laid at scales this factor apart (3 %: a pixel at 33 px)
    rim_outline_samples: int = 96  # points along the outline at each scale; their median edge strength counts


@dataclass(frozen=True)
class ShapeConfig:
    """Shape (step 4): how well a segment must fit an ideal outline."""

    min_shape_fit: float = 0.68  # least IoU with the best ideal outline: real triangles' rounded corners fit loosely
    confident_shape_fit: float = 0.72  # below it (or off confident_fill_window) an outline is marginal...
    confident_fill_window: float = 0.15  # (that window: this close to its shape's ideal fill ratio)
    # ...and reported only with this indicator, as is a round face sized by its larger axis (None: acceptance)
    marginal_shape_min_score: Optional[float] = None
    shape_ambiguity: float = 0.04  # shapes fitting within this of the best stay candidates (small disc vs octagon)
    shape_ambiguity_px: float = 1.2  # ...widened by this [px] of blur over the shorter side: blur rounds corners
    shape_fill_window: float = 0.2  # shapes this close in ideal fill ratio are tried: small triangles fill more
    compare_fill_window: float = 0.15  # fill window where outlines are compared with each other, not read alone
    half_disc_aspect: Tuple[float, float] = (1.5, 2.6)  # a face only half of which kept its colour: width / height
    half_disc_min_fit: float = 0.88  # ...whose hull fits the ideal half disc this well [IoU] (a rectangle: 0.79)
    half_disc_same_iou: float = 0.7  # ...unless a segment of its colour covers the disc this much [IoU] (a half: 0.5)
    half_disc_min_search_share: float = 0.5  # ...and, given depth, its other half lies this much in the search space


@dataclass(frozen=True)
class SizeConfig:
    """Size (step 5): a segment's metric size rounded to a standard format."""

    size_tolerance: float = 0.15  # relative deviation from a standard format
    off_format_factor: float = 1.6  # a face within this factor of a format (old, custom) is read, mapped in review
    min_round_axis_ratio: float = 0.5  # a round face at an angle is sized by its larger axis down to this axis ratio
    round_face_max_axis_scale: float = 1.15  # ...that axis between 1 and this x the larger box side (cut outlines)
    apex_completion: bool = True  # a danger triangle whose top is hidden is read from its base (hidden_apex.py)...
    apex_min_saturation: int = 60  # ...when its apex's place is coloured above this [0-255] but not red...
    apex_min_hidden: float = 0.5  # ...on at least this share
    fallback_face_sides_m: Tuple[float, float] = (0.4, 1.5)  # face sides [m] assumed where no format is catalogued


@dataclass(frozen=True)
class DepthConfig:
    """The search space (near..far in front of the camera) and depth from stereo when no depth map is given."""

    near_m: float = 4.0  # nearest depth searched [m] (Cavegn 2011): closer faces are cut by the frame
    far_m: float = 14.0  # farthest depth searched across the frame [m] (Cavegn 2011): every sign comes this close
    # farthest depth searched for a face never seen within far_m (search_range.py) [m] (None: not at all)
    reach_m: Optional[float] = None
    range_from_camera: bool = True  # reach_m follows the drive's camera (pipeline/depth_range.py); off: as set
    ahead_m: Optional[float] = None  # a pair's camera moves on this far [m] before the drive ends or turns (None: on)
    turn_deg: float = 45.0  # a camera looking farther away than this from a pair's has turned off its path [deg]
    placing_sigma_m: float = 1.0  # reach: one view's depth known this well [m] still places a sign by its road
    # a face centre's disparity error [px], depth error Z²σ/(f·B): KITTI's ~0.5 (issue 45), the larger one measured
    disparity_sigma_px: float = 0.5
    search_close_px: int = 15  # holes of a given depth's search space this small [px] are closed before it cuts colours
    search_grow_px: int = 31  # with SGBM depth the search space is grown by this much instead [px]
    face_depth_slack: float = 0.2  # a face's plane depth counts within near x (1 - this) .. far x (1 + this)
    sgbm_scale: float = 0.5  # SGBM runs on the pair at this scale: ~8x faster, disparity still sub-pixel
    sgbm_block_size: int = 5  # SGBM's block size [px at the matcher's scale]
    sgbm_rows_only: bool = True  # match only the row bands holding colour candidates
    sgbm_columns_only: bool = True  # ...and within them windows around the candidates (and their largest disparity)
    sgbm_box_windows: bool = True  # windows are the candidates' grown boxes, joined where they overlap (off: bands)
    sgbm_row_margin_px: int = 24  # margin around candidates, rows and columns [px]
    sgbm_far_factor: float = 2.0  # disparities searched down to far x this: far points then match outside the range
    sgbm_uniqueness: int = 15  # SGBM's uniqueness ratio [%]: the best match beats the second by this margin
    sgbm_p1: int = 8  # SGBM's penalty for disparity steps of 1 [x channels x block size²]: OpenCV's documented choice
    sgbm_p2: int = 32  # SGBM's penalty for larger jumps [x channels x block size²]: 4 x P1, as OpenCV documents
    sgbm_disp12_max_diff: int = 2  # left-right check: disparities of both views differing more are invalid
    sgbm_speckle_window: int = 60  # disparity blobs smaller than this [px at the matcher's scale] are noise...
    sgbm_speckle_range: int = 2  # ...where their disparities vary at most this much within
    sgbm_prefilter_cap: int = 31  # clip of the x-derivative prefilter: limits the weight of strong texture
    sgbm_warm_up_px: int = 64  # columns matched left of a window first [px]: the matcher enters it settled
    sgbm_band_max_height: float = 1.3  # no stereo rows for candidates taller than this x the tallest format near...
    sgbm_band_min_height: float = 0.5  # ...or shorter than this x the lowest format at the far limit (a half face)

    def __post_init__(self):
        if not 0 < self.near_m < self.far_m:
            raise ValueError(f"need 0 < near_m < far_m, got {self.near_m}, {self.far_m}")
        if self.reach_m is not None and self.reach_m < self.far_m:
            raise ValueError(f"need reach_m >= far_m, got {self.reach_m}, {self.far_m}")

    @property
    def farthest_m(self) -> float:
        """The farthest depth searched anywhere in the frame."""
        return max(self.far_m, self.reach_m or self.far_m)


@dataclass(frozen=True)
class PlanarityConfig:
    """Planarity (step 6): the share of a segment lying on one plane, the detection indicator."""

    detection_threshold: float = 0.5  # planar share of a segment needed to keep it
    planarity_window_px: int = 7  # side of the window a local plane is fitted in [px]
    planarity_window_min_share: float = 1 / 3  # a window's plane is fitted only where this share has a depth...
    planarity_window_min_px: int = 6  # ...and at least this many [px]: fewer fit a plane to noise
    planarity_tolerance_px: float = 0.6  # residual allowed [px of full-resolution disparity], given depth
    sgbm_planarity_tolerance_px: float = 1.0  # the same for half-scale SGBM depth, which is noisier [px]
    max_slant_deg: float = 45.0  # steepest slant kept [deg]: signs face the road, roughly along the optical axis
    planarity_refit_band: float = 3.0  # the plane is refitted (twice) on pixels within this x the tolerance of it
    min_depth_coverage: float = 0.3  # share of a segment's pixels needing a valid depth
    # depths farther than this share from the segment's median are artefacts or background (None: all count)
    max_depth_deviation: Optional[float] = 0.25


@dataclass(frozen=True)
class ClassificationConfig:
    """Classification (step 7): which classifier, which templates, and when its reading is accepted."""

    classifier: str = "auto"  # "cnn" (the catalogue's network), "ncc" (templates), "auto" (cnn if it has one)
    classification_threshold: Optional[float] = None  # indicator needed for "accepted"; None = the classifier's own
    exclude: Tuple[str, ...] = ()  # template ids never assigned
    min_surround_score: float = 0.3  # a panel reading needs its part outside the colour segment to match this well
    min_face_part: float = 0.6  # a board whose colour segment is less of its face than this is read as a panel
    min_classification_score: Optional[float] = None  # below this the segment is not reported; None = classifier's
    scales: Tuple[float, ...] = (0.92, 1.0, 1.08)  # template scales tried, x the segment's size
    shift_fraction: float = 0.08  # shift search, as a fraction of the segment size
    max_template_px: int = 96  # larger segments [px] are compared downscaled
    coarse_template_px: int = 32  # with many candidates, all are first compared at this size [px] without search...
    coarse_keep: int = 6  # ...and only this many best go on to the full scale and shift search
    tie_margin: float = 0.04  # candidates this close to the best are decided on the pictogram field (speed limits)
    inner_fraction: float = 0.14  # that field is the face without this outer share (the rim)
    surround_grow: float = 0.04  # a panel's surround is read without this margin of the face (a blurred edge)
    panel_white_min_value: int = 130  # a disc with white this bright [0-255] above and beside it is on a zone panel...
    panel_white_share: float = 0.5  # ...on this share of a strip...
    panel_depth_tolerance: Tuple[float, float] = (0.15, 0.03)  # ...within this of its depth [m, or share; the larger]
    panel_at_depth: Tuple[float, float] = (0.9, 0.6)  # ...for this share of its depths above it, and beside it
    open_set: bool = True  # a face passing every step but with its best logit below unknown_logit is mapped unknown...
    unknown_max_background: float = 0.5  # ...unless the network gives it at least this probability of no sign...
    unknown_min_print: float = 0.01  # ...and only with this share of edge pixels inside: a plain patch is no sign
    unknown_print_inset: float = 0.1  # that inside: the segment without this share of each side
    unknown_print_canny: Tuple[int, int] = (50, 150)  # Canny thresholds of those edges [grey levels]
    measured_print_inset: float = 0.2  # a face sized as measured shows such print this far inside (tail lights: none)
    text_lines_min_px: int = 18  # direction signs are told by their lines of text on faces this high [px]
    text_lines_inset: Tuple[float, float] = (0.2, 0.06)  # (width, height) share cut off each side: border, a tip
    text_lines_contrast: float = 60.0  # text is this far from the field's colour [Lab distance]
    text_lines_max_column_ink: float = 0.8  # a column this full of "text" is a pole or post in front
    text_lines_row_share: float = 0.03  # a row with this share of text pixels is text (a gap between lines: none)
    text_lines_min_height: float = 0.08  # a line is a band of text rows at least this x the face's height
    text_lines_min_band_share: float = 0.5  # ... and at least this x the highest band (umlauts above a line: none)
    same_sign_max_iou: float = 0.3  # detections of a pair overlapping more [IoU] are one sign: the best is kept...
    part_max_area_share: float = 0.7  # ...but one in an accepted face, at most this share of it, is its part

    def __post_init__(self):
        if self.classifier not in CLASSIFIERS:
            raise ValueError(f"unknown classifier {self.classifier!r}; choose one of {', '.join(CLASSIFIERS)}")


@dataclass(frozen=True)
class HoughConfig:
    """Hough fallback for faded or white/grey round signs (hough.py), and the faces it seeks without depth."""

    hough_enabled: bool = True  # seek faded and white/grey round signs by the Hough transform
    hough_scale: float = 0.5  # Hough image scale at most; less where the smallest radius sought allows
    hough_min_radius_px: float = 6.0  # smallest radius sought [px of the Hough image]: it sets the scale
    hough_circularity: float = 0.85  # param2 of HOUGH_GRADIENT_ALT: how round a circle's edges are
    hough_dp: float = 1.5  # accumulator 1.5x coarser than the image: OpenCV's advice for HOUGH_GRADIENT_ALT
    hough_edge_threshold: float = 150.0  # param1 of HOUGH_GRADIENT_ALT
    hough_mask_median_px: int = 5  # the search space's outline is median-smoothed first [px, odd]: speckle edges
    hough_ring_share: float = 0.1  # a circle's colour is read in its outer ring this share of its diameter deep
    hough_max_status: str = "review"  # status cap of Hough finds whose ring is not in full colour
    hough_max_diameter_m: float = 0.6  # largest round format sought [m]: larger only by colour (radius range = cost)
    hough_fallback_diameters_m: Tuple[float, ...] = (0.4, 0.6)  # round formats [m] if the catalogue has none
    hough_radius_slack: float = 0.2  # the formats' radius range in near..far widened by this share both ways
    max_face_px: int = 200  # largest round face sought without depth [px] (Hough, bright fields): range = cost
    hough_min_face_px: int = 28  # smallest one [px]: smaller circles double the time and are mostly clutter
    hough_covered_iou: float = 0.5  # a circle matching a face candidate's box this much [IoU] is that candidate
    hough_tint_min_saturation: int = 22  # a ring's tint is read from pixels this saturated [0-255]: < weak_sat_min
    # hue ranges [hue 0-179] that name a Hough ring's tint
    hough_tint_hues: Dict[str, Tuple[Tuple[int, int], ...]] = field(default_factory=lambda: dict(HOUGH_TINT_HUES))
    hough_tint_min_share: float = 0.25  # share of the ring's pixels a tint needs to name it; else white
    hough_strong_ring_share: float = 0.5  # a ring this much in full colour is a colour find lost: may be accepted
    hough_field_ring_share: float = 0.5  # a white circle in an annulus this much full red is a lost ring's field...
    hough_field_ring_band: Tuple[float, float] = (1.08, 1.25)  # ...that annulus, x its radius (half in the image)


@dataclass(frozen=True)
class WhiteConfig:
    """White and grey signs (white_outlines.py, white_signs.py): fields enclosed by strong edges, achromatic and
    bright, read as discs and upright rectangles over the whole image; then depth, format, planarity, standing
    free, a support below and NCC among the white entries."""

    white_signs: bool = True  # seek white and grey signs (an inventory holds them); off is faster
    white_max_side_m: float = 0.9  # formats up to this side [m]: the 1.2 m motorway discs would set the cost
    white_min_side_m: float = 0.35  # shorter sides count as this [m]: found nearer, the scan keeps its reduction
    white_scan_side_px: float = 18.0  # scan reduced by a whole factor keeping the smallest face this wide [px]
    white_canny_low: int = 40  # Canny low threshold of the outline edges [grey levels of the reduced image]
    white_canny_high: int = 110  # Canny high threshold [grey levels of the reduced image]
    white_max_saturation: int = 60  # an achromatic pixel's saturation [0-255]: faded red rims stay above
    white_min_achromatic: float = 0.8  # share of a cell's pixels that are achromatic
    white_min_brightness: float = 0.6  # a cell's mean value is at least this x the scene's median (a window: ~0.3)
    white_part_share: float = 0.35  # a cell may be this part of the smallest face (a field cut by a stripe band)
    white_min_cell_fill: float = 0.12  # cell pixels / its box: thinner cells are gaps between edges, not fields
    white_join_reach: float = 0.35  # cells within this x their size of a face's cells are read with them...
    white_join_gap: float = 0.25  # ...or within this x the smallest face side (a zone panel's ring and stripe)
    white_join_steps: int = 12  # cells joined one at a time from each, every face-like union a reading
    white_min_shape_fit: float = 0.8  # IoU with the ideal rectangle (façade patches and leaves fit loosely)
    white_max_aspect: float = 1.6  # longer / shorter side of a rectangle: zone panels are 1.4
    white_min_panel_cover: float = 0.2  # the cells fill this share of a rectangle (a zone panel's field: 0.2-0.4)
    white_min_panel_support: float = 0.8  # a rectangle no hull fits is a panel with this share of its sides on edges
    white_panel_grow: float = 0.2  # a panel's outline is sought up to this x its size beyond its cells
    white_min_disc_cover: float = 0.2  # the cells fill this share of their smallest circle (digits cut the field)
    white_support_samples: int = 48  # points on that circle (or the rectangle's sides)...
    white_min_edge_support: float = 0.65  # ...this share of them on a strong gradient across the outline
    white_refine_margin: float = 0.25  # circles this far below it are moved and resized to their best outline...
    white_circle_search: float = 0.12  # ...within this x the radius (centre and radius)
    white_circle_search_steps: int = 5  # ...on a grid of this many steps along each of the three
    white_rim_saturation_step: float = 10.0  # a ring this much more saturated than its field is a faded rim [0-255]
    white_rim_field_depth: float = 0.25  # its field: the disc without this share of its diameter all round
    white_ring_band: Tuple[float, float] = (1.06, 1.2)  # a disc whose band x its radius out is red/blue is a field...
    white_beyond_band: Tuple[float, float] = (1.5, 1.75)  # ...when the band beyond (x its radius) is not
    white_min_ring_share: float = 0.6  # share of that band red or blue by the colour step's ranges
    white_hough: bool = True  # round outlines are also sought by the Hough transform on the scanned image
    white_hough_dp: float = 1.5  # its accumulator's resolution (1.5 x coarser than the scanned image)
    white_hough_min_dist: float = 2.0  # circles' centres this x the smallest radius apart: concentric ones are one
    white_hough_edge: float = 300.0  # its edge threshold on Scharr gradients (~ Canny 110 on Sobel)...
    white_hough_roundness: float = 0.75  # ...and how round an outline must be (0-1)
    white_hough_min_radius: float = 0.85  # smallest radius, x half the smallest face side: faint outlines read short
    white_hough_coarse_radius: float = 30.0  # radii above this [px of the scan] are sought in the scan reduced by 2
    white_format_fit: bool = True  # a face between white formats is sought again as each format's outline
    white_format_min_iou: float = 0.5  # the format's outline overlaps the candidate's box at least this much [IoU]
    white_disc_in_panel: float = 0.8  # a disc this share inside a white panel found too is its zone disc, no sign
    white_panel_around: bool = True  # a disc read as a sign is sought again as the zone disc of a panel around it
    white_ring_ratios: Tuple[float, float] = (1.25, 1.75)  # an achromatic ring's outline around a disc, x its radius
    white_ring_steps: int = 11  # radii tried between the two
    white_ring_min_support: float = 0.45  # share of the ring's outline on radial gradients (a face's: 0.65)
    white_max_coloured_share: float = 0.3  # a panel with more of its pixels coloured is a coloured zone panel
    white_min_gradient: float = 80.0  # Sobel magnitude of that gradient (about 20 grey levels across the outline)
    white_max_candidates: int = 40  # per pair, largest first: bounds the stereo matching they ask for
    white_same_iou: float = 0.6  # a face overlapping a kept one this much [IoU] is the same
    white_side_gap: float = 0.15  # standing free: bands beside the face after this gap, x its width...
    white_side_band: float = 0.5  # ...this wide, x its width, hold few pixels at its depth
    white_min_side_valid: float = 0.2  # share of the bands needing a depth to judge (else: sky, no verdict)
    white_max_side_share: float = 0.35  # a façade or a van's body around a window or a panel: most at its depth
    white_same_depth_m: float = 0.4  # "at the face's depth": within this [m] (or white_same_depth_share)
    white_same_depth_share: float = 0.05  # ...or this share of the depth
    white_support_gap: float = 0.05  # a support below: a strip under the face after this gap, x its height...
    white_support_length: float = 0.4  # ...this long, x its height...
    white_support_width: float = 0.3  # ...this wide, x its width...
    white_min_support: float = 0.5  # ...this share of its rows holding a pixel at its depth (the pole, a sign)
    white_pole_edge: float = 60.0  # Sobel x response of a pole's edge (about 15 grey levels across it)...
    white_min_pole_rows: float = 0.7  # ...in this share of the strip's rows, in one column: a pole in the image
    white_min_score: float = 0.5  # NCC among the white entries: below it no template resembles the face...
    white_unsupported_min_score: float = 0.65  # ...or below this without a support seen below it
    white_accept_score: float = 0.65  # and from this on it is "accepted"
    white_network_gate: bool = True  # below white_min_score a supported face the network accepts is still a sign
    white_radial_cos: float = 0.8  # an outline point's gradient lies across the outline within this cosine (37 deg)
    white_edge_band_px: float = 1.5  # the outline is sought this far outside the cells [px of the reduced image]
    white_pole_blur_rows: int = 7  # rows the strip below a face is averaged over along the pole before its edges
    text_panels: bool = True  # seek white text panels (text_panels.py: 4.29, 4.30, 4.33): the field in the frame
    panel_canny: Tuple[int, int] = (40, 110)  # Canny thresholds of the fields' edges (grey levels, full image)
    panel_frame_margin: float = 0.045  # the frame and the white margin outside it, share of the face's height
    panel_frame_reach: float = 0.1  # the frame's dark line lies within this x the field's height outside it...
    panel_frame_contrast: float = 0.8  # ...darker than this x the field's median brightness (a blurred line: ~0.65)
    panel_min_frame: float = 0.6  # share of the field's outline with dark beside it: a candidate...
    panel_margin_brightness: float = 0.75  # ...and where that dark is a line, bright again (the panel's margin)...
    panel_line_reach_px: int = 6  # (the line and the margin are sought at least this far [px])
    panel_min_line: float = 0.35  # ...on this share of its top and bottom edges (a white board: < 0.25)...
    panel_full_line: float = 0.6  # ...the indicator (frame_indicator) falls below this share of the better edge
    panel_accept_frame: float = 0.85  # ...accepted from this indicator on (with a support below)...
    panel_unsupported_frame: float = 0.8  # ...and without a support seen below only from this on
    panel_min_aspect: float = 0.9  # field width / height (a two-line place name: ~1.2; one destination: ~6)
    panel_max_aspect: float = 10.0  # widest field width / height
    panel_min_cell_fill: float = 0.25  # the field's cell (lettering cut out) fills this share of its box...
    panel_min_fill: float = 0.75  # ...and, its lettering's holes filled, this share (a pointer: ~0.9)
    panel_min_ink: float = 0.03  # lettering: share of the filled field that is holes (a blank board has none)
    panel_max_ink: float = 0.6  # most lettering share
    panel_max_candidates: int = 12  # per pair, largest first
    panel_end_share: float = 0.25  # a field's end columns, this x its height (a corner less, a pointer's point more)...
    panel_point_ratio: float = 0.6  # ...at most this x its middle's height: it ends in a point (4.33)
    panel_stack_align: float = 0.04  # two fields stacked on a bar (4.30) share their sides within this x width
    panel_bar_max_share: float = 0.3  # and the bar between them is at most this share of their height
    panel_bar_rows: Tuple[float, float] = (0.1, 0.45)  # a 4.30's bar over its lower field, x that field's height
    panel_plate_gap: float = 0.3  # a field this x a sign's height or less below or above it is its plate
    panel_size_step_m: float = 0.05  # a panel's measured size is given to this step [m] (no standard format)


@dataclass(frozen=True)
class PlateConfig:
    """Supplementary plates (plates.py): white rectangles of a plate format right below or above a sign."""

    find_plates: bool = True  # seek supplementary plates right below or above each sign
    plate_min_cover: float = 0.6  # a white-step rectangle this much inside another sign's plate is that plate
    plate_max_gap_m: float = 0.12  # between the sign's edge and the plate [m] (both clamped to one pole)
    plate_min_gap_m: float = 0.03  # a white region reaching further [m] into the sign's box is part of its panel
    plate_box_overshoot: float = 0.1  # ...or further than this x the sign's box height: a grown box may overshoot
    plate_max_saturation: int = 60  # white and grey [saturation 0-255]: a plate in shade is grey, never coloured
    plate_min_value: int = 100  # floor of its brightness [0-255] (Otsu's split of the window raises it in the sun)
    plate_value_steps: Tuple[int, ...] = (0, 25, 50)  # further floors above that: a plate before a pale wall
    plate_edge_cut: bool = True  # the lowest floor is also cut along brightness edges: a plate before a pale façade
    plate_edge_thresholds: Tuple[int, int] = (20, 60)  # Canny thresholds of those edges [value 0-255]
    plate_depth_tolerance_m: float = 0.3  # where depth is known, the plate lies within this of the sign's depth [m]
    plate_close_m: float = 0.0  # closing before the holes are filled [m] (0: none; a plate's thin frame must stay)
    plate_frame_share: float = 0.075  # of a plate's height: its white margin and black frame line (inset)
    plate_min_fill: float = 0.85  # of its box: a rectangle
    plate_notch_m: float = 0.02  # thin dark lines across a plate [m] (a wire, a pole's edge) do not count against it
    plate_neck_m: float = 0.12  # runs of a region narrower than this [m] (a pale pole, 6-8 cm) are cut off first
    plate_neck_end_share: float = 0.15  # a cut region going on within this share at both ends is a larger frame's top
    plate_max_offset: float = 0.35  # centre off the sign's axis, share of the wider of the two
    plate_size_tolerance: float = 0.2  # relative deviation from a plate format (PLATE_FORMATS)
    plate_ink_darkness: float = 0.6  # a plate pixel darker than this x its median is ink: black print stays below
    plate_min_seen: float = 0.3  # at least this share of a plate's box seen (not hidden in front) to judge its ink
    plate_edge_px: int = 1  # a plate box within this of the image's edge [px] may be cut by it: not seen whole
    plate_depth_tolerance_share: float = 0.05  # ...the depth tolerance grows to this share of the depth (SGBM's)
    plate_min_ink: float = 0.02  # share of dark pixels (text, pictogram, frame): a blank white region is no plate
    plate_max_ink: float = 0.5  # most share of dark pixels
    plate_accept_score: float = 0.8  # fill and fit to its format: above, the plate is "accepted"
    plate_min_visible: float = 0.4  # a plate cut into pieces by something in front: this share of their box seen...
    plate_hidden_weight: float = 0.9  # ... and it scores this much less than a plate seen whole
    plate_occluder_span: float = 0.9  # a post in front: a dark run over this share of the window's height...
    plate_occluder_max_width: float = 0.3  # ...at most this x the sign's width wide (the sign's own pole is behind)
    plate_occluder_contrast: float = 0.8  # within a plate's crop, such a post is darker than this x its paper
    plate_split_min_overlap: float = 0.8  # two pieces of a plate cut by such a post are level: rows this shared
    plate_pictogram_min_score: float = 0.7  # correlation with a pictogram plate's drawing: below, a text plate
    plate_min_size_px: Tuple[int, int] = (6, 4)  # smallest region read as a plate (width, height) [px]: specks
    plate_notched_min_fill: float = 0.6  # a region filling this much of its box is measured again, notches closed
    plate_max_value_floor: int = 250  # brightness floors from this up [0-255] are not tried: only highlights
    plate_min_widening: float = 0.1  # hidden pieces are completed to a format's width only where that adds this
    plate_misfit_weight: float = 0.5  # a plate at the size tolerance's edge scores this much less (log-linear)
    plate_compare_height_px: int = 36  # a pictogram plate's crop and drawings are compared at this height [px]
    plate_compare_min_px: int = 8  # a crop or drawing narrower or lower than this [px] shows no pictogram: no score
    plate_compare_blur_px: float = 0.9  # both blurred by this Gaussian sigma at that size [px]
    plate_compare_shift_px: int = 3  # the best correlation over shifts up to this [px]: a box is found to a pixel
    plate_compare_insets: Tuple[float, ...] = (0.0, 0.06, 0.12)  # crop's height share cut off each side (best counts)
    plate_inset_candidates: int = 2  # the insets beyond the first are tried on this many most alike drawings
    plate_aspect_tolerance: float = 0.25  # a crop is compared only with drawings of its aspect within this (log)
    plate_pictogram_min_seen: float = 0.4  # share of a plate's crop seen (not hidden in front) to compare it at all


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
    template_min_field_share: float = 0.05  # an enclosed field smaller than this share of the face is a letter's hole
    template_panel_part_area: Tuple[float, float] = (0.1, 0.8)  # share of a panel its inset part (zone disc) covers
    template_bright_grey: int = 128  # a face's bright part is its pixels at least this grey [0-255]: yellow is ~190
    template_same_part_tolerance: float = 0.03  # a colour in another's range over its part within this reads as it
    template_same_place: float = 0.03  # parts of two drawings whose sides lie this close [share of the face] are one


TEMPLATE_GEOMETRY = TemplateGeometry()


@dataclass(frozen=True)
class PipelineConfig:
    """All settings of the detection steps, one section per step.

    The documented contract (``mapsigns``' main parameters) is ``depth.near_m``,
    ``depth.far_m``, ``colour.colours``, ``classification.exclude``,
    ``planarity.detection_threshold``, ``classification.classification_threshold``
    and ``classification.classifier``.
    """

    colour: ColourConfig = field(default_factory=ColourConfig)  # step 3: colour segmentation
    scene: SceneConfig = field(default_factory=SceneConfig)  # the scene pass: floors read from the image
    bright_fields: BrightFieldConfig = field(default_factory=BrightFieldConfig)  # ring fields by brightness
    rims: RimConfig = field(default_factory=RimConfig)  # face boxes measured around a coloured part
    shape: ShapeConfig = field(default_factory=ShapeConfig)  # step 4: fit to an ideal outline
    size: SizeConfig = field(default_factory=SizeConfig)  # step 5: metric size and format
    depth: DepthConfig = field(default_factory=DepthConfig)  # the search space and stereo depth
    planarity: PlanarityConfig = field(default_factory=PlanarityConfig)  # step 6: the detection indicator
    classification: ClassificationConfig = field(default_factory=ClassificationConfig)  # step 7: reading a face
    hough: HoughConfig = field(default_factory=HoughConfig)  # round faces by the Hough transform
    white: WhiteConfig = field(default_factory=WhiteConfig)  # white and grey signs, text panels
    plates: PlateConfig = field(default_factory=PlateConfig)  # supplementary plates below or above a sign


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
