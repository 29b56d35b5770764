"""Tunnels, the grazing orbit, the isotropic oscillator (chapter 9, (9.8)-(9.15), Figs. 9.8-9.11).

Every straight tunnel through a uniform Earth is the same harmonic oscillator, period
2 pi sqrt(R/g) (the 84 minutes of Fig. 9.8), in step with the grazing circular orbit; the
starlet inside is an isotropic 2-D oscillator x = X cos(w t + ax), y = Y cos(w t + ay) whose
orbits, per-dimension energies and angular momentum are computed here, with the phases and
clock hours of Figs. 9.10-9.11. SI units (m, s), angles in radians.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass
from fractions import Fraction

from mechmodel import inputs
from mechmodel.fields.earth import circular_orbit_speed, gravity_field
from mechmodel.typing import Real, Symbolic


def tunnel_period(g: Real, radius: Real) -> float:
    """Period of a full oscillation through any straight tunnel, 2 pi sqrt(R / g) (eq. (9.8)).

    It does not depend on the chord: every tunnel is a harmonic oscillator with the same
    frequency sqrt(g / R).
    """
    inputs.positive(g, "g")
    inputs.positive(radius, "radius")
    return 2 * math.pi * math.sqrt(radius / g)


def tunnel_transit_time(g: Real, radius: Real) -> float:
    """Time to fall through a tunnel to the far end, half a period: pi sqrt(R / g) (Fig. 9.8)."""
    return tunnel_period(g, radius) / 2


def round_trip_time(transit: Real) -> Real:
    """A full tunnel period from a one-way transit time: there and back, twice the transit
    (the 84-minute period from the 42 minutes of Fig. 9.8), in the transit's unit."""
    inputs.positive(transit, "transit")
    return 2 * transit


def circular_orbit_period(g: Real, radius: Real) -> float:
    """Period 2 pi R / v0 of the grazing circular orbit (Fig. 9.8)."""
    return 2 * math.pi * radius / circular_orbit_speed(g, radius)


def orbit_meeting_fraction(g: Real, radius: Real) -> float:
    """Fraction of its orbit the grazing satellite covers while a body falls through the tunnel
    to the far side: the two meet "1/2-way around" (Fig. 9.8)."""
    return tunnel_transit_time(g, radius) / circular_orbit_period(g, radius)


def chord_acceleration(g: Real, radius: Real, offset: Real, s: Real) -> float:
    """Acceleration along a straight tunnel (a chord passing ``offset`` from the centre) of a
    body at ``s`` from the chord's midpoint, m/s^2.

    The field inside points to the centre with strength g r / R; its component along the chord
    is -g s / R whatever the offset: every chord is the same harmonic oscillator.
    """
    inputs.positive(radius, "radius")
    inputs.real(offset, "offset")
    inputs.real(s, "s")
    r = math.hypot(offset, s)
    if r > radius * (1 + 8 * sys.float_info.epsilon):  # a chord's ends may round just outside
        raise ValueError("the point is outside the Earth: a tunnel runs inside it")
    if r == 0:
        return 0.0
    return gravity_field(g, radius, r) * s / r


def chord_tunnel_period(g: Real, radius: Real, offset: Real) -> float:
    """Period of a body sliding without friction through a chord passing ``offset`` from the
    centre: 2 pi / sqrt(-a(s)/s), the same for every chord (the synchrony of Fig. 9.8)."""
    inputs.positive(radius, "radius")
    inputs.real(offset, "offset")
    if not -radius < offset < radius:
        raise ValueError("a chord passes inside the Earth: |offset| < radius")
    half_chord = math.sqrt(radius * radius - offset * offset)
    stiffness = -chord_acceleration(g, radius, offset, half_chord) / half_chord
    return 2 * math.pi / math.sqrt(stiffness)


def chord_tunnel_position(g: Real, radius: Real, offset: Real, t: Real) -> tuple[float, float]:
    """Position s and velocity ds/dt, at time ``t``, of a body released at rest at the end of a
    chord passing ``offset`` from the centre (m, m/s): s = s0 cos(w t), w = 2 pi / period."""
    omega = 2 * math.pi / chord_tunnel_period(g, radius, offset)
    half_chord = math.sqrt(radius * radius - offset * offset)
    return half_chord * math.cos(omega * t), -half_chord * omega * math.sin(omega * t)


def chord_length(radius: Real, angle: Real) -> float:
    """Length 2 R sin(angle/2) of the straight tunnel between two surface points ``angle``
    (radians) apart as seen from the centre (exercise 1.9.4: R sqrt(2) for 90 degrees)."""
    inputs.positive(radius, "radius")
    inputs.real(angle, "angle")
    return 2 * radius * math.sin(angle / 2)


def time_zones(longitude: Real, hours_per_day: Real) -> float:
    """Number of hourly time zones spanned by ``longitude`` (radians): one per 2 pi / 24."""
    inputs.real(longitude, "longitude")
    inputs.positive(hours_per_day, "hours_per_day")
    return longitude / (2 * math.pi / hours_per_day)


# --- the isotropic 2-D oscillator: the starlet's orbits (9.8)-(9.15) -------------------------


@dataclass(frozen=True)
class OscillatorState:
    """Position, velocity, per-unit-mass energies of each dimension (ex, ey of (9.10)) and the
    angular momentum per unit mass x vy - y vx of an isotropic 2-D oscillator."""

    x: float
    y: float
    vx: float
    vy: float
    energy_x: float
    energy_y: float
    angular_momentum: float


def oscillator_orbit(
    omega: Real, amp_x: Real, amp_y: Real, phase_x: Real, phase_y: Real, t: Real
) -> OscillatorState:
    """State at time ``t`` of the isotropic oscillator x = X cos(w t + ax), y = Y cos(w t + ay)
    (force -m w^2 r: F = -kr implies Fx = -kx, Fy = -ky (9.15)).

    Equal amplitudes and a quarter-period lag give a circle ((9.13), the starlet of Fig. 9.8);
    zero lag a straight line (9.14); any other lag an inclined ellipse (Fig. 9.10b).
    """
    inputs.positive(omega, "omega")
    for value, name in ((amp_x, "amp_x"), (amp_y, "amp_y"), (phase_x, "phase_x")):
        inputs.real(value, name)
    inputs.real(phase_y, "phase_y")
    inputs.real(t, "t")
    x = amp_x * math.cos(omega * t + phase_x)
    y = amp_y * math.cos(omega * t + phase_y)
    vx = -amp_x * omega * math.sin(omega * t + phase_x)
    vy = -amp_y * omega * math.sin(omega * t + phase_y)
    ex = (vx * vx + omega * omega * x * x) / 2
    ey = (vy * vy + omega * omega * y * y) / 2
    return OscillatorState(x, y, vx, vy, ex, ey, x * vy - y * vx)


def oscillator_amplitude(energy: Real, stiffness: Real) -> float:
    """Amplitude X of an oscillator of energy E whose potential is 1/2 k x^2: at the turning
    point all the energy is potential, 1/2 k X^2 = E ((9.8b))."""
    inputs.positive(energy, "energy")
    inputs.positive(stiffness, "stiffness")
    return math.sqrt(energy / (stiffness / 2))


def phase_velocity(energy: Real, stiffness: Real, omega: Real, theta: Real) -> float:
    """Velocity v = dx/dt = (dtheta/dt) (dx/dtheta) of the oscillator x = X sin(theta) of
    energy E (``oscillator_amplitude``), whose phase turns at the rate ``omega`` ((9.9a))."""
    inputs.real(omega, "omega")
    inputs.real(theta, "theta")
    amplitude = oscillator_amplitude(energy, stiffness)
    dx_dtheta = amplitude * math.cos(theta)  # d/dtheta of X sin(theta)
    return omega * dx_dtheta


@dataclass(frozen=True)
class PhaseState:
    """Position and velocity of an oscillator of energy E, stiffness k and mass m at phase
    theta ((9.8b)-(9.9)): x = X sin(theta), v = dx/dt, and the phase rate omega."""

    x: float
    v: float
    omega: float


def oscillator_phase_state(energy: Real, stiffness: Real, mass: Real, theta: Real) -> PhaseState:
    """The oscillator of ``energy``, ``stiffness`` and ``mass`` at phase ``theta``: x = X
    sin(theta) with 1/2 k X^2 = E, and v = omega dx/dtheta with omega^2 = k / m, the rate
    at which m x'' = -k x turns the phase of x = X sin(omega t + alpha) ((9.8)-(9.9))."""
    inputs.mass(mass, "mass")
    inputs.real(theta, "theta")
    amplitude = oscillator_amplitude(energy, stiffness)
    omega = math.sqrt(stiffness / mass)
    return PhaseState(
        amplitude * math.sin(theta), phase_velocity(energy, stiffness, omega, theta), omega
    )


def oscillator_total_energy(
    mass: Symbolic, stiffness: Symbolic, x: Symbolic, y: Symbolic, vx: Symbolic, vy: Symbolic
) -> Symbolic:
    """Total energy of the isotropic 2-D oscillator at (x, y) with velocity (vx, vy): kinetic
    1/2 m |v|^2 plus the potential 1/2 k |r|^2 of the linear force F = -k r ((9.10), (9.15)).
    Plain operators (exact, symbolic)."""
    kinetic = mass * (vx * vx + vy * vy) / 2
    potential = stiffness * (x * x + y * y) / 2
    return kinetic + potential


def oscillator_initial_phase(x0: Real, amplitude: Real) -> float:
    """Initial phase alpha with x = X sin(alpha) = x0 at t = 0 ((9.8b), theta = w t + alpha):
    starting at the top of the swing, x0 = X, needs alpha = pi/2 (the clock of Fig. 9.10a)."""
    inputs.positive(amplitude, "amplitude")
    inputs.real(x0, "x0")
    if not -amplitude <= x0 <= amplitude:
        raise ValueError("the start lies outside the swing: |x0| <= amplitude")
    return math.asin(x0 / amplitude)


def clock_hour(hour: Real, lead: Real, clock_hours: int) -> Real:
    """The hour ``lead`` hours after ``hour`` on a clock of ``clock_hours`` hours, written from
    -clock/2 (exclusive) to clock/2 as Fig. 9.10b labels its dials (8 then -7 on 16 hours)."""
    clock = inputs.count(clock_hours, "clock_hours", minimum=1)
    inputs.real(hour, "hour")
    inputs.real(lead, "lead")
    later = (hour + lead) % clock
    return later - clock if later > Fraction(clock, 2) else later


@dataclass(frozen=True)
class PhaseLag:
    """A relative phase lag of two oscillator dimensions: radians, hours on the clock, fraction
    of a period, and the lag with the leads switched (Figs. 9.10b, 9.11)."""

    radians: Real
    hours: float
    period_fraction: float
    reversed: Real


def phase_lag(angle: Real, clock_hours: Real) -> PhaseLag:
    """The lag ``angle`` (radians) as hours of a ``clock_hours`` clock and as a fraction of the
    period; switching the leads reverses its sign (right- vs left-handed orbits)."""
    inputs.real(angle, "angle")
    inputs.positive(clock_hours, "clock_hours")
    fraction = angle / (2 * math.pi)
    return PhaseLag(angle, fraction * clock_hours, fraction, -angle)


def points_per_orbit(period: int, step: int) -> int:
    """Number of points of an orbit drawn one per ``step`` over one ``period`` (exercise 1.9.5)."""
    period = inputs.count(period, "period", minimum=1)
    step = inputs.count(step, "step", minimum=1)
    if period % step:
        raise ValueError("the period is not a whole number of steps")
    return period // step
