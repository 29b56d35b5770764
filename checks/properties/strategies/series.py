"""Strategies of chapter 10: series, binomials and phasors (mechmodel.series), complex
fields (mechmodel.complexfields)."""

from __future__ import annotations

import math
from fractions import Fraction

from hypothesis import strategies as st

# --- chapter 10: series, binomials, phasors (mechmodel.series) --------------------------------

SERIES_ARGUMENT_LIMIT = 10.0


def series_arguments() -> st.SearchStrategy[float]:
    """A real argument x (or w t) of the exponential, sine and cosine series, -10 to 10."""
    return st.floats(
        min_value=-SERIES_ARGUMENT_LIMIT, max_value=SERIES_ARGUMENT_LIMIT, allow_nan=False
    )


def series_orders() -> st.SearchStrategy[int]:
    """A precision order o of a partial sum, 0 to 30."""
    return st.integers(min_value=0, max_value=30)


def binomial_powers() -> st.SearchStrategy[int]:
    """A power n of (x + y)^n, a row of Pascal's triangle, 0 to 60."""
    return st.integers(min_value=0, max_value=60)


def phase_angles() -> st.SearchStrategy[float]:
    """A phase angle in radians, -2 pi to 2 pi."""
    return st.floats(min_value=-6.3, max_value=6.3, allow_nan=False)


def compounding_periods() -> st.SearchStrategy[int]:
    """A number m of compounding periods, 1 to 1e9, spread evenly over the decades."""
    return st.floats(min_value=0, max_value=9, allow_nan=False).map(lambda k: int(10.0**k))


def plane_points() -> st.SearchStrategy[tuple[float, float]]:
    """A point (x, y) of the plane with coordinates from -1e3 to 1e3."""
    coordinate = st.floats(min_value=-1e3, max_value=1e3, allow_nan=False)
    return st.tuples(coordinate, coordinate)


# --- complex fields (mechmodel.complexfields, chapter 10) -----------------------------------


def small_fractions() -> st.SearchStrategy[Fraction]:
    """An exact rational p/q with |p| <= 20 and 1 <= q <= 12."""
    return st.builds(Fraction, st.integers(-20, 20), st.integers(1, 12))


def gaussian_integers() -> st.SearchStrategy[tuple[int, int]]:
    """An exact complex number re + i im with integer parts from -9 to 9."""
    return st.tuples(st.integers(-9, 9), st.integers(-9, 9))


def xy_polynomials() -> st.SearchStrategy[dict[tuple[int, int], tuple[int, int]]]:
    """A polynomial in x, y of degree at most 2 in each with Gaussian-integer coefficients:
    {(i, j): (re, im)} for the term (re + i im) x^i y^j (zero terms included)."""
    keys = [(i, j) for i in range(3) for j in range(3)]
    return st.lists(st.integers(-9, 9), min_size=18, max_size=18).map(
        lambda c: {k: (c[2 * n], c[2 * n + 1]) for n, k in enumerate(keys)}
    )


def analytic_polynomials() -> st.SearchStrategy[dict[int, tuple[int, int]]]:
    """A polynomial in z alone, degree at most 3, with Gaussian-integer coefficients:
    {k: (re, im)} for the term (re + i im) z^k."""
    return st.lists(st.integers(-9, 9), min_size=8, max_size=8).map(
        lambda c: {k: (c[2 * k], c[2 * k + 1]) for k in range(4)}
    )


def laurent_terms() -> st.SearchStrategy[list[tuple[float, float, int]]]:
    """Terms (re, im, k) of a Laurent polynomial sum c_k z^k with powers -4 to 4."""
    coefficient = st.floats(min_value=-5, max_value=5, allow_nan=False)
    term = st.tuples(coefficient, coefficient, st.integers(-4, 4))
    return st.lists(term, min_size=1, max_size=6)


def loop_circles() -> st.SearchStrategy[tuple[float, float, float]]:
    """A circle (centre x, centre y, radius) whose edge keeps at least a third of its radius
    away from the origin: it either encloses the origin well or passes well clear of it."""

    def build(parts: tuple[float, float, float, bool]) -> tuple[float, float, float]:
        import math

        radius, angle, fraction, enclose = parts
        distance = fraction * radius * (0.6 if enclose else 1) + (0 if enclose else 1.4 * radius)
        return (distance * math.cos(angle), distance * math.sin(angle), radius)

    return st.tuples(
        st.floats(min_value=0.2, max_value=5),
        st.floats(min_value=-3.2, max_value=3.2),
        st.floats(min_value=0, max_value=1),
        st.booleans(),
    ).map(build)


def off_origin_points() -> st.SearchStrategy[complex]:
    """A point z of the plane with 0.3 <= |z| <= 3 (away from the poles at the origin)."""

    def build(parts: tuple[float, float]) -> complex:
        import cmath

        radius, angle = parts
        return cmath.rect(radius, angle)

    return st.tuples(
        st.floats(min_value=0.3, max_value=3), st.floats(min_value=-3.1, max_value=3.1)
    ).map(build)


def field_powers() -> st.SearchStrategy[int]:
    """An integer power n of a field z^n, -6 to 6."""
    return st.integers(-6, 6)


def sphere_angles(*, off_equator: bool = False) -> st.SearchStrategy[float]:
    """A central angle theta of a point on the projection sphere, 0.05 to 3.09 rad (not the
    poles); with ``off_equator`` also more than 1e-3 from the equator pi/2 (the draws above
    it are moved 2.5e-3 up, over it)."""
    if not off_equator:
        return st.floats(min_value=0.05, max_value=3.09)
    return st.floats(min_value=0.05, max_value=3.09 - 2.5e-3).map(
        lambda t: t if t < math.pi / 2 - 1e-3 else t + 2.5e-3
    )


def sphere_diameters() -> st.SearchStrategy[float]:
    """A sphere diameter from 0.1 to 10."""
    return st.floats(min_value=0.1, max_value=10)
