"""Private helpers of the chapter-12 models: matching lengths, the maths library (``math`` or
``mpmath``) that keeps an input's precision for roots, powers and angles, and the rational
coefficient of an exact polynomial."""

from __future__ import annotations

import math
from collections.abc import Sized
from fractions import Fraction
from types import ModuleType

from mechmodel.typing import Real


def _same_length(a: Sized, b: Sized) -> None:
    if len(a) != len(b):
        raise ValueError("one velocity (or momentum) per mass")


def _lib(*values: Real) -> ModuleType:
    import mpmath

    return mpmath if any(isinstance(v, mpmath.mpf) for v in values) else math


def _sqrt(x: Real) -> Real:
    return _lib(x).sqrt(x)


def _power(x: Real, e: Fraction) -> Real:
    """x**e: exact for a Fraction x and an integer e, else through float (or mpmath)."""
    if e.denominator == 1:
        return x ** int(e)
    return x ** float(e) if not isinstance(x, Fraction | int) else float(x) ** float(e)
