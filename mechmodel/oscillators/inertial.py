"""Centrifugal and tidal forces of rotation and orbits (chapter 11, (11.2)-(11.3), p. 171).

Rotation at w gives the centrifugal acceleration w^2 r = V^2/r (11.3) and the force m w^2 r of
a spring k = m w^2 (11.2); the radius of curvature r = V^2/a of a path (11.3c); a fast orbit a
tidal stiffness m w^2 (p. 171), whose neighbouring free-fall orbits cross twice per period.

Units: SI (N, m, s, kg, rad/s) or any consistent set.
"""

from __future__ import annotations

import math

from mechmodel import inputs
from mechmodel.exact import exact_div, exact_sqrt
from mechmodel.oscillators.orbit import orbit_derivative
from mechmodel.typing import Real


def oscillator_frequency(k: Real, mass: Real) -> Real:
    """Angular frequency w = sqrt(k/m) of a mass on a spring or in the Earth (11.2a); exact for
    rational perfect squares."""
    inputs.positive(k, "k")
    inputs.mass(mass)
    return exact_sqrt(exact_div(k, mass))


def spring_constant(mass: Real, omega: Real) -> Real:
    """Spring constant k = m w^2 (11.2b) that gives the angular frequency w to the mass m."""
    inputs.mass(mass)
    inputs.positive(omega, "omega")
    return mass * omega**2


def centrifugal_force(mass: Real, omega: Real, radius: Real) -> Real:
    """Centrifugal force m w^2 r = k r of rotation at w on a circle of radius r (11.3a)."""
    inputs.real(radius, "radius")
    return spring_constant(mass, omega) * radius


def centrifugal_acceleration(speed: Real, radius: Real) -> Real:
    """Centrifugal acceleration V^2/r of motion at speed V on a circle of radius r (11.3b)."""
    inputs.real(speed, "speed")
    inputs.positive(radius, "radius")
    return speed * speed / radius


def curvature_radius(speed: Real, acceleration: Real) -> Real:
    """Radius of curvature r = V^2/a of a path driven at speed V with transverse acceleration a
    (11.3c)."""
    inputs.real(speed, "speed")
    inputs.positive(acceleration, "acceleration")
    return speed * speed / acceleration


def circular_acceleration(radius: Real, omega: Real) -> float:
    """Magnitude of the acceleration of uniform motion at the rate w on a circle of radius r:
    the orbit (11.5a) with a = b = r differentiated twice ((11.5b), the acceleration vector at
    any time; taken at t = 0). The centrifugal acceleration of (11.3b) is its reaction."""
    inputs.positive(radius, "radius")
    return math.hypot(*orbit_derivative(radius, radius, omega, 0, 2))


def circular_acceleration_at_speed(radius: Real, speed: Real) -> float:
    """The same acceleration for the rim speed V: the rate is w = V/r (V = w r, (11.3))."""
    inputs.positive(radius, "radius")
    inputs.positive(speed, "speed")
    return circular_acceleration(radius, speed / radius)


def circular_force(mass: Real, radius: Real, omega: Real) -> float:
    """Centrifugal force on a mass m turning at w on a circle of radius r (Fig. 11.2, (11.3a)):
    m times the acceleration its circular motion needs."""
    inputs.mass(mass)
    return mass * circular_acceleration(radius, omega)


def circular_force_at_speed(mass: Real, radius: Real, speed: Real) -> float:
    """The same centrifugal force for the rim speed V ((11.3a))."""
    inputs.mass(mass)
    return mass * circular_acceleration_at_speed(radius, speed)


def curvature_radius_at_speed(speed: Real, acceleration: Real) -> float:
    """Radius of the circle of curvature of a path driven at speed V with transverse
    acceleration a (11.3c): at fixed V the circular acceleration falls in inverse proportion to
    the radius (the orbit scaled by s at the rate w/s), so r = (acceleration at r = 1)/a."""
    inputs.positive(acceleration, "acceleration")
    return circular_acceleration_at_speed(1, speed) / acceleration


def curvature_radius_at_rate(omega: Real, acceleration: Real) -> float:
    """Radius of the circle of curvature for the angular rate w and transverse acceleration a
    (11.3c): at fixed w the circular acceleration grows in proportion to the radius (the orbit
    (11.5a) is linear in a = b = r), so r = a/(acceleration at r = 1)."""
    inputs.positive(acceleration, "acceleration")
    return acceleration / circular_acceleration(1, omega)


def angular_frequency(frequency: Real) -> float:
    """Angular frequency w = 2 pi f, rad/s, of an orbit of f revolutions per second (p. 171:
    1 kHz gives w = 2000 pi)."""
    inputs.positive(frequency, "frequency")
    return 2 * math.pi * frequency


def tidal_force(frequency: Real, mass: Real, offset: Real) -> Real:
    """Tidal force k x = m w^2 x, N, on a mass m at distance x from the centre of gravity of a
    body orbiting at frequency f, w = 2 pi f (p. 171): the centrifugal force (11.3a) that
    gravity no longer balances off the centre."""
    return centrifugal_force(mass, angular_frequency(frequency), offset)


def hooke_force_at(force: Real, offset: Real, new_offset: Real) -> Real:
    """The linear force F = -k r at ``new_offset``, given its value at ``offset``: F grows in
    proportion to the distance (p. 171's fingertip a centimetre off centre)."""
    inputs.real(force, "force")
    inputs.positive(offset, "offset")
    inputs.real(new_offset, "new_offset")
    return force * new_offset / offset


def same_force(force: Real) -> Real:
    """A force restated in another unit (newtons, pounds-force, tons-force): the evaluator
    converts the SI value to the claim's unit (p. 171)."""
    return inputs.real(force, "force")


def crossings_per_period(samples: int = 64) -> int:
    """How often two neighbouring free-fall orbits cross per period: their separation
    d(t) = d0 cos(wt + alpha) oscillates at the same w, so count its sign changes over one
    period (sampled off its zeros)."""
    n = inputs.count(samples, "samples", minimum=8)
    values = [math.cos(2 * math.pi * (k + 0.5) / n) for k in range(n)]
    return sum(1 for k in range(n) if (values[k] > 0) != (values[(k + 1) % n] > 0))


def tidal_crossings_per_second(frequency: Real) -> Real:
    """How many times per second the left and right hands of an orbiting astronaut change
    places: crossings per period times the orbit frequency (p. 171)."""
    inputs.positive(frequency, "frequency")
    return crossings_per_period() * frequency
