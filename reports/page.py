"""The errata report: ``index.html`` (one self-contained page), ``errata.csv``, ``errata.md``
and ``claims.json`` (design section 4), built from the evaluated catalog and the scan; what the
page shows of each part is prepared in ``reports.views``.

The page is rendered from jinja2 templates in ``reports/templates`` with autoescaping on, so
everything it quotes from the book or the catalog shows as text.
"""

from __future__ import annotations

from collections import Counter
from typing import Any

from jinja2 import Environment, PackageLoader, select_autoescape

from reference.book import Book
from reference.catalog import Catalog
from reference.compare import VERDICTS
from reference.evaluation import Evaluation
from reference.scan import ScanResult
from reference.schema import Assumption
from reports import bangcheck_version
from reports.errata_sheet import ERRATA_COLUMNS, errata_counts, errata_markdown, error_rows
from reports.figures import RenderedFigure, render_all, verdict_chart
from reports.output import claims_json, csv_text
from reports.views import chapters_named, claim_row, dated_card, error_card, invariants_view

EXAMPLES_PER_RULE = 3


def _coverage(scan: ScanResult) -> list[dict[str, Any]]:
    out = []
    for key, c in scan.chapters.items():
        done = c.catalogued + c.excluded_rule + c.excluded_hand
        out.append(
            {
                "chapter": key,
                "tokens": c.tokens,
                "catalogued": c.catalogued,
                "excluded_rule": c.excluded_rule,
                "excluded_hand": c.excluded_hand,
                "missing": c.missing,
                "percent": round(100 * done / c.tokens, 1) if c.tokens else 100.0,
            }
        )
    return out


def _exclusion_examples(book: Book, scan: ScanResult) -> dict[str, list[dict[str, Any]]]:
    per_chapter: dict[str, dict[str, dict[str, Any]]] = {}
    for tok in scan.tokens:
        if tok.status != "excluded":
            continue
        name = f"hand: {tok.by}" if tok.hand else tok.by or ""
        group = per_chapter.setdefault(tok.chapter, {}).setdefault(
            name, {"name": name, "count": 0, "examples": []}
        )
        group["count"] += 1
        if len(group["examples"]) < EXAMPLES_PER_RULE:
            text = book.line(tok.line)
            context = text[max(0, tok.start - 30) : tok.end + 30].strip()
            group["examples"].append({"line": tok.line, "token": tok.text, "context": context})
    return {
        chapter: sorted(groups.values(), key=lambda g: (-g["count"], g["name"]))
        for chapter, groups in per_chapter.items()
    }


def report_meta(evaluation: Evaluation, scan: ScanResult) -> dict[str, Any]:
    counts = evaluation.verdict_counts()
    return {
        "bangcheck": bangcheck_version(),
        "book": {
            "title": evaluation.book.identity.title,
            "sha256": evaluation.book.identity.sha256,
            "lines": evaluation.book.identity.lines,
        },
        "claims": len(evaluation),
        "verdicts": {v: counts[v] for v in VERDICTS},
        "errata": counts["erratum"],
        "errors": errata_counts(evaluation)[1],
        "coverage": {row["chapter"]: row for row in _coverage(scan)},
        # the chapters of a report of some chapters (all its counts are theirs); null: all
        "chapters": None if evaluation.chapters is None else list(evaluation.chapters),
    }


def _environment() -> Environment:
    return Environment(
        loader=PackageLoader("reports", "templates"),
        autoescape=select_autoescape(enabled_extensions=("html", "j2"), default=True),
        trim_blocks=True,
        lstrip_blocks=True,
    )


def _power_section(evaluation: Evaluation) -> dict[str, Any]:
    """The detection power (design 3a) as the page shows it: rates per class and per chapter,
    the targets missed, and every claim that lets a last-digit misprint through, with why."""
    report = evaluation.power()
    # the targets are the whole book's: not for a report of some chapters (or of a sample)
    whole_book = evaluation.chapters is None and len(evaluation) == sum(
        1 for _ in evaluation.catalog.claims()
    )
    letting_through: dict[str, dict[str, Any]] = {}
    for miss in report.misses:
        if miss.cls != "last-digit":
            continue
        row = letting_through.setdefault(
            miss.id,
            {
                "id": miss.id,
                "line": miss.line,
                "printed": miss.printed,
                "misprints": [],
                "reasons": [],
            },
        )
        row["misprints"].append(miss.misprint)
        if (miss.reason or "no reason") not in row["reasons"]:
            row["reasons"].append(miss.reason or "no reason")
    return {
        "claims": report.claims,
        "classes": report.classes,
        "chapters": report.chapters,
        "failures": report.failures() if whole_book else [],  # the targets are the book's
        "whole_book": whole_book,
        "unexplained": report.unexplained,
        "last_digit_misses": list(letting_through.values()),
    }


def _assumptions(evaluation: Evaluation) -> list[dict[str, str]]:
    by_id = evaluation.catalog.by_id()
    out = []
    for c in evaluation:
        if not c.assumptions:
            continue
        rounded = set(c.rounded_assumptions)
        assumed = ", ".join(
            f"{k} = {v}{' (rounded)' if k in rounded else ''}" for k, v in c.assumptions.items()
        )
        reasons = [a.reason for a in by_id[c.id].assumptions.values() if isinstance(a, Assumption)]
        out.append(
            {"id": c.id, "assumed": assumed, "reason": c.precision_reason or "; ".join(reasons)}
        )
    return out


def _tolerances(evaluation: Evaluation) -> list[dict[str, str]]:
    out = []
    for c in evaluation:
        settings = []
        if c.rel_tol is not None:
            settings.append(f"rel_tol {c.rel_tol}")
        if c.sigfigs is not None:
            settings.append(f"sigfigs {c.sigfigs}")
        if c.rounding:
            settings.append(f"declared {c.rounding}")
        if c.exact:
            settings.append("exact integer")
        if c.relation != "=" or settings:
            out.append(
                {
                    "id": c.id,
                    "relation": c.relation,
                    "setting": ", ".join(settings),
                    "reason": c.precision_reason or "",
                }
            )
    return out


def render_page(
    evaluation: Evaluation,
    scan: ScanResult,
    catalog: Catalog,
    properties: dict[str, Any] | None,
    figures: list[RenderedFigure],
) -> str:
    """The report page as one HTML string, with ``figures`` already rendered
    (``reports.figures.render_all``)."""
    book = evaluation.book
    titles = {c.key: c.title for c in book.identity.chapters}
    chapters = []
    for key, title in titles.items():
        rows = [claim_row(c) for c in evaluation if c.chapter == key]
        if rows:
            chapters.append({"key": key, "title": title, "rows": rows})
    per_chapter: dict[str, Counter[str]] = {
        key: Counter(c.verdict for c in evaluation if c.chapter == key)
        for key in titles
        if any(c.chapter == key for c in evaluation)
    }
    selected = evaluation.chapters
    slips = sorted(
        (
            s
            for f in catalog.files
            if selected is None or f.meta.chapter in selected
            for s in f.slips
        ),
        key=lambda s: s.line,
    )
    template = _environment().get_template("index.html.j2")
    return template.render(
        meta=report_meta(evaluation, scan),
        selection=None if selected is None else chapters_named(selected),
        verdicts=VERDICTS,
        present=[v for v in VERDICTS if any(c.verdict == v for c in evaluation)],
        per_chapter=per_chapter,
        titles=titles,
        chart=verdict_chart({k: dict(v) for k, v in per_chapter.items()}, VERDICTS),
        coverage=_coverage(scan),
        errata=[error_card(evaluation, e) for e in evaluation.errors()],
        dated=[dated_card(evaluation, c) for c in evaluation if c.verdict == "dated"],
        chapters=chapters,
        failing=[c for c in evaluation if not c.passed and c.verdict != "unmodeled"],
        power=_power_section(evaluation),
        figures=figures,
        unmodeled=[c for c in evaluation if c.verdict == "unmodeled"],
        properties=invariants_view(properties),
        slips=slips,
        assumptions=_assumptions(evaluation),
        tolerances=_tolerances(evaluation),
        exclusions=_exclusion_examples(book, scan),
    )


def build_report(
    evaluation: Evaluation,
    scan: ScanResult,
    catalog: Catalog,
    properties: dict[str, Any] | None,
    figure_workers: int | None = None,
) -> dict[str, str]:
    """The report's files by name: ``index.html``, ``errata.csv``, ``claims.json``; the
    figures drawn by ``figure_workers`` processes (``render_all``'s default if None)."""
    figures = render_all(evaluation, figure_workers)
    return {
        "index.html": render_page(evaluation, scan, catalog, properties, figures),
        "errata.csv": csv_text(ERRATA_COLUMNS, error_rows(evaluation)),
        "errata.md": errata_markdown(evaluation),
        "claims.json": claims_json(
            report_meta(evaluation, scan), [c.to_json() for c in evaluation]
        ),
    }
