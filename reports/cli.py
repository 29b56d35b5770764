"""The ``bangcheck`` command: ``claims``, ``scan`` and ``report`` (design section 4).

Data on stdout, progress and messages on stderr. Exit 0 on success, 1 when findings fail the
command's check, 2 on usage errors, an invalid catalog, or a missing or wrong book.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from collections import Counter
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from reference.book import BOOK_ENV, Book, BookError, book_path, chapter_keys, load_book
from reference.calls import ModelCallError
from reference.catalog import Catalog, CatalogDirectoryError, catalog_paths, default_directory
from reference.compare import VERDICTS
from reference.evaluation import EvaluatedClaim, Evaluation, evaluate_catalog
from reference.formulas import unicode_formula
from reference.power import ClassRate, PowerReport
from reference.scan import ScanResult, scan
from reference.schema import CatalogError
from reference.validate import checked_catalog
from reports import bangcheck_version
from reports.errata_sheet import verdict_summary
from reports.invariants import (
    CACHE_DIR,
    PROPERTIES_FILE,
    PropertiesError,
    default_properties_path,
    read_properties,
)
from reports.outdir import OutputError, check_target_now, shown, write_report_dir
from reports.views import chapters_named, printed_shown

EXIT_OK, EXIT_FINDINGS, EXIT_USAGE = 0, 1, 2
EXIT_INTERRUPTED = 130  # 128 + SIGINT, as shells report it


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="bangcheck",
        description="Check the numbers of Classical Mechanics with a BANG! (Unit 1).",
    )
    parser.add_argument("--version", action="version", version=f"bangcheck {bangcheck_version()}")
    _common_options(parser, None)
    sub = parser.add_subparsers(dest="command", required=True)
    common = argparse.ArgumentParser(add_help=False)
    # given after the command, an option overrides the same one given before it; not given
    # there, it leaves the value from before the command (or None) alone
    _common_options(common, argparse.SUPPRESS)

    claims = sub.add_parser("claims", parents=[common], help="the evaluated catalog")
    claims.add_argument("--json", action="store_true", help="one JSON object per claim")
    claims.add_argument("--verdict", choices=VERDICTS, help="only claims with this verdict")
    claims.add_argument("--strict", action="store_true", help="unmodeled claims also fail")

    scanner = sub.add_parser("scan", parents=[common], help="every number token's status")
    scanner.add_argument("--json", action="store_true", help="one JSON document")
    scanner.add_argument("--missing", action="store_true", help="list every missing token")

    power = sub.add_parser(
        "power", parents=[common], help="detection power: would a misprint have been caught?"
    )
    power.add_argument("--json", action="store_true", help="one JSON document")

    fmt = sub.add_parser(
        "fmt", parents=[common], help="write the catalog in its canonical form (docs/catalog.md)"
    )
    fmt.add_argument(
        "--check",
        action="store_true",
        help="write nothing: show a diff, exit 1 if any file differs",
    )

    report = sub.add_parser("report", parents=[common], help="the errata report (HTML, CSV, JSON)")
    report.add_argument(
        "--out",
        type=_directory_argument,
        default=Path("reports/out"),
        help="output directory (reports/out); written only when it is missing, empty or a "
        "previous report",
    )
    report.add_argument(
        "--properties",
        type=Path,
        default=None,
        help="the property suite's record of its invariants, shown when present (default: "
        f"the nearest {CACHE_DIR}/{PROPERTIES_FILE}, which pytest writes)",
    )
    return parser


def _common_options(parser: argparse.ArgumentParser, default: object) -> None:
    """``--book``, ``--chapter`` and ``--catalog``, taken before the command or after it."""
    parser.add_argument(
        "--book", default=default, help="path of bang-unit1.txt (default: $BANGCHECK_BOOK)"
    )
    parser.add_argument(
        "--chapter", default=default, help='chapters: "8", "0-3", "4,5", "A1" (default: all)'
    )
    parser.add_argument(
        "--catalog",
        type=Path,
        default=default,
        help="a catalog directory of chNN.toml files to use instead of "
        "the packaged one (for drafting)",
    )


def _fmt(value: float | list[float] | None) -> str:
    if value is None:
        return "-"
    if isinstance(value, list):
        return "[" + ", ".join(_fmt(v) for v in value) + "]"
    return f"{value:.10g}"


def _failing(evaluation: Evaluation, strict: bool) -> list[EvaluatedClaim]:
    return [c for c in evaluation if not c.passed and (c.verdict != "unmodeled" or strict)]


def _say_failing(failing: list[EvaluatedClaim]) -> None:
    """Each failing claim (ten at most) with why: a verdict other than its ``expect``, an
    erratum whose model disagrees with its ``correct``, a dated claim of another edition."""
    print(f"bangcheck: {len(failing)} claim(s) differ from the catalog:", file=sys.stderr)
    for c in failing[:10]:
        print(f"  {c.id} (line {c.line}): {c.failure}", file=sys.stderr)
    if len(failing) > 10:
        print(f"  and {len(failing) - 10} more", file=sys.stderr)


CELL = 24  # the widest printed cell of the claims table; longer formulas go below the row


def _cell(text: str, width: int) -> str:
    """``text`` cut to ``width`` characters, an ellipsis marking the cut."""
    return text if len(text) <= width else text[: width - 1] + "…"


def _print_claims(evaluation: Evaluation, as_json: bool, verdict: str | None) -> None:
    rows = [c for c in evaluation if verdict is None or c.verdict == verdict]
    if as_json:
        for c in rows:
            print(json.dumps(c.to_json(), ensure_ascii=False, sort_keys=False))
        return
    width = max((len(c.id) for c in rows), default=2)
    shown = [printed_shown(c) for c in rows]
    pwidth = min(max((len(s) for s in shown), default=7), CELL)
    pad = " " * (width + 2)
    print(f"{'id':<{width}}  {'line':>5}  {'printed':>{pwidth}}  {'model':>16}  verdict (expect)")
    for c, printed in zip(rows, shown, strict=True):
        mark = "" if c.passed else "   <-- differs"
        reason = (
            f" [{c.rounding_reason or c.matched_edition}]"
            if c.rounding_reason or (c.matched_edition)
            else ""
        )
        if c.kind == "formula":
            model = unicode_formula(c.model_expression) if c.model_expression else "-"
        else:
            model = _fmt(c.model_value)
        print(
            f"{c.id:<{width}}  {c.line:>5}  {_cell(printed, pwidth):>{pwidth}}  "
            f"{_cell(model, 16):>16}  {c.verdict}{reason} ({c.expect}){mark}"
        )
        if len(printed) > pwidth:  # a long formula in full, below its row
            print(f"{pad}printed: {printed}")
        if len(model) > 16:
            print(f"{pad}model: {model}")
        if c.verdict in ("erratum", "dated"):
            diagnosis = c.diagnosis or {}
            correct = c.correct or "-"
            if c.kind == "formula" and c.correct:
                correct = unicode_formula(c.correct)
            print(f"{pad}correct: {correct}")
            if diagnosis.get("kind"):
                print(f"{pad}diagnosis: {diagnosis['kind']}: {diagnosis['note']}")
            if diagnosis.get("auto"):
                print(f"{pad}automatic: {diagnosis['auto']}")


def _claims(args: argparse.Namespace) -> int:
    book = load_book(book_path(args.book))
    catalog = _catalog(args, book)
    evaluation = evaluate_catalog(catalog, book, args.chapters, progress=True)
    _print_claims(evaluation, args.json, args.verdict)
    counts = evaluation.verdict_counts()
    errors = len(evaluation.errors())
    summary = verdict_summary(((v, counts[v]) for v in VERDICTS), errors)
    print(f"bangcheck: {len(evaluation)} claims: {summary or 'none'}", file=sys.stderr)
    failing = _failing(evaluation, args.strict)
    if failing:
        _say_failing(failing)
        return EXIT_FINDINGS
    return EXIT_OK


def _scan_json(result: ScanResult) -> dict[str, Any]:
    return {
        "chapters": {
            key: {
                "tokens": c.tokens,
                "catalogued": c.catalogued,
                "excluded_rule": c.excluded_rule,
                "excluded_hand": c.excluded_hand,
                "missing": c.missing,
                "rules": dict(sorted(c.rules.items())),
                "hand_reasons": dict(sorted(c.reasons.items())),
            }
            for key, c in result.chapters.items()
        },
        "conflicts": result.conflicts,
        "tokens": [t.to_json() for t in result.tokens],
    }


def _print_scan(result: ScanResult, book_lines: Sequence[str], list_missing: bool) -> None:
    print(
        f"{'chapter':>7}  {'tokens':>6}  {'catalogued':>10}  {'by rule':>7}  "
        f"{'by hand':>7}  {'missing':>7}"
    )
    total: Counter[str] = Counter()
    for key, c in result.chapters.items():
        print(
            f"{key:>7}  {c.tokens:>6}  {c.catalogued:>10}  {c.excluded_rule:>7}  "
            f"{c.excluded_hand:>7}  {c.missing:>7}"
        )
        total.update(
            tokens=c.tokens,
            catalogued=c.catalogued,
            rule=c.excluded_rule,
            hand=c.excluded_hand,
            missing=c.missing,
        )
    rules = [name for name, _ in result.rule_counts().most_common()]
    reasons = sorted({r for c in result.chapters.values() for r in c.reasons})
    width = max([18, *(len(n) for n in rules), *(len("hand: " + r) for r in reasons)])
    print("\nexcluded per rule and chapter:")
    print(f"  {'rule':<{width}} {'total':>6}  " + " ".join(f"{k:>5}" for k in result.chapters))
    for name in rules:
        per_chapter = " ".join(f"{c.rules[name]:>5}" for c in result.chapters.values())
        print(f"  {name:<{width}} {result.rule_counts()[name]:>6}  {per_chapter}")
    for reason in reasons:
        per_chapter = " ".join(f"{c.reasons[reason]:>5}" for c in result.chapters.values())
        count = sum(c.reasons[reason] for c in result.chapters.values())
        print(f"  {'hand: ' + reason:<{width}} {count:>6}  {per_chapter}")
    if list_missing:
        print("\nmissing tokens:" + ("" if result.missing else " none"))
        for t in result.missing:
            text = book_lines[t.line - 1]
            print(f"  {t.line:>5}  {t.text:<12} {text[max(0, t.start - 30) : t.end + 30].strip()}")
    for conflict in result.conflicts:
        print(f"conflict: {conflict}")
    print(
        f"\ntotal: {total['tokens']} tokens; {total['catalogued']} catalogued; "
        f"{total['rule']} excluded by rule, {total['hand']} by hand; "
        f"{total['missing']} missing"
    )


def _scan(args: argparse.Namespace) -> int:
    book = load_book(book_path(args.book))
    catalog = _catalog(args, book)
    result = scan(book, catalog, args.chapters)
    if args.json:
        print(json.dumps(_scan_json(result), ensure_ascii=False))
    else:
        _print_scan(result, book.lines, args.missing)
    return EXIT_FINDINGS if result.missing or result.conflicts else EXIT_OK


def _rate_row(name: str, rate: ClassRate) -> str:
    shown = "-" if rate.rate is None else f"{rate.rate:.4f}"
    target = "" if rate.target is None else f"{rate.target:>7}"
    return f"  {name:<16} {rate.misprints:>9} {rate.caught:>7} {shown:>7} {target}"


def _print_power(report: PowerReport, whole_book: bool) -> None:
    header = f"  {'':<16} {'misprints':>9} {'caught':>7} {'rate':>7}"
    print(f"detection power over {report.claims} claims (relation '=', expected verified)")
    print(f"\nper class:\n{header} {'target':>7}")
    for rate in report.classes:
        print(_rate_row(rate.cls, rate))
    if not whole_book:
        print("  (the targets are the whole book's: a selection of chapters is not judged by them)")
    for title, groups in (("number form", report.forms), ("chapter", report.chapters)):
        print(f"\nper {title}:")
        for key, rates in groups.items():
            print(f"  {key}:")
            for rate in rates.values():
                print(_rate_row("  " + rate.cls, rate))
    reasons = Counter(m.reason or "(no reason)" for m in report.misses)
    print(
        "\nmisses by reason: " + (", ".join(f"{r} {n}" for r, n in reasons.most_common()) or "none")
    )
    for miss in report.misses:
        print(
            f"  {miss.id} (line {miss.line}) {miss.cls}: {miss.printed} -> {miss.misprint} is "
            f"{miss.verdict}: {miss.reason or 'unexplained'}"
        )
    if whole_book:
        for failure in report.failures():
            print(f"target missed: {failure}")


def _power(args: argparse.Namespace) -> int:
    book = load_book(book_path(args.book))
    catalog = _catalog(args, book)
    evaluation = evaluate_catalog(catalog, book, args.chapters, progress=True)
    report = evaluation.power()
    whole_book = evaluation.chapters is None  # the targets are the whole book's
    if args.json:
        print(json.dumps(report.to_json(), ensure_ascii=False))
    else:
        _print_power(report, whole_book)
    failed = bool(report.unexplained) or (whole_book and bool(report.failures()))
    return EXIT_FINDINGS if failed else EXIT_OK


def _directory_argument(text: str) -> Path:
    """``--out`` as typed: a path, not an empty string (which would mean the working
    directory)."""
    if not text.strip():
        raise argparse.ArgumentTypeError("give a directory, not an empty string")
    return Path(text)


def _output_path(given: Path) -> Path:
    """``--out`` made absolute with its symbolic links followed (the report replaces the
    directory a link points to, never the link); ``OutputError`` for a link loop."""
    try:
        return given.resolve()
    except (OSError, RuntimeError) as err:
        raise OutputError(f"--out {shown(given)}: cannot follow its links: {err}") from err


def _invariants(given: Path | None) -> dict[str, Any] | None:
    """The tests' record of invariants: ``--properties`` must exist when given; the default,
    found from the working directory up, is shown when it can be read and skipped with a
    warning when it cannot."""
    if given is not None:
        if not given.is_file():
            raise PropertiesError(f"--properties {shown(given)}: no such file")
        return read_properties(given.resolve())
    try:
        return read_properties(default_properties_path())
    except PropertiesError as err:
        print(f"bangcheck: warning: {err}; the report shows no invariants", file=sys.stderr)
        return None


def _fmt_catalog(args: argparse.Namespace) -> int:
    """``bangcheck fmt``: every catalog file (of the chosen chapters) in canonical form, written
    only when the whole catalog validates (against the book when one is given); ``--check``
    writes nothing and exits 1 with a diff when a file is not in canonical form."""
    from reference.catalog_format import diff, format_text, write_atomically

    directory = args.catalog if args.catalog is not None else Path(str(default_directory()))
    book = load_book(book_path(args.book)) if args.book or os.environ.get(BOOK_ENV) else None
    catalog = _catalog(args, book, note=False)
    chosen = {f.stem for f in catalog.files if f.meta.chapter in args.chapters}
    changed = read = 0
    for path in catalog_paths(directory):
        path = Path(str(path))
        if path.stem not in chosen:
            continue
        read += 1
        text = path.read_text(encoding="utf-8")
        formatted = format_text(text)
        if formatted == text:
            continue
        changed += 1
        if args.check:
            sys.stdout.write(diff(path, text, formatted))
        else:
            write_atomically(path, formatted)
            print(f"bangcheck: formatted {shown(path)}", file=sys.stderr)
    if args.check and changed:
        print(f"bangcheck: {changed} catalog file(s) not in canonical form", file=sys.stderr)
        return EXIT_FINDINGS
    if not changed:
        print(f"bangcheck: {read} catalog file(s) already in canonical form", file=sys.stderr)
    return EXIT_OK


def _report(args: argparse.Namespace) -> int:
    from reports.page import build_report

    out = _output_path(args.out)
    check_target_now(out)  # before the work: a refused directory is said at once
    properties = _invariants(args.properties)
    book = load_book(book_path(args.book))
    catalog = _catalog(args, book)
    evaluation = evaluate_catalog(catalog, book, args.chapters, progress=True)
    result = scan(book, catalog, args.chapters)
    print("bangcheck: rendering the report", file=sys.stderr)
    files = build_report(evaluation, result, catalog, properties)
    write_report_dir(out, files)
    print(
        f"bangcheck: wrote {shown(out / 'index.html')}, errata.csv, errata.md and claims.json",
        file=sys.stderr,
    )
    print(out / "index.html")
    failing = _failing(evaluation, strict=False)
    if failing:
        _say_failing(failing)
        print(
            "bangcheck: the report marks them: their verdicts are not findings about the book "
            "until the catalog or the model is fixed",
            file=sys.stderr,
        )
        return EXIT_FINDINGS
    return EXIT_OK


def main(argv: Sequence[str] | None = None) -> int:
    """Run ``bangcheck``; returns the exit status."""
    try:
        return _run(argv)
    except BrokenPipeError:
        # the reader went away (``bangcheck scan | head``): stop quietly, as Unix tools do
        sys.stderr.close()
        return EXIT_OK
    except KeyboardInterrupt:
        # the report's directory is swapped in by renames: an interrupted run leaves the
        # previous report, or debris the next run cleans up
        print("bangcheck: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED


def _catalog(args: argparse.Namespace, book: Book | None, note: bool = True) -> Catalog:
    """The validated catalog of the run. A ``--catalog`` directory that lacks some chapters is
    a draft of the others: a note says which it holds (unless ``note`` is false: ``fmt``
    writes what there is), and ``args.chapters`` becomes the chapters it holds, so that the
    command works on those as with ``--chapter``; a ``--chapter`` it has no file for is an
    error (``CatalogDirectoryError``), not a report of no claims."""
    catalog = checked_catalog(book, args.catalog)
    if args.catalog is None:
        return catalog
    held = catalog.chapters
    if args.chapter is not None:  # chapters asked for by name
        absent = [key for key in args.chapters if key not in held]
        if absent:
            raise CatalogDirectoryError(
                f"the catalog directory {args.catalog} has no file for "
                f"{chapters_named(absent)} (it holds {chapters_named(held)})"
            )
    elif note and book is not None and len(held) < len(book.identity.chapters):
        print(
            f"bangcheck: note: the catalog directory {args.catalog} holds "
            f"{chapters_named(held)} only; the other chapters are left out",
            file=sys.stderr,
        )
    # every command then works on the chapters the draft holds: its scan, power and report
    # are of those chapters, as with --chapter
    args.chapters = tuple(key for key in args.chapters if key in held)
    return catalog


def _run(argv: Sequence[str] | None) -> int:
    parser = _parser()
    args = parser.parse_args(argv)
    try:
        args.chapters = chapter_keys(args.chapter)
    except ValueError as err:
        parser.error(str(err))
    if args.catalog is not None:
        try:
            catalog_paths(args.catalog)
        except CatalogDirectoryError as err:
            parser.error(str(err))
    try:
        commands = {
            "claims": _claims,
            "scan": _scan,
            "power": _power,
            "fmt": _fmt_catalog,
            "report": _report,
        }
        return commands[args.command](args)
    except (BookError, CatalogDirectoryError, OutputError, PropertiesError) as err:
        print(f"bangcheck: error: {err}", file=sys.stderr)
    except CatalogError as err:
        print(
            f"bangcheck: the catalog is invalid ({len(err.problems)} problem(s)):", file=sys.stderr
        )
        for problem in err.problems:
            print(str(problem), file=sys.stderr)
    except ModelCallError as err:
        print(f"bangcheck: error: a model could not be evaluated: {err}", file=sys.stderr)
    return EXIT_USAGE


if __name__ == "__main__":
    sys.exit(main())
