"""The report's data files: CSV and JSON that are byte-identical across runs (no timestamps).

Where they are written, and how safely, is ``reports.outdir``.
"""

from __future__ import annotations

import csv
import io
import json
from collections.abc import Iterable, Mapping, Sequence
from typing import Any


def csv_text(columns: Sequence[str], rows: Iterable[Mapping[str, Any]]) -> str:
    """Rows as CSV text with a header of ``columns`` (missing values empty)."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(columns)
    for row in rows:
        writer.writerow(["" if row.get(c) is None else row[c] for c in columns])
    return buffer.getvalue()


def claims_json(meta: Mapping[str, Any], claims: list[dict[str, Any]]) -> str:
    """``{"meta": ..., "claims": [...]}`` with stable key order and no NaN."""
    return (
        json.dumps({"meta": meta, "claims": claims}, ensure_ascii=False, indent=1, allow_nan=False)
        + "\n"
    )
