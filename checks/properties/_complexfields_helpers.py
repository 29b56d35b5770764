"""Helpers shared by the property modules of mechmodel.complexfields (test_complexfields_*.py):
the exact 1/2, the strategies of non-negative powers and of radii, a printed polynomial's value
at a point, and central differences along x and i y."""

from __future__ import annotations

import re
from collections.abc import Callable
from fractions import Fraction

from hypothesis import strategies as st

from checks.properties.strategies import field_powers
from mechmodel import complexfields as cf

HALF = Fraction(1, 2)
NONNEGATIVE_POWERS = field_powers().map(abs)
RADII = st.floats(min_value=0.1, max_value=10)


def view_at(view: cf.PolyView, z: complex) -> float:
    """The real polynomial printed as ``view`` ("x2y1": coefficient of x^2 y) at x + i y."""
    total = 0.0
    for name, c in view.coefficients.items():
        match = re.fullmatch(r"x(\d+)y(\d+)", name)
        assert match is not None
        i, j = map(int, match.groups())
        total += float(c) * z.real**i * z.imag**j
    return total


def z_derivative(func: Callable[[complex], complex], z: complex) -> tuple[complex, complex]:
    """Central differences of func along x and along i y (equal for an analytic function)."""
    h = 1e-6 * abs(z)
    along_x = (func(z + h) - func(z - h)) / (2 * h)
    along_y = (func(z + 1j * h) - func(z - 1j * h)) / (2j * h)
    return along_x, along_y
