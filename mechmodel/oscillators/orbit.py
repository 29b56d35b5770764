"""The orbit of the isotropic 2-D oscillator and its derivatives (chapter 11, (11.5)-(11.6),
(11.21)-(11.22), Figs. 11.1, 11.3, 11.5, 11.8).

A mass on a linear force F = -k r (k = m w^2, (11.2)) orbits on the ellipse
r(t) = (a cos wt, b sin wt) centred on the force centre ((11.5a), Fig. 11.1). Each time
derivative is the same ellipse scaled by w and advanced a quarter turn in phase ((11.5b)-(11.6),
Fig. 11.5). The cross product r x v = a b w is constant (11.21)-(11.22): the radius sweeps equal
areas in equal times (Kepler's law, Fig. 11.8), and the speed where the orbit crosses the minor
axis is a/b times the speed at the ends of the major axis; the force's power F.V over the orbit
(Fig. 11.3).

Units: lengths a, b in m, w in rad/s, times in s, masses in kg (or any consistent set).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from mechmodel import inputs
from mechmodel.oscillators._common import check_semi_axes
from mechmodel.planar import Vector, cross, dot
from mechmodel.typing import Real


def _phase(omega: Real, t: Real) -> Real:
    inputs.positive(omega, "omega")
    inputs.real(t, "t")
    return omega * t


# -- the orbit and its derivatives (11.5)-(11.6), Fig. 11.5 ----------------------------------
_DERIVATIVE_OF = {"cos": "-sin", "-sin": "-cos", "-cos": "sin", "sin": "cos"}


def _trig(function: str, u: Real) -> float:
    sign = -1 if function.startswith("-") else 1
    name = function.lstrip("-")
    return sign * (math.cos(u) if name == "cos" else math.sin(u))


@dataclass(frozen=True)
class OrbitDerivative:
    """The n-th time derivative of r(t) = (a cos wt, b sin wt):
    (a w^n x_function(wt), b w^n y_function(wt)), each function one of cos, sin, -cos, -sin."""

    order: int
    omega_power: int
    x_function: str
    y_function: str


def orbit_derivative_form(order: int) -> OrbitDerivative:
    """Differentiate the orbit (11.5a) ``order`` times with d/dt cos wt = -w sin wt and
    d/dt sin wt = w cos wt; each step brings one more factor w by the chain rule
    ((11.5b)-(11.5d): v, a = -w^2 r, jerk j = -w^2 v, inauguration i = w^4 r)."""
    n = inputs.count(order, "order")
    x, y, power = "cos", "sin", 0
    for _ in range(n):
        x, y, power = _DERIVATIVE_OF[x], _DERIVATIVE_OF[y], power + 1
    return OrbitDerivative(n, power, x, y)


def orbit_derivative(a: Real, b: Real, omega: Real, t: Real, order: int = 0) -> Vector:
    """The ``order``-th time derivative of the orbit position at time t (order 0: r itself,
    1: velocity v, 2: acceleration a, 3: jerk j, 4: inauguration i, (11.5))."""
    check_semi_axes(a, b)
    u = _phase(omega, t)
    form = orbit_derivative_form(order)
    scale = omega**form.omega_power
    return (a * scale * _trig(form.x_function, u), b * scale * _trig(form.y_function, u))


def orbit_position(a: Real, b: Real, omega: Real, t: Real) -> Vector:
    """r(t) = (a cos wt, b sin wt) (11.5a): x is the shadow of the a-circle clock hand
    (Fig. 11.1)."""
    return orbit_derivative(a, b, omega, t, 0)


def orbit_velocity(a: Real, b: Real, omega: Real, t: Real) -> Vector:
    """v(t) = (-a w sin wt, b w cos wt) (11.5b)."""
    return orbit_derivative(a, b, omega, t, 1)


def derivative_phase(order: int) -> float:
    """Phase advance, radians in [0, 2 pi), of the ``order``-th derivative scaled by w^-n over
    r: r^(n)(t)/w^n = (a cos(wt + d), b sin(wt + d)) ((11.6), Fig. 11.5). Read off the
    derivative at wt = 0, where r points along the major axis."""
    form = orbit_derivative_form(order)
    advance = math.atan2(_trig(form.y_function, 0.0), _trig(form.x_function, 0.0))
    return advance % (2 * math.pi)


def derivative_in_terms_of(order: int, base_order: int, omega: Real, base: Real) -> Real:
    """The ``order``-th time derivative of the orbit written through its ``base_order``-th
    derivative ``base`` (a component or the vector's length): c * base, where the two derivatives
    share their trigonometric functions up to one common sign and c = +-w^(order - base_order)
    by the chain rule (text after (11.5b)-(11.5d): a = -w^2 r, j = -w^2 v, i = w^4 r; the fifth
    derivative is w^4 v). ``ValueError`` where the two are not proportional (v is no multiple of
    r: they are a quarter turn apart)."""
    inputs.positive(omega, "omega")
    high, low = orbit_derivative_form(order), orbit_derivative_form(base_order)
    if high.order < low.order:
        raise ValueError("order must not be below base_order")
    signs = set()
    for mine, theirs in ((high.x_function, low.x_function), (high.y_function, low.y_function)):
        if mine.lstrip("-") != theirs.lstrip("-"):
            raise ValueError(f"derivative {high.order} is no multiple of derivative {low.order}")
        signs.add(1 if mine.startswith("-") == theirs.startswith("-") else -1)
    if len(signs) != 1:
        raise ValueError("the two components change sign differently")  # pragma: no cover
    return signs.pop() * omega ** (high.omega_power - low.omega_power) * base


def angular_momentum(mass: Real, a: Real, b: Real, omega: Real, t: Real) -> float:
    """Orbital angular momentum L = m (x v_y - y v_x) at time t ((11.21)-(11.22))."""
    inputs.mass(mass)
    return mass * cross(orbit_position(a, b, omega, t), orbit_velocity(a, b, omega, t))


def orbit_energy(mass: Real, a: Real, b: Real, omega: Real, t: Real) -> float:
    """Total energy 1/2 m v.v + 1/2 m w^2 r.r of the oscillator at time t (exercise 1.11.1(b);
    potential 1/2 k r^2 with k = m w^2 (11.2b))."""
    inputs.mass(mass)
    r = orbit_position(a, b, omega, t)
    v = orbit_velocity(a, b, omega, t)
    return mass * dot(v, v) / 2 + mass * omega**2 * dot(r, r) / 2


def _time_of(omega: Real, turns: Real) -> float:
    """Time after apogee at which ``turns`` (a fraction of the period 2 pi/w) have passed."""
    inputs.positive(omega, "omega")
    inputs.real(turns, "turns")
    return 2 * math.pi * turns / omega


def force_power(mass: Real, a: Real, b: Real, omega: Real, turns: Real) -> float:
    """Power P = F.V of the force F = -m w^2 r on the orbiting mass, ``turns`` of a period after
    apogee: positive while it falls toward perigee, negative while it rises (Fig. 11.3)."""
    inputs.mass(mass)
    t = _time_of(omega, turns)
    force = tuple(-mass * omega**2 * c for c in orbit_position(a, b, omega, t))
    return dot(force, orbit_velocity(a, b, omega, t))


def force_velocity_angle(a: Real, b: Real, omega: Real, turns: Real) -> float:
    """Angle theta, radians, between the force -k r and the velocity V, ``turns`` of a period
    after apogee: 90 degrees only at apogee and perigee (Fig. 11.3)."""
    t = _time_of(omega, turns)
    r = orbit_position(a, b, omega, t)
    v = orbit_velocity(a, b, omega, t)
    force = (-r[0], -r[1])
    return math.atan2(abs(cross(force, v)), dot(force, v))


@dataclass(frozen=True)
class ApsisSpeeds:
    """Speeds where the orbit crosses the major axis (x = a, apogee) and the minor axis
    (y = b, perigee), and their ratio perigee/apogee."""

    apogee: Real
    perigee: Real
    ratio: Real


def apsis_speeds(a: Real, b: Real, omega: Real) -> ApsisSpeeds:
    """Apsis speeds from the conservation of angular momentum (11.22): L/m = |r x v| is the same
    all along the orbit and r is perpendicular to v at the apsides, so v = (L/m)/r there:
    v_b = L/(m b) = a w at perigee, v_a = L/(m a) = b w at apogee ("exactly a/b times faster",
    text after Fig. 11.1)."""
    check_semi_axes(a, b)
    per_mass = abs(angular_momentum(1, a, b, omega, 0))
    apogee, perigee = per_mass / a, per_mass / b
    return ApsisSpeeds(apogee, perigee, perigee / apogee)


def time_to_perigee(omega: Real) -> float:
    """Time from apogee (x = a) to perigee (x = 0): a cos wt = 0 first at wt = pi/2, t = pi/2w
    (Fig. 11.8)."""
    inputs.positive(omega, "omega")
    return math.acos(0.0) / omega


def orbit_area(a: Real, b: Real) -> float:
    """Area of the orbit ellipse: the a-circle (area pi a^2) squeezed in y by b/a, as the
    construction of Fig. 11.1 squeezes it: pi a b (text after (11.22))."""
    check_semi_axes(a, b)
    return math.pi * a * a * (b / a)


def orbit_period(omega: Real) -> float:
    """Period 2 pi/w of every orbit of the oscillator (text after Fig. 11.1)."""
    inputs.positive(omega, "omega")
    return 2 * math.pi / omega


def areal_velocity(a: Real, b: Real, omega: Real) -> float:
    """Area swept per unit time: the whole orbit's area in one period (Kepler's equal areas)."""
    return orbit_area(a, b) / orbit_period(omega)


def area_swept(angular_momentum: Real, mass: Real, dt: Real) -> float:
    """Area swept in the time dt by the radius vector of a mass m of orbital angular momentum L
    (text after Fig. 11.8, Kepler's equal areas): it depends on L/m = |r x v| alone (11.22), so
    take the circular orbit a = b = 1 with that |r x v| = a b w, w = L/m, and its whole
    area pi a b per period 2 pi/w, at the constant rate of the area law."""
    inputs.positive(angular_momentum, "angular_momentum")
    inputs.mass(mass)
    inputs.real(dt, "dt")
    return areal_velocity(1, 1, angular_momentum / mass) * dt


def eccentric_anomaly(a: Real, b: Real, point: Sequence[Real]) -> float:
    """The clock-hand angle u of a point (a cos u, b sin u) of the ellipse (Fig. 11.1)."""
    check_semi_axes(a, b)
    return math.atan2(point[1] / b, point[0] / a)


def elliptic_sector_area(a: Real, b: Real, start: Sequence[Real], end: Sequence[Real]) -> float:
    """Area swept counterclockwise by the radius from the centre between two points of the
    ellipse: the circular sector of the a-circle between their clock hands, squeezed by b/a
    (Fig. 11.1), a^2 du/2 * b/a."""
    du = (eccentric_anomaly(a, b, end) - eccentric_anomaly(a, b, start)) % (2 * math.pi)
    return a * a * du / 2 * (b / a)


def swept_area(a: Real, b: Real, omega: Real, t0: Real, t1: Real) -> float:
    """Area swept by the radius vector from time t0 to t1 >= t0 (Fig. 11.8): whole orbits plus
    the sector between the end points."""
    if t1 < t0:
        raise ValueError("t1 must not precede t0")
    period = orbit_period(omega)
    whole = math.floor((t1 - t0) / period)
    start = orbit_position(a, b, omega, t0)
    end = orbit_position(a, b, omega, t1)
    return whole * orbit_area(a, b) + elliptic_sector_area(a, b, start, end)
