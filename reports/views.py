"""What the report page shows, prepared for its template: text only, never a Python repr.

Each function turns evaluated claims (or the scan, or the tests' record) into plain dicts of
strings and numbers for ``reports/templates/index.html.j2``: the errata as one card per error in
book order, the claims table's rows, the invariants with the scope and age of their run.
Missing values are empty strings or "–" where a cell needs a mark, so that no "None" reaches
the page.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from datetime import UTC, datetime
from typing import Any

from reference.book import Book
from reference.errata import Error
from reference.evaluation import EvaluatedClaim, Evaluation
from reference.formulas import unicode_formula
from reference.locate import find
from reference.tables import constants

DASH = "–"
CONTEXT = 2  # non-blank book lines shown before and after an erratum's line
_SUPERSCRIPTS = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")


def number(value: float | list[float] | None) -> str:
    """A model value or bound as the page prints it: 10 significant figures, a complex value
    as a + bi, nothing for a missing one."""
    if value is None:
        return ""
    if isinstance(value, list):
        re_part, im_part = value
        sign = "−" if im_part < 0 else "+"
        return f"{re_part:.10g} {sign} {abs(im_part):.10g}i"
    return f"{value:.10g}"


def means_shown(text: str) -> str:
    """A ``means`` string as the book would print it: "3^2" as "3²", "1e-34" as is."""
    return re.sub(r"\^(-?\d+)", lambda m: m[1].translate(_SUPERSCRIPTS), text)


_E_NOTATION = re.compile(r"(-?\d+(?:\.\d+)?)[eE]([+-]?\d+)")


def superscript_power(number: str) -> str:
    """A number in E notation as a book with superscripts prints it: "5.9742e24" ->
    "5.9742·10²⁴" (others as they are)."""
    power = _E_NOTATION.fullmatch(number.strip())
    if power is None:
        return number
    return f"{power[1]}·10{str(int(power[2])).translate(_SUPERSCRIPTS)}"


def chapters_named(keys: Sequence[str]) -> str:
    """ "chapter 8", "chapters 4 and 9", "chapters 0, 4 and 7"."""
    if len(keys) == 1:
        return f"chapter {keys[0]}"
    return f"chapters {', '.join(keys[:-1])} and {keys[-1]}"


def printed_shown(claim: EvaluatedClaim) -> str:
    """The printed number, and what a garbled one means: "32 (means 3²)"."""
    if claim.kind == "formula":
        return unicode_formula(claim.expression or "")
    printed = claim.printed or ""
    if claim.means and claim.means != printed:
        meant = means_shown(claim.means)
        return f"{printed} (means {meant})" if printed else f"(states {meant})"
    return printed


def interval_shown(claim: EvaluatedClaim) -> str:
    if claim.interval:
        lo, hi = claim.interval
        wide = " (wide)" if claim.interval_wide else ""
        return f"[{lo:.6g}, {hi:.6g}]{wide}"
    return claim.interval_note or ""


def tolerance_shown(claim: EvaluatedClaim) -> str:
    text = "" if claim.tolerance is None else f"±{claim.tolerance:.3g}"
    if claim.relation != "=":
        text = f"{text} ({claim.relation})".strip()
    return text


def verdict_shown(claim: EvaluatedClaim) -> str:
    text: str = claim.verdict
    if claim.rounding_reason:
        text += f" ({claim.rounding_reason})"
    if claim.matched_edition:
        text += f" ({claim.matched_edition})"
    return text


def search_text(claim: EvaluatedClaim) -> str:
    """What the claims table's search box looks through: id, quote, quantity, printed and
    meant value, line."""
    parts = [claim.id, claim.quote, claim.quantity, claim.printed or "", claim.means or ""]
    parts += [claim.expression or "", str(claim.line)]
    return " ".join(parts).lower()


def claim_row(claim: EvaluatedClaim) -> dict[str, Any]:
    """One row of the claims table."""
    differs = not claim.passed and claim.verdict != "unmodeled"
    note = ""
    if claim.verdict != claim.expect:
        note = f"≠ expected {claim.expect}"
    elif differs:
        note = "model ≠ correct"
    value = claim.model_expression if claim.kind == "formula" else number(claim.model_value)
    return {
        "id": claim.id,
        "line": claim.line,
        "quantity": claim.quantity,
        "printed": printed_shown(claim),
        "model": unicode_formula(value) if claim.kind == "formula" and value else value or "",
        "formula": claim.kind == "formula",
        "interval": interval_shown(claim),
        "tolerance": tolerance_shown(claim),
        "verdict": claim.verdict,
        "verdict_text": verdict_shown(claim),
        "differs": differs,
        "note": note,
        "search": search_text(claim),
    }


def _context(book: Book, claim: EvaluatedClaim) -> list[dict[str, Any]]:
    """The claim's line with up to ``CONTEXT`` non-blank lines either side, the printed number
    picked out on its own line."""
    lines = []
    number_ = claim.line - 1
    before: list[int] = []
    while number_ >= 1 and len(before) < CONTEXT:
        if book.line(number_).strip():
            before.insert(0, number_)
        number_ -= 1
    after: list[int] = []
    number_ = claim.line + 1
    while number_ <= len(book.lines) and len(after) < CONTEXT:
        if book.line(number_).strip():
            after.append(number_)
        number_ += 1
    for n in [*before, claim.line, *after]:
        text = book.line(n).strip()
        row = {"number": n, "before": text, "mark": "", "after": "", "own": n == claim.line}
        if n == claim.line and claim.printed:
            match, _ = find(book, n, claim.printed, claim.occurrence)
            if match is not None:
                raw = book.line(n)
                lead = len(raw) - len(raw.lstrip())
                a, b = match.start - lead, match.end - lead
                row.update(before=text[:a], mark=text[a:b], after=text[b:])
        elif n == claim.line:
            start = text.find(claim.quote)
            if start >= 0:
                end = start + len(claim.quote)
                row.update(before=text[:start], mark=text[start:end], after=text[end:])
        lines.append(row)
    return lines


def _call(claim: EvaluatedClaim, values: dict[str, EvaluatedClaim]) -> str:
    """How the model was called: ``module.function(arg=value, ...)`` and the pick."""
    if claim.restates:
        return f"restates {claim.restates}"
    if not claim.model:
        return ""
    args = ", ".join(f"{k}={_arg(v, values)}" for k, v in claim.args.items())
    extra = ", ".join(f"{k}={v}" for k, v in claim.assumptions.items())
    call = f"{claim.model}({', '.join(x for x in (args, extra) if x)})"
    return f"{call}.{claim.pick}" if claim.pick else call


def _arg(value: object, values: dict[str, EvaluatedClaim]) -> str:
    """An argument as the claim's JSON has it: a number, a string, a list, a claim or a symbol."""
    if isinstance(value, dict) and set(value) == {"claim"}:
        ref = values.get(value["claim"])
        return f"{value['claim']} = {ref.printed if ref and ref.printed else '?'}"
    if isinstance(value, dict) and set(value) == {"symbol"}:
        return value["symbol"]
    if isinstance(value, list):
        return "[" + ", ".join(_arg(v, values) for v in value) + "]"
    return str(value)


def model_call(claim: EvaluatedClaim, values: dict[str, EvaluatedClaim]) -> str:
    """The model call of a claim as text (public: the CLI and tests use it)."""
    return _call(claim, values)


def _source(evaluation: Evaluation, claim: EvaluatedClaim) -> str:
    key = evaluation.catalog.by_id()[claim.id].constant
    entry = constants().get(key or "")
    return "" if entry is None else f"{entry.source} ({entry.edition})"


def _diagnosis(claim: EvaluatedClaim) -> tuple[str, str]:
    d = claim.diagnosis or {}
    curator = f"{d['kind']}: {d['note']}" if d.get("kind") else ""
    return curator, d.get("auto") or ""


def _member(evaluation: Evaluation, claim: EvaluatedClaim) -> dict[str, Any]:
    values = evaluation.by_id()
    curator, auto = _diagnosis(claim)
    correct = claim.correct or ""
    if claim.kind == "formula":
        correct = unicode_formula(correct)
    source = _source(evaluation, claim) if claim.kind == "constant" else ""
    return {
        "id": claim.id,
        "line": claim.line,
        "quantity": claim.quantity,
        "context": _context(evaluation.book, claim),
        "printed": printed_shown(claim),
        "correct": correct or DASH,
        "model": unicode_formula(claim.model_expression or "")
        if claim.kind == "formula"
        else number(claim.model_value),
        "reads": claim.reads or "",
        "unit": "" if claim.unit in ("1", "scaled") else claim.unit,
        "curator": curator,
        "auto": auto,
        "call": "" if source else _call(claim, values),
        "source": source,
        "differs": not claim.passed,
        "expect": claim.expect,
    }


def error_card(evaluation: Evaluation, error: Error) -> dict[str, Any]:
    """One card of the errata section: where, what is wrong, and every claim that prints it."""
    evaluated = evaluation.by_id()
    members = [evaluated[c.id] for c in error.claims if c.id in evaluated]
    first = members[0]
    where = [f"Chapter {error.chapter}"]
    where += [f"“{error.section}”"] if error.section else []
    where += [f"eq. {error.equation}"] if error.equation else []
    where += [error.figure] if error.figure else []
    lines = sorted({m.line for m in members})
    where.append(("line " if len(lines) == 1 else "lines ") + ", ".join(map(str, lines)))
    return {
        "anchor": f"error-{first.id}",
        "where": " · ".join(where),
        "title": first.quantity,
        "class": error.error_class,
        "summary": error.summary or "",
        "members": [_member(evaluation, m) for m in members],
        "differs": any(not m.passed for m in members),
    }


def dated_card(evaluation: Evaluation, claim: EvaluatedClaim) -> dict[str, Any]:
    """A constant the book prints in an older edition: where, then and now."""
    key = evaluation.catalog.by_id()[claim.id].constant
    entry = constants().get(key or "")
    older = None
    if entry is not None:
        older = next((o for o in entry.older if o.edition == claim.matched_edition), None)
    where = [f"Chapter {claim.chapter}"]
    where += [f"“{claim.section}”"] if claim.section else []
    where += [f"line {claim.line}"]
    return {
        "anchor": f"dated-{claim.id}",
        "where": " · ".join(where),
        "title": claim.quantity,
        "member": _member(evaluation, claim),
        "edition": claim.matched_edition or "",
        "then": older.source if older is not None else "",
        "today": f"{entry.value:g} ({entry.edition})" if entry is not None else "",
        "now": entry.source if entry is not None else "",
    }


def invariants_view(
    record: dict[str, Any] | None, now: datetime | None = None
) -> dict[str, Any] | None:
    """The tests' record of invariants with what the page says of its run: whole suite or a
    selection (and which), when, and how long before this report."""
    if record is None:
        return None
    date = record.get("date", "")
    age = ""
    try:
        then = datetime.fromisoformat(date)
        hours = ((now or datetime.now(UTC)) - then).total_seconds() / 3600
        age = f"{hours:.0f} hours" if hours < 48 else f"{hours / 24:.0f} days"
    except (TypeError, ValueError):
        pass
    scope = record.get("scope") or {}
    partial = bool(scope.get("partial"))
    rows = [
        {
            "name": r.get("name", ""),
            "law": r.get("law", ""),
            "reference": r.get("reference", ""),
            # a test of fixed cases (a parametrized example) runs one, not zero, examples
            "examples": "1 case" if r.get("examples") is None else r["examples"],
            "worst": "" if r.get("worst_error") is None else f"{r['worst_error']:.3g}",
            "outcome": r.get("outcome", ""),
        }
        for r in record.get("invariants", [])
    ]
    return {
        "date": date,
        "age": age,
        "profile": record.get("profile") or "",
        "partial": partial,
        "selection": scope.get("selection") or "",
        "tests": scope.get("collected"),
        "rows": rows,
        "failed": sum(r["outcome"] not in ("passed", "") for r in rows),
    }
