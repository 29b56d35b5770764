"""Series for the exponential (chapter 10).

e^x = sum_k x^k / k! (eq. (10.5)); the partial sum to order o keeps the terms k = 0..o (the
precision order is the power of the highest term used, (10.6)). Exact with int or Fraction
``x`` when ``exact`` or with Fraction ``x``; floats otherwise; mpmath numbers also work.
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Any

from mechmodel import inputs


def exp_series_term(x: Any, k: Any, *, exact: bool = False) -> Any:
    """The k-th term x^k / k! of the exponential series (10.5b)."""
    inputs.real(x, "x")
    k = inputs.count(k, "k")
    if exact:
        x = Fraction(x)
    return x**k / math.factorial(k)


def exp_partial_sum(x: Any, order: Any, *, exact: bool = False) -> Any:
    """Partial sum of e^x to precision order ``order``: sum_{k=0}^{order} x^k / k! (10.6)."""
    order = inputs.count(order, "order")
    return sum(exp_series_term(x, k, exact=exact) for k in range(order + 1))
