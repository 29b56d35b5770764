"""The verdict counts at the end of the terminal summary, just before pytest's final line: of
the claims whose tests the session selected (all, or those ``-k`` kept), with the number of
distinct errors; under xdist a worker hands its counts to the controller."""

from __future__ import annotations

from collections import Counter
from collections.abc import Generator
from typing import Any

import pytest

from checks.plugins import keys
from checks.plugins.book_catalog import catalog_of
from checks.plugins.caches import evaluation_of
from reference.compare import VERDICTS
from reports.errata_sheet import verdict_summary

_VERDICTS_KEY = "bangcheck_verdicts"  # in an xdist worker's workeroutput
_ERRORS_KEY = "bangcheck_errors"


def pytest_collection_finish(session: pytest.Session) -> None:
    ids = (
        item.callspec.params.get("claim_id")
        for item in session.items
        if isinstance(item, pytest.Function) and hasattr(item, "callspec")  # parametrized only
    )
    session.config.stash[keys.SELECTED] = {i for i in ids if isinstance(i, str)}


def _selected_counts(config: pytest.Config) -> tuple[Counter[str], int] | None:
    """Verdict counts and distinct errors of the claims whose tests this session selected;
    None when it selected no claim test."""
    selected = config.stash.get(keys.SELECTED, set())
    if not selected:
        return None
    evaluation = evaluation_of(config)
    if evaluation is None:
        return None
    counts: Counter[str] = Counter(c.verdict for c in evaluation if c.id in selected)
    errors = [e for e in evaluation.errors() if any(c.id in selected for c in e.claims)]
    return counts, len(errors)


def pytest_sessionfinish(session: pytest.Session) -> None:
    """An xdist worker that evaluated the catalog hands its verdict counts (of the selected
    claims) to the controller."""
    output = getattr(session.config, "workeroutput", None)
    if output is not None and keys.EVALUATION in session.config.stash:
        found = _selected_counts(session.config)
        if found is not None:
            output[_VERDICTS_KEY] = dict(found[0])
            output[_ERRORS_KEY] = found[1]


@pytest.hookimpl(optionalhook=True)
def pytest_testnodedown(node: Any, error: object) -> None:  # node: xdist's WorkerController
    """The controller keeps the first verdict counts a worker sends (all workers evaluate the
    same catalog against the same book), so it need not evaluate the catalog once more."""
    del error
    output = getattr(node, "workeroutput", {})
    counts = output.get(_VERDICTS_KEY)
    if counts is not None and keys.WORKER_VERDICTS not in node.config.stash:
        node.config.stash[keys.WORKER_VERDICTS] = Counter(counts)
        node.config.stash[keys.WORKER_ERRORS] = output.get(_ERRORS_KEY)


@pytest.hookimpl(wrapper=True, tryfirst=True)
def pytest_terminal_summary(
    terminalreporter: pytest.TerminalReporter, exitstatus: int, config: pytest.Config
) -> Generator[None]:
    result = yield
    if config.option.collectonly:
        return result  # nothing was judged (and evaluating the catalog to say so takes seconds)
    counts = config.stash.get(keys.WORKER_VERDICTS, None)
    if counts is None and keys.CATALOG not in config.stash:
        return result  # the catalog was refused at collection: the usage error says why
    errors = config.stash.get(keys.WORKER_ERRORS, None)
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
