"""The catalog's canonical form: ``bangcheck fmt`` (docs/catalog.md).

Every entry's keys in one fixed order (``CLAIM_KEYS`` and the others), fields equal to their
schema default left out (``unit = "1"``, ``relation = "="``, an empty ``pick``), tables and
comments kept: the file is read and written with tomlkit, which keeps comments, multi-line
strings and inline tables as written. A comment inside an entry stays with that entry, after its
keys. Files are written atomically, and only for a catalog that validates.
"""

from __future__ import annotations

import difflib
import os
import tempfile
from collections.abc import Iterable
from pathlib import Path
from typing import Any

import tomlkit
from tomlkit.items import AoT, Comment, Table, Whitespace

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


def _defaults(model: type[Any]) -> dict[str, Any]:
    """The schema's default of each field that has one (None fields are simply absent)."""
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


def format_text(text: str) -> str:
    """One catalog file's text in canonical form (comments and the text of values kept)."""
    document = tomlkit.parse(text)
    out = tomlkit.document()
    for _, item in document.body:  # the file's opening comments
        if isinstance(item, Comment | Whitespace):
            out.add(item)
        else:
            break
    if "meta" in document:
        out.add("meta", _reorder(document["meta"], META_KEYS, _defaults(Meta)))
    for name, (model, order) in TABLES.items():
        if name not in document:
            continue
        rows = document[name]
        assert isinstance(rows, AoT)
        out.add(name, tomlkit.aot())
        for row in rows:
            out[name].append(_reorder(row, order, _defaults(model)))
    for key in document:
        if key not in out:
            out.add(key, document[key])
    return _tidy(tomlkit.dumps(out))


def _tidy(text: str) -> str:
    """One blank line before each table header, none doubled, one newline at the end."""
    lines = text.splitlines()
    out: list[str] = []
    for line in lines:
        if line.startswith("[") and out and out[-1].strip():
            out.append("")
        if line.strip() or (out and out[-1].strip()):
            out.append(line)
    return "\n".join(out).rstrip("\n") + "\n"


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
