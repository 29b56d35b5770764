"""The triad sequence of Fig. 11.7 ((11.16)-(11.19), chapter 11).

On the ellipse r.Q.r = 1, the radius r at timer angle phi_k has polar angle phi_k-1 and the
perpendicular p = Q.r has polar angle phi_k+1: stepping k turns a line of slope tan phi_0 into
one of slope (a/b)^k tan phi_0 (11.19). The book's triads (11.18) let ab = 1.

Units: lengths a, b in any unit, angles in radians.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from mechmodel import inputs
from mechmodel.exact import exact_div
from mechmodel.oscillators._common import check_semi_axes
from mechmodel.oscillators.forms import ellipse_form
from mechmodel.planar import Vector, apply
from mechmodel.typing import Real


def _polar_angle(v: Sequence[Real]) -> float:
    return math.atan2(v[1], v[0])


def triad_angle(a: Real, b: Real, phi0: Real, k: int) -> Real:
    """The slope angle phi_k of the triad sequence started at phi_0 (Fig. 11.7): the radius
    r = (a cos phi_k, b sin phi_k) at timer angle phi_k has polar angle phi_k-1 and the
    perpendicular p = Q.r has polar angle phi_k+1 ((11.16)-(11.17)); step |k| times."""
    check_semi_axes(a, b)
    inputs.real(phi0, "phi0")
    k = int(k)
    phi = phi0
    q = ellipse_form(a, b)
    for _ in range(abs(k)):
        r = (a * math.cos(phi), b * math.sin(phi))
        phi = _polar_angle(apply(q, r) if k > 0 else r)
    return phi


def triad_slope(a: Real, b: Real, phi0: Real, k: int) -> float:
    """Slope tan(phi_k) of the k-th line of Fig. 11.7 ((a/b)^k tan phi_0, (11.19))."""
    return math.tan(triad_angle(a, b, phi0, k))


@dataclass(frozen=True)
class TriadVectors:
    """The radius r(phi_k-1) = (a cos phi_k, b sin phi_k) and perpendicular p(phi_k+1) = Q.r of
    the k-th triad (11.18), with the divisors of their components in the book's form
    r = (a/dx, b/dy), p = (b/ex, a/ey) (valid for ab = 1)."""

    r: Vector
    p: Vector
    r_x_divisor: Real
    r_y_divisor: Real
    p_x_divisor: Real
    p_y_divisor: Real


def triad_vectors(a: Real, area_product: Real, phi0: Real, k: int = 0) -> TriadVectors:
    """The vectors of the k-th triad for radii a and b = ``area_product``/a (the book lets
    ab = 1, unit scale S = 1, before (11.18)): r(phi_k-1) and p(phi_k+1) = Q.r(phi_k-1) (11.18)."""
    inputs.positive(area_product, "area_product")
    b = exact_div(area_product, a)
    phi = triad_angle(a, b, phi0, k)
    r = (a * math.cos(phi), b * math.sin(phi))
    p = apply(ellipse_form(a, b), r)
    return TriadVectors(r, p, a / r[0], b / r[1], b / p[0], a / p[1])


@dataclass(frozen=True)
class TriadDirection:
    """The direction of the k-th line of the triad sequence: cos phi_k, sin phi_k and the slope
    tan phi_k (Fig. 11.7, (11.19))."""

    cos: float
    sin: float
    slope: float


def triad_direction(a: Real, b: Real, start_slope: Real, k: int) -> TriadDirection:
    """Direction of the k-th line of the sequence started on the line of slope ``start_slope``
    (phi_0 = atan of it: the book's phi_0 = pi/4 has slope 1), stepped by ``triad_angle``."""
    inputs.real(start_slope, "start_slope")
    phi = triad_angle(a, b, math.atan(start_slope), k)
    return TriadDirection(math.cos(phi), math.sin(phi), math.tan(phi))


@dataclass(frozen=True)
class BookTriad:
    """The radius r(phi_j) = (a cos phi_j+1, b sin phi_j+1) and the perpendicular
    p(phi_j) = Q.r(phi_j-2) = (b cos phi_j-1, a sin phi_j-1) of the book's triads (11.18)."""

    r: Vector
    p: Vector


def book_triad(a: Real, b: Real, area_product: Real, start_slope: Real, j: int) -> BookTriad:
    """The vectors r(phi_j) and p(phi_j) of (11.18) with the book's matrix at unit scale: the
    book lets ab = 1 and writes Q = diag(1/a^2, 1/b^2) as diag(b/a, a/b) (before (11.18),
    S = sqrt(ab) = 1 in (11.11)), which is Q times ab/``area_product`` for
    ``area_product`` = 1; that form is kept for any a and b. phi_j is the polar angle of both
    vectors; the timer angles are those of ``triad_direction``."""
    inputs.positive(area_product, "area_product")
    j = int(j)
    q = ellipse_form(a, b)
    scale = a * b / area_product
    book_q = tuple(tuple(scale * e for e in row) for row in q)

    def radius(index: int) -> Vector:
        d = triad_direction(a, b, start_slope, index + 1)
        return (a * d.cos, b * d.sin)

    return BookTriad(radius(j), apply(book_q, radius(j - 2)))
