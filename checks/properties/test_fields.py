"""Laws of the common potential fields (mechmodel.fields): chapter 9.

Floats are compared within 1e-12 of the sum of the magnitudes involved (a few ulps more where a
square root or a trigonometric function of a large phase intervenes, as said); Fraction inputs
must give exact equality.
"""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import assume, example, given, target
from hypothesis import strategies as st

from checks.properties.closeness import assert_close
from checks.properties.strategies import (
    chord_offsets,
    clock_hours,
    clock_sizes,
    fraction_coefficients,
    fraction_quantities,
    lengths,
    oscillator_amplitudes,
    oscillator_frequencies,
    oscillator_times,
    phase_angles,
    planet_radii,
    radial_fractions,
    rationals,
    slopes,
    surface_gravities,
)
from mechmodel import fields

pytestmark = pytest.mark.properties
REL = 1e-12
TRIG = 1e-9  # cos and sin of phases up to ~1e3 radians lose a few digits of the phase


# --- tunnels: every chord is the same 84-minute oscillator (Fig. 9.8) ------------------------


@given(surface_gravities(), planet_radii(), chord_offsets())
@example(9.8, 6.4e6, 0.0)  # the book's diameter tunnel to Australia
def test_tunnel_period_does_not_depend_on_the_chord(g: float, radius: float, offset: float) -> None:
    """Any straight tunnel through a uniform planet has the period 2 pi sqrt(R/g), whatever
    its chord (Fig. 9.8: all motions inside the Earth have the same 84-minute period)."""
    period = fields.chord_tunnel_period(g, radius, offset * radius)
    expected = fields.tunnel_period(g, radius)
    error = abs(period - expected) / expected
    target(error, label="relative period error")
    assert error <= 8 * REL


@given(surface_gravities(), planet_radii(), chord_offsets(), radial_fractions())
def test_chord_acceleration_is_harmonic(g: float, radius: float, offset: float, u: float) -> None:
    """Along any chord the pull is -g s / R, proportional to the distance s from the chord's
    middle (the projection of the linear field (9.4a) on the chord)."""
    d = offset * radius
    half = math.sqrt(radius * radius - d * d)
    s = half * math.sin(u)  # a point of the chord, either side of its middle
    acc = fields.chord_acceleration(g, radius, d, s)
    assert_close(acc, -g * s / radius, scale=g * half / radius)


@given(surface_gravities(), planet_radii(), chord_offsets(), oscillator_times())
def test_chord_motion_conserves_energy(g: float, radius: float, offset: float, t: float) -> None:
    """A body sliding through any chord keeps v^2/2 + U(r) constant, with the parabolic
    interior potential of Fig. 9.7 ((9.5): E = KE + PE = const.)."""
    d = offset * radius
    period = fields.tunnel_period(g, radius)
    s, v = fields.chord_tunnel_position(g, radius, d, t * period / 10)
    energy = v * v / 2 + fields.gravity_potential(g, radius, math.hypot(d, s))
    start = fields.gravity_potential(g, radius, radius)  # at rest at the chord's end
    scale = 3 * g * radius
    target(abs(energy - start) / scale, label="relative energy error")
    assert_close(energy, start, rel=TRIG, scale=scale)


@given(surface_gravities(), planet_radii(), oscillator_times())
def test_tunnel_keeps_pace_with_the_grazing_orbit(g: float, radius: float, t: float) -> None:
    """A body dropped through the diameter tunnel always has the x and the x-velocity of the
    satellite in the grazing circular orbit (speed sqrt(gR), (9.7b)): they meet on the far side
    (Fig. 9.8)."""
    omega = fields.circular_orbit_speed(g, radius) / radius
    time = t * fields.tunnel_period(g, radius) / 10
    s, v = fields.chord_tunnel_position(g, radius, 0.0, time)
    assert_close(s, radius * math.cos(omega * time), rel=TRIG, scale=radius)
    assert_close(v, -radius * omega * math.sin(omega * time), rel=TRIG, scale=radius * omega)


@given(
    surface_gravities(),
    planet_radii(),
    chord_offsets(),
    st.floats(min_value=1e-9, max_value=9.0),
)
@example(9.8, 6.4e6, 0.0, 0.5)  # halfway out to twice the radius
def test_no_tunnel_reaches_outside_the_planet(
    g: float, radius: float, offset: float, excess: float
) -> None:
    """A tunnel runs inside the planet: a point R (1 + excess) from the centre is on no chord,
    and a chord as far from the centre as the surface is no tunnel (Fig. 9.8); both are a
    ValueError, never a number."""
    r = radius * (1 + excess)
    d = offset * radius
    with pytest.raises(ValueError, match="outside"):
        fields.chord_acceleration(g, radius, d, math.sqrt(r * r - d * d))
    with pytest.raises(ValueError, match="inside"):
        fields.chord_tunnel_period(g, radius, math.copysign(radius, offset))


@given(surface_gravities(), planet_radii())
def test_orbit_covers_half_a_turn_while_the_tunnel_is_crossed(g: float, radius: float) -> None:
    """The tunnel transit time is half the period of the grazing orbit (Fig. 9.8: they meet
    1/2-way around)."""
    assert_close(fields.orbit_meeting_fraction(g, radius), 0.5, rel=4 * REL, scale=1.0)


# --- the uniform Earth's field and potential, inside and out (9.4), Fig. 9.7 -----------------


@given(surface_gravities(), planet_radii())
def test_field_and_potential_are_continuous_at_the_surface(g: float, radius: float) -> None:
    """Inside and outside formulas meet at the surface: the field is -g on both sides and the
    potential -gR (Fig. 9.7: UIN(1) = -1 = UEX(1), FIN(1) = -1 = FEX(1))."""
    just_out = math.nextafter(radius, math.inf)
    inside_f = fields.gravity_field(g, radius, radius)
    outside_f = fields.gravity_field(g, radius, just_out)
    inside_u = fields.gravity_potential(g, radius, radius)
    outside_u = fields.gravity_potential(g, radius, just_out)
    assert_close(inside_f, -g, scale=g)
    assert_close(outside_f, -g, rel=4 * REL, scale=g)
    assert_close(inside_u, -g * radius, scale=g * radius)
    assert_close(outside_u, -g * radius, scale=g * radius)


@given(surface_gravities(), planet_radii())
def test_the_centre_feels_no_pull_and_is_the_bottom_of_the_well(g: float, radius: float) -> None:
    """At the centre the linear field -g r / R (9.4a) vanishes and the parabolic potential has
    its bottom, -3 g R / 2 (Fig. 9.7: (x^2 - 3)/2 at x = 0); r is a distance, never negative."""
    assert fields.gravity_field(g, radius, 0.0) == 0
    assert_close(fields.gravity_potential(g, radius, 0.0), -1.5 * g * radius, scale=g * radius)
    for law in (fields.gravity_field, fields.gravity_potential):
        with pytest.raises(ValueError, match="distance"):
            law(g, radius, -radius / 2)


@given(surface_gravities(), planet_radii(), radial_fractions())
def test_field_is_minus_the_slope_of_the_potential(g: float, radius: float, x: float) -> None:
    """F = -dU/dr inside and outside (Force = -Slope, (6.9); (9.2b)), by a central difference."""
    assume(abs(x - 1) > 1e-3 and x > 1e-3)
    r = x * radius
    h = 1e-6 * radius
    slope = (
        fields.gravity_potential(g, radius, r + h) - fields.gravity_potential(g, radius, r - h)
    ) / (2 * h)
    assert_close(-slope, fields.gravity_field(g, radius, r), rel=1e-6, scale=g)


@given(surface_gravities(), planet_radii(), radial_fractions())
def test_the_field_inside_is_linear_and_outside_inverse_square(
    g: float, radius: float, x: float
) -> None:
    """Inside only the mass within r pulls, M(r) = M r^3/R^3, so F = -g r/R (9.4a); outside the
    whole mass pulls as from the centre, F = -g R^2/r^2."""
    assume(x > 1e-3)
    r = x * radius
    enclosed = min(x, 1.0) ** 3  # fraction of the planet's mass within r
    expected = -g * enclosed / (x * x)
    assert_close(fields.gravity_field(g, radius, r), expected, scale=g * (1 + enclosed / x**2))


@given(fraction_coefficients())
@example(Fraction(1))  # the Earth of Fig. 9.7, in Earth radii
def test_interior_potential_meets_the_exterior_exactly(surface: Fraction) -> None:
    """The parabola inside meets -1/x at the surface with the same slope (Fig. 9.7, GM = 1)."""
    pot = fields.interior_potential(surface)
    assert pot.surface_potential == -1 / surface
    assert pot.surface_force == -1 / surface**2
    assert pot.surface_slope == 1 / surface**2 == -pot.surface_force
    assert pot.quadratic * surface**2 + pot.offset == pot.surface_potential


@given(fraction_coefficients())
def test_escape_takes_three_equal_steps(surface: Fraction) -> None:
    """Centre to surface, surface to grazing orbit, orbit to escape: three equal steps of
    GM/(2R), 1/2 mgR each ("Starlet escapes! (In 3 equal steps)", (9.11))."""
    ladder = fields.escape_ladder(surface)
    assert ladder.steps[0] == ladder.steps[1] == ladder.steps[2] == 1 / (2 * surface)
    assert ladder.equal_steps == 3


@given(surface_gravities(), planet_radii())
def test_escape_speed_is_root_two_times_orbit_speed(g: float, radius: float) -> None:
    """Ve = v0 sqrt(2) = sqrt(2gR) (9.11a): the kinetic energy of escape is twice the orbit's."""
    speeds = fields.surface_speeds(g, radius)
    assert_close(speeds.escape, speeds.orbit * math.sqrt(2), rel=4 * REL, scale=speeds.escape)
    assert_close(speeds.escape_over_orbit, math.sqrt(2), rel=4 * REL, scale=1.0)
    assert_close(speeds.orbit_over_escape, math.sqrt(0.5), rel=4 * REL, scale=1.0)
    assert_close(speeds.escape_factor, 2.0, rel=4 * REL, scale=1.0)  # Ve^2 = 2 g R
    assert_close(
        speeds.escape, fields.escape_speed_from_orbit_speed(speeds.orbit), scale=speeds.escape
    )


@given(lengths())
def test_sphere_area_is_the_slope_of_its_volume(radius: float) -> None:
    """A sphere of radius r has the area 4 pi r^2 (the bang-ball count falls off as its
    inverse, after Fig. 9.5) and the ball the volume 4 pi r^3 / 3 (7.4): the area is dV/dr, a
    shell's volume per unit thickness, and doubling the radius quadruples the area."""
    area = fields.sphere_area(radius)
    h = radius * 1e-6
    slope = (fields.sphere_volume(radius + h) - fields.sphere_volume(radius - h)) / (2 * h)
    assert math.isclose(slope, area, rel_tol=1e-9)
    assert math.isclose(fields.sphere_area(2 * radius), 4 * area, rel_tol=4 * REL)


@given(fraction_quantities(), fraction_quantities(), fraction_quantities(), fraction_quantities())
def test_gravity_falls_off_as_the_inverse_square(
    big_g: Fraction, m1: Fraction, m2: Fraction, r: Fraction
) -> None:
    """Newton's F = G m1 m2 / r^2 (9.3), exactly: symmetric in the masses, a quarter at twice the
    distance, and at a planet's surface the weight m g with g = G M / R^2."""
    force = fields.gravitational_force(big_g, m1, m2, r)
    assert force * r * r == big_g * m1 * m2
    assert fields.gravitational_force(big_g, m2, m1, r) == force
    assert fields.gravitational_force(big_g, m1, m2, 2 * r) == force / 4
    assert fields.weight(m2, fields.gravitational_force(big_g, m1, 1, r)) == force


@given(surface_gravities(), planet_radii(), surface_gravities())
def test_light_cannot_escape_from_the_black_hole_radius(g: float, mass: float, c: float) -> None:
    """At R = 2GM/c^2 (9.12b) the escape speed sqrt(2GM/R) (9.11b) is c (9.12a)."""
    big_g = 6.5e-11 * g  # any positive G
    radius = fields.schwarzschild_radius(big_g, mass, c)
    assert_close(math.sqrt(2 * big_g * mass / radius), c, rel=4 * REL, scale=c)


@given(oscillator_frequencies(), oscillator_frequencies(), oscillator_frequencies())
def test_shell_elements_cancel(solid_angle: float, near: float, far: float) -> None:
    """The shell elements cut by a cone of sight pull equally and oppositely: m/d^2 = M/D^2
    since both masses grow as distance squared (Fig. 9.6)."""
    assert_close(fields.shell_pair_pull(solid_angle, near, far), 0.0, scale=2 * solid_angle)


# --- the starlet's orbits: the isotropic 2-D oscillator (9.8)-(9.15) -------------------------


@given(
    oscillator_frequencies(),
    oscillator_amplitudes(),
    oscillator_amplitudes(),
    oscillator_times(),
    oscillator_times(),
    oscillator_times(),
)
def test_each_dimension_keeps_its_energy(
    omega: float, ax: float, ay: float, px: float, py: float, t: float
) -> None:
    """ex = 1/2 m vx^2 + 1/2 k x^2 and ey are each constant (9.10), with k = m omega^2."""
    start = fields.oscillator_orbit(omega, ax, ay, px, py, 0.0)
    later = fields.oscillator_orbit(omega, ax, ay, px, py, t)
    scale = omega * omega * (ax * ax + ay * ay) + 1e-300
    error = abs(later.energy_x - start.energy_x) + abs(later.energy_y - start.energy_y)
    target(error / scale, label="relative energy error")
    assert error <= TRIG * scale
    assert_close(later.energy_x, omega * omega * ax * ax / 2, rel=TRIG, scale=scale)
    assert_close(later.energy_y, omega * omega * ay * ay / 2, rel=TRIG, scale=scale)


@given(
    oscillator_frequencies(),
    oscillator_amplitudes(),
    oscillator_amplitudes(),
    oscillator_times(),
    oscillator_times(),
    oscillator_times(),
)
def test_starlet_orbit_keeps_its_angular_momentum(
    omega: float, ax: float, ay: float, px: float, py: float, t: float
) -> None:
    """The central force F = -kr (9.15) exerts no torque: x vy - y vx is constant, and equals
    omega X Y sin(alpha_x - alpha_y)."""
    start = fields.oscillator_orbit(omega, ax, ay, px, py, 0.0)
    later = fields.oscillator_orbit(omega, ax, ay, px, py, t)
    scale = omega * (ax * ax + ay * ay) + 1e-300
    error = abs(later.angular_momentum - start.angular_momentum)
    target(error / scale, label="relative angular momentum error")
    assert error <= TRIG * scale
    assert_close(start.angular_momentum, omega * ax * ay * math.sin(px - py), rel=TRIG, scale=scale)


@given(
    oscillator_frequencies(), oscillator_amplitudes(), oscillator_amplitudes(), oscillator_times()
)
def test_quadrature_orbit_is_the_ellipse_of_its_amplitudes(
    omega: float, a: float, b: float, t: float
) -> None:
    """With x a quarter period behind y, x = a cos wt and y = b sin wt trace x^2/a^2 + y^2/b^2 = 1
    ((9.13)); in phase they trace the line y = (b/a) x ((9.14))."""
    assume(abs(a) > 1e-3 and abs(b) > 1e-3)
    quad = fields.oscillator_orbit(omega, a, b, 0.0, -math.pi / 2, t)
    assert_close((quad.x / a) ** 2 + (quad.y / b) ** 2, 1.0, rel=TRIG, scale=1.0)
    line = fields.oscillator_orbit(omega, a, b, 0.0, 0.0, t)
    assert_close(line.y, b / a * line.x, rel=TRIG, scale=abs(b))


@given(lengths(), st.floats(min_value=-1.0, max_value=1.0))
@example(2.0, 1.0)  # the top of the swing
def test_initial_phase_puts_the_oscillator_at_its_start(amplitude: float, u: float) -> None:
    """x = X sin(alpha) (9.8b) gives back the start x0 for the phase alpha found, which lies in
    [-pi/2, pi/2]; starting at the top of the swing needs alpha = pi/2 (Fig. 9.10a), and a
    start beyond the swing is a ValueError."""
    x0 = u * amplitude
    alpha = fields.oscillator_initial_phase(x0, amplitude)
    assert_close(amplitude * math.sin(alpha), x0, rel=4 * REL, scale=amplitude)
    assert abs(alpha) <= math.pi / 2
    if u == 1:
        assert alpha == math.pi / 2
    with pytest.raises(ValueError, match="outside"):
        fields.oscillator_initial_phase(2 * amplitude, amplitude)


# --- the parabola: focus, directrix, kites (Figs. 9.1, 9.3, 9.4) ------------------------------


@given(fraction_coefficients(), slopes())
def test_parabola_points_are_as_far_from_focus_as_from_directrix(a: Fraction, x: float) -> None:
    """Every point of y = a x^2 is equally far from the focus and the directrix (Fig. 9.3b)."""
    geo = fields.parabola_geometry(float(a))
    to_focus = geo.focal_radius(x)
    to_directrix = geo.directrix_distance(x)
    assert_close(to_focus, to_directrix, rel=4 * REL, scale=to_focus + to_directrix)


@given(fraction_coefficients())
def test_parabola_lengths_are_exact(a: Fraction) -> None:
    """x^2 = 4 p y = 2 lambda y: lambda = 2p is the half-width at the focus, the tip's radius of
    curvature and the focus-directrix distance; the slope there is 1 (Figs. 9.3, 9.4)."""
    geo = fields.parabola_geometry(a)
    p, lam = geo.focal_height, geo.semi_latus_rectum
    assert lam == 2 * p == geo.focus_to_directrix == geo.tip_radius_of_curvature
    assert geo.height(lam) == p  # the latus rectum's ends are level with the focus
    assert geo.latus_end_slope == 1
    assert geo.focal_factor == 4
    assert geo.latus_factor == 2
    assert geo.directrix_height == -p


@given(fraction_coefficients(), slopes())
def test_force_triangle_altitude_is_constant(a: Fraction, x: float) -> None:
    """Each force triangle of U = a x^2 has the altitude 1/(2a) = lambda, and its hypotenuse is
    normal to the tangent (Fig. 9.1a); its base, the scaled force, is -x."""
    assume(abs(x) > 1e-6)
    tri = fields.force_triangle(float(a), x)
    assert_close(tri.altitude, 1 / (2 * float(a)), rel=4 * REL, scale=tri.altitude)
    assert_close(tri.base, -x, rel=4 * REL, scale=abs(x))
    slope = 2 * float(a) * x  # the tangent's direction (1, slope) is normal to the hypotenuse
    assert_close(
        tri.base + tri.altitude * slope,
        0.0,
        scale=abs(float(tri.base)) + abs(float(tri.altitude) * slope),
    )


@given(fraction_coefficients(), rationals(-10, 10, 12))
@example(Fraction(3), Fraction(0))  # the vertex: no force, no slope
def test_force_triangles_are_exact_and_alike_at_the_vertex(a: Fraction, x: Fraction) -> None:
    """On U = a x^2 the Hooke force is F = -dU/dx = -2 a x, minus the central difference
    quotient (exact for a parabola), and every force triangle has the scale and the altitude
    1/(2a) and the base -x, the vertex's too as the limit of its neighbours' (Fig. 9.1a)."""
    tri = fields.force_triangle(a, x)
    h = Fraction(1, 7)
    assert tri.force == -(a * (x + h) ** 2 - a * (x - h) ** 2) / (2 * h)
    assert tri.scale == tri.altitude == 1 / (2 * a)
    assert tri.base == -x


@given(fraction_coefficients(), rationals(-10, 10, 12))
@example(Fraction(3), Fraction(0))  # the tip, where the normal is the axis itself
def test_every_normal_meets_the_axis_lambda_above_its_point(a: Fraction, x: Fraction) -> None:
    """The normal at any point of y = a x^2 crosses the axis lambda = 1/(2a) higher up, the
    constant vertical of the tangent-kites of Fig. 9.4: the rise is x over the tangent's slope,
    a central difference quotient (exact for a parabola); at the tip, its limit lambda."""
    geo = fields.parabola_geometry(a)
    h = Fraction(1, 7)
    tangent = (geo.height(x + h) - geo.height(x - h)) / (2 * h)
    rise = geo.semi_latus_rectum if x == 0 else x / tangent
    assert geo.subnormal(x) == rise == 1 / (2 * a)


@given(fraction_coefficients(), st.integers(min_value=0, max_value=6), rationals(-10, 10, 12))
@example(Fraction(3), 1, Fraction(0))  # a linear potential pushes at the origin too
@example(Fraction(3), 0, Fraction(1))  # a constant potential does not push at all
def test_power_law_force_is_minus_the_slope(a: Fraction, n: int, x: Fraction) -> None:
    """F = -dU/dx of U = a x^n (Force = -Slope, (6.9); Hooke's F = -2x of Fig. 9.1b): x F = -n U
    exactly, as the power rule has it, and F is minus the complex-step slope of U; a power below
    1 has an infinite force at x = 0, a ValueError."""
    n = max(n, 1) if x == 0 else n
    force = fields.power_law_force(a, n, x)
    assert x * force == -n * a * x**n
    step = 1e-30
    expected = -(float(a) * (float(x) + step * 1j) ** n).imag / step
    assert_close(float(force), expected, scale=abs(expected) + float(a))
    if x == 0:
        assert force == (-a if n == 1 else 0)
        with pytest.raises(ValueError, match="infinite"):
            fields.power_law_force(a, Fraction(1, 2), x)


@given(fraction_coefficients(), fraction_coefficients())
def test_similar_triangles_square_exactly(x: Fraction, unit: Fraction) -> None:
    """The two-step construction of Fig. 9.1a gives y = x^2 / unit exactly (y = x^2 for the
    default unit 1)."""
    assert fields.parabola_point(x, unit) == x * x / unit
    assert fields.parabola_point(x) == x * x


@given(slopes())
@example(1.0)  # y = x and y = -x
@example(0.0)  # the axis: its normal is vertical, with no slope
def test_normal_lines_are_perpendicular(slope: float) -> None:
    """The lines y = s x and y = -x/s meet at 90 degrees (Fig. 9.2); a horizontal line's normal
    has no slope."""
    if slope == 0:
        with pytest.raises(ValueError, match="vertical"):
            fields.normal_slope(slope)
        return
    assume(abs(slope) > 1e-6)
    normal = fields.normal_slope(slope)
    assert_close(fields.angle_between_lines(slope, normal), math.pi / 2, rel=4 * REL, scale=1.0)


@given(slopes(), slopes())
@example(10.0, -10.0)  # steep lines either side of the vertical: an acute angle between them
def test_angle_between_lines_is_the_acute_angle_of_their_directions(s1: float, s2: float) -> None:
    """Lines of slopes s1 and s2 meet at the acute angle whose tangent is |s2 - s1| / |1 + s1 s2|
    (the cross and dot products of their directions (1, s1) and (1, s2)): 0 to 90 degrees, the
    90-degree marks of Fig. 9.2 for y = s x and y = -x/s."""
    expected = math.atan2(abs(s2 - s1), abs(1 + s1 * s2))
    assert_close(fields.angle_between_lines(s1, s2), expected, rel=4 * REL, scale=1.0)


@given(slopes())
def test_tangent_bisects_focal_radius_and_drop_line(slope: float) -> None:
    """At the point of slope s, the angle between focal radius and drop line is twice the angle
    between tangent and drop line (the reflection law of Figs. 9.3b, 9.4, 9.7)."""
    x = slope / 2  # on y = x^2 the slope 2x is s
    geo = fields.parabola_geometry(1)
    to_focus = math.atan2(geo.focal_height - geo.height(x), -x)  # direction to the focus
    drop = -math.pi / 2
    angle = abs(math.remainder(to_focus - drop, 2 * math.pi))
    assert_close(angle, fields.focal_drop_angle(abs(slope)), rel=1e-9, scale=math.pi)


# --- calculus, clocks and counts ------------------------------------------------------------


@given(fraction_coefficients())
def test_antiderivative_undoes_the_derivative(n: Fraction) -> None:
    """d/dr r^n = n r^(n-1) and the antiderivative of r^(n-1) is r^n / n ((9.2b)-(9.2c))."""
    assume(n != 0)
    down = fields.power_law_calculus(n)
    up = fields.power_law_calculus(down.derivative_exponent)
    assert up.antiderivative_exponent == n
    assert up.antiderivative_coefficient is not None  # n - 1 != -1: a power, not a log
    assert up.antiderivative_coefficient * down.derivative_coefficient == 1


@given(clock_hours(), clock_hours(), clock_sizes())
def test_clock_hours_wrap_onto_the_dial(hour: int, lead: int, clock: int) -> None:
    """The hour lead hours later is the same hour modulo the clock, written from -clock/2
    (exclusive) to clock/2 like the dials of Fig. 9.10."""
    later = fields.clock_hour(hour, lead, clock)
    assert (later - hour - lead) % clock == 0
    assert -Fraction(clock, 2) < later <= Fraction(clock, 2)


@given(st.integers(min_value=1, max_value=100), st.integers(min_value=1, max_value=12))
@example(1, 1)  # one point per period
def test_an_orbit_of_whole_steps_has_one_point_per_step(points: int, step: int) -> None:
    """An orbit drawn one point per step over a period of points x step time units has exactly
    that many points (exercise 1.9.5: 24 points for 24 hours); a period that is not a whole
    number of steps is a ValueError."""
    assert fields.points_per_orbit(points * step, step) == points
    if step > 1:
        with pytest.raises(ValueError, match="whole number"):
            fields.points_per_orbit(points * step + 1, step)


@given(planet_radii(), radial_fractions())
def test_chord_is_never_longer_than_the_diameter(radius: float, u: float) -> None:
    """A straight tunnel between surface points an angle apart is 2 R sin(angle/2): at most the
    diameter, which the half-turn reaches (exercise 1.9.4: R sqrt(2) for 90 degrees)."""
    angle = u * math.pi / 10
    assert fields.chord_length(radius, angle) <= 2 * radius * (1 + REL)
    assert_close(fields.chord_length(radius, math.pi), 2 * radius, scale=radius)
    assert_close(
        fields.chord_length(radius, math.pi / 2), radius * math.sqrt(2), rel=4 * REL, scale=radius
    )


@given(
    surface_gravities(), planet_radii(), radial_fractions(), st.floats(min_value=0.1, max_value=10)
)
def test_potential_energy_is_mass_times_potential_and_its_slope_the_force(
    g: float, radius: float, fraction: float, mass: float
) -> None:
    """U = m Phi, and the field is minus the slope of the potential, -dPhi/dr = F/m, inside and
    outside a uniform Earth (Fig. 9.7)."""
    r = 2 * radius * fraction + radius / 100
    energy = fields.potential_energy(mass, g, radius, r)
    assert math.isclose(energy, mass * fields.gravity_potential(g, radius, r), rel_tol=1e-12)
    h = r * 1e-6
    phi = fields.gravity_potential
    slope = (phi(g, radius, r + h) - phi(g, radius, r - h)) / (2 * h)
    # the central difference cancels digits of a potential far larger than its slope near r = 0
    cancellation = 1e-9 * abs(float(phi(g, radius, r))) / h
    field = fields.gravity_field(g, radius, r)
    assert math.isclose(-slope, field, rel_tol=1e-6, abs_tol=cancellation)


@given(st.floats(min_value=0.1, max_value=10), st.floats(min_value=0.1, max_value=10))
def test_coulomb_force_is_minus_the_slope_of_coulomb_energy(q: float, r: float) -> None:
    """F = k q1 q2 / r^2 is -dU/dr of U = k q1 q2 / r (9.1)-(9.2a): halving r quadruples F."""
    k = 1.0
    h = r * 1e-6
    slope = (fields.coulomb_energy(k, q, q, r + h) - fields.coulomb_energy(k, q, q, r - h)) / (
        2 * h
    )
    force = fields.coulomb_force(k, q, q, r)
    assert math.isclose(-slope, force, rel_tol=1e-6)
    assert math.isclose(fields.coulomb_force(k, q, q, r / 2), 4 * force, rel_tol=1e-12)


# --- the formulas of chapter 9 as the book writes them: parabola by p or lambda, Coulomb by
# calculus, a uniform ball, the starlet's energy, the oscillator's phase, escape ----------------


@given(fraction_coefficients(), st.integers(min_value=0, max_value=6), rationals(-10, 10, 12))
@example(Fraction(1), 2, Fraction(3))  # Fig. 9.1b: the Hooke line of U = x^2 has slope -2
def test_force_slope_is_the_power_rule_again(a: Fraction, n: int, x: Fraction) -> None:
    """The slope of F = -dU/dx for U = a x^n: x dF/dx = (n - 1) F (F goes as x^(n-1)),
    exactly; for the oscillator n = 2 it is the constant -2a of the straight Hooke line."""
    if x == 0:
        x = Fraction(1, 3)
    slope = fields.power_law_force_slope(a, n, x)
    assert x * slope == (n - 1) * fields.power_law_force(a, n, x)
    assert fields.power_law_force_slope(a, 2, x) == -2 * a


@given(fraction_coefficients())
@example(Fraction(1, 4))  # y = x^2: p = 1/4, lambda = 1/2
def test_parabola_by_focus_and_by_latus_agree(p: Fraction) -> None:
    """The parabola whose focus is p above its tip is the one of half-width lambda = 2p at the
    focus (Figs. 9.3-9.4): exactly; its tip is p below the focus and p above the directrix,
    the points lambda across are at the focus's height, and the tip's radius of curvature is
    lambda."""
    by_focus = fields.parabola_for_focus(p)
    assert by_focus.focal_height == p
    assert fields.parabola_for_latus(by_focus.semi_latus_rectum) == by_focus
    lam = by_focus.semi_latus_rectum
    assert by_focus.height(lam) == by_focus.focal_height == by_focus.tip_to_directrix
    assert by_focus.tip_radius_of_curvature == lam


@given(st.floats(min_value=0.01, max_value=100), st.floats(min_value=-10, max_value=10))
def test_parabola_slope_and_its_point_of_slope_one(p: float, x: float) -> None:
    """The slope of the parabola of focal height p is the derivative of its height (a central
    difference agrees); it is 1 at the end of the latus rectum, level with the focus, whose
    focal radius is then horizontal: its distance from the focus is its distance x across."""
    h = 1e-6 * max(abs(x), p)
    height = fields.parabola_height_for_focus
    difference = (height(p, x + h) - height(p, x - h)) / (2 * h)
    slope = fields.parabola_slope_for_focus(p, x)
    assert math.isclose(slope, difference, rel_tol=1e-6, abs_tol=1e-9 * (1 + abs(x) / p))
    point = fields.parabola_unit_slope_point(p)
    assert math.isclose(fields.parabola_slope_for_focus(p, point.x), 1, rel_tol=4 * REL)
    assert math.isclose(height(p, point.x), p, rel_tol=4 * REL)
    assert math.isclose(point.focal_distance, point.x, rel_tol=4 * REL)


@given(st.floats(min_value=0.01, max_value=100), st.floats(min_value=-30, max_value=30))
def test_the_equidistant_point_is_on_the_parabola(p: float, x: float) -> None:
    """The point found from the definition (as far from the focus as from the directrix) is
    at the height 4 p y = x^2 gives, and of the parabola of semi-latus rectum 2p."""
    y = fields.equidistant_height(p, x)
    assert math.isclose(math.hypot(x, y - p), y + p, rel_tol=1e-12)
    assert math.isclose(y, fields.parabola_height_for_focus(p, x), rel_tol=1e-9, abs_tol=1e-12 * p)
    latus = fields.equidistant_height_for_latus(2 * p, x)
    assert math.isclose(latus, y, rel_tol=1e-12, abs_tol=1e-15 * p)


@given(
    st.floats(min_value=-10, max_value=10).filter(lambda q: abs(q) > 1e-3),
    st.floats(min_value=0.1, max_value=10),
    st.floats(min_value=0.1, max_value=10),
    st.floats(min_value=0.1, max_value=10),
)
def test_coulomb_force_and_potential_by_calculus(
    q: float, big_q: float, epsilon0: float, r: float
) -> None:
    """(9.2b)-(9.2c): the force found as -dU/dr of the potential, and the potential found as
    minus the integral of the force from infinity, are Coulomb's k q Q / r^2 and k q Q / r
    with k = 1/(4 pi eps0); the potential's slope is minus the force."""
    k = 1 / (4 * math.pi * epsilon0)
    force = fields.coulomb_force_from_potential(q, big_q, epsilon0, r)
    potential = fields.coulomb_potential_from_force(q, big_q, epsilon0, r)
    assert math.isclose(force, fields.coulomb_force(k, q, big_q, r), rel_tol=4 * REL)
    assert math.isclose(potential, fields.coulomb_energy(k, q, big_q, r), rel_tol=4 * REL)
    h = r * 1e-6
    slope = (
        fields.coulomb_potential_from_force(q, big_q, epsilon0, r + h)
        - fields.coulomb_potential_from_force(q, big_q, epsilon0, r - h)
    ) / (2 * h)
    assert math.isclose(-slope, force, rel_tol=1e-6)


@given(surface_gravities(), planet_radii(), st.floats(min_value=0.01, max_value=1))
def test_a_uniform_ball_pulls_linearly_inside(g: float, radius: float, fraction: float) -> None:
    """Inside a uniform ball only the mass within r pulls (9.4a): the pull grows linearly with
    r, reaches the surface gravity G R 4 pi rho / 3 at r = R (9.4b), and matches the field of a
    uniform Earth of that surface gravity; the inside mass is the density times the volume."""
    big_g = 6.7e-11
    density = g / (big_g * radius * 4 * math.pi / 3)  # the density that gives the gravity g
    r = fraction * radius
    assert math.isclose(
        fields.inside_mass(density, r), density * fields.sphere_volume(r), rel_tol=4 * REL
    )
    pull = fields.inside_gravity_force(big_g, density, 1.0, r)
    half = fields.inside_gravity_force(big_g, density, 1.0, r / 2)
    assert math.isclose(half, pull / 2, rel_tol=8 * REL)
    surface = fields.uniform_surface_gravity(big_g, density, radius)
    assert math.isclose(surface, g, rel_tol=8 * REL)
    assert math.isclose(pull, -fields.gravity_field(g, radius, r), rel_tol=8 * REL)
    assert math.isclose(fields.inside_gravity_force(big_g, density, 3.0, r), 3 * pull, rel_tol=REL)


@given(fraction_coefficients(), rationals(-1, 1, 12))
@example(Fraction(1), Fraction(1))  # Fig. 9.7: U(1) = -1 = -1/x at the surface
def test_interior_curve_is_the_parabola_under_the_surface(surface: Fraction, u: Fraction) -> None:
    """The interior potential at x (|x| <= surface) is its spring part x^2 / (2 s^3), zero at
    the centre, plus the offset; it meets -1/x at the surface, exactly. Its parabola's
    half-width at the focus is s^3 (lambda = 1 in Fig. 9.7)."""
    x = u * surface
    curve = fields.interior_potential_at(surface, x)
    pot = fields.interior_potential(surface)
    assert curve.spring == x * x / (2 * surface**3)
    assert curve.value - curve.spring == pot.offset
    assert fields.interior_potential_at(surface, surface).value == -1 / surface
    assert fields.interior_potential_at(surface, 0).spring == 0
    assert fields.interior_parabola(surface).semi_latus_rectum == surface**3
    with pytest.raises(ValueError, match="outside"):
        fields.interior_potential_at(surface, 2 * surface)


@given(surface_gravities(), planet_radii(), st.floats(min_value=0.1, max_value=10))
def test_the_starlet_keeps_its_energy_from_surface_to_centre(
    g: float, radius: float, mass: float
) -> None:
    """Dropped from rest at the surface, the starlet passes the centre with v^2 = g R, the
    grazing orbit's speed squared ((9.6)-(9.7)): its energy KE + PE is the same at both."""
    v2 = fields.centre_speed_squared(g, radius)
    assert math.isclose(v2, fields.circular_orbit_speed(g, radius) ** 2, rel_tol=4 * REL)
    at_surface = fields.starlet_energy(mass, g, radius, radius, 0)
    at_centre = fields.starlet_energy(mass, g, radius, 0, math.sqrt(v2))
    assert math.isclose(at_surface, at_centre, rel_tol=8 * REL)
    assert math.isclose(at_surface, -mass * g * radius, rel_tol=8 * REL)


@given(surface_gravities(), planet_radii(), surface_gravities())
def test_escape_speed_three_ways(g: float, radius: float, c: float) -> None:
    """The escape speed from the grazing orbit speed (9.11a), from G M and R (9.11b) and from
    g and R agree; it falls as 1/sqrt(R); at the black-hole radius it is c (9.12), which is
    the Schwarzschild radius 2GM/c^2."""
    big_g = 6.7e-11
    mass = g * radius * radius / big_g
    escape = fields.escape_speed(g, radius)
    orbit = fields.circular_orbit_speed(g, radius)
    assert math.isclose(fields.escape_speed_of_orbit(orbit), escape, rel_tol=4 * REL)
    assert math.isclose(fields.escape_speed_gm(big_g, mass, radius), escape, rel_tol=8 * REL)
    quarter = fields.escape_speed_gm(big_g, mass, 4 * radius)
    assert math.isclose(quarter, escape / 2, rel_tol=8 * REL)
    hole = fields.black_hole_radius(big_g, mass, c)
    assert math.isclose(fields.escape_speed_gm(big_g, mass, hole), c, rel_tol=8 * REL)
    assert math.isclose(hole, fields.schwarzschild_radius(big_g, mass, c), rel_tol=8 * REL)


@given(
    st.floats(min_value=0.1, max_value=10),
    st.floats(min_value=0.1, max_value=10),
    st.floats(min_value=0.1, max_value=10),
    phase_angles(),
)
def test_oscillator_phase_state_keeps_the_energy(
    energy: float, k: float, mass: float, theta: float
) -> None:
    """At every phase the oscillator's kinetic and potential energies add up to E ((9.8a));
    the velocity is the phase rate omega = sqrt(k/m) times dx/dtheta ((9.9)), the time
    derivative of x = X sin(omega t) (a central difference agrees)."""
    state = fields.oscillator_phase_state(energy, k, mass, theta)
    total = mass * state.v**2 / 2 + k * state.x**2 / 2
    assert math.isclose(total, energy, rel_tol=8 * REL)
    assert math.isclose(state.omega**2, k / mass, rel_tol=4 * REL)
    assert state.v == fields.phase_velocity(energy, k, state.omega, theta)
    h = 1e-6 / state.omega
    ahead = fields.oscillator_phase_state(energy, k, mass, theta + state.omega * h).x
    behind = fields.oscillator_phase_state(energy, k, mass, theta - state.omega * h).x
    amplitude = fields.oscillator_amplitude(energy, k)
    assert math.isclose((ahead - behind) / (2 * h), state.v, abs_tol=1e-6 * amplitude * state.omega)


@given(
    oscillator_frequencies(),
    oscillator_amplitudes(),
    oscillator_amplitudes(),
    phase_angles(),
    oscillator_times(),
)
def test_total_energy_is_the_sum_of_the_dimensions(
    omega: float, amp_x: float, amp_y: float, lag: float, t: float
) -> None:
    """The isotropic oscillator's total energy is ex + ey, the energies of its x and y motions
    ((9.10)): for a unit mass with k = omega^2 it is the sum of the orbit's two per-dimension
    energies, the same at every time."""
    state = fields.oscillator_orbit(omega, amp_x, amp_y, 0.0, lag, t)
    total = fields.oscillator_total_energy(1, omega * omega, state.x, state.y, state.vx, state.vy)
    expected = omega * omega * (amp_x * amp_x + amp_y * amp_y) / 2  # at the turning points
    assert_close(total, state.energy_x + state.energy_y, scale=expected)
    assert_close(total, expected, rel=TRIG, scale=expected)


@given(fraction_quantities(), fraction_quantities(), fraction_quantities(), fraction_quantities())
def test_constant_units_keep_the_laws_in_any_units(
    newton: Fraction, metre: Fraction, kilogram: Fraction, coulomb: Fraction
) -> None:
    """Measured in other units (a newton, metre, kilogram, coulomb worth the given numbers, a
    joule a newton metre), G and Coulomb's constant take the factors of their units, and
    Newton's law (9.3) and the potential (9.2a) hold unchanged, exactly: N = [G] kg^2/m^2 and
    J = [k] C^2/m."""
    g_unit = fields.gravitational_constant_unit(newton, metre, kilogram)
    assert g_unit * kilogram * kilogram / (metre * metre) == newton
    joule = newton * metre
    k_unit = fields.coulomb_constant_unit(joule, metre, coulomb)
    assert k_unit * coulomb * coulomb / metre == joule
    assert fields.gravitational_constant_unit(1, 1, 1) == fields.coulomb_constant_unit(1, 1, 1) == 1
