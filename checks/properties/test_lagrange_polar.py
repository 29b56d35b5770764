"""Laws of polar coordinates (mechmodel.lagrange.polar): chapter 12, (12.26)-(12.37).

The Jacobian, Kajobian and metrics, the polar Lagrangian, its Lagrange equations along
oscillator orbits, momenta, forces and the Hamiltonian.

Floats are compared within 1e-12 of the sum of the magnitudes involved, or within the
stated error of a central difference; Fraction results must be exact. Tolerances shared by
the lagrange modules are in ``_lagrange_helpers``.
"""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import given
from hypothesis import strategies as st

from checks.properties._lagrange_helpers import FLOOR
from checks.properties.closeness import assert_close, magnitude
from checks.properties.strategies import oscillator_orbits
from mechmodel import lagrange

pytestmark = pytest.mark.properties


@given(st.floats(min_value=0.01, max_value=100), st.floats(min_value=-7, max_value=7))
def test_kajobian_inverts_the_jacobian(r: float, phi: float) -> None:
    """K J = 1 (12.20): the contravariant rows of K are dual to the covariant columns of J, and
    the metrics J^T J = diag(1, r^2) and K K^T = diag(1, 1/r^2) are mutual inverses (12.30)."""
    j, k = lagrange.polar_jacobian(r, phi), lagrange.polar_kajobian(r, phi)
    for m in range(2):
        for n in range(2):
            kj = sum(k[m][i] * j[i][n] for i in range(2))
            assert abs(kj - (m == n)) <= 1e-12 * (1 + r + 1 / r)
    g, h = lagrange.polar_metric(r, phi), lagrange.polar_inverse_metric(r, phi)
    assert_close(g[0][0], 1, abs=FLOOR)
    assert_close(g[1][1], r**2, abs=FLOOR)
    assert abs(g[0][1]) <= 1e-12 * r
    assert abs(h[0][1]) <= 1e-12 / r
    assert_close(h[1][1] * g[1][1], 1, abs=FLOOR)


def _oscillator_state(orbit: tuple[float, float, float, float, float]) -> lagrange.PolarState:
    a_amp, b_amp, a, b, t = orbit
    pos = (a_amp * math.cos(t + a), b_amp * math.cos(t + b))
    vel = (-a_amp * math.sin(t + a), -b_amp * math.sin(t + b))
    acc = (-pos[0], -pos[1])  # omega = 1
    return lagrange.polar_state(pos, vel, acc)


@given(oscillator_orbits(), st.floats(min_value=0.1, max_value=10))
def test_euler_lagrange_residual_vanishes_on_oscillator_orbits(
    orbit: tuple[float, float, float, float, float], mass: float
) -> None:
    """Along a true motion of the oscillator U = M r^2/2 the polar Lagrange equations (12.33)
    hold: M r'' = M r phi'^2 - dU/dr and d(M r^2 phi')/dt = M r^2 phi'' + 2 M r r' phi' = 0."""
    state = _oscillator_state(orbit)
    if state.r < 1e-3:
        return  # polar coordinates are singular at the origin
    res_r, res_phi = lagrange.euler_lagrange_residual(mass, state, (mass * state.r, 0.0))
    f = lagrange.polar_forces(mass, state)
    scale = mass * (abs(float(state.rddot)) + state.r * state.phidot**2 + state.r) + 1
    assert abs(res_r) <= 1e-9 * scale
    angular = mass * state.r**2 * abs(float(state.phiddot))
    assert abs(res_phi) <= 1e-9 * (abs(float(f.coriolis)) + angular + 1)
    # a central force keeps p_phi: the Coriolis term balances M r^2 phi'' (12.33)
    assert abs(f.coriolis + mass * state.r**2 * state.phiddot) <= 1e-9 * (angular + 1)


@given(
    oscillator_orbits(),
    st.floats(min_value=0.1, max_value=10),
    st.floats(min_value=0.3, max_value=3),
)
def test_euler_lagrange_residual_vanishes_on_anisotropic_orbits(
    orbit: tuple[float, float, float, float, float], mass: float, wy: float
) -> None:
    """The polar Lagrange equations (12.25c), (12.33) hold for the non-central oscillator
    U = M (x^2 + wy^2 y^2)/2, whose x = A cos(t + a), y = B cos(wy t + b): with
    dU/dr = M r (cos^2 + wy^2 sin^2) and dU/dphi = M r^2 (wy^2 - 1) sin cos, the angular
    momentum changes at d p_phi/dt = -dU/dphi."""
    a_amp, b_amp, a, b, t = orbit
    pos = (a_amp * math.cos(t + a), b_amp * math.cos(wy * t + b))
    vel = (-a_amp * math.sin(t + a), -wy * b_amp * math.sin(wy * t + b))
    state = lagrange.polar_state(pos, vel, (-pos[0], -wy * wy * pos[1]))
    if state.r < 1e-3:
        return  # polar coordinates are singular at the origin
    c, s = math.cos(state.phi), math.sin(state.phi)
    du_dr = mass * state.r * (c * c + wy * wy * s * s)
    du_dphi = mass * state.r**2 * (wy * wy - 1) * s * c
    res_r, res_phi = lagrange.euler_lagrange_residual(mass, state, (du_dr, du_dphi))
    f = lagrange.polar_forces(mass, state)
    scale = mass * (abs(float(state.rddot)) + state.r * state.phidot**2 + state.r * (1 + wy * wy))
    assert abs(res_r) <= 1e-9 * (scale + 1)
    assert abs(res_phi) <= 1e-9 * (
        abs(float(f.coriolis)) + abs(float(f.angular_momentum_rate)) + scale * state.r + 1
    )
    assert abs(f.angular_momentum_rate + du_dphi) <= 1e-9 * (
        abs(float(f.coriolis)) + scale * state.r + 1
    )


@given(oscillator_orbits(), st.floats(min_value=0.1, max_value=10))
def test_hamiltonian_is_total_energy(
    orbit: tuple[float, float, float, float, float], mass: float
) -> None:
    """H = p_r^2/(2M) + p_phi^2/(2 M r^2) + U = p q' - L = T + U (12.36a), (12.37); without a
    potential (U = 0, free motion) H is the kinetic energy T alone."""
    state = _oscillator_state(orbit)
    if state.r < 1e-3:
        return
    f = lagrange.polar_forces(mass, state)
    u = mass * state.r**2 / 2
    t = mass * (state.rdot**2 + state.r**2 * state.phidot**2) / 2
    h = lagrange.polar_hamiltonian(mass, state.r, f.radial_momentum, f.angular_momentum, u)
    legendre = f.radial_momentum * state.rdot + f.angular_momentum * state.phidot - (t - u)
    assert_close(h, t + u, scale=magnitude(h, t + u, t, u), abs=FLOOR)
    assert_close(h, legendre, scale=magnitude(h, legendre, t, u), abs=FLOOR)
    free = lagrange.polar_hamiltonian(mass, state.r, f.radial_momentum, f.angular_momentum)
    assert_close(free, t, scale=magnitude(free, t, t), abs=FLOOR)


def test_polar_mechanics_is_the_books_algebra() -> None:
    """g = diag(1, r^2), g^-1 = diag(1, r^-2), L = M (r'^2 + r^2 phi'^2)/2, p_phi = M r^2 phi',
    centrifugal M r phi'^2 and Coriolis 2 M r r' phi' (12.26)-(12.33)."""
    p = lagrange.polar_mechanics()
    assert (p.metric_rr, p.metric_rphi, p.metric_phir, p.metric_phiphi_r_power) == (
        Fraction(1),
        Fraction(0),
        Fraction(0),
        2,
    )
    assert (p.inverse_metric_rr, p.inverse_metric_phiphi_r_power) == (Fraction(1), -2)
    assert p.kinetic_radial_coefficient == p.kinetic_angular_coefficient == Fraction(1, 2)
    assert (p.angular_momentum_r_power, p.centrifugal_rate_power, p.coriolis_coefficient) == (
        2,
        2,
        Fraction(2),
    )
    assert p.jacobian_determinant_r_power == 1
    assert (p.metric_phiphi_coefficient, p.inverse_metric_phiphi_coefficient) == (Fraction(1),) * 2
    assert (p.inverse_metric_rphi, p.inverse_metric_phir) == (Fraction(0),) * 2
    assert (p.kinetic_angular_rate_power, p.kinetic_angular_r_power) == (2, 2)
    assert (p.radial_momentum_coefficient, p.angular_momentum_rate_r_power) == (Fraction(1), 2)


# -- formula models: the polar Lagrangian and momenta at a Cartesian state ---------------------


def _cartesian_state(
    orbit: tuple[float, float, float, float, float],
) -> tuple[tuple[float, float], tuple[float, float]]:
    a_amp, b_amp, a, b, t = orbit
    pos = (a_amp * math.cos(t + a), b_amp * math.cos(t + b))
    vel = (-a_amp * math.sin(t + a), -b_amp * math.sin(t + b))
    return pos, vel


@given(oscillator_orbits(), st.floats(min_value=0.1, max_value=10), st.floats(-5, 5))
def test_polar_lagrangian_and_momenta_are_the_cartesian_ones(
    orbit: tuple[float, float, float, float, float], mass: float, u: float
) -> None:
    """At a Cartesian state, the polar Lagrangian from (r, r', phi') is M |v|^2/2 - U (12.32),
    p_phi is the angular momentum M (x vy - y vx) and p_r = M r.v/r (12.25e); dL/dr at fixed
    rates (a central difference) is the centrifugal force minus dU/dr (12.33)."""
    pos, vel = _cartesian_state(orbit)
    state = lagrange.polar_state(pos, vel, (0.0, 0.0))
    if state.r < 1e-3:
        return
    speed2 = vel[0] ** 2 + vel[1] ** 2
    lag = lagrange.polar_lagrangian(mass, state.r, state.rdot, state.phidot, u, state.phi)
    assert abs(lag - (mass * speed2 / 2 - u)) <= 1e-12 * (mass * speed2 + abs(u) + 1)
    terms = lagrange.polar_terms(mass, state.r, state.rdot, state.phidot)
    cross = pos[0] * vel[1] - pos[1] * vel[0]
    momentum = terms.angular_momentum
    swept = mass * state.r * math.sqrt(speed2)
    assert_close(momentum, mass * cross, scale=magnitude(momentum, mass * cross, swept), abs=FLOOR)
    dot = (pos[0] * vel[0] + pos[1] * vel[1]) / state.r
    momentum, speed = terms.radial_momentum, math.sqrt(speed2)
    assert_close(
        momentum, mass * dot, scale=magnitude(momentum, mass * dot, mass * speed), abs=FLOOR
    )
    h = 1e-6 * state.r
    d_lag = (
        lagrange.polar_lagrangian(mass, state.r + h, state.rdot, state.phidot)
        - lagrange.polar_lagrangian(mass, state.r - h, state.rdot, state.phidot)
    ) / (2 * h)
    forces = lagrange.polar_generalized_forces(mass, state.r, state.rdot, state.phidot, u, -u)
    assert abs(forces.radial - (d_lag - u)) <= 1e-6 * (mass * speed2 / state.r + abs(u) + 1)
    assert forces.angular == u
    with pytest.raises(ValueError, match="positive"):
        lagrange.polar_terms(mass, 0.0, state.rdot, state.phidot)
