"""The catalog's canonical form: ``bangcheck fmt`` (docs/catalog.md).

Every entry's keys in one fixed order (``CLAIM_KEYS`` and the others), fields equal to their
schema default left out (``unit = "1"``, ``relation = "="``, an empty ``pick``), tables and
comments kept: the file is read and written with tomlkit, which keeps comments, multi-line
strings and inline tables as written. A comment inside an entry stays with that entry, after its
keys. Files are written atomically, and only for a catalog that validates.
"""

from __future__ import annotations

import difflib
import functools
import os
import tempfile
from collections.abc import Iterable
from pathlib import Path
from typing import Any

import tomlkit
from tomlkit.items import AoT, Comment, Table

from reference.schema import Claim, Excluded, Meta, Slip

META_KEYS = ("chapter", "title", "lines", "complete", "schema")
CLAIM_KEYS = (
    "id",
    "line",
    "line_end",
    "occurrence",
    "quote",
    "printed",
    "means",
    "garble",
    "quantity",
    "kind",
    "unit",
    "constant",
    "edition",
    "model",
    "args",
    "pick",
    "expression",
    "symbols",
    "tokens",
    "relation",
    "rel_tol",
    "bounds",
    "sigfigs",
    "exact",
    "rounding",
    "monotonic",
    "rounded",
    "precision_reason",
    "assumptions",
    "restates",
    "expect",
    "correct",
    "reads",
    "diagnosis",
    "same_error",
    "summary",
    "figure",
    "equation",
    "depends_on",
    "note",
)
EXCLUDED_KEYS = ("line", "lines", "token", "occurrence", "reason", "unit", "means")
SLIP_KEYS = ("id", "line", "quote", "printed", "correct", "note")
TABLES = {
    "claim": (Claim, CLAIM_KEYS),
    "excluded": (Excluded, EXCLUDED_KEYS),
    "slip": (Slip, SLIP_KEYS),
}


@functools.cache
def _defaults(model: type[Any]) -> dict[str, Any]:
    """The schema's default of each field that has one (None fields are simply absent); one
    dictionary per model, which the caller reads and never changes."""
    out = {}
    for name, field in model.model_fields.items():
        if field.is_required():
            continue
        value = field.get_default(call_default_factory=True)
        if value is not None:
            out[field.alias or name] = value
    return out


def _reorder(table: Table, order: Iterable[str], defaults: dict[str, Any]) -> Table:
    """``table`` with its keys in ``order`` (unknown keys after, as they were), defaults
    dropped, and its comments after its keys."""
    keys = [k for k in order if k in table]
    keys += [k for k in table if k not in keys]
    out = tomlkit.table()
    for key in keys:
        item = table.item(key)
        if key in defaults and item.unwrap() == defaults[key]:
            continue
        out.add(key, item)
    for _, item in table.value.body:
        if isinstance(item, Comment):
            out.add(item)
    return out


def _chunks(text: str) -> list[str]:
    """The file split before each table header: the preamble, then one chunk per entry (its
    header, its keys, and the comment lines after them, which open the next section)."""
    chunks: list[list[str]] = [[]]
    for line in text.splitlines():
        if line.startswith("["):
            chunks.append([])
        chunks[-1].append(line)
    return ["\n".join(c) + "\n" for c in chunks if c]


def _split_trailer(chunk: str) -> tuple[str, str]:
    """An entry's text and the comment and blank lines after its last key, which open the
    next section and are kept as written."""
    lines = chunk.splitlines()
    cut = len(lines)
    while cut > 1 and (not lines[cut - 1].strip() or lines[cut - 1].startswith("#")):
        cut -= 1
    return "\n".join(lines[:cut]) + "\n", "".join(line + "\n" for line in lines[cut:])


def _format_chunk(chunk: str) -> str:
    body, trailer = _split_trailer(chunk)
    document = tomlkit.parse(body)
    names = list(document)
    if len(names) != 1:  # the preamble (comments only) or an unknown shape: as written
        return chunk
    name = names[0]
    container = document[name]
    out = tomlkit.document()
    if name == "meta" and isinstance(container, Table):
        out.add(name, _reorder(container, META_KEYS, _defaults(Meta)))
    elif name in TABLES and isinstance(container, AoT) and len(container) == 1:
        model, order = TABLES[name]
        rows = tomlkit.aot()
        rows.append(_reorder(container[0], order, _defaults(model)))
        out.add(name, rows)
    else:
        return chunk
    return tomlkit.dumps(out) + trailer


def format_text(text: str) -> str:
    """One catalog file's text in canonical form: each entry's keys in the fixed order and
    without defaults; entries, their order and the comments between them as written."""
    return _tidy("".join(_format_chunk(chunk) for chunk in _chunks(text)))


def _tidy(text: str) -> str:
    """One blank line before each table header, or before the comments that open it; blank
    lines the author left kept, none doubled; one newline at the end."""
    lines = [line.rstrip() for line in text.splitlines()]
    out: list[str] = []
    for i, line in enumerate(lines):
        if not line:
            if out and out[-1]:
                out.append("")
            continue
        opens = line.startswith("[") or (
            line.startswith("#") and _next_nonblank(lines, i).startswith("[")
        )
        follows_comment = bool(out) and out[-1].startswith("#") and line.startswith("[")
        if opens and out and out[-1] and not follows_comment:
            out.append("")
        out.append(line)
    return "\n".join(out).strip("\n") + "\n"


def _next_nonblank(lines: list[str], i: int) -> str:
    """The first line after ``i`` that is neither blank nor a comment."""
    for line in lines[i + 1 :]:
        if line.strip() and not line.startswith("#"):
            return line
    return ""


def diff(path: Path, text: str, formatted: str) -> str:
    """The unified diff from a file's text to its canonical form."""
    return "".join(
        difflib.unified_diff(
            text.splitlines(keepends=True),
            formatted.splitlines(keepends=True),
            fromfile=str(path),
            tofile=f"{path} (formatted)",
        )
    )


def write_atomically(path: Path, text: str) -> None:
    """Replace ``path`` by ``text`` in one rename (a reader never sees half a file)."""
    fd, temporary = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as handle:
            handle.write(text)
        os.chmod(temporary, path.stat().st_mode & 0o777)
        os.replace(temporary, path)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise
