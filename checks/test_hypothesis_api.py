"""The Hypothesis internals behind ``checks/plugins/hypothesis_api.py`` still work: if an
upgrade moves them, these fail and say what to update, instead of the floor on examples
silently letting a thin property pass or the report recording no examples."""

from __future__ import annotations

from typing import Any

import pytest
from hypothesis import given, settings, target
from hypothesis import strategies as st

from checks.plugins.hypothesis_api import collecting, settings_of

pytestmark = pytest.mark.integrity


def test_the_settings_of_a_property_are_read() -> None:
    @settings(max_examples=7, database=None)
    @given(st.integers())
    def thin(n: int) -> None:
        del n

    def plain() -> None:
        pass

    found = settings_of(thin)
    assert found is not None
    assert found.max_examples == 7
    assert settings_of(plain) is None
    assert settings_of(None) is None


def test_the_run_statistics_of_a_property_are_collected() -> None:
    seen: list[dict[str, Any]] = []

    @settings(max_examples=60, database=None, derandomize=True)
    @given(st.integers(min_value=0, max_value=10**6))
    def scored(n: int) -> None:
        target(float(n % 97), label="error")

    with collecting(seen.append):
        scored()
    assert len(seen) == 1
    stats = seen[0]
    valid = sum(
        case.get("status") == "valid"
        for phase, data in stats.items()
        if phase.endswith("-phase") and isinstance(data, dict)
        for case in data.get("test-cases", [])
    )
    assert valid >= 60
    assert 0 < stats["targets"]["error"] <= 96
