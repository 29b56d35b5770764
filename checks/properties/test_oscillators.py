"""Laws of the oscillator orbit, inertial forces, quadratic forms and triads
(mechmodel.oscillators): chapter 11.

Floats are compared within 1e-12 of the sum of the magnitudes involved (1e-9 where sines and
cosines of phases up to a few turns intervene); Fraction inputs must give exact equality.
"""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import example, given, target
from hypothesis import strategies as st

from checks.properties.closeness import assert_close
from checks.properties.strategies import (
    derivative_orders,
    exact_distinct_radii,
    exact_radii,
    form_angles,
    matrix_powers,
    orbit_fractions,
    orbit_omegas,
    orbit_phases,
    orbit_radii,
    rational_half_angle_tans,
    triad_indices,
    triad_start_angles,
)
from mechmodel import oscillators as osc
from mechmodel import planar

pytestmark = pytest.mark.properties
REL = 1e-12
TRIG = 1e-9


# --- the orbit and its conserved quantities (11.5), (11.21)-(11.22), Fig. 11.8 --------------


@given(orbit_radii(), orbit_radii(), orbit_omegas(), orbit_phases())
@example(2.2, 1.0, 1.0, 1.0)  # the ellipse of Fig. 11.1
def test_angular_momentum_is_constant_on_the_orbit(a: float, b: float, w: float, u: float) -> None:
    """r x v = a b w at every time (11.21): the orbital angular momentum L = m a b w (11.22)
    is conserved."""
    mass = 1.7
    value = osc.angular_momentum(mass, a, b, w, u / w)
    expected = mass * a * b * w
    error = abs(value - expected) / expected
    target(error, label="relative angular momentum error")
    assert error <= TRIG


@given(orbit_radii(), orbit_radii(), orbit_omegas(), orbit_phases())
def test_energy_is_constant_on_the_orbit(a: float, b: float, w: float, u: float) -> None:
    """1/2 m v.v + 1/2 m w^2 r.r = 1/2 m w^2 (a^2 + b^2) at every time: the oscillator's energy
    is conserved (exercise 1.11.1(b), k = m w^2 (11.2b))."""
    mass = 0.3
    value = osc.orbit_energy(mass, a, b, w, u / w)
    expected = mass * w * w * (a * a + b * b) / 2
    assert_close(value, expected, rel=TRIG, scale=expected)


@given(
    orbit_radii(),
    orbit_radii(),
    orbit_omegas(),
    orbit_phases(),
    orbit_phases(),
    st.integers(min_value=0, max_value=3),
)
@example(2.2, 1.0, 1.0, 0.0, math.pi / 3, 0)  # the snapshots t = 0 and pi/3w of Fig. 11.8
def test_equal_areas_in_equal_times(
    a: float, b: float, w: float, u0: float, u1: float, turns: int
) -> None:
    """The radius sweeps the same area in any two equal time intervals, the areal velocity
    times the interval (Kepler's law, Fig. 11.8): the sectors are measured geometrically, from
    the end points' clock hands (Fig. 11.1), not from the time; each whole period adds the
    ellipse's area pi a b, and no time sweeps no area."""
    period = osc.orbit_period(w)
    dt = (turns + 0.37) * period
    first = osc.swept_area(a, b, w, u0 / w, u0 / w + dt)
    second = osc.swept_area(a, b, w, u1 / w, u1 / w + dt)
    rate = osc.areal_velocity(a, b, w) * dt
    assert_close(first, second, rel=TRIG, scale=rate)
    assert_close(first, rate, rel=TRIG, scale=rate)
    assert_close(osc.orbit_area(a, b), math.pi * a * b, scale=a * b)
    assert osc.swept_area(a, b, w, u0 / w, u0 / w) == 0
    with pytest.raises(ValueError, match="precede"):
        osc.swept_area(a, b, w, u0 / w, u0 / w - 0.1 * period)


@given(orbit_radii(), orbit_radii(), orbit_omegas(), orbit_phases())
def test_area_law_coefficient_is_one_half(a: float, b: float, w: float, u: float) -> None:
    """dA/dt = 1/2 |r x v| (text after Fig. 11.8): the whole orbit pi a b per period over
    r x v = a b w."""
    t = u / w
    r, v = osc.orbit_position(a, b, w, t), osc.orbit_velocity(a, b, w, t)
    assert_close(osc.areal_velocity(a, b, w) / abs(planar.cross(r, v)), 0.5, rel=TRIG, scale=1.0)


@given(orbit_radii(), orbit_radii(), orbit_omegas())
@example(2.2, 1.0, 1.0)
def test_apsis_speeds_follow_from_angular_momentum(a: float, b: float, w: float) -> None:
    """v_b = L/(m b) = a w at perigee and v_a = L/(m a) = b w at apogee (text after
    Fig. 11.8) agree with the velocity formula (11.5b) at t = 0 and t = pi/2w."""
    speeds = osc.apsis_speeds(a, b, w)
    v0 = osc.orbit_velocity(a, b, w, 0.0)
    v1 = osc.orbit_velocity(a, b, w, osc.time_to_perigee(w))
    assert_close(speeds.apogee, math.hypot(*v0), rel=TRIG, scale=(a + b) * w)
    assert_close(speeds.perigee, math.hypot(*v1), rel=TRIG, scale=(a + b) * w)
    assert_close(speeds.ratio, a / b, scale=a / b)


@given(orbit_radii(), orbit_radii(), orbit_omegas(), orbit_phases(), derivative_orders())
def test_every_second_derivative_is_minus_omega_squared_times(
    a: float, b: float, w: float, u: float, n: int
) -> None:
    """Hooke's law F = -k r gives a = -w^2 r, j = -w^2 v, ..., r^(n+2) = -w^2 r^(n), and the
    fourth derivative is w^4 r (11.5b)-(11.5d)."""
    t = u / w
    here = osc.orbit_derivative(a, b, w, t, n)
    two_on = osc.orbit_derivative(a, b, w, t, n + 2)
    scale = (a + b) * w ** (n + 2)
    for c, d in zip(here, two_on, strict=True):
        assert_close(d, -w * w * c, rel=TRIG, scale=scale)
    assert osc.orbit_derivative_form(n + 4).omega_power == n + 4
    four_on = osc.orbit_derivative_form(n + 4)
    form = osc.orbit_derivative_form(n)
    assert (four_on.x_function, four_on.y_function) == (form.x_function, form.y_function)


@given(orbit_radii(), orbit_radii(), orbit_omegas(), orbit_phases(), derivative_orders())
def test_derivatives_follow_the_orbit_a_quarter_turn_apart(
    a: float, b: float, w: float, u: float, n: int
) -> None:
    """r^(n)(t)/w^n = r at phase wt + n pi/2: the four vectors r, v/w, a/w^2, j/w^3 follow each
    other on one ellipse (11.6), Fig. 11.5."""
    t = u / w
    scaled = [c / w**n for c in osc.orbit_derivative(a, b, w, t, n)]
    advance = osc.derivative_phase(n)
    assert_close(advance, (n % 4) * math.pi / 2, scale=1.0)
    ahead = osc.orbit_position(a, b, w, t + advance / w)
    for c, d in zip(scaled, ahead, strict=True):
        assert_close(c, d, rel=TRIG, scale=a + b)
    assert osc.orbit_derivative(a, b, w, t) == osc.orbit_position(a, b, w, t)  # order 0: r


@given(orbit_radii(), orbit_radii(), orbit_omegas(), orbit_fractions())
def test_power_is_the_rate_of_kinetic_energy(a: float, b: float, w: float, turns: float) -> None:
    """P = F.V = d(KE)/dt, positive while the mass falls toward perigee and negative while it
    rises (Fig. 11.3); F and V are perpendicular only at apogee and perigee."""
    mass = 1.3
    t = turns * osc.orbit_period(w)
    h = 1e-6 * osc.orbit_period(w)

    def kinetic(time: float) -> float:
        v = osc.orbit_velocity(a, b, w, time)
        return mass * (v[0] ** 2 + v[1] ** 2) / 2

    numeric = (kinetic(t + h) - kinetic(t - h)) / (2 * h)
    power = osc.force_power(mass, a, b, w, turns)
    scale = mass * w**3 * (a * a + b * b)
    assert_close(power, numeric, rel=1e-6, scale=scale)
    angle = osc.force_velocity_angle(a, b, w, turns)
    if abs(power) > 1e-9 * scale:
        assert (angle < math.pi / 2) == (power > 0)
    # P = |F| |V| cos(theta), F = -m w^2 r; theta = 90 degrees at apogee and perigee
    r, v = osc.orbit_position(a, b, w, t), osc.orbit_velocity(a, b, w, t)
    magnitudes = mass * w * w * math.hypot(*r) * math.hypot(*v)
    assert_close(magnitudes * math.cos(angle), power, rel=TRIG, scale=magnitudes)
    for apsis in (0, 0.25, 0.5, 0.75):
        assert_close(osc.force_velocity_angle(a, b, w, apsis), math.pi / 2, rel=TRIG, scale=1.0)


# --- centrifugal and tidal forces (11.2)-(11.3), p. 171 --------------------------------------


@given(orbit_omegas(), orbit_radii())
def test_centrifugal_force_has_both_famous_forms(w: float, r: float) -> None:
    """m w^2 r = m V^2/r with V = w r (11.3a); the circle of curvature of that motion has
    radius V^2/a = r (11.3c)."""
    mass = 2.5
    v = w * r
    force = osc.centrifugal_force(mass, w, r)
    assert_close(force, mass * osc.centrifugal_acceleration(v, r), scale=force)
    assert_close(osc.curvature_radius(v, force / mass), r, scale=r)


@given(exact_radii(), exact_radii())
def test_spring_constant_inverts_the_frequency(k: Fraction, m: Fraction) -> None:
    """k = m w^2 (11.2b) undoes w = sqrt(k/m) (11.2a): exactly, where k/m is a square."""
    w = osc.oscillator_frequency(k * k * m, m)
    assert w == k
    assert osc.spring_constant(m, w) == k * k * m


@given(orbit_omegas(), st.integers(min_value=8, max_value=500))
@example(1.0, 8)  # the fewest samples allowed
def test_neighbouring_orbits_cross_twice_a_period(f: float, samples: int) -> None:
    """Two free-fall orbits a little apart cross twice each period (p. 171: 2000 times a
    second at 1 kHz), whatever the frequency, and however finely the separation
    d0 cos(wt + alpha) is sampled."""
    assert osc.tidal_crossings_per_second(f) == 2 * f
    assert osc.crossings_per_period(samples) == 2
    with pytest.raises(ValueError, match="at least 8"):
        osc.crossings_per_period(7)


@given(exact_radii(), exact_radii(), exact_radii(), exact_radii())
def test_linear_force_grows_in_proportion_to_the_offset(
    m: Fraction, w: Fraction, x: Fraction, x_new: Fraction
) -> None:
    """The centrifugal (tidal) force m w^2 r = k r (11.3a), k = m w^2 (11.2b), is linear in the
    offset: restated at another offset it is the old force times the ratio of offsets (p. 171's
    fingertip a centimetre off centre), exactly."""
    force = osc.centrifugal_force(m, w, x)
    assert force == osc.spring_constant(m, w) * x
    assert osc.hooke_force_at(force, x, x_new) == osc.centrifugal_force(m, w, x_new)
    assert osc.hooke_force_at(force, x, -x_new) == -osc.centrifugal_force(m, w, x_new)


# --- quadratic forms (11.7)-(11.20), exercise 1.11.1 -----------------------------------------


@given(exact_radii(), exact_radii(), rational_half_angle_tans())
def test_duality_relations_hold_exactly(a: Fraction, b: Fraction, s: Fraction) -> None:
    """With p = Q.r on the orbit r.Q.r = 1: r'.p = 0 = p'.r, p.r = p'.r' = 1, and p lies on
    p.Q^-1.p = 1 ((11.8b), (11.9), (11.10c), (11.17))."""
    d = osc.duality_products(a, b, s)
    assert d.r_form == 1
    assert d.p_dual_form == 1
    assert d.p_dot_r == 1
    assert d.pdot_dot_rdot == 1
    assert d.rdot_dot_p == 0
    assert d.pdot_dot_r == 0


@given(exact_radii(), exact_radii())
def test_dual_ellipse_radii_are_inverse(a: Fraction, b: Fraction) -> None:
    """The p-ellipse p.Q^-1.p = 1 has radii 1/a and 1/b (11.9), and the axis vectors are
    eigenvectors of Q with eigenvalues 1/a^2 and 1/b^2 (11.15c,d)."""
    dual = osc.dual_ellipse(a, b)
    assert (dual.radius_x, dual.radius_y) == (1 / a, 1 / b)
    assert (dual.radius_x_times_a, dual.radius_y_times_b) == (1, 1)
    eigen = osc.axis_eigenvalues(a, b, 2)
    assert (eigen.a_axis, eigen.b_axis) == (1 / a**2, 1 / b**2)


@given(exact_radii(), exact_radii(), matrix_powers())
def test_powers_of_r_multiply_slopes_by_powers_of_a_over_b(
    a: Fraction, b: Fraction, power: int
) -> None:
    """R^p multiplies the slope of any vector by (a/b)^p ((11.12)-(11.13), (11.16)) and keeps
    the axis vectors, with eigenvalues a^-p and b^-p (11.14)-(11.15)."""
    assert osc.slope_gain(a, b, power) == (a / b) ** power
    eigen = osc.axis_eigenvalues(a, b, power)
    assert (eigen.a_axis, eigen.b_axis) == (a**-power, b**-power)
    assert (eigen.a_axis_scaled, eigen.b_axis_scaled) == (1, 1)
    # whole-number radii give the same exact operator as the equal Fractions
    n, m = a.numerator, b.numerator
    assert osc.slope_operator(n, m) == osc.slope_operator(Fraction(n), Fraction(m))
    assert osc.slope_gain(n, m, power) == Fraction(n, m) ** power


@given(exact_radii(), exact_radii())
def test_scaled_radii_are_reciprocal(a: Fraction, b: Fraction) -> None:
    """Scaled by S = sqrt(ab), a_S = 1/b_S (11.11): exactly when ab is a rational square."""
    scaled = osc.scaled_radii(a * a * b, b)
    assert scaled.product == 1
    assert scaled.a_scaled == 1 / scaled.b_scaled


@given(orbit_radii(), orbit_radii())
def test_inverse_ellipse_is_a_quarter_turn(a: float, b: float) -> None:
    """The S-scaled inverse ellipse r.Q^-1.r = 1 is the S-scaled Q-ellipse turned by 90
    degrees (after (11.11))."""
    if abs(a - b) < 1e-3 * (a + b):
        return
    assert_close(osc.inverse_ellipse_rotation(a, b), math.pi / 2, rel=TRIG, scale=1.0)


@given(orbit_radii(), orbit_radii(), form_angles())
@example(1.0, 2.0, math.pi / 4)
def test_rotated_form_keeps_its_eigenvalues(a: float, b: float, angle: float) -> None:
    """Q' = Rot Q Rot^-1 has the eigenvalues 1/a^2 and 1/b^2 whatever the angle, so its trace
    and determinant are invariant, and its ellipse has the radii a and b again (exercise
    1.11.1(a), (b))."""
    form = osc.rotated_form(a, b, angle)
    hi, lo = osc.form_eigenvalues(form.A, form.B, form.C)
    e1, e2 = sorted((1 / a**2, 1 / b**2), reverse=True)
    scale = e1 + e2
    assert_close(hi, e1, rel=TRIG, scale=scale)
    assert_close(lo, e2, rel=TRIG, scale=scale)
    assert_close(form.A + form.C, e1 + e2, rel=TRIG, scale=scale)
    assert_close(form.A * form.C - form.B**2, e1 * e2, rel=TRIG, scale=scale * scale)
    ellipse = osc.ellipse_from_form(form.A, form.B, form.C)
    radii = sorted((ellipse.radius, ellipse.other_radius))
    assert_close(radii[0], min(a, b), rel=1e-6, scale=a + b)
    assert_close(radii[1], max(a, b), rel=1e-6, scale=a + b)


@given(
    orbit_radii(),
    st.floats(min_value=1.2, max_value=5),
    st.booleans(),
    form_angles(),
)
@example(1.0, 2.0, True, math.pi / 4)
def test_rotated_ellipse_is_read_back_turned(
    a: float, factor: float, wider: bool, angle: float
) -> None:
    """The ellipse of radii a (along x) and b turned by an angle has its a-axis along that
    angle (exercise 1.11.1(a)): ellipse_from_form finds the direction of the larger eigenvalue
    (the shorter radius) and major_axis_angle the longer radius, both modulo pi."""
    b = a * factor if wider else a / factor
    form = osc.rotated_form(a, b, angle)
    ellipse = osc.ellipse_from_form(form.A, form.B, form.C)
    short_along = angle if a < b else angle + math.pi / 2
    long_along = angle if a > b else angle + math.pi / 2
    assert abs(math.sin(ellipse.angle - short_along)) <= TRIG
    assert_close(ellipse.radius, min(a, b), rel=TRIG, scale=a + b)
    assert (
        abs(math.sin(osc.major_axis_angle(((form.A, form.B), (form.B, form.C))) - long_along))
        <= TRIG
    )
    assert 0 <= osc.major_axis_angle(((form.A, form.B), (form.B, form.C))) < math.pi


@given(exact_radii(), exact_radii(), rational_half_angle_tans())
def test_form_expands_to_a_x2_plus_2b_xy_plus_c_y2(a: Fraction, b: Fraction, s: Fraction) -> None:
    """(x y).(A B; B C).(x y) = A x^2 + 2B xy + C y^2 (11.20), exactly."""
    A, B, C = a, b - a, s  # noqa: N806
    x, y = a + s, b - 1
    value = osc.form_value(((A, B), (B, C)), (x, y))
    assert value == A * x * x + 2 * B * x * y + C * y * y


@given(exact_radii(), exact_radii())
def test_opposite_eigenvalues_give_a_hyperbola(a: Fraction, b: Fraction) -> None:
    """Eigenvalues 1/a^2 and -1/b^2 make r.Q.r = 1 a hyperbola (exercise 1.11.1(c)); two
    positive ones an ellipse; (a x + b y)^2 = 1, the form (a^2 ab; ab b^2) with eigenvalues
    a^2 + b^2 and 0, is a pair of parallel lines (no ellipse radii), and two negative
    eigenvalues leave no real points (11.20)."""
    assert osc.conic_type(1 / a**2, 0, -1 / b**2) == "hyperbola"
    assert osc.conic_type(1 / a**2, 0, 1 / b**2) == "ellipse"
    assert osc.form_eigenvalues(a * a, a * b, b * b) == (a * a + b * b, 0)
    assert osc.conic_type(a * a, a * b, b * b) == "parallel lines"
    with pytest.raises(ValueError, match="parallel lines"):
        osc.ellipse_from_form(a * a, a * b, b * b)
    assert osc.conic_type(-1 / a**2, 0, -1 / b**2) == "empty"
    assert osc.conic_type(0, 0, -1 / b**2) == "empty"  # -y^2/b^2 = 1
    assert osc.conic_type(0, 0, 0) == "empty"
    # a circle: equal eigenvalues, radius a along the x axis
    assert osc.form_eigenvalues(1 / a**2, 0, 1 / a**2) == (1 / a**2, 1 / a**2)
    circle = osc.ellipse_from_form(1 / a**2, 0, 1 / a**2)
    assert (circle.radius, circle.other_radius, circle.angle) == (a, a, 0.0)


# --- triads (11.16)-(11.19), Fig. 11.7 --------------------------------------------------------


@given(exact_distinct_radii(), triad_start_angles(), triad_indices())
@example((Fraction(2), Fraction(1, 2)), math.pi / 4, 0)  # the triad of Fig. 11.7(a)
@example((Fraction(1, 6), Fraction(33)), 1.0, -3)  # a slope of 1.2e7, nearly vertical
def test_triad_slopes_form_a_geometric_series(
    ab: tuple[Fraction, Fraction], phi0: float, k: int
) -> None:
    """tan phi_k = (a/b)^k tan phi_0: each step of the triad sequence multiplies the slope by
    a/b ((11.16), (11.19), Fig. 11.7). Compared as line directions (angles modulo pi): a
    slope near the vertical is ill-conditioned, the line it stands for is not."""
    a, b = ab
    expected = float(a / b) ** k * math.tan(phi0)
    turn = (math.atan(osc.triad_slope(a, b, phi0, k)) - math.atan(expected)) % math.pi
    assert min(turn, math.pi - turn) <= TRIG


@given(exact_distinct_radii(), triad_start_angles(), triad_indices())
def test_triad_radius_and_perpendicular_are_dual(
    ab: tuple[Fraction, Fraction], phi0: float, k: int
) -> None:
    """In the k-th triad r(phi_k-1) lies on the Q-ellipse, p(phi_k+1) = Q.r(phi_k-1) projects 1
    on it and has the polar angle phi_k+1 (11.17)."""
    a, b = ab
    v = osc.triad_vectors(a, a * b, phi0, k)
    q = osc.ellipse_form(float(a), float(b))
    assert_close(osc.form_value(q, v.r), 1.0, rel=TRIG, scale=1.0)
    assert_close(planar.dot(v.p, v.r), 1.0, rel=TRIG, scale=1.0)
    phi_next = osc.triad_angle(a, b, phi0, k + 1)
    assert_close(math.atan2(v.p[1], v.p[0]), phi_next, rel=TRIG, scale=1.0)
    assert osc.triad_vectors(a, a * b, phi0) == osc.triad_vectors(a, a * b, phi0, 0)
    # with ab = 1 (11.18): r = (a/dx, b/dy) and p = (b/dx, a/dy) share their divisors
    unit = osc.triad_vectors(a, 1, phi0, k)
    bu = 1 / a
    assert_close(a / unit.r_x_divisor, unit.r[0], rel=TRIG, scale=abs(unit.r[0]))
    assert_close(bu / unit.r_y_divisor, unit.r[1], rel=TRIG, scale=abs(unit.r[1]))
    assert_close(unit.p_x_divisor, unit.r_x_divisor, rel=TRIG, scale=abs(unit.r_x_divisor))
    assert_close(unit.p_y_divisor, unit.r_y_divisor, rel=TRIG, scale=abs(unit.r_y_divisor))


@given(
    st.floats(min_value=0.1, max_value=1e4),
    st.floats(min_value=0.1, max_value=10),
    st.floats(min_value=1e-3, max_value=1),
)
def test_tidal_force_is_the_centrifugal_force_at_the_orbit_frequency(
    frequency: float, mass: float, offset: float
) -> None:
    """The tidal force on a mass off the centre of gravity is m (2 pi f)^2 x (11.3a), linear in
    the offset."""
    force = osc.tidal_force(frequency, mass, offset)
    assert math.isclose(force, mass * (2 * math.pi * frequency) ** 2 * offset, rel_tol=1e-12)
    assert math.isclose(osc.tidal_force(frequency, mass, 2 * offset), 2 * force, rel_tol=1e-12)


# --- formulas of the book checked whole (formula claims) -------------------------------------


@given(
    orbit_radii(),
    orbit_radii(),
    orbit_omegas(),
    orbit_phases(),
    st.integers(min_value=0, max_value=8),
    st.integers(min_value=0, max_value=2),
)
@example(2.2, 1.0, 1.0, 0.3, 1, 2)  # the fifth derivative through v: w^4 v
def test_derivatives_through_r_or_v(
    a: float, b: float, w: float, u: float, base: int, half_steps: int
) -> None:
    """The derivative of order n = m + 2j is +-w^(2j) times the m-th at every time (a = -w^2 r,
    j = -w^2 v, i = w^4 r, the fifth w^4 v); an odd step is no multiple."""
    t = u / w
    order = base + 2 * half_steps
    low = osc.orbit_derivative(a, b, w, t, base)
    high = osc.orbit_derivative(a, b, w, t, order)
    scale = (a + b) * w**order
    for c, d in zip(low, high, strict=True):
        assert_close(osc.derivative_in_terms_of(order, base, w, c), d, rel=TRIG, scale=scale)
    assert osc.derivative_in_terms_of(order, base, w, 1.0) == (-1) ** half_steps * w ** (
        2 * half_steps
    )
    with pytest.raises(ValueError, match="no multiple"):
        osc.derivative_in_terms_of(order + 1, base, w, 1.0)
    with pytest.raises(ValueError, match="below"):
        osc.derivative_in_terms_of(base, base + 2, w, 1.0)


@given(orbit_radii(), orbit_radii(), orbit_omegas(), orbit_phases(), orbit_fractions())
@example(2.2, 1.0, 1.0, 0.0, 0.25)
def test_swept_area_from_the_angular_momentum(
    a: float, b: float, w: float, u: float, turns: float
) -> None:
    """The area swept in dt by the orbit of L = m a b w (11.22), measured as a sector of the
    ellipse, is what ``area_swept`` gives from L and m alone: (1/2)(L/m) dt, not (L/m) dt."""
    mass = 1.9
    dt = turns * osc.orbit_period(w)
    swept = osc.swept_area(a, b, w, u / w, u / w + dt)
    from_momentum = osc.area_swept(mass * a * b * w, mass, dt)
    assert_close(from_momentum, swept, rel=TRIG, scale=swept)
    assert_close(from_momentum, a * b * w * dt / 2, rel=TRIG, scale=swept)


@given(orbit_radii(), orbit_omegas())
def test_circular_motion_needs_omega_squared_r(r: float, w: float) -> None:
    """The acceleration of uniform circular motion is w^2 r = V^2/r (11.3b): against a finite
    difference of the positions; the force is m times it (11.3a); the circle of curvature of
    that motion has the radius V^2/a = a/w^2 = r (11.3c)."""
    mass = 2.5
    v = w * r
    accel = osc.circular_acceleration(r, w)
    h = 1e-4 / w
    plus, here, minus = (osc.orbit_position(r, r, w, s) for s in (h, 0.0, -h))
    difference = math.hypot(*(p - 2 * q + m for p, q, m in zip(plus, here, minus, strict=True)))
    assert_close(difference / (h * h), accel, rel=1e-6, scale=accel)
    assert_close(osc.circular_acceleration_at_speed(r, v), accel, scale=accel)
    assert_close(accel, osc.centrifugal_acceleration(v, r), scale=accel)
    assert_close(osc.circular_force(mass, r, w), mass * accel, scale=mass * accel)
    assert_close(osc.circular_force_at_speed(mass, r, v), mass * accel, scale=mass * accel)
    assert_close(osc.curvature_radius_at_speed(v, accel), r, scale=r)
    assert_close(osc.curvature_radius_at_rate(w, accel), r, scale=r)


@given(exact_radii(), exact_radii(), exact_radii(), exact_radii(), exact_radii())
def test_quadratic_form_expands_with_twice_the_cross_term(
    A: Fraction,  # noqa: N803
    B: Fraction,  # noqa: N803
    C: Fraction,  # noqa: N803
    x: Fraction,
    y: Fraction,
) -> None:
    """(x y).(A B; B C).(x y) = A x^2 + 2B xy + C y^2 (11.20), exactly; swapping the axes swaps
    A and C."""
    value = osc.quadratic_form(A, B, C, x, y)
    assert value == A * x * x + 2 * B * x * y + C * y * y
    assert value == osc.quadratic_form(C, B, A, y, x)
    assert osc.quadratic_form(A, B, C, 2 * x, 2 * y) == 4 * value


@given(orbit_radii(), orbit_radii(), orbit_phases())
def test_dual_vector_is_perpendicular_and_projects_to_one(a: float, b: float, u: float) -> None:
    """p = Q.r = ((1/a) cos phi, (1/b) sin phi) (11.8b) is perpendicular to the velocity
    (-a sin phi, b cos phi) and p.r = 1 (11.10c)."""
    p = osc.dual_vector(a, b, u)
    r = (a * math.cos(u), b * math.sin(u))
    rdot = (-a * math.sin(u), b * math.cos(u))
    scale = (a + b) * (1 / a + 1 / b)
    assert_close(planar.dot(p, r), 1.0, rel=TRIG, scale=scale)
    assert_close(planar.dot(p, rdot), 0.0, rel=TRIG, scale=scale)


@given(exact_radii(), exact_radii(), matrix_powers(), matrix_powers(), exact_radii(), exact_radii())
def test_operator_images_compose_as_powers(
    a: Fraction, b: Fraction, m: int, n: int, x: Fraction, y: Fraction
) -> None:
    """R^m.(R^n.r) = R^(m+n).r exactly; Q = R^2 and Q^-1 = R^-2 undo each other (11.13); the
    image's slope is (a/b)^n times the slope of r (11.12)."""
    inner = osc.operator_image(a, b, n, x, y)
    assert osc.operator_image(a, b, m, *inner) == osc.operator_image(a, b, m + n, x, y)
    assert osc.operator_image(a, b, -2, *osc.operator_image(a, b, 2, x, y)) == (x, y)
    assert inner[1] / inner[0] == (a / b) ** n * (y / x)


@given(orbit_radii(), orbit_radii(), matrix_powers(), st.floats(min_value=-1.3, max_value=1.3))
def test_image_slope_multiplies_the_tangent(a: float, b: float, power: int, angle: float) -> None:
    """tan of the image of a vector at ``angle`` is (a/b)^power tan(angle) ((11.16) for Q)."""
    expected = osc.slope_gain(a, b, power) * math.tan(angle)
    assert_close(
        osc.image_slope(a, b, power, angle), expected, rel=TRIG, scale=abs(expected) + 1e-300
    )


@given(exact_radii(), exact_radii())
def test_unit_scale_is_the_geometric_mean(a: Fraction, b: Fraction) -> None:
    """S = sqrt(ab) (11.11), exact for rational squares: S^2 = ab, the scale of
    ``scaled_radii``; ab = 1 gives S = 1."""
    square = a * a * b * b
    assert osc.unit_scale(square) == a * b
    assert osc.unit_scale(a * a * b * b) == osc.scaled_radii(a * a * b, b).scale
    assert osc.unit_scale(1) == 1


@given(orbit_radii(), orbit_radii(), triad_start_angles(), triad_indices())
def test_triad_direction_is_a_geometric_slope_series(
    a: float, b: float, phi0: float, k: int
) -> None:
    """tan phi_k = (a/b)^k tan phi_0 (11.19, (11.16)), so with phi_0 = pi/4
    cos phi_k = b^k/sqrt(a^2k + b^2k) and sin phi_k = a^k/sqrt(a^2k + b^2k)."""
    d = osc.triad_direction(a, b, math.tan(phi0), k)
    assert_close(d.cos**2 + d.sin**2, 1.0, rel=TRIG, scale=1.0)
    expected = (a / b) ** k * math.tan(phi0)
    assert_close(d.slope, expected, rel=TRIG, scale=expected)
    assert d.cos > 0  # the first quadrant is kept
    assert d.sin > 0


@given(orbit_radii(), orbit_radii(), exact_radii(), triad_indices())
def test_book_triad_vectors(a: float, b: float, area: Fraction, j: int) -> None:
    """r(phi_j) lies on the ellipse and points along phi_j; p(phi_j) = Q.r(phi_j-2) scaled by
    ab/P points along phi_j too and projects to ab/P on r(phi_j-2) (11.17b) (P = ab = 1 in the
    book); with P = 1 its components are (b cos phi_j-1, a sin phi_j-1) (11.18)."""
    t = osc.book_triad(a, b, area, 1.0, j)
    before = osc.book_triad(a, b, area, 1.0, j - 2)
    here = osc.triad_direction(a, b, 1.0, j)
    previous = osc.triad_direction(a, b, 1.0, j - 1)
    assert_close((t.r[0] / a) ** 2 + (t.r[1] / b) ** 2, 1.0, rel=TRIG, scale=1.0)
    for v in (t.r, t.p):
        norm = math.hypot(*v)
        assert_close(v[0] / norm, here.cos, rel=TRIG, scale=1.0)
        assert_close(v[1] / norm, here.sin, rel=TRIG, scale=1.0)
    ratio = a * b / float(area)
    assert_close(planar.dot(t.p, before.r), ratio, rel=TRIG, scale=ratio)
    unit = osc.book_triad(a, b, 1, 1.0, j)
    assert_close(unit.p[0], b * previous.cos, rel=TRIG, scale=a + b)
    assert_close(unit.p[1], a * previous.sin, rel=TRIG, scale=a + b)
