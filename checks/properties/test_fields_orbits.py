"""Laws of the tunnels, the grazing orbit and the isotropic 2-D oscillator
(mechmodel.fields.orbits): chapter 9, (9.8)-(9.15), Figs. 9.8-9.11.

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
    lengths,
    oscillator_amplitudes,
    oscillator_frequencies,
    oscillator_times,
    phase_angles,
    planet_radii,
    radial_fractions,
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


# --- clocks, counts and chords ----------------------------------------------------------------


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


# --- the formulas of chapter 9 as the book writes them: the oscillator ------------------------


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
