"""Polar coordinates: Jacobian, Kajobian, metric, Lagrangian, momenta and forces,
(12.26)-(12.37).

The Jacobian J = d(x, y)/d(r, phi) and its inverse, the "Kajobian" K (12.26); the covariant and
contravariant metrics J^T J and K K^T (12.30); the Lagrangian L = M (r'^2 + r^2 phi'^2)/2 - U
(12.32), derived exactly from x = r cos phi, y = r sin phi; the momenta p_r = M r',
p_phi = M r^2 phi' and the forces of the Lagrange equations: centrifugal M r phi'^2 and Coriolis
2 M r r' phi' (12.33); the residuals of those equations along a motion, and the Hamiltonian
g^mn p_m p_n/(2M) + U (12.37c). SI units: r in m, phi in radians, M in kg.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction

from mechmodel import inputs
from mechmodel.algebra import Laurent
from mechmodel.ellipse import kinetic_energy
from mechmodel.lagrange._common import _lib
from mechmodel.lagrange.calculus import angle_derivative, time_derivative
from mechmodel.typing import Real, Vector


def polar_jacobian(r: Real, phi: Real) -> list[list[float]]:
    """Jacobian J[j][m] = dx^j/dq^m of x = r cos phi, y = r sin phi (12.26); its columns are the
    covariant bases E_r, E_phi."""
    inputs.real(r, "r")
    lib = _lib(r, phi)
    c, s = lib.cos(phi), lib.sin(phi)
    return [[c, -r * s], [s, r * c]]


def polar_kajobian(r: Real, phi: Real) -> list[list[float]]:
    """The inverse ("Kajobian") K[m][j] = dq^m/dx^j of the polar Jacobian (12.26); its rows
    are the contravariant bases E^r, E^phi. ``ValueError`` at the origin."""
    inputs.real(r, "r")
    if r == 0:
        raise ValueError("polar coordinates are singular at r = 0")
    lib = _lib(r, phi)
    c, s = lib.cos(phi), lib.sin(phi)
    return [[c, s], [-s / r, c / r]]


def polar_metric(r: Real, phi: Real = 0) -> list[list[float]]:
    """Covariant metric g_mn = E_m . E_n = (J^T J)_mn of polar coordinates (12.30b)."""
    j = polar_jacobian(r, phi)
    return [[sum(j[k][m] * j[k][n] for k in range(2)) for n in range(2)] for m in range(2)]


def polar_inverse_metric(r: Real, phi: Real = 0) -> list[list[float]]:
    """Contravariant metric g^mn = E^m . E^n = (K K^T)^mn of polar coordinates (12.30c)."""
    k = polar_kajobian(r, phi)
    return [[sum(k[m][j] * k[n][j] for j in range(2)) for n in range(2)] for m in range(2)]


_POLAR_RATES = {
    "r": Laurent.var("rd"),
    "rd": Laurent.var("rdd"),
    "pd": Laurent.var("pdd"),
    "c": -Laurent.var("s") * Laurent.var("pd"),
    "s": Laurent.var("c") * Laurent.var("pd"),
}


@dataclass(frozen=True)
class PolarMechanics:
    """Exact results of the polar-coordinate Lagrange mechanics (12.26)-(12.33).

    Variables: r, its rate rd (r'), the angular rate pd (phi'), M the mass. Matrices are given
    entry by entry as coefficients of the power of r shown.
    """

    jacobian_determinant_r_power: int
    metric_rr: Fraction
    metric_rphi: Fraction
    metric_phir: Fraction
    metric_phiphi_coefficient: Fraction
    metric_phiphi_r_power: int
    inverse_metric_rr: Fraction
    inverse_metric_rphi: Fraction
    inverse_metric_phir: Fraction
    inverse_metric_phiphi_coefficient: Fraction
    inverse_metric_phiphi_r_power: int
    kinetic_radial_coefficient: Fraction  # T = coef M r'^2 + ...
    kinetic_angular_coefficient: Fraction  # ... + coef M r^2 phi'^2
    kinetic_angular_rate_power: int
    kinetic_angular_r_power: int
    radial_momentum_coefficient: Fraction  # p_r = coef M r'
    angular_momentum_r_power: int  # p_phi = M r^k phi'
    centrifugal_rate_power: int  # dL/dr = M r phi'^k
    angular_momentum_rate_r_power: int  # dp_phi/dt = M r^k phi'' + ...
    coriolis_coefficient: Fraction  # ... + coef M r r' phi'


def _polar_lagrangian() -> tuple[Laurent, dict[str, Laurent]]:
    """T = M (x'^2 + y'^2)/2 with x = r cos phi, y = r sin phi, in r, r', phi'."""
    r, c, s = Laurent.var("r"), Laurent.var("c"), Laurent.var("s")
    x, y = r * c, r * s
    xd, yd = time_derivative(x, _POLAR_RATES), time_derivative(y, _POLAR_RATES)
    kinetic = (Laurent.var("M") * (xd**2 + yd**2) / 2).reduce_trig("c", "s")
    return kinetic, {"x": x, "y": y}


def polar_mechanics() -> PolarMechanics:
    """Polar Jacobian, metric, Lagrangian, momenta and forces, derived exactly.

    J = d(x, y)/d(r, phi) by differentiation (angle derivatives with cos' = -sin, sin' = cos);
    K = J^-1 by the adjugate over det J (a single term, r); g = J^T J and g^-1 = K K^T, reduced
    with sin^2 = 1 - cos^2 (12.26), (12.30). T = M (x'^2 + y'^2)/2 becomes
    M r'^2/2 + M r^2 phi'^2/2 (12.32); p_r = dL/dr', p_phi = dL/dphi'; the Lagrange equations
    (12.25d) give dp_r/dt = dL/dr = M r phi'^2 - dU/dr (centrifugal) and
    dp_phi/dt = d(M r^2 phi')/dt = M r^2 phi'' + 2 M r r' phi' (Coriolis), (12.33).
    """
    kinetic, xy = _polar_lagrangian()
    cols = [
        [xy[k].diff("r") for k in ("x", "y")],
        [angle_derivative(xy[k], "c", "s") for k in ("x", "y")],
    ]
    jac = [[cols[m][j] for m in range(2)] for j in range(2)]  # jac[j][m] = dx^j/dq^m
    det = (jac[0][0] * jac[1][1] - jac[0][1] * jac[1][0]).reduce_trig("c", "s")
    inv_det = det.monomial_inverse()
    kaj = [
        [(jac[1][1] * inv_det).reduce_trig("c", "s"), (-jac[0][1] * inv_det).reduce_trig("c", "s")],
        [(-jac[1][0] * inv_det).reduce_trig("c", "s"), (jac[0][0] * inv_det).reduce_trig("c", "s")],
    ]
    metric = [
        [
            sum((jac[k][m] * jac[k][n] for k in range(2)), Laurent()).reduce_trig("c", "s")
            for n in range(2)
        ]
        for m in range(2)
    ]
    inverse = [
        [
            sum((kaj[m][j] * kaj[n][j] for j in range(2)), Laurent()).reduce_trig("c", "s")
            for n in range(2)
        ]
        for m in range(2)
    ]
    radial = kinetic.part("rd", 2)
    angular = kinetic.part("pd", 2)
    p_r = kinetic.diff("rd")
    p_phi = kinetic.diff("pd")
    centrifugal = kinetic.diff("r")
    p_phi_rate = time_derivative(p_phi, _POLAR_RATES)
    return PolarMechanics(
        jacobian_determinant_r_power=det.power("r"),
        metric_rr=Laurent.rational(metric[0][0].value()),
        metric_rphi=Laurent.rational(metric[0][1].value()),
        metric_phir=Laurent.rational(metric[1][0].value()),
        metric_phiphi_coefficient=Laurent.rational(metric[1][1].only_coefficient()),
        metric_phiphi_r_power=metric[1][1].power("r"),
        inverse_metric_rr=Laurent.rational(inverse[0][0].value()),
        inverse_metric_rphi=Laurent.rational(inverse[0][1].value()),
        inverse_metric_phir=Laurent.rational(inverse[1][0].value()),
        inverse_metric_phiphi_coefficient=Laurent.rational(inverse[1][1].only_coefficient()),
        inverse_metric_phiphi_r_power=inverse[1][1].power("r"),
        kinetic_radial_coefficient=Laurent.rational(radial.only_coefficient()),
        kinetic_angular_coefficient=Laurent.rational(angular.only_coefficient()),
        kinetic_angular_rate_power=angular.power("pd"),
        kinetic_angular_r_power=angular.power("r"),
        radial_momentum_coefficient=Laurent.rational(p_r.only_coefficient()),
        angular_momentum_r_power=p_phi.power("r"),
        centrifugal_rate_power=centrifugal.power("pd"),
        angular_momentum_rate_r_power=p_phi_rate.part("pdd", 1).power("r"),
        coriolis_coefficient=Laurent.rational(p_phi_rate.part("pdd", 0).only_coefficient()),
    )


@dataclass(frozen=True)
class PolarState:
    """Polar coordinates of a plane motion and their first and second time derivatives."""

    r: Real
    phi: Real
    rdot: Real
    phidot: Real
    rddot: Real
    phiddot: Real


def polar_state(position: Vector, velocity: Vector, acceleration: Vector) -> PolarState:
    """(r, phi) and their rates from Cartesian position, velocity and acceleration, by the
    Kajobian (12.26): q' = K x', and q'' from differentiating q' = K x' once more."""
    x, y = (inputs.real(v, "position") for v in position)
    vx, vy = velocity
    ax, ay = acceleration
    r = math.hypot(x, y)
    if r == 0:
        raise ValueError("polar coordinates are singular at r = 0")
    phi = math.atan2(y, x)
    rdot = (x * vx + y * vy) / r
    phidot = (x * vy - y * vx) / r**2
    rddot = (vx**2 + vy**2 + x * ax + y * ay) / r - rdot**2 / r
    phiddot = (x * ay - y * ax) / r**2 - 2 * rdot * phidot / r
    return PolarState(r, phi, rdot, phidot, rddot, phiddot)


@dataclass(frozen=True)
class PolarForces:
    """Terms of the polar Lagrange equations (12.33) at one state, from the exact Lagrangian."""

    radial_momentum: Real  # p_r = M r'
    angular_momentum: Real  # p_phi = M r^2 phi'
    radial_momentum_rate: Real  # d p_r / dt = M r''
    centrifugal: Real  # dT/dr = M r phi'^2
    angular_momentum_rate: Real  # d p_phi / dt = M r^2 phi'' + 2 M r r' phi'
    coriolis: Real  # 2 M r r' phi'


def polar_forces(mass: Real, state: PolarState) -> PolarForces:
    """Evaluate the derived polar momenta and forces (12.32)-(12.33) at a state."""
    inputs.mass(mass)
    kinetic, _ = _polar_lagrangian()
    p_r, p_phi = kinetic.diff("rd"), kinetic.diff("pd")
    values = {
        "M": mass,
        "r": state.r,
        "rd": state.rdot,
        "pd": state.phidot,
        "rdd": state.rddot,
        "pdd": state.phiddot,
    }
    p_phi_rate = time_derivative(p_phi, _POLAR_RATES)
    return PolarForces(
        radial_momentum=p_r.evaluate_real(values),
        angular_momentum=p_phi.evaluate_real(values),
        radial_momentum_rate=time_derivative(p_r, _POLAR_RATES).evaluate_real(values),
        centrifugal=kinetic.diff("r").evaluate_real(values),
        angular_momentum_rate=p_phi_rate.evaluate_real(values),
        coriolis=p_phi_rate.part("pdd", 0).evaluate_real(values),
    )


def euler_lagrange_residual(
    mass: Real, state: PolarState, potential_gradient: Sequence[float]
) -> tuple[float, float]:
    """Residuals d/dt(dL/dq') - dL/dq of the polar Lagrange equations (12.25c) for
    L = T - U(r, phi), with (dU/dr, dU/dphi) given: zero along a true motion."""
    f = polar_forces(mass, state)
    du_dr, du_dphi = potential_gradient
    return (
        f.radial_momentum_rate - (f.centrifugal - du_dr),
        f.angular_momentum_rate - (0 - du_dphi),
    )


def polar_hamiltonian(
    mass: Real, r: Real, radial_momentum: Real, angular_momentum: Real, potential: Real = 0
) -> float:
    """H = p_r^2/(2M) + p_phi^2/(2 M r^2) + U = g^mn p_m p_n /(2M) + U (12.37c), with the
    polar inverse metric diag(1, 1/r^2)."""
    inputs.mass(mass)
    inputs.positive(r, "r")
    g = polar_inverse_metric(r)
    p = (radial_momentum, angular_momentum)
    return sum(g[m][n] * p[m] * p[n] for m in range(2) for n in range(2)) / (2 * mass) + potential


def polar_lagrangian(
    mass: Real, r: Real, rdot: Real, phidot: Real, potential: Real = 0, phi: Real = 0
) -> float:
    """L = T - U (12.25b) of a particle at polar (r, phi) moving at rates (r', phi'): the
    Cartesian velocity is J.q' by the polar Jacobian (12.19), (12.26), and
    T = M (vx^2 + vy^2)/2 (12.23). Floats (the Jacobian takes the cosine and sine)."""
    j = polar_jacobian(r, phi)
    velocity = [j[k][0] * rdot + j[k][1] * phidot for k in range(2)]
    return float(kinetic_energy([mass, mass], velocity) - potential)  # the velocity is float


def polar_terms(
    mass: Real, r: Real, rdot: Real, phidot: Real, rddot: Real = 0, phiddot: Real = 0
) -> PolarForces:
    """The polar momenta and forces of (12.32)-(12.33), ``polar_forces``, at a state given by
    its polar coordinate rates (the angle itself does not enter)."""
    for value, name in ((rdot, "rdot"), (phidot, "phidot"), (rddot, "rddot"), (phiddot, "phiddot")):
        inputs.real(value, name)
    inputs.positive(r, "r")
    return polar_forces(mass, PolarState(r, 0.0, rdot, phidot, rddot, phiddot))


@dataclass(frozen=True)
class PolarGeneralizedForces:
    """dL/dq of the polar Lagrangian L = T - U: the right sides dp_m/dt of (12.25d), (12.33)."""

    radial: Real  # dL/dr = M r phi'^2 - dU/dr
    angular: Real  # dL/dphi = -dU/dphi


def polar_generalized_forces(
    mass: Real, r: Real, rdot: Real, phidot: Real, du_dr: Real, du_dphi: Real = 0
) -> PolarGeneralizedForces:
    """dL/dr and dL/dphi of L = T - U(r, phi) in polar coordinates (12.33): the kinetic part
    differentiated exactly (the centrifugal term of ``polar_terms``), minus the potential's
    gradient (dU/dr, dU/dphi)."""
    inputs.real(du_dr, "du_dr")
    inputs.real(du_dphi, "du_dphi")
    terms = polar_terms(mass, r, rdot, phidot)
    return PolarGeneralizedForces(radial=terms.centrifugal - du_dr, angular=0 - du_dphi)
