"""The evaluation report as a self-contained HTML page, for people: what was compared, Tables 1 and 2 and a plot
of the error vectors first, then every mapped sign with its status and verdict and the missed reference signs;
the run's settings last, folded away.

The plot is inline SVG drawn here (no plotting library, no scripts, no WebKit
needed to show it): each matched sign's planimetric error as an arrow in the
across/along track frame, magnified so centimetre errors are visible.
"""

from __future__ import annotations

import html

import numpy as np

from .accuracy import COMPONENTS, NO_DIFFERENCES, EvaluationReport, table1_texts

LABELS = {"across": "across track", "along": "along track", "height": "height", "planimetric": "planimetric",
          "3d": "3D"}


def _m(x: float) -> str:
    return "–" if not np.isfinite(x) else f"{x:.3f}"


def error_plot_svg(differences: np.ndarray, size_px: int = 360) -> str:
    """Scatter of (across, along) errors with arrows from the origin; axes in metres."""
    d = np.asarray(differences, float).reshape(-1, 5)
    half = size_px / 2
    extent = max(0.05, float(np.abs(d[:, :2]).max()) * 1.15) if len(d) else 0.05
    scale = (half - 30) / extent
    parts = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{size_px}" height="{size_px}" '
        f'viewBox="0 0 {size_px} {size_px}" font-family="sans-serif" font-size="11">',
        f'<rect width="{size_px}" height="{size_px}" fill="white" stroke="#ccc"/>',
        f'<line x1="20" y1="{half}" x2="{size_px - 20}" y2="{half}" stroke="#999"/>',
        f'<line x1="{half}" y1="20" x2="{half}" y2="{size_px - 20}" stroke="#999"/>',
        f'<text x="{size_px - 22}" y="{half - 6}" text-anchor="end">across +{extent:.2f} m</text>',
        f'<text x="{half + 6}" y="30">along +{extent:.2f} m</text>',
    ]
    for across, along, *_ in d:
        x, y = half + across * scale, half - along * scale
        parts.append(f'<line x1="{half}" y1="{half}" x2="{x:.1f}" y2="{y:.1f}" stroke="#1f4fa3" '
                     'stroke-opacity="0.5"/>')
        parts.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="2.5" fill="#d52b1e"/>')
    parts.append("</svg>")
    return "\n".join(parts)


def sign_rows(report: EvaluationReport, mapped_ids, mapped_labels=None, statuses=None) -> list[tuple]:
    """One row per mapped sign: (label, status, mapped id, reference id or '', verdict, 3D difference or None)."""
    rows, k = [], 0
    labels = list(mapped_labels) if mapped_labels is not None else [str(i + 1) for i in range(len(mapped_ids))]
    statuses = list(statuses) if statuses is not None else [""] * len(mapped_ids)
    for i, ref in enumerate(report.match):
        if ref < 0:
            rows.append((labels[i], statuses[i], mapped_ids[i], "", "false positive", None))
            continue
        reference = report.reference_ids[ref] if ref < len(report.reference_ids) else ""
        verdict = "correct" if str(mapped_ids[i]) == str(reference) else "misclassified"
        rows.append((labels[i], statuses[i], mapped_ids[i], reference, verdict, float(report.differences[k][4])))
        k += 1
    return rows


def missed_rows(report: EvaluationReport, reference_xyz, reference_labels=None) -> list[tuple]:
    """Reference signs no mapped sign matched: (label, reference id, E, N, H)."""
    matched = {int(r) for r in report.match if r >= 0}
    xyz = np.asarray(reference_xyz, float).reshape(-1, 3)
    labels = list(reference_labels) if reference_labels is not None else [str(i + 1) for i in range(len(xyz))]
    return [(labels[j], report.reference_ids[j], *xyz[j]) for j in range(len(xyz)) if j not in matched]


def _esc(value) -> str:
    return html.escape(str(value))


def _signs_table(signs: list) -> str:
    rows = "".join(
        f"<tr><td>{_esc(label)}</td><td>{_esc(status) or '–'}</td><td>{_esc(mapped)}</td>"
        f"<td>{_esc(reference) or '–'}</td><td class=\"{verdict.replace(' ', '-')}\">{verdict}</td>"
        f"<td>{_m(d3) if d3 is not None else '–'}</td></tr>" for label, status, mapped, reference, verdict, d3 in signs)
    return ("<h2>Mapped signs</h2><table><tr><th>sign</th><th>status</th><th>mapped</th><th>reference</th>"
            f"<th>verdict</th><th>3D difference [m]</th></tr>{rows}</table>")


def _missed_table(missed: list) -> str:
    rows = "".join(f"<tr><td>{_esc(label)}</td><td>{_esc(rid)}</td><td>{e:.3f}</td><td>{n:.3f}</td><td>{h:.3f}</td>"
                   "</tr>" for label, rid, e, n, h in missed)
    body = (f"<table><tr><th>reference</th><th>type</th><th>E</th><th>N</th><th>H</th></tr>{rows}</table>"
            if missed else "<p>None: every reference sign was mapped.</p>")
    return f"<h2>Missed reference signs ({len(missed)})</h2>{body}"


def _settings(run: dict) -> str:
    """The run and its settings, folded: long values (the pipeline's and the fusion's JSON) set as code."""
    rows = []
    for key, value in run.items():
        text = str(value)
        shown = f"<pre>{_esc(text)}</pre>" if len(text) > 120 else _esc(text)
        rows.append(f"<tr><td>{_esc(key)}</td><td>{shown}</td></tr>")
    return (f"<details><summary><b>Run and parameters</b> ({len(run)} entries)</summary><table>{''.join(rows)}"
            "</table></details>")


def report_html(report: EvaluationReport, title: str, notes: list[str] | None = None, run: dict | None = None,
                signs: list | None = None, missed: list | None = None, about: dict | None = None) -> str:
    """The page; ``about`` (what was compared: label -> value) heads it, ``signs`` (:func:`sign_rows`) and
    ``missed`` (:func:`missed_rows`) follow the figures, ``run`` (parameter -> value) closes it, folded."""
    texts = table1_texts(report.table1)
    rows1 = [
        ("Reference signs", texts["reference signs"]),
        ("Detected signs", texts["detected signs"]),
        ("Correctly classified signs", texts["correctly classified signs"]),
        ("Mapped features", texts["mapped features"]),
        ("False positives (features matching no reference sign)", texts["false positive features"]),
        ("Duplicates (reference signs matched by more than one feature)", texts["reference signs with >1 feature"]),
    ]
    if report.table2[COMPONENTS[0]].n == 0:
        rows2 = f'<tr><td colspan="6">{html.escape(NO_DIFFERENCES)}</td></tr>'
    else:
        rows2 = "\n".join(
            f"<tr><td>{LABELS[c]}</td><td>{report.table2[c].n}</td><td>{_m(report.table2[c].mean)}</td>"
            f"<td>{_m(report.table2[c].std)}</td><td>{_m(report.table2[c].rms)}</td>"
            f"<td>{_m(report.table2[c].max_abs)}</td></tr>"
            for c in COMPONENTS
        )
    confusions = "".join(f"<li>{html.escape(a)} → {html.escape(b)}</li>" for a, b in report.confusions)
    notes_html = "".join(f"<li>{html.escape(n)}</li>" for n in (notes or []))
    about_html = "".join(f"<tr><td>{_esc(k)}</td><td>{_esc(v)}</td></tr>" for k, v in (about or {}).items())
    return f"""<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>{html.escape(title)}</title>
<style>body{{font-family:sans-serif;margin:2em;max-width:64em}} table{{border-collapse:collapse;margin-bottom:1.5em}}
td,th{{border:1px solid #bbb;padding:4px 10px;text-align:right}} td:first-child,th:first-child{{text-align:left}}
.figures{{display:flex;flex-wrap:wrap;gap:2em;align-items:flex-start}} .misclassified,.false-positive{{color:#c62828}}
pre{{text-align:left;white-space:pre-wrap;max-width:50em;margin:0}} summary{{cursor:pointer;margin:1em 0}}
</style></head><body>
<h1>{html.escape(title)}</h1>
{f'<table class="about">{about_html}</table>' if about_html else ""}
<div class="figures"><div>
<h2>Table 1: detection and classification</h2>
<table>{"".join(f"<tr><td>{html.escape(k)}</td><td>{v}</td></tr>" for k, v in rows1)}</table>
<h2>Table 2: coordinate differences, mapped − reference [m]</h2>
<table><tr><th>component</th><th>n</th><th>mean</th><th>empirical σ</th><th>RMS</th><th>max |d|</th></tr>
{rows2}</table>
</div><div>
<h2>Error vectors (across / along track)</h2>
{error_plot_svg(report.differences)}
</div></div>
{f"<h2>Misclassified (reference → assigned)</h2><ul>{confusions}</ul>" if confusions else ""}
{_signs_table(signs) if signs is not None else ""}
{_missed_table(missed) if missed is not None else ""}
{f"<h2>Notes</h2><ul>{notes_html}</ul>" if notes_html else ""}
{_settings(run) if run else ""}
</body></html>
"""
