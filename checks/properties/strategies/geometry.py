"""Strategies of slope geometry and trigonometry (mechmodel.geometry, chapter 1)."""

from __future__ import annotations

from fractions import Fraction

from hypothesis import strategies as st

from checks.properties.strategies.exact import rationals

ANGLE_MARGIN = 0.01  # radians kept away from the zeros of sin and cos


def angles() -> st.SearchStrategy[float]:
    """Any angle from -4π to 4π radians (two turns either way)."""
    return st.floats(min_value=-4 * 3.141592653589793, max_value=4 * 3.141592653589793)


def oblique_angles() -> st.SearchStrategy[float]:
    """An angle at least ANGLE_MARGIN away from every multiple of π/2, built as a whole number
    of quarter turns (-8 to 7) plus an offset, so that all six trigonometric segments are
    finite."""
    quarter = 3.141592653589793 / 2
    return st.tuples(
        st.integers(min_value=-8, max_value=7),
        st.floats(min_value=ANGLE_MARGIN, max_value=quarter - ANGLE_MARGIN),
    ).map(lambda kd: kd[0] * quarter + kd[1])


def acute_angles() -> st.SearchStrategy[float]:
    """A slope angle strictly inside the first quadrant, ANGLE_MARGIN from its ends."""
    return st.floats(min_value=ANGLE_MARGIN, max_value=3.141592653589793 / 2 - ANGLE_MARGIN)


def unit_interval_values() -> st.SearchStrategy[float]:
    """A value of sine or cosine: -1 to 1."""
    return st.floats(min_value=-1.0, max_value=1.0)


def slopes() -> st.SearchStrategy[float]:
    """A slope Δy/Δx from -1e3 to 1e3."""
    return st.floats(min_value=-1e3, max_value=1e3)


def lengths() -> st.SearchStrategy[float]:
    """A positive length (or scale factor) from 1e-3 to 1e3, spread evenly over the decades."""
    return st.floats(min_value=-3, max_value=3).map(lambda k: 10.0**k)


def secants() -> st.SearchStrategy[float]:
    """A secant sec σ >= 1: the distance of a point outside the unit circle, 1 to 1e3."""
    return st.floats(min_value=0, max_value=3).map(lambda k: 10.0**k)


def fraction_lengths() -> st.SearchStrategy[Fraction]:
    """An exact positive length (or speed, or scale factor) p/q."""
    return rationals(Fraction(1, 1000), 1000, 1000)


def fraction_slopes() -> st.SearchStrategy[Fraction]:
    """An exact non-zero slope or speed p/q from -1000 to 1000."""
    sign = st.sampled_from((-1, 1))
    return st.builds(lambda s, x: s * x, sign, rationals(Fraction(1, 1000), 1000, 1000))


def molecule_sizes() -> st.SearchStrategy[int]:
    """Number of atoms N of a non-linear molecule, 3 to 1000."""
    return st.integers(min_value=3, max_value=1000)
