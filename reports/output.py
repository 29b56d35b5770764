"""Writing the report's files: CSV and JSON that are byte-identical across runs, and an atomic
swap of the whole output directory.

The files are written into a temporary directory beside the target, which then replaces the
target in two renames; a crash leaves either the old directory or the new one, never a mix.
Files the report does not write (``properties.json``, left by the property suite) are carried
over into the new directory.
"""

from __future__ import annotations

import csv
import io
import json
import shutil
import tempfile
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

ERRATA_COLUMNS = (
    "id",
    "chapter",
    "line",
    "quantity",
    "printed",
    "correct",
    "model_value",
    "diagnosis_kind",
    "diagnosis_auto",
    "note",
    "quote",
)
KEEP = ("properties.json",)


def errata_csv(rows: Iterable[Mapping[str, Any]]) -> str:
    """The errata as CSV text (header ``ERRATA_COLUMNS``), rows in catalog order."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(ERRATA_COLUMNS)
    for row in rows:
        writer.writerow(["" if row.get(c) is None else row[c] for c in ERRATA_COLUMNS])
    return buffer.getvalue()


def claims_json(meta: Mapping[str, Any], claims: list[dict[str, Any]]) -> str:
    """``{"meta": ..., "claims": [...]}`` with stable key order and no NaN."""
    return (
        json.dumps({"meta": meta, "claims": claims}, ensure_ascii=False, indent=1, allow_nan=False)
        + "\n"
    )


def write_atomically(out_dir: Path, files: Mapping[str, str | bytes]) -> None:
    """Replace ``out_dir`` by a directory holding ``files`` (name to content), atomically."""
    out_dir = out_dir.resolve()
    out_dir.parent.mkdir(parents=True, exist_ok=True)
    staging = Path(tempfile.mkdtemp(prefix=f".{out_dir.name}.new-", dir=out_dir.parent))
    staging.chmod(0o755)  # mkdtemp makes it private; the report is for reading
    try:
        for name, content in files.items():
            path = staging / name
            if isinstance(content, bytes):
                path.write_bytes(content)
            else:
                path.write_text(content, encoding="utf-8")
        for name in KEEP:
            if name not in files and (out_dir / name).is_file():
                shutil.copy2(out_dir / name, staging / name)
        old = None
        if out_dir.exists():
            old = Path(tempfile.mkdtemp(prefix=f".{out_dir.name}.old-", dir=out_dir.parent))
            old.rmdir()
            out_dir.rename(old)
        staging.rename(out_dir)
        if old is not None:
            shutil.rmtree(old, ignore_errors=True)
    finally:
        if staging.exists():
            shutil.rmtree(staging, ignore_errors=True)
