"""Laws of the Lagrangian and Hamiltonian models (mechmodel.lagrange): chapter 12.

Floats are compared within 1e-12 of the sum of the magnitudes involved, or within the stated
error of a numerical search or quadrature; Fraction and Laurent-polynomial results must be exact.
The numerical Legendre transform is checked against sympy's symbolic one.
"""

from __future__ import annotations

import math
from fractions import Fraction
from functools import cache

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from checks.properties.strategies import (
    convex_lagrangian_coefficients,
    exact_masses,
    exact_square_mass_ratios,
    exact_velocities,
    gravities,
    launch_angles,
    launch_speeds,
    legendre_slopes,
    oscillator_orbits,
)
from mechmodel import lagrange
from mechmodel.lagrange import Laurent

pytestmark = pytest.mark.properties
REL = 1e-12
SEARCH = 1e-9  # relative error allowed to a Legendre value found by a bounded scalar search


def _quartic(a: float, b: float):
    return lambda v: a * v**2 / 2 + b * v**4 / 4


def _close(x: float, y: float, *scale: float, rel: float = REL) -> bool:
    return abs(x - y) <= rel * (abs(x) + abs(y) + sum(abs(s) for s in scale) + 1e-300)


# -- the Legendre contact transformation (12.11)-(12.13) --------------------------------------


def _hamiltonian(a: float, b: float, p: float) -> lagrange.LegendreResult:
    bound = abs(p) / a + 1  # |L'(v)| >= a |v|, so the contact velocity is inside
    return lagrange.legendre_transform(_quartic(a, b), p, -bound, bound)


@settings(max_examples=50)
@given(convex_lagrangian_coefficients(), legendre_slopes())
@example((1.0, 0.0), 1.6)  # the quadratic L of Fig. 12.3's momentum
def test_legendre_transform_is_an_involution(coefficients: tuple[float, float], v: float) -> None:
    """Transforming L(v) to H(p) = max_v (p v - L) and H back gives L again (12.11a-b):
    the Legendre contact transformation is its own inverse for a convex L (Fig. 12.9)."""
    a, b = coefficients
    top = a * (abs(v) + 1) + b * (abs(v) + 1) ** 3  # |H'(p)| reaches |v| inside [-top, top]
    back = lagrange.legendre_transform(lambda p: _hamiltonian(a, b, p).value, v, -top, top)
    lag = _quartic(a, b)(v)
    assert abs(back.value - lag) <= SEARCH * (abs(lag) + abs(v) * top + 1)


@given(convex_lagrangian_coefficients(), legendre_slopes())
def test_hamiltonian_is_pv_minus_l_at_the_tangent_point(
    coefficients: tuple[float, float], p: float
) -> None:
    """H(p) = p v - L(v) (12.11b) at the velocity v where L has slope p: dL/dv = p there
    (12.10a), the tangent contact of Fig. 12.3."""
    a, b = coefficients
    h = _hamiltonian(a, b, p)
    v = h.argument
    assert _close(h.value, p * v - _quartic(a, b)(v), p * v)
    slope = a * v + b * v**3
    assert abs(slope - p) <= 1e-6 * (abs(p) + 1)


@cache
def _sympy_hamiltonians():
    """H(p) of L = m v^2/2 + c v and of L = m (e^v - 1 - v), derived by sympy: solve
    dL/dv = p for v (one real root each) and put it into p v - L."""
    import sympy

    v, p, m, c = sympy.symbols("v p m c", real=True)
    out = []
    for lag in (m * v**2 / 2 + c * v, m * (sympy.exp(v) - 1 - v)):
        (vp,) = sympy.solve(sympy.Eq(sympy.diff(lag, v), p), v)
        h = sympy.simplify(p * vp - lag.subs(v, vp))
        out.append((sympy.lambdify((m, c, v), lag, "math"), sympy.lambdify((m, c, p), h, "math")))
    return out


@settings(max_examples=50)
@given(
    st.floats(min_value=0.2, max_value=5),
    st.floats(min_value=-2, max_value=2),
    legendre_slopes(),
    st.sampled_from([0, 1]),
)
def test_legendre_transform_matches_sympy(m: float, c: float, p: float, which: int) -> None:
    """The numerical transform agrees with sympy's symbolic H(p) = p v(p) - L(v(p)) for a
    shifted quadratic and an exponential Lagrangian (12.11b)."""
    if which == 1:
        p = max(p, -0.9 * m)  # e^v - 1 > -1: slopes of the exponential L exceed -m
    lag, ham = _sympy_hamiltonians()[which]
    bound = (abs(p) + abs(c)) / m + 5  # beyond the contact velocity of either Lagrangian
    got = lagrange.legendre_transform(lambda v: lag(m, c, v), p, -bound, bound)
    want = ham(m, c, p)
    assert abs(got.value - want) <= SEARCH * (abs(want) + abs(p) * bound + 1)


@given(st.lists(st.tuples(exact_masses(), exact_velocities()), min_size=1, max_size=4))
def test_l_e_and_h_are_one_energy(pairs: list[tuple[Fraction, Fraction]]) -> None:
    """L(v), E(V) and H(p) take the same value (12.3)-(12.5): the quasi-velocities V = sqrt(m) v
    and momenta p = m v rescale one kinetic energy; exact where roots are not needed."""
    masses = [m for m, _ in pairs]
    velocities = [v for _, v in pairs]
    lag = lagrange.kinetic_energy(masses, velocities)
    ham = lagrange.hamiltonian_free(masses, lagrange.momenta(masses, velocities))
    assert lag == ham
    est = lagrange.estrangian(
        lagrange.quasi_velocities([float(m) for m in masses], [float(v) for v in velocities])
    )
    assert _close(est, float(lag), rel=1e-12)


@given(exact_square_mass_ratios())
@example(Fraction(16))  # Fig. 12.1
def test_collision_line_is_normal_to_the_bisector_only_in_v_space(ratio: Fraction) -> None:
    """In the Estrangian V plane the energy ellipse is a circle, so the collision line (tangent
    at the COM point) is perpendicular to the COM bisector: their slopes multiply to -1
    (Fig. 12.1b); the tangent is the collision line in all three planes; in the p plane the
    collision line has slope -1 whatever the masses (Fig. 12.1c). Exact."""
    s = lagrange.ke_ellipse_slopes(-ratio)
    assert s.quasi_collision * s.quasi_bisector == -1
    assert s.velocity_tangent == s.velocity_collision == -ratio
    assert s.quasi_tangent == s.quasi_collision
    assert s.momentum_tangent == s.momentum_collision == -1
    assert s.momentum_bisector == 1 / ratio
    assert s.quasi_bisector**2 == s.momentum_bisector


@given(st.lists(exact_masses(), min_size=1, max_size=3), st.floats(min_value=0.01, max_value=1e3))
def test_h_ellipse_radius_is_mass_times_l_ellipse_radius(masses: list[Fraction], e: float) -> None:
    """On each axis the H(p) = E ellipse reaches m_k times as far as the L(v) = E ellipse, and
    both radii lie on their ellipses (Fig. 12.2)."""
    ms = [float(m) for m in masses]
    radii = lagrange.energy_ellipse_radii(ms, e)
    for m, rv, rp in zip(ms, radii.velocity, radii.momentum, strict=True):
        assert _close(rp, m * rv)
        assert _close(m * rv**2 / 2, e)
        assert _close(rp**2 / (2 * m), e)


# -- the projectile family and its envelope (12.14)-(12.17) ------------------------------------


@given(launch_speeds(), launch_angles(), gravities(), st.floats(min_value=-3, max_value=3))
def test_each_trajectory_touches_the_envelope_once_where_the_model_says(
    v0: float, alpha: float, g: float, offset: float
) -> None:
    """y_env(x) - y(x) = (g / 2 v0^2)(x tan a - v0^2/g)^2 >= 0 (from (12.14c) and (12.17)): every
    trajectory lies under the envelope and touches it at exactly one point, x = v0^2/(g tan a)
    (12.16c), where the two curves also share their slope (Figs. 12.5-12.6)."""
    xc, yc = lagrange.contact_point(v0, alpha, g)
    x = xc * (1 + offset)
    gap = lagrange.envelope_height(x, v0, g) - lagrange.trajectory_height(x, v0, alpha, g)
    square = g / (2 * v0**2) * (x * math.tan(alpha) - v0**2 / g) ** 2
    scale = v0**2 / g + g * x**2 / v0**2 * (1 + math.tan(alpha) ** 2) + abs(x * math.tan(alpha))
    assert abs(gap - square) <= REL * 10 * scale
    assert gap >= -REL * 10 * scale
    assert _close(lagrange.trajectory_height(xc, v0, alpha, g), yc, v0**2 / g)
    h = 1e-6 * max(xc, 1e-3)
    slope_gap = (
        lagrange.envelope_height(xc + h, v0, g)
        - lagrange.envelope_height(xc - h, v0, g)
        - lagrange.trajectory_height(xc + h, v0, alpha, g)
        + lagrange.trajectory_height(xc - h, v0, alpha, g)
    ) / (2 * h)
    assert abs(slope_gap) <= 1e-6 * (1 + math.tan(alpha) + g * xc / v0**2)


@given(launch_speeds(), launch_angles(), gravities(), st.floats(min_value=0, max_value=5))
@example(2.0, 0.0, 9.8, 1.0)  # a horizontal launch: y = -g x^2 / (2 v0^2)
def test_positions_lie_on_the_trajectory_curve(v0: float, alpha: float, g: float, t: float) -> None:
    """Eliminating t from x(t), y(t) (12.14a-b) gives y(x) (12.14c), whose form the symbolic
    derivation fixes: y = x tan a - g x^k / (d v0^j cos^l a)."""
    fam = lagrange.projectile_family()
    x, y = lagrange.trajectory_position(t, v0, alpha, g)
    assert _close(y, lagrange.trajectory_height(x, v0, alpha, g), v0 * t, g * t**2)
    formula = x * math.tan(alpha) - g * x**fam.x_power / (
        float(fam.quadratic_denominator) * v0**fam.v0_power * math.cos(alpha) ** fam.cos_power
    )
    assert _close(formula, y, v0 * t, g * t**2)


def test_projectile_family_is_the_books_algebra() -> None:
    """The symbolic derivation gives (12.14)-(12.17): y = v0 sin(a) t - g t^2/2,
    y = x tan a - g x^2/(2 v0^2 cos^2 a), d(cos^-2 a)/da = 2 sin a/cos^3 a,
    1/cos^2 = 1 + tan^2, tan a = v0^2/(g x), y_env = v0^2/(2g) - g x^2/(2 v0^2), and only the
    horizontal trajectory shares the envelope's shape."""
    fam = lagrange.projectile_family()
    assert (fam.time_coefficient, fam.time_power) == (Fraction(1, 2), 2)
    assert (fam.quadratic_denominator, fam.x_power, fam.v0_power, fam.cos_power) == (2, 2, 2, 2)
    assert (fam.secant_derivative_coefficient, fam.secant_derivative_cos_power) == (2, 3)
    assert (fam.secant_tan_constant, fam.secant_tan_power, fam.tan_derivative_cos_power) == (
        1,
        2,
        2,
    )
    assert (fam.contact_tan_v0_power, fam.contact_tan_square_v0_power) == (2, 4)
    assert (fam.envelope_constant_denominator, fam.envelope_constant_v0_power) == (2, 2)
    assert fam.envelope_shape_angle == 0


# -- polar coordinates (12.26)-(12.37) ---------------------------------------------------------


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
    assert _close(g[0][0], 1)
    assert _close(g[1][1], r**2)
    assert abs(g[0][1]) <= 1e-12 * r
    assert abs(h[0][1]) <= 1e-12 / r
    assert _close(h[1][1] * g[1][1], 1)


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
    scale = mass * (abs(state.rddot) + state.r * state.phidot**2 + state.r) + 1
    assert abs(res_r) <= 1e-9 * scale
    assert abs(res_phi) <= 1e-9 * (abs(f.coriolis) + mass * state.r**2 * abs(state.phiddot) + 1)


@given(oscillator_orbits(), st.floats(min_value=0.1, max_value=10))
def test_hamiltonian_is_total_energy(
    orbit: tuple[float, float, float, float, float], mass: float
) -> None:
    """H = p_r^2/(2M) + p_phi^2/(2 M r^2) + U = p q' - L = T + U (12.36a), (12.37)."""
    state = _oscillator_state(orbit)
    if state.r < 1e-3:
        return
    f = lagrange.polar_forces(mass, state)
    u = mass * state.r**2 / 2
    t = mass * (state.rdot**2 + state.r**2 * state.phidot**2) / 2
    h = lagrange.polar_hamiltonian(mass, state.r, f.radial_momentum, f.angular_momentum, u)
    legendre = f.radial_momentum * state.rdot + f.angular_momentum * state.phidot - (t - u)
    assert _close(h, t + u, t, u)
    assert _close(h, legendre, t, u)


def test_polar_mechanics_is_the_books_algebra() -> None:
    """g = diag(1, r^2), g^-1 = diag(1, r^-2), L = M (r'^2 + r^2 phi'^2)/2, p_phi = M r^2 phi',
    centrifugal M r phi'^2 and Coriolis 2 M r r' phi' (12.26)-(12.33)."""
    p = lagrange.polar_mechanics()
    assert (p.metric_rr, p.metric_rphi, p.metric_phir, p.metric_phiphi_r_power) == (1, 0, 0, 2)
    assert (p.inverse_metric_rr, p.inverse_metric_phiphi_r_power) == (1, -2)
    assert p.kinetic_radial_coefficient == p.kinetic_angular_coefficient == Fraction(1, 2)
    assert (p.angular_momentum_r_power, p.centrifugal_rate_power, p.coriolis_coefficient) == (
        2,
        2,
        2,
    )
    assert p.jacobian_determinant_r_power == 1


# -- exact algebra --------------------------------------------------------------------------------


_POLYS = st.lists(
    st.tuples(
        st.integers(-3, 3),
        st.integers(-2, 3),
        st.integers(-2, 3),
    ),
    min_size=1,
    max_size=4,
).map(
    lambda terms: sum(
        (Laurent.constant(c) * Laurent.var("x", i) * Laurent.var("y", j) for c, i, j in terms),
        Laurent(),
    )
)


@given(_POLYS, _POLYS)
def test_laurent_derivative_obeys_leibniz(p: Laurent, q: Laurent) -> None:
    """d(pq)/dx = p dq/dx + q dp/dx, and differentiation undoes integration, exactly (the
    calculus behind every derived coefficient of chapter 12)."""
    assert (p * q).diff("x") == p * q.diff("x") + q * p.diff("x")
    if all(dict(k).get("x", 0) != -1 for k in p.terms):
        assert p.integrate("x").diff("x") == p


@given(st.integers(0, 4), st.integers(0, 5), st.floats(min_value=-3, max_value=3))
def test_trig_reduction_keeps_values(i: int, j: int, angle: float) -> None:
    """Rewriting sin^2 = 1 - cos^2 changes the form, not the value, of cos^i sin^j."""
    p = Laurent.var("c", i) * Laurent.var("s", j)
    values = {"c": math.cos(angle), "s": math.sin(angle)}
    assert abs(p.reduce_trig("c", "s").evaluate(values) - p.evaluate(values)) <= 1e-12 * 2**j


# -- action and phase (12.42)-(12.46) -----------------------------------------------------------


@given(st.integers(0, 50))
def test_bohr_phase_factor_is_one(n: int) -> None:
    """e^(i 2 pi upsilon) = 1 for every integer quantum number upsilon (12.45)."""
    z = lagrange.phase_factor(lagrange.bohr_phase(n))
    assert abs(z - 1) <= 1e-15 * (1 + 2 * math.pi * n)


@settings(max_examples=50)
@given(
    st.floats(min_value=0.1, max_value=3),
    st.floats(min_value=0, max_value=3),
    st.floats(min_value=0, max_value=6.283),
)
def test_oscillator_loop_action_is_two_pi_energy_over_omega(
    r0: float, speed: float, angle: float
) -> None:
    """Over one period of the 2-D oscillator (omega = M = 1) the reduced action
    S_H = integral p . dr = integral 2T dt is 2 pi E (virial theorem: mean T = E/2), the loop
    action Bohr quantizes in (12.45)."""
    if speed == 0:
        speed = 1e-3
    paths = lagrange.oscillator_paths((r0, 0.0), speed, [angle], 2 * math.pi, samples=2001)
    e = (speed**2 + r0**2) / 2
    assert abs(paths.action[0, -1] - 2 * math.pi * e) <= 1e-5 * (1 + e)


@given(st.floats(min_value=-5, max_value=5), st.floats(min_value=0.1, max_value=5))
def test_path_action_of_uniform_motion(v: float, duration: float) -> None:
    """S = integral L dt of a free particle at constant speed is m v^2 T / 2 (12.38)."""
    times = [duration * k / 10 for k in range(11)]
    lag = [v**2 / 2] * 11
    assert _close(lagrange.path_action(lag, times), v**2 * duration / 2)


def test_common_speed_rejects_different_speeds() -> None:
    """The starlet fragments of exercise 1.12.3 share one speed; a list that does not is an
    error, not an average."""
    assert lagrange.common_speed([[0, 1], [1, 0], [-(2**-0.5), 2**-0.5]]) == pytest.approx(1)
    with pytest.raises(ValueError, match="different speeds"):
        lagrange.common_speed([[0, 1], [1, 1]])
