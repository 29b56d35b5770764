"""Laws of simple, compound and continuous interest (mechmodel.series.interest): chapter 10,
(10.3)-(10.4).

Floats are compared within 1e-12 of the sum of the magnitudes involved (or of the function's
size); integer and Fraction results must be exact; mpmath results are compared far below their
working precision.
"""

from __future__ import annotations

import math
from fractions import Fraction

import mpmath
import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from checks.properties._series_helpers import _mp
from checks.properties.strategies import compounding_periods, rationals
from mechmodel import series

pytestmark = pytest.mark.properties
REL = 1e-12


# -- compound interest ---------------------------------------------------------------------------


@given(compounding_periods())
@example(1_000_000_000)
def test_compound_interest_halts_just_below_e(m: int) -> None:
    """e/(2m + 2) < e - (1 + 1/m)^m < e/(2m) (10.3); (1 + 1/m)^m shares its first s figures
    with e = 2.71... (its "solid figures", truncated) but not s + 1, leaving a gap below
    10^-(s-1)."""
    figures = series.compound_solid_figures(1, m)
    with mpmath.workdps(series.DIGITS):
        value, e = _mp(series.compound_growth(1, m)), series.euler_number()
        for shared in (figures, figures + 1):  # 2.7182... truncated to so many figures
            same = mpmath.floor(value * 10 ** (shared - 1)) == mpmath.floor(e * 10 ** (shared - 1))
            assert same == (shared == figures)
    assert series.compound_solid_figures(1, m, 1, 3) == figures - 3  # beyond the "2.71"
    assert series.compound_solid_figures(Fraction(1, 2), m, 2) == figures  # r t alone counts
    assert series.compound_solid_figures(3, 1) == 0  # 4 and e^3 = 20.08... share no figure
    with mpmath.workdps(series.DIGITS):
        e = series.euler_number()
        gap = e - _mp(series.compound_growth(1, m))
        assert e / (2 * m + 2) < gap < e / (2 * m)
        assert gap < mpmath.mpf(10) ** (-(figures - 1))


@given(
    rationals(0, 3, 10),
    st.integers(min_value=1, max_value=24),
    st.integers(min_value=1, max_value=24),
)
def test_compounding_more_often_pays_more(rate: Fraction, m: int, extra: int) -> None:
    """(1 + r/m)^m grows with m and stays below e^r; mpmath and exact Fractions agree."""
    low = series.compound_growth_exact(rate, m)
    high = series.compound_growth_exact(rate, m + extra)
    assert low <= high
    assert (low < high) == (rate > 0)
    with mpmath.workdps(series.DIGITS):
        assert _mp(high) <= series.continuous_growth(rate)
        assert abs(series.compound_growth(rate, m) - low) < Fraction(1, 10**30)


@given(
    rationals(0, 3, 10),
    rationals(0, 10, 12),
    rationals(Fraction(1, 100), 10_000, 100),
    st.integers(min_value=1, max_value=24),
)
@example(Fraction(1), Fraction(1), Fraction(1), 2)  # $1 at 100% for a year, twice: $2.25
def test_interest_is_the_principal_times_a_growth_factor_of_r_t(
    rate: Fraction, time: Fraction, principal: Fraction, m: int
) -> None:
    """p(t) = (1 + r t/m)^m p(0) (10.3) is p(0) times a factor that depends on r t alone; one
    period is simple interest (1 + r t) p(0); each of the m periods ends t/m later and
    multiplies by 1 + r t/m; the 40-digit value agrees; the limit is p(0) e^(r t) (10.4),
    above every compounding."""
    grown = series.compound_growth_exact(rate, m, time, principal)
    assert grown == principal * series.compound_growth_exact(rate * time, m)
    assert series.simple_interest(rate, time, principal) == series.compound_growth_exact(
        rate, 1, time, principal
    )
    period = series.compound_period(m, time)
    assert m * period == series.compound_period(m, time, m) == time
    assert series.compound_period(m, time, 2) == 2 * period
    assert m * series.compound_period(m) == 1  # a year by default
    factor = series.compound_factor(rate, m, time)
    assert factor == 1 + rate * period == series.compound_factor(rate * time, m)
    assert factor**m * principal == grown
    as_float = series.compound_factor(float(rate), m, float(time))
    assert math.isclose(as_float, float(factor), rel_tol=REL)
    with mpmath.workdps(series.DIGITS):
        assert abs(series.compound_growth(rate, m, time, principal) - grown) < grown / 10**30
        limit = series.continuous_growth(rate, time, principal)
        exact_limit = _mp(principal) * mpmath.exp(_mp(rate * time))
        assert abs(limit - exact_limit) <= exact_limit * mpmath.mpf(10) ** -35
        assert abs(series.continuous_growth(rate * time) * _mp(principal) - limit) <= (
            exact_limit * mpmath.mpf(10) ** -35
        )
        assert _mp(grown) <= limit
