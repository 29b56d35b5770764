"""The layering of design section 1: mechmodel imports nothing of ours, reads no files;
reference does not import reports or checks; reports does not import checks."""

from __future__ import annotations

import ast
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).parents[1]
pytestmark = pytest.mark.integrity
OURS = {"mechmodel", "reference", "reports", "checks", "conftest"}
FORBIDDEN = {
    "mechmodel": {"reference", "reports", "checks", "conftest"},
    "reference": {"reports", "checks", "conftest"},
    "reports": {"checks", "conftest"},
}
MECHMODEL_MAY_IMPORT = set(sys.stdlib_module_names) | {
    "numpy",
    "scipy",
    "mpmath",
    "sympy",
    "mechmodel",
}
FILE_CALLS = {"open", "read_text", "read_bytes", "loadtxt", "genfromtxt", "load", "files"}


def imports(path: Path) -> set[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found |= {alias.name.split(".")[0] for alias in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
            found.add(node.module.split(".")[0])
    return found


@pytest.mark.parametrize("package", sorted(FORBIDDEN))
def test_no_forbidden_imports(package: str) -> None:
    bad = {
        (path.name, name)
        for path in (ROOT / package).rglob("*.py")
        for name in imports(path) & FORBIDDEN[package]
    }
    assert not bad


def test_mechmodel_imports_only_the_standard_library_and_numerics() -> None:
    bad = {
        (path.name, name)
        for path in (ROOT / "mechmodel").rglob("*.py")
        for name in imports(path) - MECHMODEL_MAY_IMPORT
    }
    assert not bad


def test_mechmodel_reads_no_files() -> None:
    calls = set()
    for path in (ROOT / "mechmodel").rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Call):
                func = node.func
                name = func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", "")
                if name in FILE_CALLS:
                    calls.add((path.name, name))
    assert not calls


def test_the_layering_test_sees_a_violation(tmp_path: Path) -> None:
    bad = tmp_path / "bad.py"
    bad.write_text("from reference.tables import units\nimport reports.cli\n", encoding="utf-8")
    assert imports(bad) & FORBIDDEN["mechmodel"] == {"reference", "reports"}
