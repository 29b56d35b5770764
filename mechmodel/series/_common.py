"""Shared by the exponential and interest models of chapter 10: the mpmath working precision.

e, e^x and compound interest are computed in mpmath at ``DIGITS`` significant digits, since
(1 + 1/m)^m in floating point loses digits from m = 1e6 on; ``_mp`` makes an mpmath number of
an int, float or Fraction and ``_fraction`` gives an mpmath number back as its exact Fraction.
"""

from __future__ import annotations

from fractions import Fraction

import mpmath

from mechmodel.typing import Real

DIGITS = 40  # mpmath working precision (significant digits) for e and compound interest


def _fraction(value: mpmath.mpf) -> Fraction:
    """The exact rational value of an mpmath number: no digit of its precision is lost."""
    mantissa, exponent = mpmath.mpf(value).man_exp
    return Fraction(int(mantissa)) * Fraction(2) ** int(exponent)


def _mp(value: Real | mpmath.mpf) -> mpmath.mpf:
    """An mpmath number from an int, float, Fraction or mpmath number (at the current dps)."""
    if isinstance(value, Fraction):
        return mpmath.mpf(value.numerator) / value.denominator
    return mpmath.mpf(value)
