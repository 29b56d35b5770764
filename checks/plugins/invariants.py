"""A pytest plugin that records what the property suite checked, for the report.

For every test marked ``properties`` it records the invariant (the test's name), the law (its
docstring's first paragraph), the book's equations and figures the docstring cites, how many
examples ran (None for a test of fixed cases, not a Hypothesis ``@given``), the worst value of
any ``hypothesis.target`` score (the suite targets its conservation errors there) and the
outcome. At the end of the session the controller (not an xdist worker) writes
``.bangcheck/properties.json`` in pytest's rootdir (``reports.invariants``), which ``bangcheck
report`` shows with its date. Examples and scores come from the run statistics Hypothesis hands
over once per test (``checks.plugins.hypothesis_api.collecting``; the same ones its pytest plugin
prints with ``--hypothesis-show-statistics``); they cost nothing per example.
"""

from __future__ import annotations

import inspect
import re
from collections.abc import Generator
from datetime import UTC, datetime
from typing import Any

import pytest
from hypothesis import is_hypothesis_test, settings

from checks.plugins.hypothesis_api import collecting
from reports.invariants import write_properties

_REFERENCE = re.compile(r"\((?:\d+|1\.A)\.\d+[a-z]?\)|Figs?\. \d+\.\d+(?:\([a-z]\)|[a-z])?")
_KEY = "bangcheck-invariant"


def _law(doc: str | None) -> str:
    first = (doc or "").strip().split("\n\n")[0]
    return " ".join(first.split())


class _Statistics:
    """Receives a test's run statistics: the valid examples and the worst target score."""

    def __init__(self) -> None:
        self.examples = 0
        self.worst: float | None = None

    def __call__(self, stats: dict[str, Any]) -> None:
        for phase, data in stats.items():
            if phase.endswith("-phase") and isinstance(data, dict):
                cases = data.get("test-cases", [])
                self.examples += sum(case.get("status") == "valid" for case in cases)
        scores = [v for v in stats.get("targets", {}).values() if isinstance(v, int | float)]
        if scores:
            self.worst = max(scores)


class InvariantRecorder:
    """The plugin: register one per session with ``config.pluginmanager.register``."""

    def __init__(self, config: pytest.Config) -> None:
        self.config = config
        self.records: list[dict[str, Any]] = []
        self.deselected = 0

    def pytest_deselected(self, items: list[pytest.Item]) -> None:
        self.deselected += len(items)

    def scope(self) -> dict[str, Any]:
        """Whether the run was the whole suite or a selection, and which: test paths other
        than the configured ``testpaths``, ``-k``, ``-m``, deselected tests."""
        option = self.config.option
        root = self.config.rootpath
        default = {(root / p).resolve() for p in self.config.getini("testpaths")}
        paths = [a for a in self.config.args if (root / a.split("::")[0]).resolve() not in default]
        parts = [f"paths {' '.join(paths)}"] if paths else []
        if getattr(option, "keyword", ""):
            parts.append(f"-k {option.keyword!r}")
        if getattr(option, "markexpr", ""):
            parts.append(f"-m {option.markexpr!r}")
        if self.deselected:
            parts.append(f"{self.deselected} tests deselected")
        return {"partial": bool(parts), "selection": "; ".join(parts)}

    @pytest.hookimpl(wrapper=True, trylast=True)  # inside Hypothesis's own wrapper
    def pytest_runtest_call(self, item: pytest.Item) -> Generator[None]:
        if item.get_closest_marker("properties") is None:
            return (yield)
        observer = _Statistics()
        try:
            with collecting(observer):
                return (yield)
        finally:
            function = getattr(item, "function", None)
            doc = inspect.getdoc(function) if function else None
            item.user_properties.append(
                (
                    _KEY,
                    {
                        "name": item.name,
                        "module": getattr(getattr(item, "module", None), "__name__", ""),
                        "law": _law(doc),
                        "reference": ", ".join(dict.fromkeys(_REFERENCE.findall(doc or ""))),
                        "examples": (
                            observer.examples
                            if function is not None and is_hypothesis_test(function)
                            else None
                        ),
                        "worst_error": observer.worst,
                    },
                )
            )

    def pytest_runtest_logreport(self, report: pytest.TestReport) -> None:
        if report.when != "call":
            return
        for key, value in report.user_properties:
            if key == _KEY and isinstance(value, dict):  # the record written above
                self.records.append({**value, "outcome": report.outcome})

    def pytest_sessionfinish(self, session: pytest.Session) -> None:
        if hasattr(self.config, "workerinput") or not self.records:
            return  # an xdist worker, or no property ran: the controller writes, once
        data = {
            "date": datetime.now(UTC).isoformat(timespec="seconds"),
            "profile": settings.get_current_profile_name(),
            "scope": {**self.scope(), "collected": len(self.records)},
            "invariants": sorted(self.records, key=lambda r: (r["module"], r["name"])),
        }
        write_properties(self.config.rootpath, data)
