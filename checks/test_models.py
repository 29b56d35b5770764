"""Resolving a claim's ``model = "module.function"`` (reference.models.resolve)."""

from __future__ import annotations

import math
import sys
import types

import pytest

from reference.models import resolve

pytestmark = pytest.mark.integrity


def test_a_public_function_resolves() -> None:
    func = resolve("collisions.collide")
    assert func.__name__ == "collide"


@pytest.mark.parametrize(
    "name",
    ["collisions.dataclass", "operators.math", "bangs.dataclass", "collisions._nope", "nope.f"],
)
def test_an_imported_private_or_missing_name_is_no_model(name: str) -> None:
    with pytest.raises(LookupError, match="mechmodel"):
        resolve(name)


def test_a_shared_layer_function_resolves_through_its_topic() -> None:
    from mechmodel import numeric

    assert resolve("fields.line_angle") is numeric.line_angle


def test_a_module_with_all_exports_exactly_those(monkeypatch: pytest.MonkeyPatch) -> None:
    module = types.ModuleType("mechmodel.fake_topic")

    def own(x: float) -> float:
        return x

    def kept(x: float) -> float:
        return x

    for func in (own, kept):
        func.__module__ = module.__name__
        setattr(module, func.__name__, func)
    module.hypot = math.hypot  # type: ignore[attr-defined]
    module.__all__ = ["hypot", "kept"]  # type: ignore[attr-defined]
    monkeypatch.setitem(sys.modules, "mechmodel.fake_topic", module)
    assert resolve("fake_topic.hypot") is math.hypot  # re-exported on purpose
    assert resolve("fake_topic.kept") is kept
    with pytest.raises(LookupError):
        resolve("fake_topic.own")  # defined there, but not in __all__
