"""The isotropic 2-D oscillator orbit, inertial forces, quadratic forms and triads (chapter 11).

A mass on a linear force F = -k r (k = m w^2, (11.2)) orbits on the ellipse
r(t) = (a cos wt, b sin wt) centred on the force centre ((11.5a), Fig. 11.1). Each time
derivative is the same ellipse scaled by w and advanced a quarter turn in phase ((11.5b)-(11.6),
Fig. 11.5). The cross product r x v = a b w is constant (11.21)-(11.22): the radius sweeps equal
areas in equal times (Kepler's law, Fig. 11.8), and the speed where the orbit crosses the minor
axis is a/b times the speed at the ends of the major axis. Rotation at w gives the centrifugal
acceleration w^2 r = V^2/r (11.3), and a fast orbit a tidal stiffness m w^2 (p. 171).

The orbit is the quadratic form r.Q.r = 1 with Q = diag(1/a^2, 1/b^2) = R^2 ((11.7)-(11.13));
p = Q.r is perpendicular to the velocity and lies on the dual ellipse p.Q^-1.p = 1 of radii 1/a,
1/b ((11.8)-(11.10)); Q and R multiply slopes by powers of a/b and have the axes as eigenvectors
((11.12)-(11.16)); the triads of Fig. 11.7 ((11.16)-(11.19)); a rotated form
A x^2 + 2B xy + C y^2 = 1 (11.20) and its ellipse parameters (exercise 1.11.1).

Types: lengths a, b, times and frequencies are floats or ``fractions.Fraction``; anything with
a trigonometric function gives a float. Matrices, slopes, dot products of points given by a
rational phase (``rational_phase``) and square roots of perfect squares stay exact for ``int`` and
``Fraction`` inputs, so that identities such as p.r = 1 can be checked exactly.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

from mechmodel import inputs
from mechmodel.exact import exact_sqrt
from mechmodel.planar import (
    Matrix,
    Vector,
    apply,
    cross,
    dot,
    matrix_inverse,
    matrix_power,
    matrix_product,
    rotation,
)


# -- small exact helpers ----------------------------------------------------------------------
def rational_phase(half_angle_tan: Any) -> Vector:
    """(cos u, sin u) of the phase u with tan(u/2) = ``half_angle_tan``: the rational
    parametrization ((1 - s^2)/(1 + s^2), 2s/(1 + s^2)) of the unit circle, exact for
    ``Fraction`` s, so that orbit points can be exact."""
    s = inputs.real(half_angle_tan, "half_angle_tan")
    if isinstance(s, int):
        s = Fraction(s)
    return ((1 - s * s) / (1 + s * s), 2 * s / (1 + s * s))


def _rational(*values: Any) -> bool:
    return all(isinstance(v, int | Fraction) for v in values)


def _div(x: Any, y: Any) -> Any:
    """x/y, exact when both are rational."""
    return Fraction(x) / Fraction(y) if _rational(x, y) else x / y


def _semi_axes(a: Any, b: Any) -> None:
    inputs.positive(a, "a")
    inputs.positive(b, "b")


def _phase(omega: Any, t: Any) -> Any:
    inputs.positive(omega, "omega")
    inputs.real(t, "t")
    return omega * t


# -- the orbit and its derivatives (11.5)-(11.6), Fig. 11.5 ----------------------------------
_DERIVATIVE_OF = {"cos": "-sin", "-sin": "-cos", "-cos": "sin", "sin": "cos"}


def _trig(function: str, u: Any) -> Any:
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


def orbit_derivative_form(order: Any) -> OrbitDerivative:
    """Differentiate the orbit (11.5a) ``order`` times with d/dt cos wt = -w sin wt and
    d/dt sin wt = w cos wt; each step brings one more factor w by the chain rule
    ((11.5b)-(11.5d): v, a = -w^2 r, jerk j = -w^2 v, inauguration i = w^4 r)."""
    n = inputs.count(order, "order")
    x, y, power = "cos", "sin", 0
    for _ in range(n):
        x, y, power = _DERIVATIVE_OF[x], _DERIVATIVE_OF[y], power + 1
    return OrbitDerivative(n, power, x, y)


def orbit_derivative(a: Any, b: Any, omega: Any, t: Any, order: Any = 0) -> Vector:
    """The ``order``-th time derivative of the orbit position at time t (order 0: r itself,
    1: velocity v, 2: acceleration a, 3: jerk j, 4: inauguration i, (11.5))."""
    _semi_axes(a, b)
    u = _phase(omega, t)
    form = orbit_derivative_form(order)
    scale = omega**form.omega_power
    return (a * scale * _trig(form.x_function, u), b * scale * _trig(form.y_function, u))


def orbit_position(a: Any, b: Any, omega: Any, t: Any) -> Vector:
    """r(t) = (a cos wt, b sin wt) (11.5a): x is the shadow of the a-circle clock hand
    (Fig. 11.1)."""
    return orbit_derivative(a, b, omega, t, 0)


def orbit_velocity(a: Any, b: Any, omega: Any, t: Any) -> Vector:
    """v(t) = (-a w sin wt, b w cos wt) (11.5b)."""
    return orbit_derivative(a, b, omega, t, 1)


def derivative_phase(order: Any) -> float:
    """Phase advance, radians in [0, 2 pi), of the ``order``-th derivative scaled by w^-n over
    r: r^(n)(t)/w^n = (a cos(wt + d), b sin(wt + d)) ((11.6), Fig. 11.5). Read off the
    derivative at wt = 0, where r points along the major axis."""
    form = orbit_derivative_form(order)
    advance = math.atan2(_trig(form.y_function, 0.0), _trig(form.x_function, 0.0))
    return advance % (2 * math.pi)


def derivative_in_terms_of(order: Any, base_order: Any, omega: Any, base: Any) -> Any:
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


def angular_momentum(mass: Any, a: Any, b: Any, omega: Any, t: Any) -> Any:
    """Orbital angular momentum L = m (x v_y - y v_x) at time t ((11.21)-(11.22))."""
    inputs.mass(mass)
    return mass * cross(orbit_position(a, b, omega, t), orbit_velocity(a, b, omega, t))


def orbit_energy(mass: Any, a: Any, b: Any, omega: Any, t: Any) -> Any:
    """Total energy 1/2 m v.v + 1/2 m w^2 r.r of the oscillator at time t (exercise 1.11.1(b);
    potential 1/2 k r^2 with k = m w^2 (11.2b))."""
    inputs.mass(mass)
    r = orbit_position(a, b, omega, t)
    v = orbit_velocity(a, b, omega, t)
    return mass * dot(v, v) / 2 + mass * omega**2 * dot(r, r) / 2


def _time_of(omega: Any, turns: Any) -> Any:
    """Time after apogee at which ``turns`` (a fraction of the period 2 pi/w) have passed."""
    inputs.positive(omega, "omega")
    inputs.real(turns, "turns")
    return 2 * math.pi * turns / omega


def force_power(mass: Any, a: Any, b: Any, omega: Any, turns: Any) -> float:
    """Power P = F.V of the force F = -m w^2 r on the orbiting mass, ``turns`` of a period after
    apogee: positive while it falls toward perigee, negative while it rises (Fig. 11.3)."""
    inputs.mass(mass)
    t = _time_of(omega, turns)
    force = tuple(-mass * omega**2 * c for c in orbit_position(a, b, omega, t))
    return dot(force, orbit_velocity(a, b, omega, t))


def force_velocity_angle(a: Any, b: Any, omega: Any, turns: Any) -> float:
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

    apogee: Any
    perigee: Any
    ratio: Any


def apsis_speeds(a: Any, b: Any, omega: Any) -> ApsisSpeeds:
    """Apsis speeds from the conservation of angular momentum (11.22): L/m = |r x v| is the same
    all along the orbit and r is perpendicular to v at the apsides, so v = (L/m)/r there:
    v_b = L/(m b) = a w at perigee, v_a = L/(m a) = b w at apogee ("exactly a/b times faster",
    text after Fig. 11.1)."""
    _semi_axes(a, b)
    per_mass = abs(angular_momentum(1, a, b, omega, 0))
    apogee, perigee = per_mass / a, per_mass / b
    return ApsisSpeeds(apogee, perigee, perigee / apogee)


def time_to_perigee(omega: Any) -> float:
    """Time from apogee (x = a) to perigee (x = 0): a cos wt = 0 first at wt = pi/2, t = pi/2w
    (Fig. 11.8)."""
    inputs.positive(omega, "omega")
    return math.acos(0.0) / omega


def orbit_area(a: Any, b: Any) -> float:
    """Area of the orbit ellipse: the a-circle (area pi a^2) squeezed in y by b/a, as the
    construction of Fig. 11.1 squeezes it: pi a b (text after (11.22))."""
    _semi_axes(a, b)
    return math.pi * a * a * (b / a)


def orbit_period(omega: Any) -> float:
    """Period 2 pi/w of every orbit of the oscillator (text after Fig. 11.1)."""
    inputs.positive(omega, "omega")
    return 2 * math.pi / omega


def areal_velocity(a: Any, b: Any, omega: Any) -> float:
    """Area swept per unit time: the whole orbit's area in one period (Kepler's equal areas)."""
    return orbit_area(a, b) / orbit_period(omega)


def area_swept(angular_momentum: Any, mass: Any, dt: Any) -> float:
    """Area swept in the time dt by the radius vector of a mass m of orbital angular momentum L
    (text after Fig. 11.8, Kepler's equal areas): it depends on L/m = |r x v| alone (11.22), so
    take the circular orbit a = b = 1 with that |r x v| = a b w, w = L/m, and its whole
    area pi a b per period 2 pi/w, at the constant rate of the area law."""
    inputs.positive(angular_momentum, "angular_momentum")
    inputs.mass(mass)
    inputs.real(dt, "dt")
    return areal_velocity(1, 1, angular_momentum / mass) * dt


def eccentric_anomaly(a: Any, b: Any, point: Sequence[Any]) -> float:
    """The clock-hand angle u of a point (a cos u, b sin u) of the ellipse (Fig. 11.1)."""
    _semi_axes(a, b)
    return math.atan2(point[1] / b, point[0] / a)


def elliptic_sector_area(a: Any, b: Any, start: Sequence[Any], end: Sequence[Any]) -> float:
    """Area swept counterclockwise by the radius from the centre between two points of the
    ellipse: the circular sector of the a-circle between their clock hands, squeezed by b/a
    (Fig. 11.1), a^2 du/2 * b/a."""
    du = (eccentric_anomaly(a, b, end) - eccentric_anomaly(a, b, start)) % (2 * math.pi)
    return a * a * du / 2 * (b / a)


def swept_area(a: Any, b: Any, omega: Any, t0: Any, t1: Any) -> float:
    """Area swept by the radius vector from time t0 to t1 >= t0 (Fig. 11.8): whole orbits plus
    the sector between the end points."""
    if t1 < t0:
        raise ValueError("t1 must not precede t0")
    period = orbit_period(omega)
    whole = math.floor((t1 - t0) / period)
    start = orbit_position(a, b, omega, t0)
    end = orbit_position(a, b, omega, t1)
    return whole * orbit_area(a, b) + elliptic_sector_area(a, b, start, end)


# -- centrifugal and tidal forces (11.2)-(11.3), p. 171 --------------------------------------
def oscillator_frequency(k: Any, mass: Any) -> Any:
    """Angular frequency w = sqrt(k/m) of a mass on a spring or in the Earth (11.2a); exact for
    rational perfect squares."""
    inputs.positive(k, "k")
    inputs.mass(mass)
    return exact_sqrt(_div(k, mass))


def spring_constant(mass: Any, omega: Any) -> Any:
    """Spring constant k = m w^2 (11.2b) that gives the angular frequency w to the mass m."""
    inputs.mass(mass)
    inputs.positive(omega, "omega")
    return mass * omega**2


def centrifugal_force(mass: Any, omega: Any, radius: Any) -> Any:
    """Centrifugal force m w^2 r = k r of rotation at w on a circle of radius r (11.3a)."""
    inputs.real(radius, "radius")
    return spring_constant(mass, omega) * radius


def centrifugal_acceleration(speed: Any, radius: Any) -> Any:
    """Centrifugal acceleration V^2/r of motion at speed V on a circle of radius r (11.3b)."""
    inputs.real(speed, "speed")
    inputs.positive(radius, "radius")
    return speed * speed / radius


def curvature_radius(speed: Any, acceleration: Any) -> Any:
    """Radius of curvature r = V^2/a of a path driven at speed V with transverse acceleration a
    (11.3c)."""
    inputs.real(speed, "speed")
    inputs.positive(acceleration, "acceleration")
    return speed * speed / acceleration


def circular_acceleration(radius: Any, omega: Any) -> float:
    """Magnitude of the acceleration of uniform motion at the rate w on a circle of radius r:
    the orbit (11.5a) with a = b = r differentiated twice ((11.5b), the acceleration vector at
    any time; taken at t = 0). The centrifugal acceleration of (11.3b) is its reaction."""
    inputs.positive(radius, "radius")
    return math.hypot(*orbit_derivative(radius, radius, omega, 0, 2))


def circular_acceleration_at_speed(radius: Any, speed: Any) -> float:
    """The same acceleration for the rim speed V: the rate is w = V/r (V = w r, (11.3))."""
    inputs.positive(radius, "radius")
    inputs.positive(speed, "speed")
    return circular_acceleration(radius, speed / radius)


def circular_force(mass: Any, radius: Any, omega: Any) -> float:
    """Centrifugal force on a mass m turning at w on a circle of radius r (Fig. 11.2, (11.3a)):
    m times the acceleration its circular motion needs."""
    inputs.mass(mass)
    return mass * circular_acceleration(radius, omega)


def circular_force_at_speed(mass: Any, radius: Any, speed: Any) -> float:
    """The same centrifugal force for the rim speed V ((11.3a))."""
    inputs.mass(mass)
    return mass * circular_acceleration_at_speed(radius, speed)


def curvature_radius_at_speed(speed: Any, acceleration: Any) -> float:
    """Radius of the circle of curvature of a path driven at speed V with transverse
    acceleration a (11.3c): at fixed V the circular acceleration falls in inverse proportion to
    the radius (the orbit scaled by s at the rate w/s), so r = (acceleration at r = 1)/a."""
    inputs.positive(acceleration, "acceleration")
    return circular_acceleration_at_speed(1, speed) / acceleration


def curvature_radius_at_rate(omega: Any, acceleration: Any) -> float:
    """Radius of the circle of curvature for the angular rate w and transverse acceleration a
    (11.3c): at fixed w the circular acceleration grows in proportion to the radius (the orbit
    (11.5a) is linear in a = b = r), so r = a/(acceleration at r = 1)."""
    inputs.positive(acceleration, "acceleration")
    return acceleration / circular_acceleration(1, omega)


def angular_frequency(frequency: Any) -> float:
    """Angular frequency w = 2 pi f, rad/s, of an orbit of f revolutions per second (p. 171:
    1 kHz gives w = 2000 pi)."""
    inputs.positive(frequency, "frequency")
    return 2 * math.pi * frequency


def tidal_force(frequency: Any, mass: Any, offset: Any) -> float:
    """Tidal force k x = m w^2 x, N, on a mass m at distance x from the centre of gravity of a
    body orbiting at frequency f, w = 2 pi f (p. 171): the centrifugal force (11.3a) that
    gravity no longer balances off the centre."""
    return centrifugal_force(mass, angular_frequency(frequency), offset)


def hooke_force_at(force: Any, offset: Any, new_offset: Any) -> Any:
    """The linear force F = -k r at ``new_offset``, given its value at ``offset``: F grows in
    proportion to the distance (p. 171's fingertip a centimetre off centre)."""
    inputs.real(force, "force")
    inputs.positive(offset, "offset")
    inputs.real(new_offset, "new_offset")
    return force * new_offset / offset


def same_force(force: Any) -> Any:
    """A force restated in another unit (newtons, pounds-force, tons-force): the evaluator
    converts the SI value to the claim's unit (p. 171)."""
    return inputs.real(force, "force")


def crossings_per_period(samples: Any = 64) -> int:
    """How often two neighbouring free-fall orbits cross per period: their separation
    d(t) = d0 cos(wt + alpha) oscillates at the same w, so count its sign changes over one
    period (sampled off its zeros)."""
    n = inputs.count(samples, "samples", minimum=8)
    values = [math.cos(2 * math.pi * (k + 0.5) / n) for k in range(n)]
    return sum(1 for k in range(n) if (values[k] > 0) != (values[(k + 1) % n] > 0))


def tidal_crossings_per_second(frequency: Any) -> Any:
    """How many times per second the left and right hands of an orbiting astronaut change
    places: crossings per period times the orbit frequency (p. 171)."""
    inputs.positive(frequency, "frequency")
    return crossings_per_period() * frequency


# -- quadratic forms and their matrices (11.7)-(11.15) ----------------------------------------
def _reciprocal(x: Any) -> Any:
    return Fraction(1, x) if isinstance(x, int) else 1 / x


def slope_operator(a: Any, b: Any) -> Matrix:
    """R = diag(1/a, 1/b): it multiplies the slope y/x of a vector by a/b (11.12a)."""
    _semi_axes(a, b)
    return ((_reciprocal(a), 0), (0, _reciprocal(b)))


def ellipse_form(a: Any, b: Any) -> Matrix:
    """Q = R^2 = diag(1/a^2, 1/b^2), the matrix of the ellipse x^2/a^2 + y^2/b^2 = r.Q.r = 1
    ((11.7), (11.8a), (11.13))."""
    r = slope_operator(a, b)
    return matrix_product(r, r)


def form_value(matrix: Matrix, vector: Sequence[Any]) -> Any:
    """The quadratic form r.M.r (11.7), (11.20)."""
    return dot(vector, apply(matrix, vector))


def quadratic_form(A: Any, B: Any, C: Any, x: Any, y: Any) -> Any:  # noqa: N803
    """The form (x y).(A B; B C).(x y) of (11.20), by the matrix products (plain operators:
    exact for rationals, an expression for sympy symbols)."""
    return form_value(((A, B), (B, C)), (x, y))


@dataclass(frozen=True)
class DualityProducts:
    """Dot products of the orbit point r, its velocity r' (w = 1), p = Q.r and p' = Q.r'
    ((11.8b), (11.10c), (11.17)), and the forms r.Q.r and p.Q^-1.p."""

    r: Vector
    p: Vector
    rdot_dot_p: Any
    pdot_dot_r: Any
    p_dot_r: Any
    pdot_dot_rdot: Any
    r_form: Any
    p_dual_form: Any


def duality_products(a: Any, b: Any, half_angle_tan: Any) -> DualityProducts:
    """The duality of the Q-ellipse and its p-ellipse at the orbit point of phase u,
    tan(u/2) = ``half_angle_tan`` (exact for rationals): r.v = ... p = Q.r is perpendicular to
    the velocity (r'.p = 0 = p'.r) and projects to 1 on r (p.r = p'.r' = 1); p lies on the
    ellipse p.Q^-1.p = 1 ((11.8)-(11.10), (11.17))."""
    _semi_axes(a, b)
    c, s = rational_phase(half_angle_tan)
    r = (a * c, b * s)
    rdot = (-a * s, b * c)
    q = ellipse_form(a, b)
    p, pdot = apply(q, r), apply(q, rdot)
    return DualityProducts(
        r,
        p,
        dot(rdot, p),
        dot(pdot, r),
        dot(p, r),
        dot(pdot, rdot),
        form_value(q, r),
        form_value(matrix_inverse(q), p),
    )


@dataclass(frozen=True)
class EllipseParameters:
    """An ellipse of a quadratic form: ``radius`` along the direction ``angle`` (radians, in
    (-pi/2, pi/2]), ``other_radius`` across it; ``kind`` is the conic's name."""

    radius: Any
    other_radius: Any
    angle: float
    kind: str


def form_eigenvalues(A: Any, B: Any, C: Any) -> tuple[Any, Any]:  # noqa: N803
    """Eigenvalues (larger, smaller) of the symmetric matrix (A B; B C)."""
    mean = (A + C) / 2
    spread = exact_sqrt(((A - C) / 2) ** 2 + B * B)
    return mean + spread, mean - spread


def conic_type(A: Any, B: Any, C: Any) -> str:  # noqa: N803
    """Curve of r.(A B; B C).r = 1 (11.20): an ellipse for two positive eigenvalues, a
    hyperbola for eigenvalues of opposite sign (exercise 1.11.1(c)), parallel lines for one zero
    and one positive eigenvalue, else no real points."""
    hi, lo = form_eigenvalues(A, B, C)
    if lo > 0:
        return "ellipse"
    if hi > 0 > lo:
        return "hyperbola"
    if hi > 0 and lo == 0:
        return "parallel lines"
    return "empty"


def ellipse_from_form(A: Any, B: Any, C: Any) -> EllipseParameters:  # noqa: N803
    """Radii and orientation of the conic r.(A B; B C).r = 1 (exercise 1.11.1(a)): writing
    (A B; B C) = Rot(t) diag(l1, l2) Rot(-t) gives A - C = (l1 - l2) cos 2t and
    2B = (l1 - l2) sin 2t, so t = atan2(2B, A - C)/2 points along the eigenvalue l1 >= l2, and
    the radius there is 1/sqrt(l1)."""
    hi, lo = form_eigenvalues(A, B, C)
    kind = conic_type(A, B, C)
    if kind not in ("ellipse", "hyperbola"):
        raise ValueError(f"r.Q.r = 1 is {kind}, not an ellipse or hyperbola")
    angle = math.atan2(2 * B, A - C) / 2 if (B != 0 or A != C) else 0.0
    radius = _reciprocal(exact_sqrt(hi))
    other = _reciprocal(exact_sqrt(abs(lo)))
    return EllipseParameters(radius, other, angle, kind)


@dataclass(frozen=True)
class QuadraticForm:
    """The symmetric matrix (A B; B C) of a form A x^2 + 2B xy + C y^2 (11.20)."""

    A: Any
    B: Any
    C: Any


def rotated_form(a: Any, b: Any, angle: Any) -> QuadraticForm:
    """The ellipse of radii a, b turned by ``angle``: Q' = Rot Q Rot^-1 (exercise 1.11.1(a));
    B != 0 marks a rotated ellipse (text after Fig. 11.7)."""
    rot = rotation(angle)
    q = matrix_product(matrix_product(rot, ellipse_form(a, b)), matrix_inverse(rot))
    return QuadraticForm(q[0][0], (q[0][1] + q[1][0]) / 2, q[1][1])


@dataclass(frozen=True)
class DualEllipse:
    """The p-ellipse p.Q^-1.p = 1: radii along x and y, and those radii times a and b."""

    radius_x: Any
    radius_y: Any
    radius_x_times_a: Any
    radius_y_times_b: Any


def dual_ellipse(a: Any, b: Any) -> DualEllipse:
    """Radii of the ellipse p.Q^-1.p = 1 traced by p = Q.r: the inverse (1/a, 1/b) of the
    Q-ellipse radii (11.9). From the diagonal of Q^-1: radius = 1/sqrt(entry)."""
    qi = matrix_inverse(ellipse_form(a, b))
    rx = _reciprocal(exact_sqrt(qi[0][0]))
    ry = _reciprocal(exact_sqrt(qi[1][1]))
    return DualEllipse(rx, ry, rx * a, ry * b)


def dual_vector(a: Any, b: Any, phi: Any) -> Vector:
    """The vector p = Q.r of the orbit point r = (a cos phi, b sin phi), phi the time-phase
    angle (11.8): the matrix Q = diag(1/a^2, 1/b^2) applied to r."""
    inputs.real(phi, "phi")
    return apply(ellipse_form(a, b), (a * math.cos(phi), b * math.sin(phi)))


def operator_image(a: Any, b: Any, power: Any, x: Any, y: Any) -> Vector:
    """R^power applied to the vector (x, y), R = diag(1/a, 1/b) ((11.12)-(11.13): power 2 is
    Q.r, power -2 is Q^-1.r)."""
    return apply(matrix_power(slope_operator(a, b), power), (x, y))


def image_slope(a: Any, b: Any, power: Any, angle: Any) -> float:
    """Slope tan of the polar angle of R^power applied to a vector of polar angle ``angle``
    ((11.16): p(phi_k+1) = Q.r(phi_k-1) for power 2)."""
    inputs.real(angle, "angle")
    x, y = operator_image(a, b, power, math.cos(angle), math.sin(angle))
    return y / x


@dataclass(frozen=True)
class ScaledRadii:
    """Radii scaled by the geometric mean S = sqrt(ab): a_S = a/S, b_S = b/S, and a_S b_S."""

    scale: Any
    a_scaled: Any
    b_scaled: Any
    product: Any


def scaled_radii(a: Any, b: Any) -> ScaledRadii:
    """Scale the ellipse by S = sqrt(ab) (11.11): a_S = sqrt(a/b) = 1/b_S."""
    _semi_axes(a, b)
    s = exact_sqrt(a * b)
    a_s, b_s = _div(a, s), _div(b, s)
    return ScaledRadii(s, a_s, b_s, a_s * b_s)


def unit_scale(area_product: Any) -> Any:
    """The geometric-mean scale S = sqrt(ab) of (11.11) from the product ab of the radii (the
    triads' ab = 1 gives the unit scale S = 1, before (11.18)); exact for rational squares."""
    inputs.positive(area_product, "area_product")
    return exact_sqrt(area_product)


def major_axis_angle(matrix: Matrix) -> float:
    """Direction, radians in [0, pi), of the major (longest) axis of r.M.r = 1: the eigenvector
    of the smaller eigenvalue."""
    A, B, C = matrix[0][0], (matrix[0][1] + matrix[1][0]) / 2, matrix[1][1]  # noqa: N806
    return (ellipse_from_form(A, B, C).angle + math.pi / 2) % math.pi


def inverse_ellipse_rotation(a: Any, b: Any) -> float:
    """Angle, radians in [0, pi), that turns the S-scaled Q-ellipse (form S^2 Q) onto the
    S-scaled p-ellipse (form Q^-1/S^2): the axis switch after (11.11)."""
    if a == b:
        raise ValueError("a circle has no axes to switch: a != b")
    s2 = a * b
    q = ellipse_form(a, b)
    qi = matrix_inverse(q)
    scaled_q = tuple(tuple(s2 * e for e in row) for row in q)
    scaled_qi = tuple(tuple(e / s2 for e in row) for row in qi)
    return (major_axis_angle(scaled_qi) - major_axis_angle(scaled_q)) % math.pi


def slope_gain(a: Any, b: Any, power: Any) -> Any:
    """Factor by which R^power multiplies the slope y/x of a vector (R = diag(1/a, 1/b);
    power 2 is Q, -1 is R^-1): (11.12)-(11.13), (11.16). Exact for rational a, b."""
    operator = matrix_power(slope_operator(a, b), power)
    x, y = apply(operator, (1, 1))
    return _div(y, x)


@dataclass(frozen=True)
class AxisEigenvalues:
    """Eigenvalues of R^power on the axis vectors a^ = (1, 0) and b^ = (0, 1), and those
    eigenvalues times a^power and b^power (11.14)-(11.15)."""

    a_axis: Any
    b_axis: Any
    a_axis_scaled: Any
    b_axis_scaled: Any


def axis_eigenvalues(a: Any, b: Any, power: Any) -> AxisEigenvalues:
    """R^power maps a^ to a multiple of itself (no slope change, (11.14)): the eigenvalue is
    the ratio of image to vector; R^2 = Q gives 1/a^2 and 1/b^2 (11.15c,d)."""
    operator = matrix_power(slope_operator(a, b), power)
    ea = apply(operator, (1, 0))
    eb = apply(operator, (0, 1))
    if ea[1] != 0 or eb[0] != 0:
        raise ValueError("the axes are not eigenvectors")  # pragma: no cover
    n = int(power)
    return AxisEigenvalues(ea[0], eb[1], ea[0] * a**n, eb[1] * b**n)


# -- the triad sequence of Fig. 11.7, (11.16)-(11.19) ---------------------------------------------
def _polar_angle(v: Sequence[Any]) -> float:
    return math.atan2(v[1], v[0])


def triad_angle(a: Any, b: Any, phi0: Any, k: Any) -> float:
    """The slope angle phi_k of the triad sequence started at phi_0 (Fig. 11.7): the radius
    r = (a cos phi_k, b sin phi_k) at timer angle phi_k has polar angle phi_k-1 and the
    perpendicular p = Q.r has polar angle phi_k+1 ((11.16)-(11.17)); step |k| times."""
    _semi_axes(a, b)
    inputs.real(phi0, "phi0")
    k = int(k)
    phi = phi0
    q = ellipse_form(a, b)
    for _ in range(abs(k)):
        r = (a * math.cos(phi), b * math.sin(phi))
        phi = _polar_angle(apply(q, r) if k > 0 else r)
    return phi


def triad_slope(a: Any, b: Any, phi0: Any, k: Any) -> float:
    """Slope tan(phi_k) of the k-th line of Fig. 11.7 ((a/b)^k tan phi_0, (11.19))."""
    return math.tan(triad_angle(a, b, phi0, k))


@dataclass(frozen=True)
class TriadVectors:
    """The radius r(phi_k-1) = (a cos phi_k, b sin phi_k) and perpendicular p(phi_k+1) = Q.r of
    the k-th triad (11.18), with the divisors of their components in the book's form
    r = (a/dx, b/dy), p = (b/ex, a/ey) (valid for ab = 1)."""

    r: Vector
    p: Vector
    r_x_divisor: Any
    r_y_divisor: Any
    p_x_divisor: Any
    p_y_divisor: Any


def triad_vectors(a: Any, area_product: Any, phi0: Any, k: Any = 0) -> TriadVectors:
    """The vectors of the k-th triad for radii a and b = ``area_product``/a (the book lets
    ab = 1, unit scale S = 1, before (11.18)): r(phi_k-1) and p(phi_k+1) = Q.r(phi_k-1) (11.18)."""
    inputs.positive(area_product, "area_product")
    b = _div(area_product, a)
    phi = triad_angle(a, b, phi0, k)
    r = (a * math.cos(phi), b * math.sin(phi))
    p = apply(ellipse_form(a, b), r)
    return TriadVectors(r, p, a / r[0], b / r[1], b / p[0], a / p[1])


@dataclass(frozen=True)
class TriadDirection:
    """The direction of the k-th line of the triad sequence: cos phi_k, sin phi_k and the slope
    tan phi_k (Fig. 11.7, (11.19))."""

    cos: float
    sin: float
    slope: float


def triad_direction(a: Any, b: Any, start_slope: Any, k: Any) -> TriadDirection:
    """Direction of the k-th line of the sequence started on the line of slope ``start_slope``
    (phi_0 = atan of it: the book's phi_0 = pi/4 has slope 1), stepped by ``triad_angle``."""
    inputs.real(start_slope, "start_slope")
    phi = triad_angle(a, b, math.atan(start_slope), k)
    return TriadDirection(math.cos(phi), math.sin(phi), math.tan(phi))


@dataclass(frozen=True)
class BookTriad:
    """The radius r(phi_j) = (a cos phi_j+1, b sin phi_j+1) and the perpendicular
    p(phi_j) = Q.r(phi_j-2) = (b cos phi_j-1, a sin phi_j-1) of the book's triads (11.18)."""

    r: Vector
    p: Vector


def book_triad(a: Any, b: Any, area_product: Any, start_slope: Any, j: Any) -> BookTriad:
    """The vectors r(phi_j) and p(phi_j) of (11.18) with the book's matrix at unit scale: the
    book lets ab = 1 and writes Q = diag(1/a^2, 1/b^2) as diag(b/a, a/b) (before (11.18),
    S = sqrt(ab) = 1 in (11.11)), which is Q times ab/``area_product`` for
    ``area_product`` = 1; that form is kept for any a and b. phi_j is the polar angle of both
    vectors; the timer angles are those of ``triad_direction``."""
    inputs.positive(area_product, "area_product")
    j = int(j)
    q = ellipse_form(a, b)
    scale = a * b / area_product
    book_q = tuple(tuple(scale * e for e in row) for row in q)

    def radius(index: int) -> Vector:
        d = triad_direction(a, b, start_slope, index + 1)
        return (a * d.cos, b * d.sin)

    return BookTriad(radius(j), apply(book_q, radius(j - 2)))
