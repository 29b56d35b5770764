"""Private helpers of the chapter-12 models: matching lengths, and the maths library
(``math`` or ``mpmath``) that keeps an input's precision for roots, powers and angles."""

from __future__ import annotations

import math
from collections.abc import Sequence
from fractions import Fraction
from typing import Any


def _same_length(a: Sequence[Any], b: Sequence[Any]) -> None:
    if len(a) != len(b):
        raise ValueError("one velocity (or momentum) per mass")


def _lib(*values: Any) -> Any:
    import mpmath

    return mpmath if any(isinstance(v, mpmath.mpf) for v in values) else math


def _sqrt(x: Any) -> Any:
    return _lib(x).sqrt(x)


def _power(x: Any, e: Fraction) -> Any:
    """x**e: exact for a Fraction x and an integer e, else through float (or mpmath)."""
    if e.denominator == 1:
        return x ** int(e)
    return x ** float(e) if not isinstance(x, Fraction | int) else float(x) ** float(e)
