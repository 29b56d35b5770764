"""The errata as a publisher wants them: one row of ``errata.csv`` per error of the book, and
``errata.md``, the errata sheet in book order with the constants to update after it (design
2a). Both are byte-identical across runs on the same inputs.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from reference.errata import Error
from reference.evaluation import EvaluatedClaim, Evaluation
from reference.formulas import unicode_formula
from reference.tables import constants
from reports.views import chapters_named, means_shown, superscript_power

# The columns of design section 4, then those revision 2 appends (fixed: extend, never rename)
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
    "lines",
    "ids",
    "class",
    "section",
    "equation",
    "figure",
    "summary",
)


def _members(evaluation: Evaluation, error: Error) -> list[EvaluatedClaim]:
    evaluated = evaluation.by_id()
    return [evaluated[c.id] for c in error.claims if c.id in evaluated]


def error_rows(evaluation: Evaluation) -> list[dict[str, Any]]:
    """One row per error: its first claim's id, line, quantity and diagnosis; every claim's
    printed and correct value joined with "; " in line order; its class and location."""
    rows = []
    for error in evaluation.errors():
        members = _members(evaluation, error)
        first = members[0]
        diagnosis = first.diagnosis or {}
        rows.append(
            {
                "id": first.id,
                "chapter": error.chapter,
                "line": first.line,
                "quantity": first.quantity,
                "printed": "; ".join(m.printed or m.means or "" for m in members),
                "correct": "; ".join(m.correct or "" for m in members),
                "model_value": first.model_value,
                "diagnosis_kind": diagnosis.get("kind"),
                "diagnosis_auto": diagnosis.get("auto"),
                "note": diagnosis.get("note"),
                "quote": first.quote,
                "lines": "; ".join(str(m.line) for m in members),
                "ids": "; ".join(m.id for m in members),
                "class": error.error_class,
                "section": error.section,
                "equation": error.equation,
                "figure": error.figure,
                "summary": error.summary,
            }
        )
    return rows


def _pretty(number: str) -> str:
    """A ``means`` or ``correct`` string as the book prints it: "10^40" -> "10⁴⁰"."""
    return unicode_formula(number) if "^" not in number else means_shown(number)


def _correction(claim: EvaluatedClaim) -> tuple[str, str]:
    """("for" the quoted span, "read" the correction) of one claim, as the book writes it: a
    garbled number shown as it stands in the book (its ``means``), a formula as transcribed, a
    correction in words as the catalog's ``reads`` gives it."""
    correct = claim.correct or ""
    if claim.reads:  # a correction in words: "5% shorter" read "5% longer"
        return claim.quote, claim.reads
    if claim.kind == "formula":  # the formula as transcribed: a quote may be a fragment of it
        return unicode_formula(claim.expression or ""), unicode_formula(correct)
    printed, quote = claim.printed, claim.quote
    if printed and printed in quote:
        shown = _pretty(claim.means) if claim.means else printed
        before = quote.replace(printed, shown, 1)
        return before, quote.replace(printed, _pretty(correct), 1) if correct else correct
    return quote, correct


def _where(
    chapter: str, line: int, section: str | None, equation: str | None, figure: str | None
) -> str:
    parts = [f"Chapter {chapter}", f"line {line}"]
    if section:
        parts.append(f"“{section}”")
    if equation:
        parts.append(f"eq. {equation}")
    if figure:
        parts.append(figure)
    return ", ".join(parts)


def _source(key: str | None) -> str | None:
    entry = constants().get(key or "")
    return None if entry is None else f"{entry.source} ({entry.edition})"


def _entry(evaluation: Evaluation, error: Error) -> list[str]:
    members = _members(evaluation, error)
    first = members[0]
    where = _where(error.chapter, first.line, error.section, error.equation, error.figure)
    fixes = "; ".join(
        f"for “{before}” read “{after}”" for before, after in map(_correction, members)
    )
    lines = [f"- **{where}**: {fixes}."]
    # a correction the catalog states but the model does not confirm is not to be published
    # as it stands (the command exits 1 and names it)
    lines += [f"  NOT CONFIRMED: {m.id}: {m.failure}." for m in members if not m.passed]
    if error.summary:
        lines.append(f"  {error.summary}")
    source = _source(error.first.constant)
    if source:
        lines.append(f"  Source: {source}.")
    return lines


def _count(n: int, one: str, many: str | None = None) -> str:
    """ "1 error", "2 errors"."""
    return f"{n} {one if n == 1 else many or one + 's'}"


def _selection(evaluation: Evaluation) -> str:
    """What a sheet of some chapters says first: "Chapters 8 and 9 only: "; nothing for all."""
    chapters = evaluation.chapters
    if chapters is None:
        return ""
    named = chapters_named(chapters)
    return named[0].upper() + named[1:] + " only: "


def errata_markdown(evaluation: Evaluation) -> str:
    """``errata.md``: every error in book order, by chapter (where, "for ... read ...", the
    summary, the source of a constant or date), then the dated constants to update."""
    book = evaluation.book.identity
    errors = evaluation.errors()
    claims = sum(len(e.claims) for e in errors)
    out = [
        f"# Errata: {book.title}",
        "",
        f"{_selection(evaluation)}{_count(len(errors), 'error')} "
        f"({_count(claims, 'printed value or formula', 'printed values or formulas')}), "
        "in book order. Lines are those of the text the catalog cites (sha256 "
        f"`{book.sha256[:16]}…`); sections are the book's headings.",
        "",
    ]
    titles = {c.key: c.title for c in book.chapters}
    chapter = None
    for error in errors:
        if error.chapter != chapter:
            chapter = error.chapter
            out += ["", f"## Chapter {chapter}: {titles.get(chapter, '')}", ""]
        out += _entry(evaluation, error)
    out += ["", "## Constants to update", ""]
    dated = [c for c in evaluation if c.verdict == "dated"]
    if not dated:
        out.append("None.")
    for c in dated:
        out += _dated_entry(evaluation, c)
    return "\n".join(out).rstrip("\n") + "\n"


def _dated_entry(evaluation: Evaluation, c: EvaluatedClaim) -> list[str]:
    claim = evaluation.catalog.by_id()[c.id]
    key = claim.constant
    entry = constants().get(key or "")
    section = c.section
    where = _where(c.chapter, c.line, section, c.equation, c.figure)
    # a garbled number (its superscript flattened: "5.9742·1024") as the book prints it, and
    # today's value in the same style
    style = superscript_power if c.means else str
    printed = style(c.means) if c.means else c.printed
    today = f"{style(f'{entry.value:g}')} ({entry.edition})" if entry else "today's value"
    lines = [
        f"- **{where}**: {c.quantity}: the book's {printed} is the {c.matched_edition} value; "
        f"today it is {style(c.correct) if c.correct else today}."
    ]
    if entry is not None:
        older = next((o for o in entry.older if o.edition == c.matched_edition), None)
        if older is not None and older.source:
            lines.append(f"  Then: {older.source}.")
        lines.append(f"  Now: {entry.source}.")
    return lines


def errata_counts(evaluation: Evaluation) -> tuple[int, int]:
    """(erratum claims, errors): "erratum 45 (37 errors)"."""
    return sum(c.verdict == "erratum" for c in evaluation), len(evaluation.errors())


def verdict_summary(counts: Iterable[tuple[str, int]], errors: int | None) -> str:
    """The verdict counts as the CLI and pytest print them, errata with their errors."""
    parts = []
    for verdict, n in counts:
        if not n:
            continue
        if verdict == "erratum" and errors is not None:
            parts.append(f"erratum {n} ({errors} error{'' if errors == 1 else 's'})")
        else:
            parts.append(f"{verdict} {n}")
    return ", ".join(parts)
