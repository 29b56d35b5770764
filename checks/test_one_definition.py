"""No public function or class of mechmodel is defined in two modules: the shared maths
(``algebra``, ``planar``, ``ellipse``, ``numeric``, ``exact``, ``inputs``, ``typing``) is defined
once and imported, and a topic
module re-exports what the catalog names ``topic.function``."""

from __future__ import annotations

import ast
from collections import defaultdict
from pathlib import Path

import pytest

ROOT = Path(__file__).parents[1]
pytestmark = pytest.mark.integrity


def _is_overload(node: ast.stmt) -> bool:
    """A ``@typing.overload`` signature: the function is defined by its implementation."""
    return isinstance(node, ast.FunctionDef) and any(
        (isinstance(d, ast.Name) and d.id == "overload")
        or (isinstance(d, ast.Attribute) and d.attr == "overload")
        for d in node.decorator_list
    )


def public_definitions(root: Path) -> dict[str, list[str]]:
    """Each public top-level def or class name under ``root`` (subpackages included) and the
    modules that define it, as dotted paths relative to ``root`` (an overloaded function once,
    by its implementation)."""
    where: dict[str, list[str]] = defaultdict(list)
    for path in sorted(root.rglob("*.py")):
        module = ".".join(path.relative_to(root).with_suffix("").parts)
        for node in ast.parse(path.read_text(encoding="utf-8")).body:
            if (
                isinstance(node, ast.FunctionDef | ast.ClassDef)
                and not node.name.startswith("_")
                and not _is_overload(node)
            ):
                where[node.name].append(module)
    return where


def test_no_public_name_is_defined_in_two_mechmodel_modules() -> None:
    where = public_definitions(ROOT / "mechmodel")
    assert {name: mods for name, mods in where.items() if len(mods) > 1} == {}


def test_the_check_sees_a_second_definition_in_a_subpackage(tmp_path: Path) -> None:
    (tmp_path / "one.py").write_text("def dot(u, v):\n    return 0\n", encoding="utf-8")
    (tmp_path / "topic").mkdir()
    (tmp_path / "topic" / "__init__.py").write_text("from one import dot\n", encoding="utf-8")
    (tmp_path / "topic" / "two.py").write_text("def dot(u, v):\n    return 1\n")
    assert public_definitions(tmp_path)["dot"] == ["one", "topic.two"]


def test_an_overloaded_function_is_one_definition(tmp_path: Path) -> None:
    (tmp_path / "one.py").write_text(
        "from typing import overload\n\n\n@overload\ndef f(x: int) -> int: ...\n"
        "@overload\ndef f(x: str) -> str: ...\ndef f(x):\n    return x\n",
        encoding="utf-8",
    )
    assert public_definitions(tmp_path)["f"] == ["one"]
