"""Writing mapped signs into a Signalo database: support per pole, azimut per face direction, frame, sign.

Signalo's model (``signalo_db``): a support (pole, 2D point) carries azimuts (the
direction the faces look towards, whole degrees), each carrying frames (ranked
from the top), each carrying signs that reference the official sign types by
SSV number. Mapped signs within ``pole_radius_m`` of each other (planimetric)
are one pole; on it, faces within ``azimuth_gap_deg`` share an azimut; each
sign gets its own frame, ranked by height. The support records the free height
under its lowest sign (the mapped mounting height).

A supplementary plate (a mapped feature with ``plate_of``) is written as Signalo
models it: one more sign in its sign's frame, ranked by height (a plate below its
sign comes after it), of its own official type (its SSV id, ``plate_types``): a
pictogram plate without inscription (``5.31``), a layout plate with its text
(``5.03`` "2,5 km"), a text plate with its lines (``5.01`` "200 m", ``5.00-2``
"Mo–Fr", "7–19 h"; ``5.00-exception`` with what is excepted), its parent
(``fk_parent``) the sign it belongs to; a direction plate (``5.02-r``) as its
Signalo id with its direction (``natural_direction_or_left``). A plate whose sign
is not written by this export is reported, not written on its own.

Everything happens in one transaction: all or nothing. Each sign's comment
starts with a tag naming our run id and sign id, so exporting the same run
again adds nothing. Signs that ``changes`` found ``confirmed`` or ``moved``
against a Signalo sign can update that sign instead of adding a new one.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Optional, Sequence

import numpy as np

from ..catalogue.plates_ch import FREE_TEXT_PLATES, RIGHT, direction_of, signalo_id
from ..plates.formats import PLATE_ID
from ..plates.types import inscriptions, text_plate_id
from ..statuses import REVIEW
from . import AZIMUTH_GAP_DEG, POLE_RADIUS_M
from .schema import OFFICIAL_SIGN_TYPE, SCHEMA, SignaloError, check_database
from .types import to_signalo

USER = "Sign Mapper"
TAG = "[signmapper run={run} sign={sign}]"
TAG_PATTERN = re.compile(r"\[signmapper run=(\S+) sign=(\d+)\]")
ROUND_SHAPES = ("circle", "octagon")


@dataclass(frozen=True)
class ExportSign:
    """A mapped sign as the export needs it; position (E, N, H) in the database's SRID."""

    sign_id: int
    template_id: str
    position: np.ndarray
    azimuth: Optional[float]
    width_m: float
    height_m: float
    format: str = ""
    shape: str = ""
    status: str = ""
    detection_indicator: Optional[float] = None
    classification_indicator: Optional[float] = None
    n_obs: Optional[int] = None
    sigma_m: Optional[float] = None
    mount_height_m: Optional[float] = None
    update_id: Optional[str] = None  # Signalo sign id to update instead of adding (changes: confirmed/moved)
    moved: bool = False  # with update_id: the sign was mapped elsewhere (changes: moved)
    plate_of: Optional[int] = None  # a supplementary plate: our sign id of its sign
    text: Optional[str] = None  # a plate's text, lines joined by " / "
    review_reason: Optional[str] = None  # why the mapping left it for review (review_reasons)


@dataclass
class SupportPlan:
    """One pole to write: its position and its signs grouped by face direction, top first."""

    easting: float
    northing: float
    azimuts: list  # [(azimut in whole degrees, [ExportSign top first])]
    free_height_m: Optional[float] = None

    @property
    def signs(self) -> list:
        return [s for _, signs in self.azimuts for s in signs]


@dataclass
class ExportResult:
    version: Optional[str]
    added: list = field(default_factory=list)  # (our sign id, Signalo sign id)
    updated: list = field(default_factory=list)  # (our sign id, Signalo sign id)
    already: list = field(default_factory=list)  # our sign ids this run had already written
    unknown: list = field(default_factory=list)  # (our sign id, template id) with no Signalo official sign
    plates_without_sign: list = field(default_factory=list)  # (our plate id, its sign id) not written now
    supports: int = 0

    def summary(self) -> str:
        text = (f"{len(self.added)} signs added on {self.supports} supports, {len(self.updated)} updated, "
                f"{len(self.already)} already exported by this run")
        if self.unknown:
            text += f", {len(self.unknown)} not written (type not in Signalo: " + \
                ", ".join(f"sign {i} {t}" for i, t in self.unknown) + ")"
        if self.plates_without_sign:
            text += f", {len(self.plates_without_sign)} plates not written (their sign is not written by this " \
                    "export: " + ", ".join(f"plate {i} of sign {s}" for i, s in self.plates_without_sign) + ")"
        return text


def plate_type(plate: ExportSign, official_ids) -> Optional[tuple[str, list, bool]]:
    """(Signalo official sign id, inscriptions, natural direction or left) of a supplementary plate, None if
    Signalo has no such type. A plate mapped untyped (``plate``: its text not read, or a run of before plates
    were typed) is typed by its text here, a 5.00-1 without one."""

    template_id = plate.template_id
    if template_id == PLATE_ID:
        template_id = text_plate_id(plate.text) if plate.text else FREE_TEXT_PLATES[0]
    official = signalo_id(template_id)
    if official not in official_ids:
        return None
    return official, inscriptions(template_id, plate.text), direction_of(template_id) != RIGHT


def _circular_mean(degrees: Sequence[float]) -> float:
    a = np.radians(np.asarray(degrees, float))
    return float(np.degrees(np.arctan2(np.sin(a).mean(), np.cos(a).mean())) % 360.0)


def _angle_gap(a: float, b: float) -> float:
    return abs((a - b + 180.0) % 360.0 - 180.0)


def plan_supports(signs: Sequence[ExportSign], pole_radius_m: float = POLE_RADIUS_M,
                  azimuth_gap_deg: float = AZIMUTH_GAP_DEG) -> list[SupportPlan]:
    """Group signs into poles (single linkage within ``pole_radius_m``) and each pole's faces into azimuts."""
    n = len(signs)
    parent = list(range(n))

    def root(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    xy = np.array([s.position[:2] for s in signs], float).reshape(-1, 2)
    for i in range(n):
        for j in range(i + 1, n):
            if np.hypot(*(xy[i] - xy[j])) <= pole_radius_m:
                parent[root(i)] = root(j)
    poles = {}
    for i in range(n):
        poles.setdefault(root(i), []).append(signs[i])
    plans = []
    for members in sorted(poles.values(), key=lambda m: min(s.sign_id for s in m)):
        groups = []  # [[azimuths], [signs]]
        for sign in sorted(members, key=lambda s: (s.azimuth is None, s.azimuth or 0.0)):
            facing = sign.azimuth if sign.azimuth is not None else 0.0
            for azimuths, grouped in groups:
                if _angle_gap(facing, azimuths[0]) <= azimuth_gap_deg:
                    azimuths.append(facing)
                    grouped.append(sign)
                    break
            else:
                groups.append([[facing], [sign]])
        azimuts = {}
        for azimuths, grouped in groups:
            value = int(round(_circular_mean(azimuths))) % 360
            while value in azimuts:  # Signalo: one azimut per value and support
                value = (value + 1) % 360
            azimuts[value] = sorted(grouped, key=lambda s: -float(s.position[2]))
        mounts = [s.mount_height_m for s in members if s.mount_height_m is not None]
        centre = np.mean([s.position[:2] for s in members], axis=0)
        plans.append(SupportPlan(float(centre[0]), float(centre[1]), sorted(azimuts.items()),
                                 min(mounts) if mounts else None))
    return plans


def sign_comment(run_id: str, sign: ExportSign, previous: Optional[str] = None) -> str:
    """Our tag, then what the mapping measured; a comment already there is kept after it (without an old tag)."""
    parts = [f"Sign Mapper {sign.template_id}"]
    if sign.plate_of is not None:
        parts.append(f"plate of sign {sign.plate_of}" + (f", text \"{sign.text}\"" if sign.text else ""))
    if sign.format:
        parts.append(f"format {sign.format} {sign.width_m:.2f} x {sign.height_m:.2f} m")
    figures = [f"{label} {value:.2f}" for label, value in (("detection", sign.detection_indicator),
                                                           ("classification", sign.classification_indicator))
               if value is not None]
    if sign.n_obs is not None:
        figures.append(f"{sign.n_obs} observations")
    if sign.sigma_m is not None:
        figures.append(f"sigma {sign.sigma_m:.3f} m")
    if sign.mount_height_m is not None:
        figures.append(f"mounting height {sign.mount_height_m:.2f} m")
    if sign.status:
        why = f" ({sign.review_reason})" if sign.status == REVIEW and sign.review_reason else ""
        figures.append(f"status {sign.status}{why}")
    text = f"{TAG.format(run=run_id, sign=sign.sign_id)} {'; '.join(parts + [', '.join(figures)])}"
    kept = TAG_PATTERN.sub("", previous or "").strip()
    return f"{text}\n{kept}" if kept else text


def dimensions(sign: ExportSign) -> tuple:
    """Signalo's dimension_1, dimension_2 [m]: radius for a round face, else height and width."""
    if sign.shape in ROUND_SHAPES:
        return round(sign.width_m / 2.0, 3), None
    return round(sign.height_m, 3), round(sign.width_m, 3)


def exported_sign_ids(cursor, run_id: str) -> set:
    """Our sign ids that run ``run_id`` already wrote (their tags in sign comments)."""
    cursor.execute(f"SELECT comment FROM {SCHEMA}.sign WHERE comment LIKE %s",
                   (f"%[signmapper run={run_id} %",))
    found = set()
    for (comment,) in cursor.fetchall():
        for run, sign in TAG_PATTERN.findall(comment or ""):
            if run == run_id:
                found.add(int(sign))
    return found


def _insert(cursor, table: str, values: dict) -> str:
    names = ", ".join(values)
    marks = ", ".join("%s" for _ in values)
    cursor.execute(f"INSERT INTO {SCHEMA}.{table} ({names}) VALUES ({marks}) RETURNING id", list(values.values()))
    return str(cursor.fetchone()[0])


def _in_frame(sign: ExportSign, plates: dict) -> list:
    """The sign and its plates, top first: the order of the signs in its frame."""
    return sorted([sign] + plates.get(sign.sign_id, []), key=lambda s: -float(s.position[2]))


def _write_support(cursor, plan: SupportPlan, srid: int, run_id: str, types: dict, plates: dict) -> list:
    cursor.execute(
        f"INSERT INTO {SCHEMA}.support (geometry, height_free_under_signal, comment, needs_validation, "
        "_creation_user, _last_modification_user) VALUES (ST_SetSRID(ST_MakePoint(%s, %s), %s), %s, %s, %s, %s, %s) "
        "RETURNING id",
        (plan.easting, plan.northing, srid, None if plan.free_height_m is None else round(plan.free_height_m, 3),
         f"[signmapper run={run_id}] support of mapped signs {', '.join(str(s.sign_id) for s in plan.signs)}",
         any(s.status == REVIEW for s in plan.signs), USER, USER))
    support_id = str(cursor.fetchone()[0])
    written = []
    for value, signs in plan.azimuts:
        azimut_id = _insert(cursor, "azimut", {"fk_support": support_id, "azimut": value, "_creation_user": USER})
        for rank, sign in enumerate(signs, start=1):
            d1, d2 = dimensions(sign)
            frame_id = _insert(cursor, "frame", {"fk_azimut": azimut_id, "rank": rank, "dimension_1": d1,
                                                 "dimension_2": d2, "_creation_user": USER})
            members = _in_frame(sign, plates)
            # the sign first, its plates then with it as their parent; each at its rank in the frame, top first
            parent = None
            for member in sorted(members, key=lambda m: m is not sign):
                official, inscriptions, left = types[member.sign_id]
                inscriptions = (inscriptions if isinstance(inscriptions, list) else [inscriptions]) + [None] * 4
                m1, m2 = dimensions(member)
                sign_uuid = _insert(cursor, "sign", {
                    "fk_frame": frame_id, "rank": members.index(member) + 1, "fk_sign_type": OFFICIAL_SIGN_TYPE,
                    "fk_official_sign": official, "fk_parent": parent, "inscription_1": inscriptions[0],
                    "inscription_2": inscriptions[1], "inscription_3": inscriptions[2], "dimension_1": m1,
                    "dimension_2": m2, "natural_direction_or_left": left, "comment": sign_comment(run_id, member),
                    "needs_validation": member.status == REVIEW, "_creation_user": USER,
                    "_last_modification_user": USER})
                written.append((member.sign_id, sign_uuid))
                parent = parent or sign_uuid
    return written


def _update_sign(cursor, sign: ExportSign, srid: int, run_id: str) -> str:
    cursor.execute(f"SELECT s.comment, a.fk_support FROM {SCHEMA}.sign s JOIN {SCHEMA}.frame f ON f.id = s.fk_frame "
                   f"JOIN {SCHEMA}.azimut a ON a.id = f.fk_azimut WHERE s.id::text = %s", (sign.update_id,))
    row = cursor.fetchone()
    if row is None:
        raise SignaloError(f"sign {sign.update_id} to update (changes found mapped sign {sign.sign_id} "
                           f"{'moved' if sign.moved else 'confirmed'} against it) is not in the database")
    comment, support_id = row
    d1, d2 = dimensions(sign)
    cursor.execute(f"UPDATE {SCHEMA}.sign SET comment = %s, dimension_1 = %s, dimension_2 = %s, "
                   "_last_modification_user = %s, _last_modification_date = now() WHERE id::text = %s",
                   (sign_comment(run_id, sign, comment), d1, d2, USER, sign.update_id))
    if sign.moved:
        cursor.execute(f"SELECT count(*) FROM {SCHEMA}.sign s JOIN {SCHEMA}.frame f ON f.id = s.fk_frame "
                       f"JOIN {SCHEMA}.azimut a ON a.id = f.fk_azimut WHERE a.fk_support = %s", (support_id,))
        alone = cursor.fetchone()[0] == 1
        if alone:  # the pole carries only this sign: the pole moved
            cursor.execute(f"UPDATE {SCHEMA}.support SET geometry = ST_SetSRID(ST_MakePoint(%s, %s), %s), "
                           "_last_modification_user = %s, _last_modification_date = now() WHERE id = %s",
                           (float(sign.position[0]), float(sign.position[1]), srid, USER, support_id))
        else:  # other signs share the pole: a person decides
            cursor.execute(f"UPDATE {SCHEMA}.support SET needs_validation = true, _last_modification_user = %s, "
                           "_last_modification_date = now() WHERE id = %s", (USER, support_id))
    return str(sign.update_id)


def export_signs(connection, run_id: str, signs: Sequence[ExportSign], pole_radius_m: float = POLE_RADIUS_M,
                 azimuth_gap_deg: float = AZIMUTH_GAP_DEG, where: str = "the database") -> ExportResult:
    """Write ``signs`` into the Signalo database of ``connection`` in one transaction; SignaloError if it cannot.

    Signs the run already wrote are left alone; signs whose type Signalo lacks
    are reported in the result and not written.
    """
    if not run_id:
        raise SignaloError("the mapping run has no run id: map the drive again with this version of Sign Mapper")
    try:
        with connection, connection.cursor() as cursor:
            info = check_database(cursor, where)
            cursor.execute(f"SELECT id FROM {SCHEMA}.vl_official_sign")
            official = {row[0] for row in cursor.fetchall()}
            result = ExportResult(info.version)
            done = exported_sign_ids(cursor, run_id)
            types, to_add, plates = {}, [], {}
            for sign in sorted(signs, key=lambda s: (s.plate_of is not None, s.sign_id)):  # plates after signs
                if sign.sign_id in done:
                    result.already.append(sign.sign_id)
                    continue
                if sign.plate_of is None:
                    signalo = to_signalo(sign.template_id, official)
                    mapped = None if signalo is None else (*signalo, True)
                else:
                    mapped = plate_type(sign, official)
                if mapped is None:
                    result.unknown.append((sign.sign_id, sign.template_id))
                    continue
                if sign.plate_of is not None:
                    if not any(s.sign_id == sign.plate_of for s in to_add):
                        result.plates_without_sign.append((sign.sign_id, sign.plate_of))
                        continue
                    types[sign.sign_id] = mapped
                    plates.setdefault(sign.plate_of, []).append(sign)
                    continue
                types[sign.sign_id] = mapped
                if sign.update_id:
                    result.updated.append((sign.sign_id, _update_sign(cursor, sign, info.srid, run_id)))
                else:
                    to_add.append(sign)
            plans = plan_supports(to_add, pole_radius_m, azimuth_gap_deg)
            for plan in plans:
                result.added.extend(_write_support(cursor, plan, info.srid, run_id, types, plates))
            result.supports = len(plans)
    except SignaloError:
        raise
    except Exception as exc:  # the driver's errors, e.g. a constraint Signalo enforces
        raise SignaloError(f"{where}: writing failed, nothing was written: {type(exc).__name__}: {exc}") from exc
    return result
