"""Modules a maintainer can hold in mind: no Python file of the project over 600 lines (a topic
that grows past it becomes a package split along its physics, re-exporting what the catalog
names ``topic.function``)."""

from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).parents[1]
PACKAGES = ("mechmodel", "reference", "reports", "checks", "benchmarks")
MAX_LINES = 600

pytestmark = pytest.mark.integrity


def long_modules(root: Path, packages: tuple[str, ...] = PACKAGES) -> dict[str, int]:
    """Each Python file under ``packages`` longer than ``MAX_LINES``, with its line count."""
    sizes = {
        str(path.relative_to(root)): len(path.read_text(encoding="utf-8").splitlines())
        for package in packages
        for path in (root / package).rglob("*.py")
    }
    return {path: n for path, n in sorted(sizes.items()) if n > MAX_LINES}


def test_no_module_is_over_600_lines() -> None:
    assert long_modules(ROOT) == {}


def test_the_check_sees_a_long_module(tmp_path: Path) -> None:
    (tmp_path / "mechmodel" / "topic").mkdir(parents=True)
    (tmp_path / "mechmodel" / "topic" / "big.py").write_text("x = 1\n" * (MAX_LINES + 1))
    (tmp_path / "mechmodel" / "small.py").write_text("x = 1\n" * MAX_LINES)
    assert long_modules(tmp_path, ("mechmodel",)) == {"mechmodel/topic/big.py": MAX_LINES + 1}
