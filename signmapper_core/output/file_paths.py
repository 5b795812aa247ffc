"""Whether a path can name a file at all, said in words before any work (a path too long for the file system).

Python's own checks (``Path.is_file``, ``exists``) raise ``OSError`` for such a
path instead of answering; every front end asks :func:`path_problem` first.
"""

from __future__ import annotations

import errno
import os
from pathlib import Path
from typing import Optional

SHOWN_CHARACTERS = 60  # a path longer than this is shortened in messages to its start and end
NAME_MAX, PATH_MAX = 255, 4096  # Linux's limits, where the system does not say


def shown(path) -> str:
    """``path`` for a message: whole when short, else its start and end around "…"."""
    text = str(path)
    if len(text) <= SHOWN_CHARACTERS:
        return text
    half = SHOWN_CHARACTERS // 2
    return f"{text[:half]}…{text[-half:]}"


def _is_dir(path: Path) -> bool:
    try:
        return path.is_dir()
    except OSError:  # too long a path raises instead of answering
        return False


def _limit(path: Path, name: str, default: int) -> int:
    folder = path
    while not _is_dir(folder) and folder != folder.parent:
        folder = folder.parent
    try:
        return os.pathconf(folder, name)
    except (OSError, ValueError, AttributeError):  # not on every system
        return default


def path_problem(path) -> Optional[str]:
    """Why ``path`` cannot name a file or folder here, or None (whether or not it exists).

    Only what no writing can fix: a name or path longer than the file system allows, a name the system
    refuses. A missing file is no problem here.
    """
    path = Path(path)
    try:
        os.stat(path)
        return None
    except (FileNotFoundError, NotADirectoryError):
        return None
    except ValueError as exc:  # a NUL character
        return f"{shown(path)} is not a valid path ({exc})"
    except OSError as exc:
        if exc.errno != errno.ENAMETOOLONG:
            return f"{shown(path)}: {exc.strerror or exc}"
    longest = max(path.parts, key=lambda part: len(os.fsencode(part)))
    name_max = _limit(path, "PC_NAME_MAX", NAME_MAX)
    if len(os.fsencode(longest)) > name_max:
        return (f"the name {shown(longest)} in {shown(path)} has {len(longest)} characters, more than the "
                f"{name_max} the file system allows; use a shorter name")
    return (f"{shown(path)} has {len(str(path))} characters, more than the {_limit(path, 'PC_PATH_MAX', PATH_MAX)} "
            "the system allows for a path; use a shorter one")
