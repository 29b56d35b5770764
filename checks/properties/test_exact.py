"""Laws of the exact square root shared by the models (mechmodel.exact).

A rational perfect square gives back its root exactly, as an ``int`` for an ``int`` and as a
``Fraction`` for a ``Fraction``; anything else gives the float square root, correctly rounded.
"""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import given
from hypothesis import strategies as st

from checks.properties.strategies import rationals
from mechmodel.exact import exact_sqrt

pytestmark = pytest.mark.properties


@given(st.integers(min_value=0, max_value=10**40))
def test_an_integer_square_has_its_integer_root(root: int) -> None:
    """sqrt(k^2) = k exactly, an int, however large (the integer bang triangles of Fig. 5.2(f));
    a non-square k^2 + 1 (k > 0) gives the float root."""
    result = exact_sqrt(root * root)
    assert result == root
    assert type(result) is int
    if root:
        other = exact_sqrt(root * root + 1)
        assert isinstance(other, float)
        assert other == math.sqrt(root * root + 1)


@given(rationals(Fraction(1, 1000), 1000, 1000))
def test_a_rational_square_has_its_rational_root(root: Fraction) -> None:
    """sqrt((p/q)^2) = p/q exactly, a Fraction (the perfect-square mass ratios of chapter 12);
    a Fraction whose numerator is no square gives the float root."""
    result = exact_sqrt(root * root)
    assert result == root
    assert isinstance(result, Fraction)
    odd = Fraction(2 * root.numerator**2, root.denominator**2)  # 2 p^2 is never a square
    assert exact_sqrt(odd) == math.sqrt(odd)


@given(st.floats(min_value=0, max_value=1e300))
def test_a_float_gives_the_float_root(x: float) -> None:
    """A float is not exact: its root is math.sqrt's, correctly rounded."""
    assert exact_sqrt(x) == math.sqrt(x)


@given(st.one_of(st.integers(max_value=-1), rationals(-1000, Fraction(-1, 1000), 1000)))
def test_a_negative_number_has_no_real_root(x: int | Fraction) -> None:
    """A negative number has no real square root: a ValueError that names it."""
    with pytest.raises(ValueError, match="no real square root"):
        exact_sqrt(x)
