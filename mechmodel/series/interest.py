"""Interest: simple, compound (10.3) and continuous (10.4) (chapter 10).

A yearly rate r (a pure number: 0.03 is 3% a year), a time t in years and a principal p(0) in
dollars: simple interest (1 + r t) p(0), compound interest (1 + r t/m)^m p(0) over m periods,
and its limit p(0) e^(r t). Compound interest and the limit are computed in mpmath at
``DIGITS`` digits and compound growth is returned as the exact Fraction of that number; with
int and Fraction inputs the period factors and ``compound_growth_exact`` are exact.
"""

from __future__ import annotations

from fractions import Fraction
from typing import overload

import mpmath

from mechmodel import inputs
from mechmodel.series._common import DIGITS, _fraction, _mp
from mechmodel.series.exp_series import exponential
from mechmodel.typing import Exact, Real


def interest_rate(rate: Real) -> Real:
    """A yearly interest rate r as a pure number (r = 0.03 is 3% a year): the claim's unit
    (percent) writes it the way the text does."""
    return inputs.real(rate, "rate")


def simple_interest(rate: Real, time: Real, principal: Real) -> Real:
    """Simple interest: p(t) = (1 + r t) p(0), r per year, t in years, p in dollars."""
    for value, name in ((rate, "rate"), (time, "time"), (principal, "principal")):
        inputs.real(value, name)
    return (1 + rate * time) * principal


def compound_period(periods: int, time: Real = 1, elapsed: Real = 1) -> Fraction:
    """End of the ``elapsed``-th of ``periods`` equal compounding periods of ``time`` years:
    elapsed t/m (the half-period t/2, the 1/3rd-period t/3, 2t/3, ...)."""
    m = inputs.count(periods, "periods", minimum=1)
    inputs.real(time, "time")
    return Fraction(elapsed) * Fraction(time) / m


# exact rate and time give an exact Fraction, as the book's 9/4 and 64/27 need
@overload
def compound_factor(rate: Exact, periods: int, time: Exact = 1) -> Fraction: ...
@overload
def compound_factor(rate: Real, periods: int, time: Real = 1) -> Real: ...
def compound_factor(rate: Real, periods: int, time: Real = 1) -> Real:
    """The growth factor of one compounding period, 1 + r t/m (exact for int and Fraction)."""
    m = inputs.count(periods, "periods", minimum=1)
    inputs.real(rate, "rate")
    inputs.real(time, "time")
    if isinstance(rate, int | Fraction) and isinstance(time, int | Fraction):
        return 1 + Fraction(rate) * Fraction(time) / m
    return 1 + rate * time / m


def compound_growth(rate: Real, periods: int, time: Real = 1, principal: Real = 1) -> Fraction:
    """Compound interest p_(1/m)(t) = (1 + r t/m)^m p(0) (10.3), to ``DIGITS`` digits.

    Computed as p(0) exp(m log1p(r t/m)) in mpmath: floating point loses the digits of
    1 + 1/m from m = 1e6 on and exact fractions are hopeless at m = 1e9. Returned as the exact
    Fraction of that 40-digit number, so that no digit is lost on the way to the comparison
    (a float would not tell m = 1e9 from m = 1e9 + 1).
    """
    m = inputs.count(periods, "periods", minimum=1)
    for value, name in ((rate, "rate"), (time, "time"), (principal, "principal")):
        inputs.real(value, name)
    with mpmath.workdps(DIGITS):
        step = _mp(Fraction(rate) * Fraction(time) / m)
        return _fraction(_mp(Fraction(principal)) * mpmath.exp(m * mpmath.log1p(step)))


def compound_growth_exact(
    rate: Real, periods: int, time: Real = 1, principal: Real = 1
) -> Fraction:
    """(1 + r t/m)^m p(0) as an exact Fraction for rational inputs (the book's 9/4, 64/27...)."""
    m = inputs.count(periods, "periods", minimum=1)
    return compound_factor(Fraction(rate), m, Fraction(time)) ** m * Fraction(principal)


def continuous_growth(rate: Real, time: Real = 1, principal: Real = 1) -> mpmath.mpf:
    """The limit of compounding ever more often: p(0) e^(r t) (10.4), to ``DIGITS`` digits."""
    for value, name in ((rate, "rate"), (time, "time"), (principal, "principal")):
        inputs.real(value, name)
    with mpmath.workdps(DIGITS):
        return _mp(Fraction(principal)) * exponential(Fraction(rate) * Fraction(time))


def compound_solid_figures(rate: Real, periods: int, time: Real = 1, after: int = 0) -> int:
    """The "solid figures" of compound interest (10.3): the leading significant digits of
    (1 + r t/m)^m (truncated, not rounded) that it shares with the limit e^(r t), less the first
    ``after`` figures (those of the "2.71" the text counts beyond)."""
    after = inputs.count(after, "after")
    with mpmath.workdps(DIGITS):
        value = _mp(compound_growth(rate, periods, time))
        limit = continuous_growth(rate, time)
        scale = mpmath.mpf(10) ** (DIGITS // 2 - int(mpmath.floor(mpmath.log10(limit))))
        a = str(int(mpmath.floor(value * scale)))
        b = str(int(mpmath.floor(limit * scale)))
    same = 0
    while same < min(len(a), len(b)) and a[same] == b[same]:
        same += 1
    return same - after
