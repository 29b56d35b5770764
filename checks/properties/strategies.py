"""Hypothesis strategies for the property suite, named for what they draw.

Inputs are built valid rather than filtered; floats are bounded and never NaN or infinite.
"""

from __future__ import annotations

from fractions import Fraction

from hypothesis import strategies as st

MASS_RANGE = (1e-6, 1e6)
SPEED_LIMIT = 1e3


def masses() -> st.SearchStrategy[float]:
    """A finite positive mass from 1e-6 to 1e6, spread evenly over the decades."""
    return st.floats(min_value=-6, max_value=6, allow_nan=False).map(lambda k: 10.0**k)


def velocities() -> st.SearchStrategy[float]:
    """A velocity from -1e3 to 1e3; magnitudes below 1e-9 are drawn as exactly 0, so that
    products with masses stay normal floats (a subnormal has no relative precision)."""
    return st.floats(min_value=-SPEED_LIMIT, max_value=SPEED_LIMIT, allow_nan=False).map(
        lambda v: v if abs(v) >= 1e-9 else 0.0
    )


def restitutions() -> st.SearchStrategy[float]:
    """A restitution coefficient from 0 (sticking) to 1 (elastic)."""
    return st.floats(min_value=0.0, max_value=1.0, allow_nan=False)


def fraction_masses() -> st.SearchStrategy[Fraction]:
    """An exact positive mass p/q."""
    return st.fractions(min_value=Fraction(1, 1000), max_value=1000, max_denominator=1000)


def fraction_velocities() -> st.SearchStrategy[Fraction]:
    """An exact velocity p/q from -1000 to 1000."""
    return st.fractions(min_value=-1000, max_value=1000, max_denominator=1000)


def fraction_restitutions() -> st.SearchStrategy[Fraction]:
    """An exact restitution coefficient in [0, 1]."""
    return st.fractions(min_value=0, max_value=1, max_denominator=100)
