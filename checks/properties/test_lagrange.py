"""Laws of the Lagrangian and Hamiltonian models (mechmodel.lagrange): chapter 12.

Floats are compared within 1e-12 of the sum of the magnitudes involved, or within the stated
error of a numerical search or quadrature; Fraction and Laurent-polynomial results must be exact.
The numerical Legendre transform is checked against sympy's symbolic one.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from fractions import Fraction
from functools import cache

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from checks.properties.closeness import assert_close, magnitude
from checks.properties.strategies import (
    convex_lagrangian_coefficients,
    exact_masses,
    exact_plane_vectors,
    exact_square_mass_ratios,
    exact_symmetric_matrices,
    exact_velocities,
    gravities,
    launch_angles,
    launch_speeds,
    legendre_slopes,
    oscillator_orbits,
)
from mechmodel import lagrange

pytestmark = pytest.mark.properties
REL = 1e-12
FLOOR = REL * 1e-300  # subnormal magnitudes carry no relative precision: an absolute floor
SEARCH = 1e-9  # relative error allowed to a Legendre value found by a bounded scalar search


def _quartic(a: float, b: float) -> Callable[[float], float]:
    return lambda v: a * v**2 / 2 + b * v**4 / 4


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
    contact = p * v - _quartic(a, b)(v)
    assert_close(h.value, contact, scale=magnitude(h.value, contact, p * v), abs=FLOOR)
    slope = a * v + b * v**3
    assert abs(slope - p) <= 1e-6 * (abs(p) + 1)
    with pytest.raises(ValueError, match="lower < upper"):
        lagrange.legendre_transform(_quartic(a, b), p, v, v)  # an empty search interval


@cache
def _sympy_hamiltonians() -> list[tuple[Callable[..., float], Callable[..., float]]]:
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
    assert_close(est, float(lag), rel=1e-12, abs=FLOOR)


@given(exact_masses(), exact_velocities())
@example(Fraction(8, 5), Fraction(1))  # Fig. 12.3: L = 1.0 at v = 1.0 with slope p = 1.6
def test_legendre_tangents_meet_the_axes_at_minus_the_transform(m: Fraction, v: Fraction) -> None:
    """The tangent to L = m v^2/2 at v has slope p = dL/dv = m v (12.10a) and meets the L axis
    at L - p v = -H(p), H = p^2/(2m) (12.11b, Fig. 12.3a); the tangent to H at p, of slope
    v = dH/dp, meets the H axis at -L (12.11a, Fig. 12.3b). Exact."""
    lag = lagrange.kinetic_energy([m], [v])
    (p,) = lagrange.momenta([m], [v])
    ham = lagrange.hamiltonian_free([m], [p])
    tangent = lagrange.legendre_tangent(lag, p, v)
    assert (tangent.transform, tangent.intercept) == (ham, -ham)
    back = lagrange.legendre_tangent(ham, v, p)
    assert (back.transform, back.intercept) == (lag, -lag)


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
    assert all(isinstance(x, Fraction) for x in (s.quasi_collision, s.quasi_bisector))
    # a float slope gives the same lines in floats
    f = lagrange.ke_ellipse_slopes(-float(ratio))
    assert_close(f.mass_ratio, float(ratio), abs=FLOOR)
    assert_close(f.velocity_collision, -float(ratio), abs=FLOOR)
    assert_close(f.velocity_tangent, -float(ratio), abs=FLOOR)
    assert_close(f.quasi_collision * f.quasi_bisector, -1.0, abs=FLOOR)
    assert_close(f.quasi_bisector**2, f.momentum_bisector, abs=FLOOR)
    assert_close(f.momentum_tangent, -1.0, abs=FLOOR)
    assert_close(f.momentum_bisector, 1 / float(ratio), abs=FLOOR)


@given(st.lists(exact_masses(), min_size=1, max_size=3), st.floats(min_value=0.01, max_value=1e3))
def test_h_ellipse_radius_is_mass_times_l_ellipse_radius(masses: list[Fraction], e: float) -> None:
    """On each axis the H(p) = E ellipse reaches m_k times as far as the L(v) = E ellipse, and
    both radii lie on their ellipses (Fig. 12.2)."""
    ms = [float(m) for m in masses]
    radii = lagrange.energy_ellipse_radii(ms, e)
    for m, rv, rp in zip(ms, radii.velocity, radii.momentum, strict=True):
        assert_close(rp, m * rv, abs=FLOOR)
        assert_close(m * rv**2 / 2, e, abs=FLOOR)
        assert_close(rp**2 / (2 * m), e, abs=FLOOR)


# -- the projectile family and its envelope (12.14)-(12.17) ------------------------------------


@given(launch_speeds(), launch_angles(), gravities(), st.floats(min_value=-3, max_value=3))
def test_each_trajectory_touches_the_envelope_once_where_the_model_says(
    v0: float, alpha: float, g: float, offset: float
) -> None:
    """y_env(x) - y(x) = (g / 2 v0^2)(x tan a - v0^2/g)^2 >= 0 (from (12.14c) and (12.17)): every
    trajectory lies under the envelope and touches it at exactly one point, x = v0^2/(g tan a)
    (12.16c), where the two curves also share their slope (Figs. 12.5-12.6). The horizontal
    launch never touches it: a ValueError."""
    xc, yc = lagrange.contact_point(v0, alpha, g)
    x = xc * (1 + offset)
    gap = lagrange.envelope_height(x, v0, g) - lagrange.trajectory_height(x, v0, alpha, g)
    square = g / (2 * v0**2) * (x * math.tan(alpha) - v0**2 / g) ** 2
    scale = v0**2 / g + g * x**2 / v0**2 * (1 + math.tan(alpha) ** 2) + abs(x * math.tan(alpha))
    assert abs(gap - square) <= REL * 10 * scale
    assert gap >= -REL * 10 * scale
    height = lagrange.trajectory_height(xc, v0, alpha, g)
    assert_close(height, yc, scale=magnitude(height, yc, v0**2 / g), abs=FLOOR)
    h = 1e-6 * max(xc, 1e-3)
    slope_gap = (
        lagrange.envelope_height(xc + h, v0, g)
        - lagrange.envelope_height(xc - h, v0, g)
        - lagrange.trajectory_height(xc + h, v0, alpha, g)
        + lagrange.trajectory_height(xc - h, v0, alpha, g)
    ) / (2 * h)
    assert abs(slope_gap) <= 1e-6 * (1 + math.tan(alpha) + g * xc / v0**2)
    with pytest.raises(ValueError, match="horizontal"):  # y = -g x^2/2v0^2 stays below it
        lagrange.contact_point(v0, 0.0, g)


@given(launch_speeds(), launch_angles(), gravities(), st.floats(min_value=0, max_value=5))
@example(2.0, 0.0, 9.8, 1.0)  # a horizontal launch: y = -g x^2 / (2 v0^2)
def test_positions_lie_on_the_trajectory_curve(v0: float, alpha: float, g: float, t: float) -> None:
    """Eliminating t from x(t), y(t) (12.14a-b) gives y(x) (12.14c), whose form the symbolic
    derivation fixes: y = x tan a - g x^k / (d v0^j cos^l a)."""
    fam = lagrange.projectile_family()
    x, y = lagrange.trajectory_position(t, v0, alpha, g)
    height = lagrange.trajectory_height(x, v0, alpha, g)
    assert_close(y, height, scale=magnitude(y, height, v0 * t, g * t**2), abs=FLOOR)
    formula = x * math.tan(alpha) - g * x**fam.x_power / (
        float(fam.quadratic_denominator) * v0**fam.v0_power * math.cos(alpha) ** fam.cos_power
    )
    assert_close(formula, y, scale=magnitude(formula, y, v0 * t, g * t**2), abs=FLOOR)


def test_projectile_family_is_the_books_algebra() -> None:
    """The symbolic derivation gives (12.14)-(12.17): y = v0 sin(a) t - g t^2/2,
    y = x tan a - g x^2/(2 v0^2 cos^2 a), d(cos^-2 a)/da = 2 sin a/cos^3 a,
    1/cos^2 = 1 + tan^2, tan a = v0^2/(g x), y_env = v0^2/(2g) - g x^2/(2 v0^2), and only the
    horizontal trajectory shares the envelope's shape."""
    fam = lagrange.projectile_family()
    assert (fam.time_coefficient, fam.time_power) == (Fraction(1, 2), 2)
    assert (fam.quadratic_denominator, fam.x_power, fam.v0_power, fam.cos_power) == (
        Fraction(2),
        2,
        2,
        2,
    )
    assert (fam.secant_derivative_coefficient, fam.secant_derivative_cos_power) == (Fraction(2), 3)
    assert (fam.secant_tan_constant, fam.secant_tan_power, fam.tan_derivative_cos_power) == (
        Fraction(1),
        2,
        2,
    )
    assert (fam.contact_tan_v0_power, fam.contact_tan_square_v0_power) == (2, 4)
    assert (fam.envelope_constant_denominator, fam.envelope_constant_v0_power) == (Fraction(2), 2)
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


# -- exact algebra --------------------------------------------------------------------------------


# -- action and phase (12.42)-(12.46) -----------------------------------------------------------


@given(st.integers(0, 50))
def test_bohr_phase_factor_is_one(n: int) -> None:
    """e^(i 2 pi upsilon) = 1 for every integer quantum number upsilon (12.45)."""
    z = lagrange.phase_factor(lagrange.bohr_phase(n))
    assert abs(z - 1) <= 1e-15 * (1 + 2 * math.pi * n)


@settings(max_examples=50)
@given(
    st.floats(min_value=0.1, max_value=3),
    st.floats(min_value=-3, max_value=3),
    st.floats(min_value=0, max_value=3),
    st.floats(min_value=0, max_value=6.283),
    st.floats(min_value=0.2, max_value=5),
    st.floats(min_value=0.2, max_value=5),
)
@example(1.0, 0.0, 1.0, 0.0, 1.0, 1.0)  # the book's scaled units omega = M = 1
def test_oscillator_loop_action_is_two_pi_energy_over_omega(
    x0: float, y0: float, speed: float, angle: float, omega: float, mass: float
) -> None:
    """Over one period 2 pi/omega of the 2-D oscillator U = M omega^2 r^2/2 the reduced action
    S_H = integral p . dr = integral 2T dt is 2 pi E/omega (virial theorem: mean T = E/2), the
    loop action Bohr quantizes in (12.45); omega = M = 1 are the defaults. Along the way
    S_H(t) = integral L dt + E t (12.46) with integral L dt = M (r.v - r0.v0)/2 (as
    d(r.v)/dt = v^2 - omega^2 r^2), so a quarter period in S_H = E T/4 - M r0.v0."""
    if speed == 0:
        speed = 1e-3
    period = 2 * math.pi / omega
    start = (x0, y0)
    paths = lagrange.oscillator_paths(
        start, speed, [angle], period, samples=2001, omega=omega, mass=mass
    )
    e = mass * (speed**2 + omega**2 * (x0**2 + y0**2)) / 2
    assert abs(paths.action[0, -1] - 2 * math.pi * e / omega) <= 1e-9 * (1 + e) * period
    r0_v0 = x0 * speed * math.cos(angle) + y0 * speed * math.sin(angle)
    quarter = e * period / 4 - mass * r0_v0
    assert abs(paths.action[0, 500] - quarter) <= 1e-5 * (e * period + mass * abs(r0_v0) + 1e-3)
    if omega == mass == 1:
        default = lagrange.oscillator_paths(start, speed, [angle], period, samples=2001)
        assert (default.action == paths.action).all()


@given(
    st.floats(min_value=-3, max_value=3),
    st.floats(min_value=-3, max_value=3),
    st.floats(min_value=0.1, max_value=3),
    st.floats(min_value=0, max_value=6.283),
    st.floats(min_value=0.2, max_value=5),
)
def test_oscillator_paths_refocus_every_half_period(
    x0: float, y0: float, speed: float, angle: float, omega: float
) -> None:
    """r(t) = r0 cos(omega t) + (v0/omega) sin(omega t) (the starlet blast of exercise 1.12.3,
    U = M omega^2 r^2/2): every fragment starts at r0, is at v0/omega a quarter period later,
    at -r0 (the blast refocuses at the antipode) after half a period, and back at r0 after a
    whole one, whatever its direction."""
    period = 2 * math.pi / omega
    angles = [angle, angle + math.pi / 2]
    paths = lagrange.oscillator_paths((x0, y0), speed, angles, period, samples=5, omega=omega)
    assert paths.times.tolist() == pytest.approx([k * period / 4 for k in range(5)], rel=REL)
    scale = abs(x0) + abs(y0) + speed / omega
    for k, a in enumerate(angles):
        reach = (speed * math.cos(a) / omega, speed * math.sin(a) / omega)
        want = [(x0, y0), reach, (-x0, -y0), (-reach[0], -reach[1]), (x0, y0)]
        for j, (wx, wy) in enumerate(want):
            assert abs(paths.x[k, j] - wx) <= 1e-12 * scale
            assert abs(paths.y[k, j] - wy) <= 1e-12 * scale
    half = lagrange.oscillator_paths((x0, y0), speed, angles, period / 2, samples=2, omega=omega)
    assert half.x[:, -1] == pytest.approx([-x0, -x0], abs=1e-12 * scale)  # two samples suffice
    assert half.y[:, -1] == pytest.approx([-y0, -y0], abs=1e-12 * scale)


@given(st.floats(min_value=-5, max_value=5), st.floats(min_value=0.1, max_value=5))
def test_path_action_of_uniform_motion(v: float, duration: float) -> None:
    """S = integral L dt of a free particle at constant speed is m v^2 T / 2 (12.38)."""
    times = [duration * k / 10 for k in range(11)]
    lag = [v**2 / 2] * 11
    assert_close(lagrange.path_action(lag, times), v**2 * duration / 2, abs=FLOOR)
    assert_close(lagrange.path_action(lag[:2], [0.0, duration]), v**2 * duration / 2, abs=FLOOR)
    with pytest.raises(ValueError, match="at least two"):
        lagrange.path_action(lag[:1], [0.0])


@given(st.integers(0, 100), st.integers(1, 32))
@example(1, 8)  # the first hue step of the book's eight-colour wheel (line 16324)
@example(3, 1)  # a one-colour palette
def test_palette_hues_are_roots_of_unity(step: int, colours: int) -> None:
    """The n hues of a colour circle are the phases 2 pi k/n (12.45), (line 16324): the phase
    factor of every hue raised to the n-th power is 1, and n steps on make one whole turn."""
    phase = lagrange.palette_phase(step, colours)
    turn = lagrange.palette_phase(step + colours, colours) - phase
    assert abs(turn - 2 * math.pi) <= 1e-12 * (1 + abs(phase))
    z = lagrange.phase_factor(phase)
    assert abs(z**colours - 1) <= 1e-12 * colours * (1 + abs(phase))
    assert abs(lagrange.palette_amplitude(step, colours) - z.real) <= 1e-15


@given(
    st.floats(min_value=-3, max_value=6).map(lambda k: 10.0**k),
    st.lists(st.floats(min_value=-7, max_value=7), min_size=1, max_size=6),
)
@example(1e6, [0.0, 1.0])
def test_common_speed_is_the_speed_of_every_fragment(speed: float, angles: list[float]) -> None:
    """Fragments flying off with one speed in any directions (exercise 1.12.3) share that speed:
    common_speed returns it at any scale, exactly when every |v| is the same float (3-4-5
    triangles, or all at rest); speeds differing by rounding (1e-12) are one speed, speeds
    differing by 1% are not, whatever the units: a list of different speeds is an error, not
    an average."""
    velocities = [(speed * math.cos(a), speed * math.sin(a)) for a in angles]
    assert_close(lagrange.common_speed(velocities), speed, abs=FLOOR)
    assert lagrange.common_speed([(3, 4), (-4, 3), (0, 5), (5, 0)]) == 5
    assert lagrange.common_speed([[0, 1], [1, 0], [-(2**-0.5), 2**-0.5]]) == pytest.approx(1)
    assert lagrange.common_speed([(0, 0), (0.0, 0.0)]) == 0
    rounded = lagrange.common_speed([(speed, 0.0), (0.0, speed * (1 + 1e-12))])
    assert_close(rounded, speed, rel=1e-11, abs=FLOOR)
    with pytest.raises(ValueError, match="different speeds"):
        lagrange.common_speed([(speed, 0.0), (0.0, speed * 1.01)])


# -- formula models of chapter 12: energies, Legendre pair, root mass --------------------------


@given(st.lists(st.tuples(exact_masses(), exact_velocities()), min_size=1, max_size=3))
@example([(Fraction(4), Fraction(3)), (Fraction(9), Fraction(-2))])
def test_energy_is_the_same_in_every_scaled_coordinate(
    pairs: list[tuple[Fraction, Fraction]],
) -> None:
    """The kinetic energy of bodies given by u = m^s v is m v^2/2 whatever the scale s: in
    momenta (s = 1) it is H(p) = sum p^2/(2m) exactly (12.2), (12.4); in quasi-velocities
    (s = 1/2) it is E(V) = sum V^2/2, mass-free (12.1), (12.5); at s = 0 it is L(v) (12.3)."""
    masses = [m for m, _ in pairs]
    velocities = [v for _, v in pairs]
    lag = lagrange.kinetic_energy(masses, velocities)
    p = lagrange.momenta(masses, velocities)
    assert lagrange.scaled_coordinate_energy(masses, p, 1) == lagrange.hamiltonian_free(masses, p)
    assert lagrange.scaled_coordinate_energy(masses, p, 1) == lag
    assert lagrange.scaled_coordinate_energy(masses, velocities, 0) == lag
    fm = [float(m) for m in masses]
    quasi = lagrange.quasi_velocities(fm, [float(v) for v in velocities])
    got = lagrange.scaled_coordinate_energy(fm, quasi, Fraction(1, 2))
    assert_close(got, float(lag), abs=FLOOR)
    assert_close(got, lagrange.estrangian(quasi), abs=FLOOR)
    heavier = lagrange.scaled_coordinate_energy([2 * m for m in fm], quasi, Fraction(1, 2))
    assert_close(heavier, got, abs=FLOOR)  # E(V) has no mass in it


@given(exact_masses())
@example(Fraction(3))
def test_root_mass_maps_compose_to_the_mass_and_its_inverse(root: Fraction) -> None:
    """Two root-mass scalings make the mass, M = R^2, and two inverse ones its inverse,
    M^-1 = R^-2 (12.9): the two maps are mutual inverses, exactly."""
    maps = lagrange.root_mass_maps(root)
    assert maps.mass == root * root
    assert maps.mass * maps.inverse_mass == 1
    assert isinstance(maps.inverse_mass, Fraction)
    assert lagrange.root_mass_maps(int(root.numerator)).mass == root.numerator**2
    with pytest.raises(ValueError, match="positive"):
        lagrange.root_mass_maps(-root)


@given(st.floats(min_value=1e-3, max_value=1e3), st.floats(min_value=1e-3, max_value=1e3))
@example(0.5, 1.0)  # Fig. 12.2(d): less mass, the velocity ellipse is twice the momentum one
def test_ellipse_radius_ratio_is_one_over_the_mass(mass: float, energy: float) -> None:
    """On each axis the L(v) = E ellipse reaches 1/m times as far as the H(p) = E ellipse,
    whatever the energy (Fig. 12.2): ratio times mass is 1."""
    ratio = lagrange.ellipse_radius_ratio(mass, energy)
    assert_close(ratio * mass, 1.0, abs=FLOOR)
    assert_close(ratio, lagrange.ellipse_radius_ratio(mass), abs=FLOOR)


@given(exact_velocities(), exact_masses())
@example(Fraction(1), Fraction(8, 5))  # Fig. 12.3: v = 1.0, p = 1.6
def test_legendre_pair_is_half_pv_both_ways(v: Fraction, m: Fraction) -> None:
    """For L = m v^2/2 and p = m v: L = v p/2 and H = p v/2 numerically (line 13716), and
    H = p v - L is the Legendre transform (12.11b); exact. A zero velocity, or a p/v that is no
    positive mass, is an error."""
    if v == 0:
        v = Fraction(1)
    p = m * v
    pair = lagrange.quadratic_legendre_pair(v, p)
    assert pair.mass == m
    assert pair.lagrangian == pair.hamiltonian == p * v / 2
    assert pair.hamiltonian == lagrange.legendre_tangent(pair.lagrangian, p, v).transform
    with pytest.raises(ValueError, match="non-zero"):
        lagrange.quadratic_legendre_pair(0, p)
    with pytest.raises(ValueError, match="positive"):
        lagrange.quadratic_legendre_pair(v, -p)


# -- formula models of chapter 12: the trajectory family and its envelope ----------------------


@given(launch_speeds(), launch_angles(), gravities(), st.floats(min_value=0, max_value=5))
def test_generating_solution_vanishes_on_the_trajectory(
    v0: float, alpha: float, g: float, t: float
) -> None:
    """S(v0, a : x, y) (12.15) is zero at every point (x(t), y(t)) of the trajectory (12.14a-b)
    and grows by one for each unit the point lies lower."""
    x, y = lagrange.trajectory_position(t, v0, alpha, g)
    scale = abs(y) + v0 * t + g * t * t
    assert abs(lagrange.generating_solution(x, y, v0, alpha, g)) <= 1e-12 * (scale + 1)
    below = lagrange.generating_solution(x, y - 1, v0, alpha, g)
    assert abs(below - 1) <= 1e-12 * (scale + 1)


@given(
    launch_speeds(),
    st.floats(min_value=-1.4, max_value=1.4),
    gravities(),
    st.floats(min_value=-3, max_value=3),
)
def test_angle_derivative_is_the_slope_of_s_in_the_angle(
    v0: float, alpha: float, g: float, u: float
) -> None:
    """dS/da (12.16b) agrees with a central difference of S in the angle, at x in units of the
    reach v0^2/g; it is zero at the contact abscissa of the angle (12.16c)."""
    x = u * v0 * v0 / g
    h = 1e-5
    numeric = (
        lagrange.generating_solution(x, 0, v0, alpha + h, g)
        - lagrange.generating_solution(x, 0, v0, alpha - h, g)
    ) / (2 * h)
    exact_slope = lagrange.generating_angle_derivative(x, v0, alpha, g)
    size = (abs(x) + g * x * x / v0**2) / math.cos(alpha) ** 4
    assert abs(numeric - exact_slope) <= 1e-6 * (size + 1)
    if abs(alpha) > 0.05:
        xc = lagrange.contact_distance(v0, alpha, g)
        d = lagrange.generating_angle_derivative(xc, v0, alpha, g)
        assert abs(d) <= 1e-9 * (abs(xc) + g * xc * xc / v0**2) / math.cos(alpha) ** 4


@given(launch_speeds(), gravities(), st.floats(min_value=0.05, max_value=20))
@example(1.0, 1.0, 1.0)  # the 45-degree path touches the envelope at its landing point
def test_contact_slope_and_abscissa_are_inverse(v0: float, g: float, u: float) -> None:
    """The trajectory of slope tan a = contact_tangent(x) touches the envelope at x: its
    contact abscissa is x again, its height there is the envelope's, and dS/da vanishes
    (12.16c). Both signs of x."""
    for x in (u * v0 * v0 / g, -u * v0 * v0 / g):
        tan = lagrange.contact_tangent(x, v0, g)
        alpha = math.atan(tan)
        assert_close(lagrange.contact_distance(v0, alpha, g), x, rel=1e-12, abs=FLOOR)
        y = lagrange.trajectory_height(x, v0, alpha, g)
        assert abs(y - lagrange.envelope_by_maximum(x, v0, g)) <= 1e-10 * (
            v0 * v0 / g + g * x * x / v0**2
        )
    with pytest.raises(ValueError, match="x = 0"):
        lagrange.contact_tangent(0.0, v0, g)
    with pytest.raises(ValueError, match="horizontal"):
        lagrange.contact_distance(v0, 0.0, g)


@given(
    launch_speeds(),
    gravities(),
    st.floats(min_value=0.01, max_value=3),
    st.sampled_from([1, -1]),
    launch_angles(),
)
@example(1.0, 1.0, 0.0, 1, 0.7)  # x = 0: the top of the vertical launch, v0^2/(2g)
def test_envelope_by_maximum_bounds_every_trajectory(
    v0: float, g: float, u: float, sign: int, alpha: float
) -> None:
    """The highest point over all elevations at an abscissa lies above every trajectory there
    (also one launched backwards) and on the parabola v0^2/(2g) - g x^2/(2 v0^2) (12.17), at
    x from 1/100 to 3 reaches v0^2/g on either side, and at x = 0 (the vertical launch)."""
    x = sign * u * v0 * v0 / g
    top = lagrange.envelope_by_maximum(x, v0, g)
    scale = v0 * v0 / g + g * x * x / v0**2
    for a in (alpha, -alpha):
        assert lagrange.trajectory_height(x, v0, a, g) <= top + 1e-12 * scale
    assert abs(top - lagrange.envelope_height(x, v0, g)) <= 1e-12 * scale


# -- formula models of chapter 12: Lagrange's derivation, polar coordinates, Hamiltonians -------


@given(exact_symmetric_matrices(), exact_plane_vectors(), exact_plane_vectors())
def test_gradient_potential_has_gradient_m_dot_v(
    matrix: tuple[tuple[Fraction, ...], ...],
    v: tuple[Fraction, Fraction],
    w: tuple[Fraction, Fraction],
) -> None:
    """F(v) = integral_0^1 (M.(t v)).v dt has the directional derivative (M.v).w along any w
    (line 15022: d/dq of it is M_ij v^i dv^j/dq), vanishes at 0 and is homogeneous of degree
    two; exact (a central difference is exact for a quadratic). A non-symmetric matrix has
    no potential."""
    f = lagrange.gradient_potential
    h = Fraction(1, 7)
    plus = [v[k] + h * w[k] for k in range(2)]
    minus = [v[k] - h * w[k] for k in range(2)]
    slope = (f(matrix, plus) - f(matrix, minus)) / (2 * h)
    mv = [sum(matrix[i][j] * v[j] for j in range(2)) for i in range(2)]
    assert slope == sum(mv[i] * w[i] for i in range(2))
    assert f(matrix, [0, 0]) == 0
    assert f(matrix, [2 * v[0], 2 * v[1]]) == 4 * f(matrix, list(v))
    if matrix[0][1] != 0:
        skew = [[matrix[0][0], matrix[0][1]], [-matrix[0][1], matrix[1][1]]]
        with pytest.raises(ValueError, match="symmetric"):
            f(skew, list(v))


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


@given(
    exact_masses(),
    exact_masses(),
    exact_velocities(),
    exact_velocities(),
)
@example(Fraction(1), Fraction(1), Fraction(2), Fraction(0))  # a free particle: H = T
def test_coordinate_hamiltonian_is_the_energy_both_ways(
    mass: Fraction, metric: Fraction, rate: Fraction, potential: Fraction
) -> None:
    """H = p q' - L of L = M g q'^2/2 - U is the energy T + U (12.37b) with p = M g q'; in
    momenta, with the contravariant metric 1/g, it is the same H at the same rate (12.37c).
    Exact."""
    h = lagrange.hamiltonian_of_rate(mass, metric, rate, potential)
    assert h.momentum == mass * metric * rate
    assert h.hamiltonian == mass * metric * rate * rate / 2 + potential
    back = lagrange.hamiltonian_of_momentum(mass, 1 / metric, h.momentum, potential)
    assert (back.rate, back.hamiltonian) == (rate, h.hamiltonian)
    whole = lagrange.hamiltonian_of_momentum(mass, 1, h.momentum, potential)
    assert whole.hamiltonian == h.momentum**2 / (2 * mass) + potential


@given(exact_velocities(), exact_velocities())
@example(Fraction(2), Fraction(-4))  # line 15832: S = q^2 - 4q is stationary at q = 2
def test_quadratic_slope_is_the_central_difference(q: Fraction, b: Fraction) -> None:
    """dS/dq of S = q^2 + b q equals its central difference (exact for a quadratic) and
    vanishes at the extremum of ``quadratic_extremum`` (line 15832)."""
    h = Fraction(1, 3)

    def s(x: Fraction) -> Fraction:
        return x * x + b * x

    assert lagrange.quadratic_function_slope(q, b) == (s(q + h) - s(q - h)) / (2 * h)
    assert lagrange.quadratic_function_slope(lagrange.quadratic_extremum(b).point, b) == 0


@given(
    st.floats(min_value=0.1, max_value=10),
    st.floats(min_value=-7, max_value=7),
    st.floats(min_value=-7, max_value=7),
    st.integers(0, 16),
)
@example(1.0, math.pi / 2, math.pi / 4, 2)  # exercise 1.12.3: (0,1), (1/sqrt 2, 1/sqrt 2), (1,0)
def test_turning_sequence_turns_by_one_step(
    length: float, start: float, second: float, k: int
) -> None:
    """Each vector of the sequence is the last turned by the angle from the first to the
    second: the angle grows by one step per index and, for equal lengths, the length stays."""
    first = (length * math.cos(start), length * math.sin(start))
    nxt = (length * math.cos(second), length * math.sin(second))
    x, y = lagrange.turning_sequence(first, nxt, k)
    angle = start + k * (second - start)
    assert abs(x - length * math.cos(angle)) <= 1e-12 * length * (k + 1)
    assert abs(y - length * math.sin(angle)) <= 1e-12 * length * (k + 1)
    assert lagrange.turning_sequence(first, nxt, 0) == pytest.approx(first, abs=1e-15 * length)
    assert lagrange.turning_sequence(first, nxt, 1) == pytest.approx(nxt, rel=1e-12, abs=1e-12)
    with pytest.raises(ValueError, match="non-zero"):
        lagrange.turning_sequence((0, 0), nxt, k)


@given(
    st.lists(st.floats(min_value=-3, max_value=3), min_size=4, max_size=4),
    st.tuples(st.floats(min_value=-3, max_value=3), st.floats(min_value=-3, max_value=3)),
    st.floats(min_value=0.1, max_value=10),
)
def test_metric_energy_is_the_cartesian_energy_of_any_jacobian(
    entries: list[float], rates: tuple[float, float], mass: float
) -> None:
    """For any invertible Jacobian J the kinetic energy of the metric g = J^T J at the rates q'
    is M |J q'|^2/2 (12.31): the energy depends on the coordinates only through g. In polar
    coordinates it is the polar Lagrangian M (r'^2 + r^2 phi'^2)/2 (12.32). A metric that is
    not positive definite is refused."""
    j = [entries[:2], entries[2:]]
    det = j[0][0] * j[1][1] - j[0][1] * j[1][0]
    if abs(det) < 1e-2:
        return
    g = [[sum(j[k][m] * j[k][n] for k in range(2)) for n in range(2)] for m in range(2)]
    g[1][0] = g[0][1]
    v = [sum(j[k][m] * rates[m] for m in range(2)) for k in range(2)]
    want = mass * (v[0] ** 2 + v[1] ** 2) / 2
    size = mass * sum(x * x for x in entries) * sum(x * x for x in rates)
    assert abs(lagrange.metric_kinetic_energy(mass, g, rates) - want) <= 1e-9 * (size + 1e-12)
    r, phi = 0.5 + abs(entries[0]), entries[1]
    polar = lagrange.metric_kinetic_energy(mass, lagrange.polar_metric(r, phi), rates)
    assert_close(polar, lagrange.polar_lagrangian(mass, r, rates[0], rates[1], 0, phi), abs=FLOOR)
    with pytest.raises(ValueError, match="positive definite"):
        lagrange.metric_kinetic_energy(mass, [[1.0, 2.0], [2.0, 1.0]], rates)
