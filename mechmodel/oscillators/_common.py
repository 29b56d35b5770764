"""Exact arithmetic shared by the oscillator modules: a ratio that stays a ``Fraction`` for
rational inputs, and the check of an ellipse's semi-axes a, b > 0 (chapter 11)."""

from __future__ import annotations

from fractions import Fraction

from mechmodel import inputs
from mechmodel.typing import Real


def all_rational(*values: object) -> bool:
    """Whether every value is an ``int`` or a ``Fraction``."""
    return all(isinstance(v, int | Fraction) for v in values)


def exact_div(x: Real, y: Real) -> Real:
    """x/y, exact when both are rational."""
    return Fraction(x) / Fraction(y) if all_rational(x, y) else x / y


def check_semi_axes(a: Real, b: Real) -> None:
    """``ValueError`` unless the semi-axes a and b are positive numbers."""
    inputs.positive(a, "a")
    inputs.positive(b, "b")
