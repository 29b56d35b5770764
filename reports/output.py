"""The report's data files: CSV and JSON that are byte-identical across runs (no timestamps).

Where they are written, and how safely, is ``reports.outdir``.
"""

from __future__ import annotations

import csv
import io
import json
from collections.abc import Iterable, Mapping
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
