"""The change report as a self-contained HTML page: counts per verdict, a map-like plot and the lists.

The plot is inline SVG drawn here, like the evaluation report (``report_html``):
the drive's track, every inventory sign coloured by its verdict, new mapped
signs, and a line from each moved sign's inventory position to where it was
mapped. North is up, the scale in metres.
"""

from __future__ import annotations

import html

import numpy as np

from .compare import MOVED, NEW, VERDICT_COLOURS, VERDICTS, Change, ChangeReport


def _fmt(value, digits=2) -> str:
    return "–" if value is None else f"{value:.{digits}f}"


def map_svg(report: ChangeReport, track_xy, size_px: int = 720) -> str:
    """Plan view of the track and the verdicts, to scale, north up."""
    track = np.asarray(track_xy, float).reshape(-1, 2)
    points = [c.position[:2] for c in report.changes] + [c.mapped.position[:2] for c in report.of(MOVED)]
    everything = np.vstack([track] + ([np.array(points)] if points else []))
    lo, hi = everything.min(axis=0) - 5.0, everything.max(axis=0) + 5.0
    span = float(max(hi - lo))
    scale = (size_px - 40) / span
    height_px = int((hi[1] - lo[1]) * scale) + 40

    def xy(p):
        return 20 + (p[0] - lo[0]) * scale, height_px - 20 - (p[1] - lo[1]) * scale

    parts = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{size_px}" height="{height_px}" '
             f'viewBox="0 0 {size_px} {height_px}" font-family="sans-serif" font-size="11">',
             f'<rect width="{size_px}" height="{height_px}" fill="white" stroke="#ccc"/>']
    if len(track) > 1:
        path = " ".join(f"{x:.1f},{y:.1f}" for x, y in map(xy, track))
        parts.append(f'<polyline points="{path}" fill="none" stroke="#777" stroke-width="2"/>')
    for change in report.of(MOVED):
        (x0, y0), (x1, y1) = xy(change.inventory.position), xy(change.mapped.position)
        parts.append(f'<line x1="{x0:.1f}" y1="{y0:.1f}" x2="{x1:.1f}" y2="{y1:.1f}" stroke="{VERDICT_COLOURS[MOVED]}" '
                     'stroke-width="1.5"/>')
    for change in report.changes:
        x, y = xy(change.position)
        colour = VERDICT_COLOURS[change.verdict]
        title = html.escape(f"{change.verdict}: {_label(change)}")
        if change.verdict == NEW:
            parts.append(f'<rect x="{x - 4:.1f}" y="{y - 4:.1f}" width="8" height="8" fill="{colour}">'
                         f'<title>{title}</title></rect>')
        else:
            parts.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="4.5" fill="{colour}" stroke="white">'
                         f'<title>{title}</title></circle>')
    metres = 10 ** int(np.floor(np.log10(max(span / 4, 1.0))))
    parts.append(f'<line x1="20" y1="{height_px - 8}" x2="{20 + metres * scale:.1f}" y2="{height_px - 8}" '
                 'stroke="black" stroke-width="2"/>')
    parts.append(f'<text x="{24 + metres * scale:.1f}" y="{height_px - 4}">{metres} m</text>')
    parts.append(f'<text x="{size_px - 14}" y="16" text-anchor="middle">N ↑</text>')
    x = 20
    for verdict in VERDICTS:
        parts.append(f'<circle cx="{x}" cy="14" r="4.5" fill="{VERDICT_COLOURS[verdict]}"/>'
                     f'<text x="{x + 8}" y="18">{verdict}</text>')
        x += 12 + 7 * len(verdict) + 14
    parts.append("</svg>")
    return "\n".join(parts)


def _label(change: Change) -> str:
    if change.inventory is not None:
        inv = change.inventory
        text = f"inventory {inv.key} ({inv.label or inv.template_id})"
        if change.mapped is not None:
            text += f" ↔ mapped sign {change.mapped.sign_id} ({change.mapped.template_id})"
        return text
    return f"mapped sign {change.mapped.sign_id} ({change.mapped.template_id})"


def report_html(report: ChangeReport, track_xy, title: str, notes=None) -> str:
    counts = report.counts()
    count_rows = "".join(
        f"<tr><td><span style='color:{VERDICT_COLOURS[v]}'>●</span> {v}</td><td>{counts[v]}</td></tr>"
        for v in VERDICTS)
    rows = []
    for change in report.changes:
        inv, found = change.inventory, change.mapped
        rows.append(
            "<tr>" + "".join(f"<td>{html.escape(str(x))}</td>" for x in (
                change.verdict, inv.key if inv else "", (inv.label or inv.template_id) if inv else "",
                found.sign_id if found else "", found.template_id if found else "", _fmt(change.distance_m),
                " ".join(change.visible_pair_ids[:3]) + (" …" if len(change.views) > 3 else ""), change.reason))
            + "</tr>")
    notes_html = "".join(f"<li>{html.escape(n)}</li>" for n in (notes or []))
    cfg = report.config
    return f"""<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>{html.escape(title)}</title>
<style>body{{font-family:sans-serif;margin:2em}} table{{border-collapse:collapse;margin-bottom:1.5em}}
td,th{{border:1px solid #bbb;padding:3px 8px;text-align:left}}</style></head><body>
<h1>{html.escape(title)}</h1>
<p>{html.escape(report.summary())}. Tolerance {cfg.tolerance_m:g} m, move radius {cfg.move_radius_m:g} m,
visibility within {cfg.near_m:g}–{cfg.far_m:g} m with the face turned at most {cfg.max_face_angle_deg:g}° away.</p>
<h2>Verdicts</h2>
<table><tr><th>verdict</th><th>signs</th></tr>{count_rows}</table>
<h2>Map</h2>
{map_svg(report, track_xy)}
<h2>Signs</h2>
<table><tr><th>verdict</th><th>inventory id</th><th>inventory type</th><th>mapped sign</th><th>mapped type</th>
<th>distance [m]</th><th>pairs that should show it</th><th>why</th></tr>
{"".join(rows)}</table>
{f"<h2>Notes</h2><ul>{notes_html}</ul>" if notes_html else ""}
</body></html>
"""
