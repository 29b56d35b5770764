"""No public function or class of mechmodel is defined in two modules: the shared maths
(``algebra``, ``planar``, ``ellipse``, ``numeric``) is defined once and imported, and a topic
module re-exports what the catalog names ``topic.function``."""

from __future__ import annotations

import ast
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).parents[1]


def _is_overload(node: ast.stmt) -> bool:
    """A ``@typing.overload`` signature: the function is defined by its implementation."""
    return isinstance(node, ast.FunctionDef) and any(
        (isinstance(d, ast.Name) and d.id == "overload")
        or (isinstance(d, ast.Attribute) and d.attr == "overload")
        for d in node.decorator_list
    )


def public_definitions(paths: list[Path]) -> dict[str, list[str]]:
    """Each public top-level def or class name and the modules that define it (an overloaded
    function once, by its implementation)."""
    where: dict[str, list[str]] = defaultdict(list)
    for path in sorted(paths):
        for node in ast.parse(path.read_text(encoding="utf-8")).body:
            if (
                isinstance(node, ast.FunctionDef | ast.ClassDef)
                and not node.name.startswith("_")
                and not _is_overload(node)
            ):
                where[node.name].append(path.stem)
    return where


def test_no_public_name_is_defined_in_two_mechmodel_modules() -> None:
    where = public_definitions(list((ROOT / "mechmodel").glob("*.py")))
    assert {name: mods for name, mods in where.items() if len(mods) > 1} == {}


def test_the_check_sees_a_second_definition(tmp_path: Path) -> None:
    (tmp_path / "one.py").write_text("def dot(u, v):\n    return 0\n", encoding="utf-8")
    (tmp_path / "two.py").write_text("from one import dot\n\n\ndef dot(u, v):\n    return 1\n")
    assert public_definitions(list(tmp_path.glob("*.py")))["dot"] == ["one", "two"]


def test_an_overloaded_function_is_one_definition(tmp_path: Path) -> None:
    (tmp_path / "one.py").write_text(
        "from typing import overload\n\n\n@overload\ndef f(x: int) -> int: ...\n"
        "@overload\ndef f(x: str) -> str: ...\ndef f(x):\n    return x\n",
        encoding="utf-8",
    )
    assert public_definitions(list(tmp_path.glob("*.py")))["f"] == ["one"]
