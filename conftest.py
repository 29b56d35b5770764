"""pytest driver for bangcheck: the book option, hypothesis profiles, the catalog at collection,
and the verdict summary.

- ``--book PATH`` (else ``$BANGCHECK_BOOK``). Without a book, tests that read it skip with the
  reason; under ``CI=true`` or when a path is given, a missing or wrong book is an error.
- ``--catalog DIR``: a directory of draft ``chNN.toml`` files instead of the packaged catalog,
  as for the ``bangcheck`` command.
- The catalog is read and validated once, as collection starts (under xdist the controller
  does it while the workers start); an invalid catalog stops the run with one line per problem
  (file, claim id, field), a usage error, with or without a book.
- Hypothesis profiles ``ci`` (the default when ``CI=true``), ``dev`` (the default otherwise) and
  ``thorough``; choose with ``--hypothesis-profile``.
- The terminal summary ends with the verdict counts, just before pytest's final line.
- The property tests' invariants are recorded in ``.bangcheck/properties.json`` at the rootdir
  for the report (``checks/properties/recorder.py``).
- The garbage collector runs less often, and what lives for the whole session is frozen out of
  its reach once collected and once evaluated (the property tests' allocations otherwise cost
  seconds of full collections).
"""

from __future__ import annotations

import gc
import os
from collections import Counter
from collections.abc import Generator
from pathlib import Path
from typing import Any

import pytest
from hypothesis import settings

from checks.properties.recorder import InvariantRecorder
from reference.book import Book, BookError, book_path, load_book
from reference.catalog import Catalog, CatalogDirectoryError
from reference.compare import VERDICTS
from reference.evaluation import Evaluation, evaluate_catalog
from reference.scan import ScanResult, scan
from reference.schema import CatalogError
from reference.validate import checked_catalog
from reports.background import BackgroundReport
from reports.errata_sheet import verdict_summary

IN_CI = os.environ.get("CI", "").lower() == "true"
MIN_EXAMPLES = 50  # the ci profile's floor: speed never hollows a property out

# ci: derandomized and without the example database, whose reads and writes cost more than
# the examples of most properties
settings.register_profile(
    "ci", derandomize=True, deadline=None, max_examples=MIN_EXAMPLES, database=None
)
settings.register_profile("dev", deadline=None, max_examples=MIN_EXAMPLES)
settings.register_profile("thorough", deadline=None, max_examples=MIN_EXAMPLES * 10)
settings.load_profile("ci" if IN_CI else "dev")

_BOOK = pytest.StashKey[Book | None]()
_NO_BOOK = pytest.StashKey[str]()
_CATALOG = pytest.StashKey[Catalog]()
_EVALUATION = pytest.StashKey[Evaluation]()
_SCAN = pytest.StashKey[ScanResult]()
_REPORT = pytest.StashKey[BackgroundReport]()
_WORKER_VERDICTS = pytest.StashKey[Counter[str]]()
_SELECTED = pytest.StashKey[set[str]]()  # the claims whose tests this session runs
_WORKER_ERRORS = pytest.StashKey[int | None]()
_VERDICTS_KEY = "bangcheck_verdicts"  # in an xdist worker's workeroutput
_ERRORS_KEY = "bangcheck_errors"


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption(
        "--book", action="store", default=None, help="path of bang-unit1.txt ($BANGCHECK_BOOK)"
    )
    parser.addoption(
        "--catalog",
        action="store",
        default=None,
        type=Path,
        help="a directory of draft chNN.toml catalog files instead of the packaged catalog",
    )


def _load_book(config: pytest.Config) -> Book | None:
    given = config.getoption("--book") or os.environ.get("BANGCHECK_BOOK")
    if not given:
        reason = "no book given: pass --book PATH or set BANGCHECK_BOOK"
        if IN_CI:
            raise pytest.UsageError(f"CI=true but {reason}")
        config.stash[_NO_BOOK] = reason
        return None
    try:
        return load_book(book_path(given))
    except BookError as err:
        raise pytest.UsageError(str(err)) from err


def pytest_configure(config: pytest.Config) -> None:
    gc.set_threshold(*_GC_THRESHOLDS)
    config.pluginmanager.register(InvariantRecorder(config), "bangcheck-invariants")
    config.stash[_BOOK] = _load_book(config)


@pytest.hookimpl(tryfirst=True)
def pytest_collection(session: pytest.Session) -> None:
    """Read and validate the catalog before anything is collected; an invalid one stops the
    run. Under xdist the controller, which collects nothing itself, does this while its workers
    start, and a problem is reported by it, once, before any worker runs a test."""
    config = session.config
    try:
        config.stash[_CATALOG] = checked_catalog(config.stash[_BOOK], config.getoption("--catalog"))
    except CatalogDirectoryError as err:
        raise pytest.UsageError(str(err)) from err
    except CatalogError as err:
        raise pytest.UsageError(f"the catalog is invalid:\n{err}") from err


def catalog_of(config: pytest.Config) -> Catalog:
    """The validated catalog (read as collection starts)."""
    return config.stash[_CATALOG]


def evaluation_of(config: pytest.Config) -> Evaluation | None:
    """The run's evaluation, computed once per process; None without a book."""
    book = config.stash.get(_BOOK, None)
    if book is None:
        return None
    if _EVALUATION not in config.stash:
        config.stash[_EVALUATION] = evaluate_catalog(catalog_of(config), book)
        _freeze_long_lived()
    return config.stash[_EVALUATION]


# The property tests allocate millions of short-lived objects (Hypothesis's draws): with
# CPython's default thresholds (700, 10, 10) the collector ran 4,600 times in a serial run, 2.2 s,
# most of it full collections re-scanning what lives for the whole session. Rarer young
# collections and a frozen session heap cut that to about 0.9 s.
_GC_THRESHOLDS = (20_000, 20, 10)


def _freeze_long_lived() -> None:
    """Move what lives for the whole session (book, catalog, items, evaluation) out of the
    garbage collector's reach, so that no full collection scans it again."""
    gc.collect()
    gc.freeze()


def pytest_collection_finish(session: pytest.Session) -> None:
    session.config.stash[_SELECTED] = {
        item.callspec.params["claim_id"]
        for item in session.items
        if "claim_id" in getattr(getattr(item, "callspec", None), "params", {})
    }
    _start_report_in_background(session)
    _freeze_long_lived()


# about 5 s of property tests (the suite has 414), as long as the report takes on one core
_HIDING_PROPERTIES = 100


def _start_report_in_background(session: pytest.Session) -> None:
    """In a serial run with tests of the whole report and at least ``_HIDING_PROPERTIES``
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
        or config.stash.get(_BOOK, None) is None
    ):
        return
    items = session.items
    if not (
        any("report_dir" in getattr(item, "fixturenames", ()) for item in items)
        and sum(item.get_closest_marker("properties") is not None for item in items)
        >= _HIDING_PROPERTIES
        and BackgroundReport.available()
    ):
        return
    try:
        evaluation = evaluation_of(config)
        result = scan_of(config)
    except Exception:  # the tests that read them fail with the reason instead
        return
    assert evaluation is not None
    config.stash[_REPORT] = BackgroundReport(evaluation, result, catalog_of(config))


def pytest_unconfigure(config: pytest.Config) -> None:
    """A background report build still running (the session ended early) is stopped."""
    pending = config.stash.get(_REPORT, None)
    if pending is not None:
        pending.stop()


@pytest.fixture(scope="session")
def book(pytestconfig: pytest.Config) -> Book:
    """The verified book; skips (outside CI) when no book was given."""
    the_book = pytestconfig.stash.get(_BOOK, None)
    if the_book is None:
        pytest.skip(pytestconfig.stash.get(_NO_BOOK, "no book"))
    return the_book


@pytest.fixture(scope="session")
def catalog(pytestconfig: pytest.Config) -> Catalog:
    """The packaged catalog, validated against the book when there is one."""
    return catalog_of(pytestconfig)


@pytest.fixture(scope="session")
def evaluation(pytestconfig: pytest.Config, book: Book) -> Evaluation:
    """Every claim evaluated once for the session."""
    result = evaluation_of(pytestconfig)
    assert result is not None
    return result


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

    pending = pytestconfig.stash.get(_REPORT, None)
    if pending is not None:
        files = pending.files()
    else:
        files = build_report(evaluation, whole_scan, evaluation.catalog, None)
    out = tmp_path_factory.mktemp("report") / "out"
    write_report_dir(out, files)
    return out


def scan_of(config: pytest.Config) -> ScanResult:
    """The scan of the whole book, computed once per process (a book is needed)."""
    if _SCAN not in config.stash:
        book = config.stash[_BOOK]
        assert book is not None
        chapters = tuple(c.key for c in book.identity.chapters)
        config.stash[_SCAN] = scan(book, catalog_of(config), chapters)
    return config.stash[_SCAN]


@pytest.fixture(scope="session")
def whole_scan(pytestconfig: pytest.Config, book: Book) -> ScanResult:
    """The scan of the whole book, once per session."""
    del book  # skips without one
    return scan_of(pytestconfig)


def _selected_counts(config: pytest.Config) -> tuple[Counter[str], int] | None:
    """Verdict counts and distinct errors of the claims whose tests this session selected
    (all of them, or those ``-k`` kept); None when it selected no claim test."""
    selected = config.stash.get(_SELECTED, set())
    if not selected:
        return None
    evaluation = evaluation_of(config)
    if evaluation is None:
        return None
    counts = Counter(c.verdict for c in evaluation if c.id in selected)
    errors = [e for e in evaluation.errors() if any(c.id in selected for c in e.claims)]
    return counts, len(errors)


def pytest_sessionfinish(session: pytest.Session) -> None:
    """An xdist worker that evaluated the catalog hands its verdict counts (of the selected
    claims) to the controller."""
    output = getattr(session.config, "workeroutput", None)
    if output is not None and _EVALUATION in session.config.stash:
        found = _selected_counts(session.config)
        if found is not None:
            output[_VERDICTS_KEY] = dict(found[0])
            output[_ERRORS_KEY] = found[1]


@pytest.hookimpl(optionalhook=True)
def pytest_testnodedown(node: Any, error: object) -> None:
    """The controller keeps the first verdict counts a worker sends (all workers evaluate the
    same catalog against the same book), so it need not evaluate the catalog once more."""
    del error
    output = getattr(node, "workeroutput", {})
    counts = output.get(_VERDICTS_KEY)
    if counts is not None and _WORKER_VERDICTS not in node.config.stash:
        node.config.stash[_WORKER_VERDICTS] = Counter(counts)
        node.config.stash[_WORKER_ERRORS] = output.get(_ERRORS_KEY)


@pytest.hookimpl(wrapper=True, tryfirst=True)
def pytest_terminal_summary(
    terminalreporter: Any, exitstatus: int, config: pytest.Config
) -> Generator[None]:
    result = yield
    counts = config.stash.get(_WORKER_VERDICTS, None)
    if counts is None and _CATALOG not in config.stash:
        return result  # the catalog was refused at collection: the usage error says why
    errors = config.stash.get(_WORKER_ERRORS, None)
    if counts is None and not hasattr(config, "workerinput"):
        found = _selected_counts(config)
        if found is not None:
            counts, errors = found
    if counts is not None:
        shown = verdict_summary(((v, counts[v]) for v in VERDICTS), errors)
        total = sum(counts.values())
        everything = sum(1 for _ in catalog_of(config).claims())
        of = "" if total == everything else f" (selected of {everything})"
        terminalreporter.write_line(f"bangcheck verdicts: {total} claims{of}: {shown}")
    return result


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """The floor on examples: no property may ask for fewer than ``MIN_EXAMPLES``."""
    del config
    low = []
    for item in items:
        use = getattr(getattr(item, "obj", None), "_hypothesis_internal_use_settings", None)
        marked = item.get_closest_marker("properties") is not None
        if marked and use is not None and use.max_examples < MIN_EXAMPLES:
            low.append(f"{item.nodeid}: max_examples={use.max_examples}")
    if low:
        raise pytest.UsageError(
            f"properties below the floor of {MIN_EXAMPLES} examples:\n" + "\n".join(low)
        )


def pytest_generate_tests(metafunc: pytest.Metafunc) -> None:
    """One test per catalogued claim, its id the claim id."""
    if "claim_id" in metafunc.fixturenames:
        ids = [claim.id for _, claim in catalog_of(metafunc.config).claims()]
        metafunc.parametrize("claim_id", ids, ids=ids)
