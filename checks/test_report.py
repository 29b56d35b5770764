"""The errata report: its files, their agreement, escaping, determinism and atomic writing.

One report is built per test session (``report_dir``) with the ``bangcheck report`` command and
shared by the tests.
"""

from __future__ import annotations

import csv
import dataclasses
import io
import json
import os
import re
import time
import types
from collections import Counter
from html.parser import HTMLParser
from pathlib import Path
from typing import cast

import pytest

from reference.book import Book
from reference.catalog import Catalog
from reference.evaluation import Evaluation, evaluate_catalog
from reference.scan import ScanResult, scan
from reports.background import BackgroundReport, BackgroundReportError
from reports.cli import main
from reports.errata_sheet import ERRATA_COLUMNS, errata_markdown, error_rows
from reports.figures import registered
from reports.invariants import default_properties_path, read_properties, write_properties
from reports.outdir import MANIFEST, manifest_names
from reports.output import claims_json, csv_text
from reports.page import build_report, render_page, report_meta
from reports.views import invariants_view

# under xdist (--dist loadgroup) every test that reads the session's evaluation or scan is in
# one group, run by one worker, which evaluates the catalog, scans the book and builds the
# report once
pytestmark = [pytest.mark.report, pytest.mark.xdist_group("evaluation")]

VOID = {
    "meta",
    "br",
    "input",
    "img",
    "hr",
    "link",
    "path",
    "rect",
    "circle",
    "use",
    "stop",
    "line",
    "polyline",
    "polygon",
    "ellipse",
}
SECTIONS = [
    "summary",
    "errata",
    "claims",
    "power",
    "figures",
    "slips",
    "assumptions",
    "tolerances",
    "exclusions",
]


class Page(HTMLParser):
    """Collects ids, claim rows, sections and checks that elements nest properly."""

    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.stack: list[str] = []
        self.problems: list[str] = []
        self.ids: list[str] = []
        self.claim_rows: list[str] = []
        self.sections: list[str] = []
        self.errata_articles = 0
        self.scripts = 0
        self._in_count = False
        self.errata_count = ""
        self.errors_count = ""
        self._counting = ""

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        a = dict(attrs)
        if a.get("id"):
            self.ids.append(a["id"] or "")
        if tag == "tr" and a.get("class") == "claim":
            self.claim_rows.append((a.get("id") or "").removeprefix("claim-"))
        if tag == "section":
            self.sections.append(a.get("id") or "")
        if tag == "article" and a.get("class") == "erratum":
            self.errata_articles += 1
        if tag == "script":
            self.scripts += 1
        self._counting = (
            (a.get("id") or "") if a.get("id") in ("errata-count", "errors-count") else ""
        )
        if tag not in VOID:
            self.stack.append(tag)

    def handle_startendtag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        a = dict(attrs)
        if a.get("id"):
            self.ids.append(a["id"] or "")

    def handle_endtag(self, tag: str) -> None:
        if tag in VOID:
            return
        if not self.stack or self.stack[-1] != tag:
            self.problems.append(f"</{tag}> closes {self.stack[-1:] or 'nothing'}")
            return
        self.stack.pop()

    def handle_data(self, data: str) -> None:
        if self._counting == "errata-count":
            self.errata_count += data
        elif self._counting == "errors-count":
            self.errors_count += data
        self._counting = ""


def parse(html: str) -> Page:
    page = Page()
    page.feed(html)
    page.close()
    return page


@pytest.fixture(scope="session")
def page(report_dir: Path) -> Page:
    return parse((report_dir / "index.html").read_text(encoding="utf-8"))


def test_every_figure_is_drawn(report_dir: Path) -> None:
    html = (report_dir / "index.html").read_text("utf-8")
    keys = [spec.key for spec in registered()]
    assert len(keys) == len(set(keys))
    assert [k for k in keys if f'<figure id="figure-{k}">' not in html] == []


def test_the_command_writes_a_report_of_one_chapter(
    book: Book, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "out"
    argv = ["report", "--book", str(book.path), "--chapter", "3", "--out", str(out)]
    assert main(argv) == 0
    assert capsys.readouterr().out.strip() == str(out / "index.html")
    html = (out / "index.html").read_text("utf-8")
    assert 'id="claim-ch03.suv-vw.ke"' in html
    assert 'id="claim-ch08.tower-100-30-10.v3"' not in html
    assert '<figure id="figure-energy-ellipses">' in html
    assert '<figure id="figure-tower-100-30-10">' not in html
    # it says it is one chapter's, everywhere a reader may take its counts for the book's
    assert 'id="selection"><strong>Chapter 3 only</strong>' in html
    assert json.loads((out / "claims.json").read_text("utf-8"))["meta"]["chapters"] == ["3"]
    sheet = (out / "errata.md").read_text("utf-8")
    assert "\nChapter 3 only: 1 error (1 printed value or formula), in book order." in sheet
    slips = re.findall(r"<tr><td><code>(ch\d\d)[.\w-]*</code></td><td class=\"num\">", html)
    assert slips
    assert set(slips) == {"ch03"}


def test_the_sheet_prints_a_garbled_dated_constant_as_the_book_does(evaluation: Evaluation) -> None:
    """The Earth's mass is extracted as "5.9742·1024" (its superscript flattened): the errata
    sheet shows it, and today's value, as the book prints them."""
    sheet = errata_markdown(evaluation)
    assert "the book's 5.9742·10²⁴ is the IAU 1976 value; today it is 5.9722·10²⁴." in sheet
    assert "the book's 6.672E-11 is the CODATA 1973 value; today it is 6.674E-11." in sheet


def test_a_report_of_the_whole_book_names_no_selection(report_dir: Path) -> None:
    assert 'id="selection"' not in (report_dir / "index.html").read_text("utf-8")
    assert json.loads((report_dir / "claims.json").read_text("utf-8"))["meta"]["chapters"] is None
    sheet = (report_dir / "errata.md").read_text("utf-8")
    assert " only: " not in sheet.split("\n\n")[1]


def test_the_report_files_are_written(report_dir: Path) -> None:
    # less the browser test's screenshots, saved beside the page
    names = {p.name for p in report_dir.iterdir() if not p.match("screenshot-*.png")}
    assert sorted(names) == [MANIFEST, "claims.json", "errata.csv", "errata.md", "index.html"]
    written = frozenset({"claims.json", "errata.csv", "errata.md", "index.html"})
    assert manifest_names(report_dir) == written


def test_the_page_parses_and_nests(page: Page) -> None:
    assert page.problems == []
    assert page.stack == []


def test_every_claim_appears_once(page: Page, evaluation: Evaluation) -> None:
    assert sorted(page.claim_rows) == sorted(c.id for c in evaluation)
    assert len(page.claim_rows) == len(set(page.claim_rows))


def test_ids_are_unique_even_across_figures(page: Page) -> None:
    duplicated = [i for i, n in Counter(page.ids).items() if n > 1]
    assert not duplicated


def test_sections_come_in_order(page: Page) -> None:
    assert [s for s in page.sections if s in SECTIONS] == SECTIONS


def test_errata_counts_agree(report_dir: Path, page: Page, evaluation: Evaluation) -> None:
    """errata.csv has one row per error; claims.json counts erratum claims and errors; the
    page shows each erratum claim."""
    expected = sum(c.verdict == "erratum" for c in evaluation)
    errors = evaluation.errors()
    rows = list(csv.DictReader(io.StringIO((report_dir / "errata.csv").read_text("utf-8"))))
    data = json.loads((report_dir / "claims.json").read_text("utf-8"))
    in_json = sum(c["verdict"] == "erratum" for c in data["claims"])
    assert int(page.errata_count) == in_json == expected
    assert data["meta"]["errata"] == expected
    assert int(page.errors_count) == page.errata_articles == data["meta"]["errors"]
    assert data["meta"]["errors"] == len(rows) == len(errors) < expected
    assert [r["id"] for r in rows] == [e.first.id for e in errors]
    ids = [i for r in rows for i in r["ids"].split("; ")]
    assert sorted(ids) == sorted(c.id for c in evaluation if c.verdict == "erratum")


def test_errata_md_lists_every_error_in_book_order(
    report_dir: Path, evaluation: Evaluation
) -> None:
    """errata.md and errata.csv agree: one entry per error, in the same (book) order, each
    with its summary; the dated constants come after them."""
    text = (report_dir / "errata.md").read_text("utf-8")
    errors_part, _, dated_part = text.partition("## Constants to update")
    entries = [line for line in errors_part.splitlines() if line.startswith("- **")]
    rows = list(csv.DictReader(io.StringIO((report_dir / "errata.csv").read_text("utf-8"))))
    assert len(entries) == len(rows)
    for entry, row in zip(entries, rows, strict=True):
        assert f"line {row['line']}" in entry
    for row in rows:
        assert row["summary"]
        assert row["summary"] in errors_part
    assert dated_part.count("- **") == sum(c.verdict == "dated" for c in evaluation)


def test_csv_columns_and_json_fields(report_dir: Path, evaluation: Evaluation) -> None:
    header = (report_dir / "errata.csv").read_text("utf-8").splitlines()[0]
    assert tuple(header.split(",")) == ERRATA_COLUMNS
    data = json.loads((report_dir / "claims.json").read_text("utf-8"))
    assert set(data) == {"meta", "claims"}
    assert [c["id"] for c in data["claims"]] == [c.id for c in evaluation]
    assert data["meta"]["book"]["sha256"] == evaluation.book.identity.sha256


def test_a_fresh_run_gives_identical_csv_and_json(
    report_dir: Path, book: Book, catalog: Catalog
) -> None:
    """A second evaluation and scan from scratch writes the same bytes (no dates, no order
    that depends on the run)."""
    again = evaluate_catalog(catalog, book)
    result = scan(book, catalog, tuple(c.key for c in book.identity.chapters))
    files = {
        "claims.json": claims_json(report_meta(again, result), [c.to_json() for c in again]),
        "errata.csv": csv_text(ERRATA_COLUMNS, error_rows(again)),
        "errata.md": errata_markdown(again),
    }
    for name, text in files.items():
        assert text.encode("utf-8") == (report_dir / name).read_bytes(), name


@pytest.fixture(scope="module")
def appendix(book: Book, catalog: Catalog) -> tuple[Evaluation, ScanResult]:
    """The evaluation and scan of the shortest chapter (Appendix 1.A: one figure)."""
    return evaluate_catalog(catalog, book, ["A1"]), scan(book, catalog, ("A1",))


def test_quoted_text_is_escaped(appendix: tuple[Evaluation, ScanResult], catalog: Catalog) -> None:
    evaluation, result = appendix
    hostile = "<script>alert(1)</script>"
    claims = tuple(
        dataclasses.replace(c, quote=hostile, quantity=hostile, verdict="erratum") if i == 0 else c
        for i, c in enumerate(evaluation)
    )
    spoilt = dataclasses.replace(evaluation, claims=claims)
    html = render_page(spoilt, result, catalog, None, figures=[])
    assert hostile not in html
    assert "&lt;script&gt;alert(1)&lt;/script&gt;" in html
    assert parse(html).scripts == 1  # the page's own small script, nothing else


INVARIANTS = {
    "date": "2026-11-22T00:00:00Z",
    "profile": "ci",
    "invariants": [
        {
            "name": "momentum",
            "law": "P is conserved",
            "reference": "(2.1)",
            "examples": 100,
            "worst_error": 1e-16,
            "outcome": "passed",
        }
    ],
}


def test_a_test_of_fixed_cases_is_shown_as_one_case_not_zero_examples() -> None:
    """A property test of fixed (parametrized) cases, not a Hypothesis ``@given``, is recorded
    with ``examples`` None: the page says "1 case", never 0 examples, as if nothing ran."""
    sampled = {"name": "momentum", "law": "P is conserved", "examples": 100, "outcome": "passed"}
    fixed = {**sampled, "name": "loop[-9.0-True]", "examples": None}
    record = {"date": "2026-11-22T00:00:00Z", "invariants": [sampled, fixed]}
    view = invariants_view(record)
    assert view is not None
    assert [row["examples"] for row in view["rows"]] == [100, "1 case"]


def test_the_report_finds_the_tests_record_from_the_working_directory_up(
    book: Book, tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """pytest records its invariants in ``.bangcheck/`` at its rootdir; ``bangcheck report``,
    run anywhere below, shows them without being told where, and writes nothing there."""
    record = write_properties(tmp_path, INVARIANTS)
    assert record == tmp_path / ".bangcheck" / "properties.json"
    assert (tmp_path / ".bangcheck" / ".gitignore").read_text(encoding="utf-8").endswith("*\n")
    (tmp_path / "sub" / "deeper").mkdir(parents=True)
    monkeypatch.chdir(tmp_path / "sub" / "deeper")
    assert default_properties_path() == record
    out = tmp_path / "out"
    assert main(["report", "--book", str(book.path), "--chapter", "0", "--out", str(out)]) == 0
    capsys.readouterr()
    assert "P is conserved" in (out / "index.html").read_text(encoding="utf-8")
    assert sorted(os.listdir(tmp_path / ".bangcheck")) == [".gitignore", "properties.json"]


def test_a_missing_record_given_by_name_is_a_clear_error(
    book: Book, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    argv = ["report", "--book", str(book.path), "--chapter", "0", "--out", str(tmp_path / "o")]
    assert main([*argv, "--properties", str(tmp_path / "typo.json")]) == 2
    assert capsys.readouterr().err == (
        f"bangcheck: error: --properties {tmp_path / 'typo.json'}: no such file\n"
    )


def test_an_unreadable_default_record_is_a_warning(
    book: Book, tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    (tmp_path / ".bangcheck").mkdir()
    (tmp_path / ".bangcheck" / "properties.json").write_text("{broken", encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    argv = ["report", "--book", str(book.path), "--chapter", "0", "--out", str(tmp_path / "o")]
    assert main(argv) == 0
    assert "warning: cannot read the invariants record" in capsys.readouterr().err


def test_a_record_that_is_not_one_is_a_clear_error(
    book: Book, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    bad = tmp_path / "properties.json"
    bad.write_text("{not json", encoding="utf-8")
    argv = ["report", "--book", str(book.path), "--chapter", "0", "--out", str(tmp_path / "o")]
    assert main([*argv, "--properties", str(bad)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert f"cannot read the invariants record {bad}" in err
    assert not (tmp_path / "o").exists()


def test_properties_are_shown_when_present(
    appendix: tuple[Evaluation, ScanResult], catalog: Catalog, tmp_path: Path
) -> None:
    evaluation, result = appendix
    results = {
        "date": "2026-11-22T00:00:00Z",
        "profile": "ci",
        "invariants": [
            {
                "name": "momentum",
                "law": "P is conserved",
                "reference": "(2.1)",
                "examples": 100,
                "worst_error": 1e-16,
                "outcome": "passed",
            }
        ],
    }
    path = tmp_path / "properties.json"
    path.write_text(json.dumps(results), encoding="utf-8")
    html = render_page(evaluation, result, catalog, read_properties(path), figures=[])
    assert 'id="properties"' in html
    assert "P is conserved" in html
    assert read_properties(tmp_path / "absent.json") is None
    absent = render_page(evaluation, result, catalog, None, figures=[])
    assert "P is conserved" not in absent
    assert 'id="no-invariants"' in absent  # says how to get them


def test_rounding_shows_its_reason(page: Page, report_dir: Path, evaluation: Evaluation) -> None:
    html = (report_dir / "index.html").read_text("utf-8")
    for c in evaluation:
        if c.verdict == "rounding":
            row = re.search(
                rf'<tr class="claim" data-verdict="rounding" data-search="[^"]*" '
                rf'id="claim-{re.escape(c.id)}">(.*?)</tr>',
                html,
                re.S,
            )
            assert row, c.id
            assert f"rounding ({c.rounding_reason})" in row.group(1)


def test_the_page_is_self_contained(report_dir: Path) -> None:
    html = (report_dir / "index.html").read_text("utf-8")
    assert not re.search(r"<(link|script|img|iframe)\b[^>]*\b(href|src)=", html)
    assert not re.search(
        r"""(src|href)=["']?(https?:)?//|url\(\s*["']?(https?:)?//|@import""", html
    )


def test_a_background_build_gives_the_same_files(
    appendix: tuple[Evaluation, ScanResult], catalog: Catalog
) -> None:
    """The report built in a forked process (as a serial test session builds it) is, byte for
    byte, the report built in place."""
    evaluation, result = appendix
    in_place = build_report(evaluation, result, catalog, None)
    pending = BackgroundReport(evaluation, result, catalog)
    assert pending.files() == in_place
    assert not pending.running
    assert '<figure id="figure-' in in_place["index.html"]


def _background_with(
    build: object,
    appendix: tuple[Evaluation, ScanResult],
    catalog: Catalog,
    monkeypatch: pytest.MonkeyPatch,
) -> BackgroundReport:
    """A background build whose forked child runs ``build`` in place of ``build_report`` (the
    child inherits the patched module)."""
    monkeypatch.setattr("reports.page.build_report", build)
    return BackgroundReport(*appendix, catalog)


def test_a_failed_background_build_raises_with_its_traceback(
    appendix: tuple[Evaluation, ScanResult], catalog: Catalog, monkeypatch: pytest.MonkeyPatch
) -> None:
    def spoilt(*args: object, **kwargs: object) -> dict[str, str]:
        raise ValueError("no figures today")

    pending = _background_with(spoilt, appendix, catalog, monkeypatch)
    for _ in range(2):  # and again: the error is kept
        with pytest.raises(BackgroundReportError, match=r"(?s)failed.*ValueError: no figures"):
            pending.files()


def test_a_background_process_that_dies_is_reported(
    appendix: tuple[Evaluation, ScanResult], catalog: Catalog, monkeypatch: pytest.MonkeyPatch
) -> None:
    pending = _background_with(lambda *a, **k: os._exit(3), appendix, catalog, monkeypatch)
    with pytest.raises(BackgroundReportError, match=r"ended \(exit code 3\) without sending"):
        pending.files()


def test_a_background_build_no_longer_needed_is_stopped(
    appendix: tuple[Evaluation, ScanResult], catalog: Catalog, monkeypatch: pytest.MonkeyPatch
) -> None:
    pending = _background_with(lambda *a, **k: time.sleep(60), appendix, catalog, monkeypatch)
    assert pending.running
    pending.stop()
    assert not pending.running


def test_a_failing_evaluation_starts_no_background_build(
    book: Book, monkeypatch: pytest.MonkeyPatch
) -> None:
    """When the catalog cannot be evaluated, the session starts nothing in the background and
    raises nothing at collection: the tests that read the evaluation fail with the reason."""
    from checks.plugins import caches, keys

    def broken(config: object) -> Evaluation:
        raise ValueError("a model raised")

    monkeypatch.setattr(caches, "evaluation_of", broken)
    config = types.SimpleNamespace(option=types.SimpleNamespace(collectonly=False), stash={})
    config.stash[keys.BOOK] = book
    reporting = types.SimpleNamespace(
        fixturenames=("report_dir",), get_closest_marker=lambda name: None
    )
    prop = types.SimpleNamespace(fixturenames=(), get_closest_marker=lambda name: name)
    session = types.SimpleNamespace(config=config, items=[reporting] + [prop] * 100)
    caches.start_report_in_background(cast(pytest.Session, session))  # a stand-in of the parts read
    assert keys.REPORT not in config.stash


def test_the_detection_power_section(report_dir: Path, evaluation: Evaluation) -> None:
    """The whole book's report shows the rate of each misprint class, the claims that let a
    last-digit misprint through with their reasons, and no banner while the targets hold."""
    html = (report_dir / "index.html").read_text("utf-8")
    power = evaluation.power()
    section = html[html.index('<section id="power">') : html.index('<section id="figures">')]
    for rate in power.classes:
        assert f'<td>{rate.cls}</td><td class="num">{rate.misprints}</td>' in section
    assert 'id="power-banner"' not in section
    through = {m.id for m in power.misses if m.cls == "last-digit"}
    assert through
    for ident in through:
        assert f'<a href="#claim-{ident}"><code>{ident}</code></a>' in section


def test_a_miss_without_a_reason_raises_the_banner(
    appendix: tuple[Evaluation, ScanResult], catalog: Catalog
) -> None:
    from reference.power import Misprint, Outcome

    evaluation, result = appendix
    ident = next(iter(evaluation.misprints))
    silent = Outcome(Misprint("sign", "-9"), "verified", None)
    spoilt = dataclasses.replace(evaluation, misprints={**evaluation.misprints, ident: [silent]})
    html = render_page(spoilt, result, catalog, None, figures=[])
    assert 'id="power-banner"' in html
    assert "the misprint -9" in html


def test_a_partial_run_is_marked_with_its_scope_and_age(
    appendix: tuple[Evaluation, ScanResult], catalog: Catalog
) -> None:
    """The invariants of a run that selected only some tests say so on the page, with the
    selection; every record says when it was made and how long before the report."""
    from datetime import UTC, datetime, timedelta

    from reports.views import invariants_view

    evaluation, result = appendix
    record = {
        **INVARIANTS,
        "date": (datetime.now(UTC) - timedelta(hours=5)).isoformat(timespec="seconds"),
        "scope": {"partial": True, "selection": "-k 'momentum'", "collected": 1},
    }
    html = render_page(evaluation, result, catalog, record, figures=[])
    assert 'id="partial-run"' in html
    assert "-k &#39;momentum&#39;" in html
    assert "5 hours before this report" in html
    whole = {**record, "scope": {"partial": False, "selection": "", "collected": 1}}
    assert 'id="partial-run"' not in render_page(evaluation, result, catalog, whole, figures=[])
    view = invariants_view(record, now=datetime.now(UTC) + timedelta(days=3))
    assert view is not None
    assert view["age"] == "3 days"


def test_the_recorder_says_what_a_run_selected(tmp_path: Path) -> None:
    from checks.plugins.invariants import InvariantRecorder

    def recorder(args: list[str], keyword: str = "", markexpr: str = "") -> InvariantRecorder:
        config = types.SimpleNamespace(
            option=types.SimpleNamespace(keyword=keyword, markexpr=markexpr),
            rootpath=tmp_path,
            args=args,
            getini=lambda name: ["checks"],
        )
        return InvariantRecorder(config)  # type: ignore[arg-type]

    assert recorder(["checks"]).scope() == {"partial": False, "selection": ""}
    assert recorder(["checks"], keyword="momentum").scope() == {
        "partial": True,
        "selection": "-k 'momentum'",
    }
    assert recorder(["checks/properties/test_towers.py"]).scope()["partial"]
    assert recorder(["checks"], markexpr="properties").scope()["selection"] == "-m 'properties'"
