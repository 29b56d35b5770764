"""Exact arithmetic shared by the models: a square root that stays rational where it can.

A model given ``int`` or ``fractions.Fraction`` inputs stays exact through + - * /; a square root
stays exact too where its argument is a rational perfect square: the integer-sided bang triangle
of Fig. 5.2(f), perfect-square mass ratios (chapter 12), the area ratios of Fig. 1.A.2, and the
frequencies and radii of rational oscillators (chapter 11).
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import cast

from mechmodel import inputs
from mechmodel.typing import Real, Scalar


def magnitude(x: Scalar) -> Real:
    """|x|: exact for an exact x, a float for a float or a complex number. (mypy types ``abs``
    of a union of number types as an object; each branch here is one type.)"""
    if isinstance(x, complex):
        return abs(x)
    if isinstance(x, Fraction):
        return abs(x)
    return abs(x)


def all_rational(*values: object) -> bool:
    """Whether every value is an ``int`` or a ``Fraction``."""
    return all(isinstance(v, int | Fraction) for v in values)


def exact_div(x: Real, y: Real) -> Real:
    """x/y, exact (a ``Fraction``) when both are rational."""
    return Fraction(x) / Fraction(y) if all_rational(x, y) else x / y


def exact_sqrt(x: Real) -> Real:
    """The square root of x >= 0: an ``int`` for an int perfect square, a ``Fraction`` for a
    Fraction whose numerator and denominator are perfect squares, an mpmath number for an
    mpmath one (its precision kept), else a float."""
    inputs.real(x, "x")
    if x < 0:
        raise ValueError(f"no real square root of {x!r}")
    if type(x).__module__.startswith("mpmath"):
        import mpmath  # only where an mpmath number came in

        return cast(Real, mpmath.sqrt(x))
    if isinstance(x, int):
        root = math.isqrt(x)
        if root * root == x:
            return root
    elif isinstance(x, Fraction):
        top, bottom = math.isqrt(x.numerator), math.isqrt(x.denominator)
        if top * top == x.numerator and bottom * bottom == x.denominator:
            return Fraction(top, bottom)
    return math.sqrt(x)
