"""The Legendre contact transformation between L(v) and H(p): (12.10)-(12.13), Figs. 12.3-12.4.

H(p) = p v - L(v) at p = dL/dv and back (12.11): the quadratic pair of one body, the tangent
geometry (slope, value, intercept) of Fig. 12.3, the stationarity of the secant family (12.13)
derived exactly, and a numerical transform F*(s) = max_x (s x - F(x)) of any convex function by a
bounded scalar search (scipy). Energies in J, velocities in m/s, momenta in kg m/s (or scaled).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from fractions import Fraction

from mechmodel import inputs
from mechmodel.algebra import Laurent
from mechmodel.ellipse import kinetic_energy
from mechmodel.lagrange.energies import hamiltonian_free
from mechmodel.typing import Real


@dataclass(frozen=True)
class QuadraticLegendrePair:
    """The quadratic kinetic energy of one body as L(v) and as H(p), at a velocity v and the
    momentum p it maps to (line 13716): its mass, L and H."""

    mass: Real
    lagrangian: Real
    hamiltonian: Real


def quadratic_legendre_pair(velocity: Real, momentum: Real) -> QuadraticLegendrePair:
    """L and H of the quadratic kinetic energy whose slope dL/dv at ``velocity`` is
    ``momentum``: p = dL/dv = m v (12.10a) fixes the mass m = p / v; then L = m v^2/2 (12.3)
    and H = p^2/(2m) (12.4). Numerically L = H = p v/2 (line 13716) while H = p v - L
    (12.11b). Exact for ``int`` and ``Fraction``; ``ValueError`` where p / v is not a
    positive mass."""
    v = inputs.real(velocity, "velocity")
    p = inputs.real(momentum, "momentum")
    if v == 0:
        raise ValueError("the velocity must be non-zero to fix the mass p / v")
    mass = inputs.mass(p / v, "mass p / v")
    return QuadraticLegendrePair(
        mass=mass,
        lagrangian=kinetic_energy([mass], [v]),
        hamiltonian=hamiltonian_free([mass], [p]),
    )


@dataclass(frozen=True)
class LegendreTangent:
    """The tangent of slope s at the point x of a curve of value f there (Fig. 12.3):
    ``transform`` = s x - f, the Legendre transform (12.11); ``intercept`` = f - s x, where the
    tangent meets the axis x = 0 (minus the transform)."""

    transform: Real
    intercept: Real


def legendre_tangent(value: Real, slope: Real, point: Real) -> LegendreTangent:
    """Legendre geometry of Fig. 12.3: the tangent to L(v) at v (slope p, value L) meets the
    L axis at L - p v = -H, so H(p) = p v - L(v) (12.11b); the same with H(p), slope v and
    point p gives -L (12.11a). Exact for ``int`` and ``Fraction``."""
    for x, name in ((value, "value"), (slope, "slope"), (point, "point")):
        inputs.real(x, name)
    transform = slope * point - value
    return LegendreTangent(transform=transform, intercept=value - slope * point)


@dataclass(frozen=True)
class LegendreStationarity:
    """The first derivatives that vanish at a tangent contact point (12.13)."""

    hamiltonian_velocity_slope: Fraction  # d(p v - L(v))/dv at v = dH/dp (12.13a)
    lagrangian_momentum_slope: Fraction  # d(p v - H(p))/dp at p = dL/dv (12.13b)


def legendre_stationarity() -> LegendreStationarity:
    """For the quadratic L = m v^2/2 and H = p^2/(2m): the secant family p v - L(v) at fixed p
    is extreme where its v-derivative p - m v vanishes, which is at v = dH/dp = p/m; likewise
    v - p/m vanishes at p = dL/dv = m v. Derivatives and substitutions are symbolic."""
    m, v, p = Laurent.var("m"), Laurent.var("v"), Laurent.var("p")
    lagrangian = m * v**2 / 2
    hamiltonian = p**2 / (2 * m)
    h_of_v = (p * v - lagrangian).diff("v").substitute("v", hamiltonian.diff("p"))
    l_of_p = (p * v - hamiltonian).diff("p").substitute("p", lagrangian.diff("v"))
    return LegendreStationarity(
        hamiltonian_velocity_slope=Laurent.rational(h_of_v.value()),
        lagrangian_momentum_slope=Laurent.rational(l_of_p.value()),
    )


@dataclass(frozen=True)
class LegendreResult:
    """The Legendre transform F*(s) = max_x (s x - F(x)) and the point x where it is taken."""

    value: float
    argument: float


def legendre_transform(
    function: Callable[[float], float], slope: float, lower: float, upper: float
) -> LegendreResult:
    """Numerical Legendre transform F*(s) = max over x in [lower, upper] of s x - F(x) of a
    convex F ((12.11): H(p) = max_v (p v - L(v)), the tangent of slope p touching L at the
    maximising v, Fig. 12.4a). The maximum is found by a bounded scalar search; the value is
    insensitive to the error of the argument to second order. Floats.
    """
    from scipy.optimize import minimize_scalar

    inputs.real(slope, "slope")
    if not lower < upper:
        raise ValueError("need lower < upper")
    result = minimize_scalar(
        lambda x: function(x) - slope * x,
        bounds=(lower, upper),
        method="bounded",
        options={"xatol": 1e-12 * max(1.0, abs(lower), abs(upper))},
    )
    x = float(result.x)
    return LegendreResult(value=slope * x - function(x), argument=x)
