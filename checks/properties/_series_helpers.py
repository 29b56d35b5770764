"""Helpers the property tests of mechmodel.series share (test_series_*.py)."""

from __future__ import annotations

import math
from fractions import Fraction

import mpmath

from mechmodel.typing import Real


def _exp_scale(x: float) -> float:
    """Sum of the magnitudes of the e-series terms at x: e^|x| (float rounding scales with it)."""
    return math.exp(abs(x))


def _mp(value: Real) -> mpmath.mpf:
    exact = Fraction(value)  # a Fraction already for the exact partial sums
    return mpmath.mpf(exact.numerator) / exact.denominator
