"""Multipoles (10.40)-(10.44), Figs. 10.11-10.14: the dipole pair of line sources and its limit
the point dipole (10.41), the 4-pole (10.43), the 2^order-pole behind each Laurent term a_n z^n
(at the origin for n < 0, at infinity for n >= 0), its construction from displaced copies of
point sources, the level lines of the dipole (circles) and of any power potential (at right
angles, Cauchy-Riemann); fields and potentials at a point (``FieldPoint``). Dimensionless.
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from fractions import Fraction

import mpmath

from mechmodel import inputs
from mechmodel.algebra import Laurent
from mechmodel.complexfields._common import _integer, _point, _polar_point, _real
from mechmodel.complexfields.potentials import (
    FieldPoint,
    LaurentTerm,
    _field_point,
    laurent_derivative,
    power_antiderivative,
    power_field_at,
)
from mechmodel.typing import Estimate, Real


@dataclass(frozen=True)
class DipolePair:
    """Sources +a at z = -D/d and -a at z = +D/d (the book's f_dipole, (10.41)):
    f = a/(z + D/d) - a/(z - D/d) = (c a D) / (z^2 - D^2/k) over a common denominator.
    ``numerator_coefficient`` = c, ``delta_sq_divisor`` = k, ``point_dipole_coefficient`` the
    limit of f/D as D -> 0 times z^2/a (the f_2-pole = -a/z^2)."""

    numerator_coefficient: Fraction
    delta_sq_divisor: Fraction
    point_dipole_coefficient: Fraction


def dipole_pair(position_divisor: Real) -> DipolePair:
    """Combine the two line-source fields exactly, as polynomials in z and the separation D."""
    d = Fraction(position_divisor)
    inputs.positive(d, "position_divisor")
    z, sep = Laurent.var("z"), Laurent.var("D")  # the variable z and the separation D
    plus, minus = z + sep * (1 / d), z - sep * (1 / d)
    numerator = minus - plus  # a/(z + D/d) - a/(z - D/d), a = 1
    denominator = plus * minus
    c = _real(numerator.coefficient(D=1), "numerator")
    if numerator != sep * c or denominator.coefficient(z=2) != 1:
        raise ArithmeticError("unexpected form of the dipole fraction")
    k = -1 / _real(denominator.coefficient(D=2), "D^2 term")
    # f / D = c / (z^2 - D^2/k) -> c / z^2 as D -> 0
    return DipolePair(c, k, c)


def dipole_pair_field(z: complex, separation: float, position_divisor: float = 2) -> complex:
    """The book's f_dipole(z) = a/(z + D/d) - a/(z - D/d) with a = 1, in floats."""
    s = separation / position_divisor
    return 1 / (z + s) - 1 / (z - s)


@dataclass(frozen=True)
class QuadrupoleRelations:
    """(10.43): with f_1 = a/z, f_2 = df_1/dz = -a/z^2 and phi_2 = dphi_1/dz = a/z, the book
    normalizes f_4 = a/z^3. ``field_factor`` = f_4 / (df_2/dz); ``potential_divisor_magnitude``
    is the 2 of phi_4 = -a/(2 z^2) = integral f_4 dz; ``potential_factor`` = phi_4/(dphi_2/dz)."""

    field_factor: Fraction
    potential_divisor_magnitude: int
    potential_factor: Fraction


def quadrupole_relations() -> QuadrupoleRelations:
    """Exact Laurent-monomial algebra for the 4-pole of (10.43), a = 1."""
    f2 = laurent_derivative(1, -1)  # d/dz (a z^-1)
    df2 = laurent_derivative(f2.coefficient, f2.power)
    f4 = LaurentTerm(Fraction(1), -3)
    if df2.power != f4.power:
        raise ArithmeticError("df_2/dz is not a z^-3 field")
    anti = power_antiderivative(f4.power)
    phi2 = LaurentTerm(Fraction(1), -1)  # d/dz (a ln z) = a/z
    dphi2 = laurent_derivative(phi2.coefficient, phi2.power)
    if dphi2.power != anti.power:
        raise ArithmeticError("dphi_2/dz is not a z^-2 potential")
    return QuadrupoleRelations(
        field_factor=f4.coefficient / df2.coefficient,
        potential_divisor_magnitude=anti.divisor_magnitude,
        potential_factor=(f4.coefficient * anti.coefficient) / dphi2.coefficient,
    )


def level_line_angle(field_power: int, x: Real = 7 / 10, y: Real = 4 / 10) -> Estimate:
    """Angle (radians) between the level lines of Phi and of A of the potential of z^n at
    (x, y), from central differences of phi; 90 degrees for every analytic potential
    (Cauchy-Riemann), Fig. 10.13. Error: the O(h^2) difference error."""
    anti = power_antiderivative(field_power)
    z0 = complex(float(x), float(y))
    if z0 == 0:
        raise ValueError("the point must not be the origin")
    h = 10.0**-5 * max(1.0, abs(z0))

    def phi(z: complex) -> complex:
        return float(anti.coefficient) * z**anti.power

    def grad(part: Callable[[complex], float]) -> tuple[float, float]:
        gx = (part(z0 + h) - part(z0 - h)) / (2 * h)
        gy = (part(z0 + 1j * h) - part(z0 - 1j * h)) / (2 * h)
        return gx, gy

    gp = grad(lambda z: phi(z).real)
    ga = grad(lambda z: phi(z).imag)
    cos_angle = (gp[0] * ga[0] + gp[1] * ga[1]) / (math.hypot(*gp) * math.hypot(*ga))
    return Estimate(math.acos(max(-1.0, min(1.0, cos_angle))), 10.0**-6)


@dataclass(frozen=True)
class MultipoleTerm:
    """The multipole behind a Laurent field term a_n z^n (10.44): a 2^order-pole at the
    origin (n < 0) or at infinity (n >= 0). ``poles`` = 2^order."""

    field_power: int
    order: int
    poles: int
    location: str


def multipole_of_laurent_term(field_power: int) -> MultipoleTerm:
    """A term z^n with n < 0 is the field of ln z differentiated -(n+1) times (a 2^-(n+1)-pole
    at z = 0); with n >= 0, w = 1/z turns z^n dz into -w^(-n-2) dw, a pole term at w = 0
    (z = infinity) of order n + 1. Each z-derivative doubles the sources."""
    n = int(field_power)
    if n != field_power:
        raise ValueError(f"field_power must be an integer, got {field_power!r}")
    if n < 0:
        order, location = -(n + 1), "origin"
    else:
        w_power = -n - 2  # z^n dz = w^-n (-w^-2 dw)
        order, location = -(w_power + 1), "infinity"
    return MultipoleTerm(n, order, multipole_pole_count(order), location)


def laurent_term_of_multipole(order: int, location: str) -> int:
    """The field power n of the Laurent term of a 2^order-pole at ``location`` ("origin" or
    "infinity"), by searching the terms of (10.44)."""
    k = inputs.count(order, "order")
    if location not in ("origin", "infinity"):
        raise ValueError(f"location must be 'origin' or 'infinity', got {location!r}")
    found = [
        n
        for n in range(-k - 3, k + 3)
        if (t := multipole_of_laurent_term(n)).order == k and t.location == location
    ]
    if len(found) != 1:
        raise ArithmeticError(f"expected one term, found {found}")
    return found[0]


def multipole_sources(
    order: int, spacing: Real | mpmath.mpf = 1 / 64
) -> list[tuple[int, complex | mpmath.mpc]]:
    """Point sources (strength, position) of a 2^order-pole built as the book does: a unit
    1-pole, then repeatedly a (-)copy displaced a little (10.41), (10.43). Each step moves in
    a new direction (golden-angle turns) so that no two sources coincide. Floats, or mpmath
    numbers when ``spacing`` is an mpmath number (the sources nearly cancel far away)."""
    k = inputs.count(order, "order")
    sources: list[tuple[int, complex]] = [(1, 0j)]
    turn = math.pi * (3 - math.sqrt(5))
    for step in range(k):
        shift = spacing * cmath.rect(1.0, step * turn)
        sources = sources + [(-q, p + shift) for q, p in sources]
    return sources


def multipole_pole_count(order: int) -> int:
    """Number of distinct point sources of the 2^order-pole construction."""
    return len({(round(p.real, 12), round(p.imag, 12)) for _, p in multipole_sources(order)})


def multipole_field(z: complex, sources: Iterable[tuple[int, complex]]) -> complex:
    """Field f(z) = sum q/(z - p) of line sources."""
    return sum((q / (z - p) for q, p in sources), start=0j)


def potential_term_poles(potential_power: int) -> int:
    """The number of poles 2^order of the multipole behind the potential term a z^m/m, m != 0
    (10.44): its field term is a z^(m-1) (``multipole_of_laurent_term``)."""
    m = _integer(potential_power, "potential_power")
    if m == 0:
        raise ValueError("the m = 0 potential term is a_-1 ln z, not a power")
    return multipole_of_laurent_term(m - 1).poles


def multipole_term_at(
    order: int, location: str, x: Real, y: Real, strength_re: Real = 1, strength_im: Real = 0
) -> FieldPoint:
    """The Laurent term a z^n of a 2^order-pole at the origin or at infinity (10.44), the
    power n found by ``laurent_term_of_multipole``, with its potential (``power_field_at``)."""
    n = laurent_term_of_multipole(order, location)
    return power_field_at(n, x, y, strength_re, strength_im)


def dipole_pair_at(
    strength: Real, separation: Real, x: Real, y: Real, position_divisor: Real = 2
) -> FieldPoint:
    """The pair of line sources of (10.41): +a at z = -D/d and -a at z = +D/d (the pair whose
    field the book prints, f_dipole = a/(z + D/2) - a/(z - D/2)), at z = x + i y: the field is
    the sum of the sources' fields q/(z - p) (10.40a) and the potential the sum of their
    potentials q ln(z - p) (10.40b), principal branches."""
    inputs.real(strength, "strength")
    inputs.positive(separation, "separation")
    inputs.positive(position_divisor, "position_divisor")
    z, a = _point(x, y), float(strength)
    s = float(separation) / float(position_divisor)
    sources = ((a, -s), (-a, s))
    if any(z == p for _, p in sources):
        raise ValueError("the point must not be a source")
    field = sum((q / (z - p) for q, p in sources), start=0j)
    potential = sum((q * cmath.log(z - p) for q, p in sources), start=0j)
    return _field_point(field, potential)


def line_multipole_at(
    strength: Real, derivatives: int, x: Real, y: Real, factor: Real = 1
) -> FieldPoint:
    """The k-th z-derivative of the unit line source, k = ``derivatives`` (10.40)-(10.43): the
    field factor * d^k/dz^k (a/z) and the potential factor * d^k/dz^k (a ln z), whose
    z-derivative is that field. Each derivative is the power rule (``laurent_derivative``); the
    derivative of ln z is 1/z. k = 1 is the point dipole f_2-pole = -a/z^2 with
    phi_2-pole = a/z (10.41); the book's 4-pole is k = 2 with the factor 1/2 (10.43)."""
    k = inputs.count(derivatives, "derivatives")
    inputs.real(strength, "strength")
    inputs.real(factor, "factor")
    z = _point(x, y)
    scale = float(strength) * float(factor)
    field = LaurentTerm(Fraction(1), -1)
    for _ in range(k):
        field = laurent_derivative(field.coefficient, field.power)
    if k == 0:
        potential = cmath.log(z)
    else:
        term = LaurentTerm(Fraction(1), -1)  # d/dz ln z
        for _ in range(k - 1):
            term = laurent_derivative(term.coefficient, term.power)
        potential = float(term.coefficient) * z**term.power
    return _field_point(scale * float(field.coefficient) * z**field.power, scale * potential)


def line_multipole_polar(
    strength: Real, derivatives: int, r: Real, theta: Real, factor: Real = 1
) -> FieldPoint:
    """``line_multipole_at`` at z = r e^(i theta) (the polar labels of Fig. 10.11, (10.42))."""
    z = _polar_point(r, theta)
    return line_multipole_at(strength, derivatives, z.real, z.imag, factor)


def dipole_level_radius(strength: Real, level: Real, theta: Real, part: str) -> float:
    """The distance r along the ray at angle theta where the point-dipole potential
    phi_2-pole = a/z (10.42) has Phi = level (``part`` "phi") or A = level (``part`` "a"):
    on a ray the potential falls off as 1/r (checked at r = 1 and r = 2), so r is the value
    at r = 1 over the level; the level lines are the circles of Fig. 10.11. ``ValueError``
    where the ray does not reach that level (r <= 0)."""
    if part not in ("phi", "a"):
        raise ValueError(f"part must be 'phi' or 'a', got {part!r}")
    inputs.real(level, "level")
    if float(level) == 0:
        raise ValueError("the zero level lines are rays, not circles")
    at_one = getattr(line_multipole_polar(strength, 1, 1, theta), part)
    at_two = getattr(line_multipole_polar(strength, 1, 2, theta), part)
    if not math.isclose(at_two * 2, at_one, rel_tol=1e-12, abs_tol=1e-300):
        raise ArithmeticError("the dipole potential does not fall off as 1/r")
    r = at_one / float(level)
    if not r > 0:
        raise ValueError(f"the ray at theta = {theta} does not reach the level {level}")
    return r
