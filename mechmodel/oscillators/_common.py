"""Exact arithmetic shared by the oscillator modules: a ratio that stays a ``Fraction`` for
rational inputs, and the check of an ellipse's semi-axes a, b > 0 (chapter 11)."""

from __future__ import annotations

from fractions import Fraction
from typing import Any

from mechmodel import inputs


def all_rational(*values: Any) -> bool:
    """Whether every value is an ``int`` or a ``Fraction``."""
    return all(isinstance(v, int | Fraction) for v in values)


def exact_div(x: Any, y: Any) -> Any:
    """x/y, exact when both are rational."""
    return Fraction(x) / Fraction(y) if all_rational(x, y) else x / y


def check_semi_axes(a: Any, b: Any) -> None:
    """``ValueError`` unless the semi-axes a and b are positive numbers."""
    inputs.positive(a, "a")
    inputs.positive(b, "b")
