"""Where the property suite's record of its invariants lives, for the report to show.

pytest writes ``.bangcheck/properties.json`` in its rootdir (the project root), a cache
directory of the tool's own that git ignores; ``bangcheck report`` reads it by default from the
nearest ``.bangcheck/`` at or above the working directory. Nothing is ever written into the
report's output directory but the report.
"""

from __future__ import annotations

import json
import os
import tempfile
from pathlib import Path
from typing import Any

CACHE_DIR = ".bangcheck"
PROPERTIES_FILE = "properties.json"


def properties_path(root: Path) -> Path:
    """The record's path under a project root (pytest's rootdir)."""
    return root / CACHE_DIR / PROPERTIES_FILE


def default_properties_path(start: Path | None = None) -> Path:
    """The record nearest to ``start`` (default: the working directory): the first
    ``.bangcheck/properties.json`` at or above it, else the one ``start`` would hold."""
    here = (start or Path.cwd()).resolve()
    for directory in (here, *here.parents):
        candidate = properties_path(directory)
        if candidate.is_file():
            return candidate
    return properties_path(here)


def write_properties(root: Path, data: dict[str, Any]) -> Path:
    """Write the record under ``root`` atomically (a reader never sees half a file); the cache
    directory gets a ``.gitignore`` of its own, as pytest's does."""
    directory = root / CACHE_DIR
    directory.mkdir(exist_ok=True)
    ignore = directory / ".gitignore"
    if not ignore.exists():
        ignore.write_text("# written by bangcheck's test run\n*\n", encoding="utf-8")
    target = directory / PROPERTIES_FILE
    fd, temporary = tempfile.mkstemp(prefix=f".{PROPERTIES_FILE}.", dir=directory)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as handle:
            handle.write(json.dumps(data, indent=1) + "\n")
        os.chmod(temporary, 0o666 & ~_umask())  # mkstemp's file is private; this one is not
        os.replace(temporary, target)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise
    return target


class PropertiesError(ValueError):
    """A record that exists but cannot be read; the message names the file."""


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def read_properties(path: Path | None) -> dict[str, Any] | None:
    """The record at ``path``, or None where there is none; ``PropertiesError`` for a file
    that is not such a record."""
    if path is None or not path.is_file():
        return None
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as err:
        raise PropertiesError(f"cannot read the invariants record {path}: {err}") from err
    if not isinstance(data, dict) or not isinstance(data.get("invariants"), list):
        raise PropertiesError(
            f"{path} is not an invariants record written by the tests (no 'invariants' list)"
        )
    return data
