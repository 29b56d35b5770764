"""Input checks shared by the submodules of ``mechmodel.complexfields`` (private).

``_real`` reads an exact result that must be real; ``_point``, ``_polar_point``, ``_strength``
and ``_integer`` read the point z = x + i y (or r e^(i theta)), the complex strength
a = re + i im and an integer power that the "at a point" models take. Dimensionless.
"""

from __future__ import annotations

import cmath
from fractions import Fraction

from mechmodel import inputs
from mechmodel.algebra import Coefficient, Gaussian
from mechmodel.typing import Real


def _real(value: Coefficient, what: str) -> Fraction:
    g = Gaussian.of(value)
    if g.im != 0:
        raise ArithmeticError(f"{what} should be real, got {g}")
    return Fraction(g.re)


def _point(x: Real, y: Real) -> complex:
    inputs.real(x, "x")
    inputs.real(y, "y")
    z = complex(float(x), float(y))
    if z == 0:
        raise ValueError("the point must not be the origin (a source may sit there)")
    return z


def _polar_point(r: Real, theta: Real) -> complex:
    inputs.positive(r, "r")
    inputs.real(theta, "theta")
    return cmath.rect(float(r), float(theta))


def _strength(strength_re: Real, strength_im: Real) -> complex:
    inputs.real(strength_re, "strength_re")
    inputs.real(strength_im, "strength_im")
    return complex(float(strength_re), float(strength_im))


def _integer(value: Real, name: str) -> int:
    n = int(value)
    if n != value:
        raise ValueError(f"{name} must be an integer, got {value!r}")
    return n
