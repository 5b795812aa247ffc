"""Reading the text of plates and panels with Tesseract (Debian's ``tesseract-ocr``), called as a command.

Optional: without the ``tesseract`` command (or without its German, French and
Italian data) plates are still mapped, only their text stays empty, and
:class:`OcrUnavailable` says how to install it. All crops of a run are read in
a few calls (Tesseract takes a list of images; its TSV output numbers them by
``page_num``), so the language models are loaded once per call, not per plate: one call
per core when there are enough crops to share, since reading them is the single-threaded
end of a mapping run. Tesseract reads each image of a list on its own, so the text is the
same however the crops are shared out.
Normalising what was read is :mod:`signmapper_core.plates.text`'s job.
"""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import tempfile
import time
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Any, List, Optional, Sequence

import numpy as np

from ..machine import available_cores

LANGUAGES = ("deu", "fra", "ita")
DEBIAN_PACKAGES = ("tesseract-ocr", "tesseract-ocr-deu", "tesseract-ocr-fra", "tesseract-ocr-ita")
INSTALL_HINT = "sudo apt-get install " + " ".join(DEBIAN_PACKAGES)
BASE_TIMEOUT_S = 60.0  # loading three language models on a busy machine takes several seconds
TIMEOUT_PER_IMAGE_S = 2.0
MIN_CROPS_PER_CALL = 8  # a call per this many crops at most: loading the languages costs about as much as ~10 crops


class OcrUnavailable(RuntimeError):
    """Tesseract cannot be run here; the message says why and how to install it."""


class OcrError(RuntimeError):
    """Tesseract ran but failed (timeout, crash, unreadable output)."""


def _settings(config):
    """The run's fusion settings (``fusion.FusionConfig``), which hold the OCR's; the defaults for None."""
    if config is not None:
        return config
    from ..fusion.signs import FusionConfig  # delays OpenCV until used

    return FusionConfig()


@dataclass(frozen=True)
class Word:
    text: str
    confidence: float  # 0..1
    line: int  # 0-based line of the crop, top to bottom
    height: float = 0.0  # of the word's box in the prepared crop, pixels


@dataclass(frozen=True)
class TextReading:
    """What Tesseract read in one crop: its words by line, and their mean confidence (0..1; 0 when none).

    ``config``: the fusion settings whose ``ocr_*`` thresholds tell print from the rest (None: the defaults)."""

    words: tuple
    config: Any = None

    @property
    def kept(self) -> tuple:
        """The words that are print: not much smaller than the letters of the tallest confident line (remains
        of a frame, dirt and a shadow's edge are read as small, unsure "words"), on lines read with some
        confidence."""
        config = _settings(self.config)
        confident = [w.height for w in self.words if w.confidence >= config.ocr_confident_word and w.height > 0]
        floor = config.ocr_min_word_height_share * max(confident) if confident else 0.0
        words = [w for w in self.words if w.height >= floor]
        by_line = {}
        for word in words:
            by_line.setdefault(word.line, []).append(word.confidence)
        sure = {k for k, c in by_line.items() if np.mean(c) >= config.ocr_min_line_confidence}
        return tuple(w for w in words if w.line in sure)

    @property
    def lines(self) -> List[str]:
        out = {}
        for word in self.kept:
            out.setdefault(word.line, []).append(word.text)
        return [" ".join(out[k]) for k in sorted(out)]

    @property
    def text(self) -> str:
        """Lines joined by " / " (as drive-format's truth.csv writes a plate's text)."""
        return " / ".join(self.lines)

    @property
    def confidence(self) -> float:
        kept = self.kept
        return float(np.mean([w.confidence for w in kept])) if kept else 0.0


@lru_cache(maxsize=4)
def _languages_of(executable: str) -> tuple:
    out = subprocess.run([executable, "--list-langs"], capture_output=True, text=True, timeout=30)
    names = (out.stdout + out.stderr).split()
    return tuple(lang for lang in LANGUAGES if lang in names)


def find_tesseract(executable: Optional[str] = None) -> tuple:
    """(path of the tesseract command, the plate languages it has); :class:`OcrUnavailable` if it cannot read them.

    ``executable``: a command name or path (default: ``tesseract`` on the PATH).
    """
    path = shutil.which(executable or "tesseract")
    if path is None:
        raise OcrUnavailable(f"the OCR engine Tesseract ('{executable or 'tesseract'}') "
                             f"is not installed; on Debian or Ubuntu: {INSTALL_HINT}")
    try:
        languages = _languages_of(path)
    except (OSError, subprocess.SubprocessError) as exc:
        raise OcrUnavailable(f"{path} --list-langs failed ({exc}); reinstall it: "
                             f"{INSTALL_HINT}") from exc
    if not languages:
        raise OcrUnavailable(f"Tesseract ({path}) has none of the German, French or "
                             f"Italian language data; on Debian or Ubuntu: {INSTALL_HINT}")
    return path, languages


def without_long_lines(grey: np.ndarray, span: float, contrast: float, edge_band: float) -> np.ndarray:
    """``grey`` (uint8) with its straight lines across the plate painted over from what lies beside them.

    A pole seen through a gap, a wire, or what is left of the printed frame runs across (nearly) the whole
    plate; no letter does (the plate's margin keeps letters off its edges). Tesseract reads such a line as
    "1", "l" or "|" beside the text, or reads nothing on the line it cuts. A line: pixels darker than
    ``contrast`` x the paper's median brightness forming a vertical run of at least ``span`` x the height (or a
    horizontal one of ``span`` x the width, within ``edge_band`` x the height of the top or bottom edge: a
    row of blurred bold letters is dark all along too, and a plate's middle has no frame).
    """
    import cv2

    height, width = grey.shape[:2]
    if height < 8 or width < 8:
        return grey
    paper = float(np.median(grey))
    darker = (grey < contrast * paper).astype(np.uint8)
    vertical = cv2.morphologyEx(darker, cv2.MORPH_OPEN, np.ones((max(2, int(span * height)), 1), np.uint8))
    horizontal = cv2.morphologyEx(darker, cv2.MORPH_OPEN, np.ones((1, max(2, int(span * width))), np.uint8))
    # the rows between the edge bands hold the text
    edge = max(1, int(round(edge_band * height)))
    horizontal[edge:height - edge] = 0
    lines = cv2.dilate(vertical | horizontal, np.ones((3, 3), np.uint8))
    if not lines.any():
        return grey
    # filled in from both sides: paper where it crossed paper, a letter's stroke where it crossed one
    return cv2.inpaint(grey, lines, 3, cv2.INPAINT_TELEA)


def prepare_crop(crop: np.ndarray, config=None) -> np.ndarray:
    """A plate crop as Tesseract reads it best: its frame cut off, grey, scaled up to ``ocr_crop_height_px``,
    a plain border (Tesseract reads nothing at all on a line that touches a frame). ``config``: the fusion
    settings (None: the defaults).

    The crop is the plate's box as the plate step found it, to a pixel or two: the printed frame lies at a
    known share of its height. (Warping a looser crop square-on from the corners of its brightest region was
    tried: on the drives' crops it read fewer plates, as the outline found is often the frame's inside.)
    """
    import cv2

    config = _settings(config)
    if crop.ndim == 3:
        crop = cv2.cvtColor(crop, cv2.COLOR_BGR2GRAY)
    cut = int(round(config.ocr_frame_share * crop.shape[0]))
    if crop.shape[0] > 2 * cut + 4 and crop.shape[1] > 2 * cut + 4:
        crop = crop[cut:-cut or None, cut:-cut or None]
    if config.ocr_line_span < 1.0:
        crop = without_long_lines(crop, config.ocr_line_span, config.ocr_line_contrast, config.ocr_line_edge_band)
    height = max(crop.shape[0], 1)
    scale = np.clip(config.ocr_crop_height_px / height, 1.0, config.ocr_max_upscale)
    grey = cv2.resize(crop, None, fx=scale, fy=scale, interpolation=cv2.INTER_CUBIC)
    grey = cv2.normalize(grey, None, 0, 255, cv2.NORM_MINMAX)
    border = config.ocr_border_px
    return cv2.copyMakeBorder(grey, border, border, border, border, cv2.BORDER_REPLICATE)


def parse_tsv(tsv: str, pages: int, config=None) -> List[TextReading]:
    """Tesseract's TSV output of ``pages`` images as one :class:`TextReading` per image (in input order), read
    with the fusion settings ``config`` (None: the defaults)."""
    words: List[list] = [[] for _ in range(pages)]
    rows = tsv.splitlines()
    if not rows or not rows[0].startswith("level"):
        raise OcrError(f"Tesseract's output is not TSV: {tsv[:200]!r}")
    header = rows[0].split("\t")
    col = {name: header.index(name) for name in ("level", "page_num", "block_num", "par_num", "line_num",
                                                 "height", "conf", "text")}
    line_ids: List[dict] = [{} for _ in range(pages)]
    for row in rows[1:]:
        cells = row.split("\t")
        if len(cells) <= col["text"] or cells[col["level"]] != "5":
            continue
        text = cells[col["text"]].strip()
        if not text:
            continue
        page = int(cells[col["page_num"]]) - 1
        if not 0 <= page < pages:
            raise OcrError(f"Tesseract's output names image {page + 1} of {pages}")
        key = tuple(int(cells[col[k]]) for k in ("block_num", "par_num", "line_num"))
        line = line_ids[page].setdefault(key, len(line_ids[page]))
        confidence = max(float(cells[col["conf"]]), 0.0) / 100.0
        words[page].append(Word(text, confidence, line, float(cells[col["height"]])))
    return [TextReading(tuple(w), config) for w in words]


def call_count(crops: int, cores: int) -> int:
    """Tesseract calls to share ``crops`` crops between: one per core, each with at least ``MIN_CROPS_PER_CALL``."""
    return max(1, min(cores, crops // MIN_CROPS_PER_CALL))


PLATE_OPTIONS = ("--psm", "6")  # a block of text: one to three lines of a plate
# one line of digits: the number on a speed-limit face (a whitelist keeps Tesseract from reading "3O" or "B0")
NUMBER_OPTIONS = ("--psm", "7", "-c", "tessedit_char_whitelist=0123456789")


def read_texts(crops: Sequence[np.ndarray], config=None, executable: Optional[str] = None,
               timeout_s: Optional[float] = None, cores: Optional[int] = None) -> List[TextReading]:
    """The text of each plate crop (BGR or grey uint8, the plate's box), read with the ``ocr_*`` settings of
    ``config`` (the run's ``fusion.FusionConfig``; None: the defaults), in :func:`call_count` Tesseract calls side
    by side (``cores``: None = the cores this process may use).

    :class:`OcrUnavailable`
    when Tesseract or its language data are missing, :class:`OcrError` when it fails.
    """
    images = [prepare_crop(crop, config) for crop in crops]
    return _read(images, PLATE_OPTIONS, None, config, executable, timeout_s, cores)


def read_numbers(images: Sequence[np.ndarray], executable: Optional[str] = None, timeout_s: Optional[float] = None,
                 cores: Optional[int] = None) -> List[str]:
    """The digits Tesseract reads on each image (grey uint8, prepared: one line of dark digits on white with a
    plain border), "" where it reads none; in one language of the plates (digits are alike in all), otherwise as
    :func:`read_texts`."""
    readings = _read(list(images), NUMBER_OPTIONS, 1, None, executable, timeout_s, cores)
    return ["".join(word.text for word in reading.words) for reading in readings]


def _read(images: List[np.ndarray], options: tuple, language_count: Optional[int], config,
          executable: Optional[str], timeout_s: Optional[float], cores: Optional[int]) -> List[TextReading]:
    """Tesseract's reading of each prepared image, with ``options`` and the first ``language_count`` plate
    languages (None: all), shared over :func:`call_count` calls side by side."""
    if not images:
        return []
    import cv2

    path, languages = find_tesseract(executable)
    timeout = timeout_s if timeout_s is not None else BASE_TIMEOUT_S + TIMEOUT_PER_IMAGE_S * len(images)
    if cores is None:
        cores = available_cores()
    calls = call_count(len(images), cores)
    with tempfile.TemporaryDirectory(prefix="signmapper-ocr-") as folder:
        names = []
        for i, image in enumerate(images):
            name = Path(folder) / f"{i:05d}.png"
            if not cv2.imwrite(str(name), image):
                raise OcrError(f"could not write the crop {name} for Tesseract")
            names.append(str(name))
        shares = [names[len(names) * k // calls : len(names) * (k + 1) // calls] for k in range(calls)]
        outputs = _run_side_by_side(path, languages[:language_count], shares, Path(folder), timeout, options)
    readings: List[TextReading] = []
    for share, output in zip(shares, outputs):
        readings += parse_tsv(output, len(share), config)
    return readings


def _run_side_by_side(path: str, languages: tuple, shares: List[List[str]], folder: Path,
                      timeout: float, options: tuple = PLATE_OPTIONS) -> List[str]:
    """Tesseract's TSV output for each list of image files, its calls running at the same time."""
    env = dict(os.environ, OMP_THREAD_LIMIT="1")  # one core per call: mapping shares the machine
    processes = []
    try:
        for k, share in enumerate(shares):
            listing = folder / f"crops{k}.txt"
            listing.write_text("\n".join(share) + "\n", encoding="utf-8")
            command = [path, str(listing), "-", "-l", "+".join(languages), *options, "tsv"]
            processes.append(subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                              env=env, start_new_session=True))  # a group of its own to stop
        deadline = time.monotonic() + timeout
        outputs = []
        for process in processes:
            try:
                out, err = process.communicate(timeout=max(0.0, deadline - time.monotonic()))
            except subprocess.TimeoutExpired as exc:
                raise OcrError(f"Tesseract did not finish reading {sum(map(len, shares))} crops within "
                               f"{timeout:.0f} s") from exc
            if process.returncode != 0:
                raise OcrError(f"Tesseract failed (exit {process.returncode}): {err.strip()[:300]}")
            outputs.append(out)
        return outputs
    finally:
        for process in processes:  # a failed or timed-out call ends the others (and whatever they started)
            if process.poll() is None:
                _stop(process)
                process.communicate()


def _stop(process: subprocess.Popen) -> None:
    """Kill a Tesseract call with its process group (a wrapper script's children keep its output open)."""
    if not hasattr(os, "killpg"):  # Windows: no process groups to kill
        process.kill()
        return
    try:
        os.killpg(process.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass
