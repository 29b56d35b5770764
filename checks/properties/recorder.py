"""A pytest plugin that records what the property suite checked, for the report.

For every test marked ``properties`` it records the invariant (the test's name), the law (its
docstring's first paragraph), the book's equations and figures the docstring cites, how many
examples ran, the worst value of any ``hypothesis.target`` score (the suite targets its
conservation errors there) and the outcome. At the end of the session the controller (not an
xdist worker) writes ``reports/out/properties.json``, which ``bangcheck report`` shows with its
date. Examples and scores come from Hypothesis's observability callbacks (hypothesis >= 6.137).
"""

from __future__ import annotations

import inspect
import json
import re
from collections.abc import Generator
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

import pytest
from hypothesis import settings

from hypothesis.internal import observability
from hypothesis.internal.observability import (
    add_observability_callback,
    remove_observability_callback,
)

# Observations need no line coverage here, and collecting it slows every example severalfold.
observability.OBSERVABILITY_COLLECT_COVERAGE = False

OUTPUT = Path("reports") / "out" / "properties.json"
_REFERENCE = re.compile(r"\((?:\d+|1\.A)\.\d+[a-z]?\)|Figs?\. \d+\.\d+(?:\([a-z]\)|[a-z])?")
_KEY = "bangcheck-invariant"


def _law(doc: str | None) -> str:
    first = (doc or "").strip().split("\n\n")[0]
    return " ".join(first.split())


class _Observer:
    """Counts the passing examples of one test and keeps its worst target score."""

    def __init__(self) -> None:
        self.examples = 0
        self.worst: float | None = None

    def __call__(self, observation: Any) -> None:
        if getattr(observation, "type", None) != "test_case":
            return
        if observation.status == "passed":
            self.examples += 1
        for name, value in (observation.features or {}).items():
            if name.startswith("target:") and isinstance(value, int | float):
                self.worst = value if self.worst is None else max(self.worst, value)


class InvariantRecorder:
    """The plugin: register one per session with ``config.pluginmanager.register``."""

    def __init__(self, config: pytest.Config) -> None:
        self.config = config
        self.records: list[dict[str, Any]] = []

    @pytest.hookimpl(wrapper=True)
    def pytest_runtest_call(self, item: pytest.Item) -> Generator[None]:
        if item.get_closest_marker("properties") is None:
            return (yield)
        observer = _Observer()
        add_observability_callback(observer)
        try:
            return (yield)
        finally:
            remove_observability_callback(observer)
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
                        "examples": observer.examples,
                        "worst_error": observer.worst,
                    },
                )
            )

    def pytest_runtest_logreport(self, report: pytest.TestReport) -> None:
        if report.when != "call":
            return
        for key, value in report.user_properties:
            if key == _KEY:
                self.records.append({**value, "outcome": report.outcome})

    def pytest_sessionfinish(self, session: pytest.Session) -> None:
        if hasattr(self.config, "workerinput") or not self.records:
            return  # an xdist worker, or no property ran: the controller writes, once
        path = self.config.rootpath / OUTPUT
        path.parent.mkdir(parents=True, exist_ok=True)
        data = {
            "date": datetime.now(UTC).isoformat(timespec="seconds"),
            "profile": settings.get_current_profile_name(),
            "invariants": sorted(self.records, key=lambda r: (r["module"], r["name"])),
        }
        path.write_text(json.dumps(data, indent=1) + "\n", encoding="utf-8")
