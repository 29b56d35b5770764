"""What the session computes once: the evaluation of every claim, the scan of the whole book,
and one report of the whole book (built in the background on the core a serial run leaves
idle, when it will be needed)."""

from __future__ import annotations

from pathlib import Path

import pytest

from checks.plugins import keys
from checks.plugins.book_catalog import catalog_of
from checks.plugins.speed import freeze_long_lived
from reference.book import Book
from reference.evaluation import Evaluation, evaluate_catalog
from reference.scan import ScanResult, scan
from reports.background import BackgroundReport

# about 5 s of property tests (the suite has over 400), as long as the report takes on one core
HIDING_PROPERTIES = 100


def evaluation_of(config: pytest.Config) -> Evaluation | None:
    """The run's evaluation, computed once per process; None without a book."""
    book = config.stash.get(keys.BOOK, None)
    if book is None:
        return None
    if keys.EVALUATION not in config.stash:
        config.stash[keys.EVALUATION] = evaluate_catalog(catalog_of(config), book)
        freeze_long_lived()
    return config.stash[keys.EVALUATION]


def scan_of(config: pytest.Config) -> ScanResult:
    """The scan of the whole book, computed once per process (a book is needed)."""
    if keys.SCAN not in config.stash:
        book = config.stash[keys.BOOK]
        assert book is not None
        chapters = tuple(c.key for c in book.identity.chapters)
        config.stash[keys.SCAN] = scan(book, catalog_of(config), chapters)
    return config.stash[keys.SCAN]


def pytest_collection_finish(session: pytest.Session) -> None:
    start_report_in_background(session)
    freeze_long_lived()


def start_report_in_background(session: pytest.Session) -> None:
    """In a serial run with tests of the whole report and at least ``HIDING_PROPERTIES``
    property tests, start building the whole report in a forked process now, on the core the
    tests leave idle; the report and browser tests, which run after the property suite, then
    collect it. Not under xdist: there both cores are busy, and a worker does not know whether
    it will get the report tests. With fewer property tests to hide behind, the report is
    built when first needed, its figures drawn on every core. Should the catalog's evaluation
    or the scan fail, nothing starts: the tests that need them fail with the reason."""
    config = session.config
    if (
        config.option.collectonly
        or hasattr(config, "workerinput")
        or config.stash.get(keys.BOOK, None) is None
    ):
        return
    items = session.items
    if not (
        any("report_dir" in getattr(item, "fixturenames", ()) for item in items)
        and sum(item.get_closest_marker("properties") is not None for item in items)
        >= HIDING_PROPERTIES
        and BackgroundReport.available()
    ):
        return
    try:
        evaluation = evaluation_of(config)
        result = scan_of(config)
    except Exception:  # the tests that read them fail with the reason instead
        return
    assert evaluation is not None
    config.stash[keys.REPORT] = BackgroundReport(evaluation, result, catalog_of(config))


def pytest_unconfigure(config: pytest.Config) -> None:
    """A background report build still running (the session ended early) is stopped."""
    pending = config.stash.get(keys.REPORT, None)
    if pending is not None:
        pending.stop()


@pytest.fixture(scope="session")
def evaluation(pytestconfig: pytest.Config, book: Book) -> Evaluation:
    """Every claim evaluated once for the session."""
    del book  # skips without one
    result = evaluation_of(pytestconfig)
    assert result is not None
    return result


@pytest.fixture(scope="session")
def whole_scan(pytestconfig: pytest.Config, book: Book) -> ScanResult:
    """The scan of the whole book, once per session."""
    del book  # skips without one
    return scan_of(pytestconfig)


@pytest.fixture(scope="session")
def report_dir(
    pytestconfig: pytest.Config,
    tmp_path_factory: pytest.TempPathFactory,
    evaluation: Evaluation,
    whole_scan: ScanResult,
) -> Path:
    """One report of the whole book, built once per session from the session's evaluation for
    the report and browser tests (the command itself is tested on one chapter): collected from
    the background build if the session started one, else built now."""
    from reports.outdir import write_report_dir
    from reports.page import build_report

    pending = pytestconfig.stash.get(keys.REPORT, None)
    if pending is not None:
        files = pending.files()
    else:
        files = build_report(evaluation, whole_scan, evaluation.catalog, None)
    out = tmp_path_factory.mktemp("report") / "out"
    write_report_dir(out, files)
    return out
