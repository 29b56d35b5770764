"""Contact forces: superball geometry, stopping targets and soft collisions (chapter 7).

- The dent of a ball pressed a depth x into a flat wall (Fig. 7.1): the flat's radius
  r = sqrt(x (2R - x)) (7.1a), the sagitta x ~ r^2 / 2R (7.1b), a balloon's force P pi r^2
  (7.2) and the dent's volume (7.4).
- Stopping a falling daredevil (Figs. 7.3-7.4): a constant-force target (kiddy-pool or
  trampoline) and a linear-force target (a Hooke potential), with their forces, potentials and
  work; the parabola's shift under a constant force (7.8).
- Soft collisions: balls (and a floor) that interact only while they overlap, with the
  repulsion F = k y^n of the overlap y (Figs. 7.5-7.7, 8.1). The integrator lives in
  ``softcontact``; ``soft_collision``, its result ``SoftCollision`` and ``INTEGRATORS`` are
  re-exported here.

Units: SI or the book's scaled units, consistently. Geometry and targets take floats, ints and
Fractions (exact where only + - * / are used).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import TypeVar, cast, overload

from mechmodel import inputs
from mechmodel.algebra import polynomial_derivative, polynomial_integral
from mechmodel.exact import magnitude
from mechmodel.numeric import complex_step_derivative
from mechmodel.softcontact import INTEGRATORS as INTEGRATORS
from mechmodel.softcontact import SoftCollision as SoftCollision
from mechmodel.softcontact import soft_collision as soft_collision
from mechmodel.typing import Real, Scalar, Symbolic

_Field = TypeVar("_Field", Real, Scalar)  # a real radius gives real coefficients; complex, complex

# --- the dent: Fig. 7.1, (7.1)-(7.4) ---------------------------------------------------------


def flat_spot_radius(radius: Real, depth: Real) -> float:
    """Radius r of the flat a ball of radius R shows when pressed a depth x flat (7.1a).

    Thales: r is the geometric mean of the depth x and the rest of the diameter, 2R - x.
    """
    inputs.positive(radius, "radius")
    inputs.real(depth, "depth")
    if not 0 <= depth <= 2 * radius:
        raise ValueError("the depth must lie between 0 and the diameter 2R")
    return math.sqrt(depth * (radius + radius - depth))


def flat_area_slope(radius: Real, depth: Real) -> float:
    """d(r^2)/dx of the flat's squared radius at depth x: 2R - 2x; at x = 0 the 2 of
    r^2 ~ 2 R x (7.1a), and of the sagitta x ~ r^2 / 2R (7.1b)."""
    inputs.positive(radius, "radius")
    inputs.real(depth, "depth")
    return complex_step_derivative(lambda x: x * (radius + radius - x), depth)


def flat_radius_shallow(radius: Real, depth: Real) -> float:
    """Radius of the flat of a shallow dent, x << R, to leading order in x (7.1a).

    r^2 = x (2R - x) vanishes at first contact; its leading term is the slope d(r^2)/dx there
    times x (``flat_area_slope``), so r ~ sqrt(x d(r^2)/dx|0): the sqrt(2 R x) of (7.1a).
    """
    inputs.positive(radius, "radius")
    inputs.real(depth, "depth")
    if depth < 0:
        raise ValueError("the depth must not be negative")
    return math.sqrt(flat_area_slope(radius, 0) * depth)


def sagitta_small_flat(radius: Real, flat_radius: Real) -> float:
    """Depth x of the dent whose flat has a small radius r << R, to leading order: the bow
    formula of (7.1b). Inverting r^2 = x (2R - x) at first order in x, x ~ r^2 / (d(r^2)/dx at
    x = 0), where ``flat_area_slope`` gives the slope."""
    inputs.positive(radius, "radius")
    inputs.real(flat_radius, "flat_radius")
    return flat_radius * flat_radius / flat_area_slope(radius, 0)


def flat_area(radius: Real, depth: Real) -> float:
    """Area pi r^2 of the flat at depth x, the integrand of the dent's volume (7.4): the flat's
    radius from Thales (``flat_spot_radius``), squared."""
    r = flat_spot_radius(radius, depth)
    return math.pi * r * r


def sagitta(radius: Real, flat_radius: Real) -> float:
    """Depth x of the dent whose flat has radius r, exactly: R - sqrt(R^2 - r^2) (7.1b).

    For r << R this is r^2 / 2R, the bow (sagitta) formula of thin lenses.
    """
    inputs.positive(radius, "radius")
    inputs.real(flat_radius, "flat_radius")
    if not 0 <= flat_radius <= radius:
        raise ValueError("the flat's radius must lie between 0 and R")
    return radius - math.sqrt(radius * radius - flat_radius * flat_radius)


def balloon_force(pressure: Real, radius: Real, depth: Real) -> float:
    """Force of a balloon of pressure P pressed a depth x flat, P pi r^2 (7.2), N."""
    inputs.positive(pressure, "pressure")
    r = flat_spot_radius(radius, depth)
    return pressure * math.pi * r * r


def balloon_stiffness(pressure: Real, radius: Real, depth: Real) -> float:
    """Spring constant dF/dx of the balloon at depth x, N/m: at x = 0, 2 pi P R (7.2)."""
    inputs.positive(pressure, "pressure")
    inputs.positive(radius, "radius")
    inputs.real(depth, "depth")
    return complex_step_derivative(lambda x: pressure * math.pi * x * (radius + radius - x), depth)


def balloon_force_shallow(pressure: Real, radius: Real, depth: Real) -> float:
    """Force of a balloon pressed a shallow depth x << R flat, to first order in x (7.2): its
    spring constant at first contact (``balloon_stiffness`` at x = 0) times x, N."""
    inputs.real(depth, "depth")
    return balloon_stiffness(pressure, radius, 0) * depth


@dataclass(frozen=True)
class DentVolume:
    """The volume cut off a ball of radius R by a dent of depth X (7.4).

    ``volume`` = integral_0^X pi r(x)^2 dx = R pi X^2 - pi X^3 / 3; ``quadratic_power`` and
    ``cubic_power`` are the powers of X of its two terms, ``cubic_denominator`` the 3 of
    pi X^3 / 3; ``small_dent_power`` the local power d ln V / d ln X as X -> 0 (the X^2 of
    V ~ R pi X^2); ``whole_ball`` V(2R) / (pi R^3), the 4/3 of the ball's volume, and
    ``whole_ball_power`` the power of R in it.
    """

    volume: float
    quadratic_power: int
    cubic_power: int
    cubic_denominator: Real
    small_dent_power: float
    whole_ball: Real
    whole_ball_power: float


def _dent_polynomial(radius: _Field) -> list[_Field]:
    """pi r(x)^2 / pi = x (2R - x) = 2R x - x^2, coefficients by power of x."""
    return [0, radius + radius, -1]


@overload
def _dent_volume_over_pi(radius: Real, depth: Real) -> Real: ...
@overload
def _dent_volume_over_pi(radius: Scalar, depth: Scalar) -> Scalar: ...
def _dent_volume_over_pi(radius: Scalar, depth: Scalar) -> Scalar:
    """The dent's volume over pi, exact for rationals; complex for the complex step."""
    return polynomial_integral(_dent_polynomial(radius), depth)


def dent_volume(radius: Real, depth: Real) -> DentVolume:
    """Volume of the dent of depth X in a ball of radius R, by integrating the flat's area
    pi r(x)^2 over the depth (7.4). Exact (over pi) with Fraction inputs."""
    inputs.positive(radius, "radius")
    inputs.real(depth, "depth")
    if not 0 <= depth <= 2 * radius:
        raise ValueError("the depth must lie between 0 and the diameter 2R")
    # each term c x^k of the integrand integrates to c X^(k+1)/(k+1)
    powers = [k + 1 for k, c in enumerate(_dent_polynomial(radius)) if c != 0]
    cubic = polynomial_integral([0, 0, -1], 1)  # the -X^3/3 term at X = 1
    tiny = float(radius) * 2**-30  # a dent far shallower than the ball: the X -> 0 limit
    whole = _dent_volume_over_pi(radius, radius + radius) / (radius * radius * radius)
    return DentVolume(
        volume=math.pi * _dent_volume_over_pi(radius, depth),
        quadratic_power=powers[0],
        cubic_power=powers[1],
        cubic_denominator=-1 / cubic,
        small_dent_power=_local_power(lambda x: _dent_volume_over_pi(radius, x), tiny),
        whole_ball=whole,
        whole_ball_power=_local_power(lambda r: _dent_volume_over_pi(r, r + r), float(radius)),
    )


def dent_volume_shallow(radius: Real, depth: Real) -> float:
    """Volume of a shallow dent, X << R, to leading order (7.4): the lowest-order term of the
    integrand pi r(x)^2 = pi x (2R - x) (the power series of ``_dent_polynomial``), integrated
    from 0 to X."""
    inputs.positive(radius, "radius")
    inputs.real(depth, "depth")
    if depth < 0:
        raise ValueError("the depth must not be negative")
    coefficients = _dent_polynomial(radius)
    lowest = next(k for k, c in enumerate(coefficients) if c != 0)
    leading = [0] * lowest + [coefficients[lowest]]
    return math.pi * polynomial_integral(leading, depth)


def whole_ball_volume(radius: Real) -> float:
    """Volume of the whole ball by the dent integral (7.4): the dent as deep as the diameter,
    V(2R), which the book checks against the ball's volume."""
    inputs.positive(radius, "radius")
    return dent_volume(radius, radius + radius).volume


def _local_power(f: Callable[[Scalar], Scalar], x: float) -> float:
    """d ln f / d ln x by the complex step (f analytic and positive at x, real on the real
    axis)."""
    return x * complex_step_derivative(f, x) / float(f(x).real)


# --- stopping the daredevil: Figs. 7.3-7.4, (7.7)-(7.8) ---------------------------------------


@dataclass(frozen=True)
class ConstantTarget:
    """A constant-force target (kiddy-pool, trampoline) that stops a fall from ``height`` within
    ``distance`` (Fig. 7.3), in units of the weight Mg.

    ``force`` = h / d: the net decelerating force, and the deceleration in g (30g for 30 m into
    1 m); ``potential_slope`` = -h / d, the slope of the trampoline's potential U(y) = -30 y;
    ``energy`` = h, the energy to remove per unit weight (30 Mg newton-metres). Like the book,
    the weight acting during the stop is left out: the target removes the fall's energy M g h.
    """

    force: Real
    potential_slope: Real
    energy: Real


def constant_force_target(fall_height: Real, stop_distance: Real) -> ConstantTarget:
    """The constant target stopping a fall from ``fall_height`` within ``stop_distance``."""
    inputs.positive(fall_height, "fall_height")
    inputs.positive(stop_distance, "stop_distance")
    force = fall_height / stop_distance  # work F d = energy M g h, per unit weight
    return ConstantTarget(force=force, potential_slope=-force, energy=fall_height)


def stopping_force_reduction(
    fall_height: Real, distance_before: Real, distance_after: Real
) -> Real:
    """Factor by which the stopping force falls when the stopping distance grows (Fig. 7.3c)."""
    before = constant_force_target(fall_height, distance_before).force
    return before / constant_force_target(fall_height, distance_after).force


def deceleration(force_per_weight: Real, g: Real) -> Real:
    """Deceleration, m/s^2, of a body pushed by ``force_per_weight`` times its weight (30 g)."""
    inputs.positive(force_per_weight, "force_per_weight")
    inputs.real(g, "g")
    return force_per_weight * cast(Real, abs(g))  # mypy joins abs over a union to object


def work_of_constant_force(force: Real, distance: Real) -> Real:
    """Work (area under F vs. y) of a constant force over a distance, F d (7.5a)."""
    inputs.real(force, "force")
    inputs.real(distance, "distance")
    return force * distance


def ramp_work(force: Real, distance: Real) -> Real:
    """Work of a force rising linearly from 0 to ``force`` over ``distance``: the triangle's area
    F d / 2 (the "factor of 1/2" before (7.8)). Integrated term by term: exact with Fractions."""
    inputs.real(force, "force")
    inputs.real(distance, "distance")
    if distance == 0:
        return 0 * force
    return polynomial_integral([0, force / distance], distance)


@dataclass(frozen=True)
class LinearTarget:
    """A linear-force target U = a y^2 (y < 0) stopping a fall from y = ``fall_height`` (graph
    units, Fig. 7.4), and the same in metres.

    ``stop`` is the turning point y < 0 where the target's potential a y^2 has taken up the
    fall's energy (gravity's slope is 1 in graph units); ``stop_m`` and ``stop_depth_m`` the
    same in metres (negative and positive); ``max_force`` the target's force -dU/dy at the
    stop, in units of Mg; ``energy`` the work F d / 2 of the ramp. Like the book (and the
    kiddy-pool of Fig. 7.3), the weight acting during the stop is left out; with it the total
    potential a y^2 + y would turn at the root of a y^2 + y = fall_height instead
    (``total_stop``).
    """

    stop: float
    stop_m: float
    stop_depth_m: float
    max_force: float
    energy: Real
    total_stop: float


def linear_target(quadratic: Real, fall_height: Real, fall_height_m: Real) -> LinearTarget:
    """Stop of a fall from ``fall_height`` (graph units; ``fall_height_m`` in metres) by the
    target potential ``quadratic`` y^2 (Fig. 7.4: 8 y^2 for the hardball)."""
    inputs.positive(quadratic, "quadratic")
    inputs.positive(fall_height, "fall_height")
    inputs.positive(fall_height_m, "fall_height_m")
    scale = float(fall_height_m) / float(fall_height)  # metres per graph unit
    a, h = float(quadratic), float(fall_height)
    stop = -math.sqrt(h / a)  # a y^2 = h
    force_coefficients = [-c for c in polynomial_derivative([0, 0, a])]  # F = -dU/dy
    max_force = force_coefficients[1] * stop
    total_stop = (-1 - math.sqrt(1 + 4 * a * h)) / (2 * a)  # a y^2 + y = h
    return LinearTarget(
        stop=stop,
        stop_m=stop * scale,
        stop_depth_m=-stop * scale,
        max_force=max_force,
        energy=ramp_work(max_force, -stop),
        total_stop=total_stop,
    )


@dataclass(frozen=True)
class QuadraticForce:
    """The force f(y) = -du/dy of u(y) = a y^2 + b y: ``slope`` -2a and ``constant`` -b, and
    their sizes (the book prints the minus signs outside: f(y) = -16y - 1)."""

    slope: Real
    constant: Real
    slope_magnitude: Real
    constant_magnitude: Real


def quadratic_potential_force(a: Real, b: Real) -> QuadraticForce:
    """Force of the total potential u = a y^2 + b y (Fig. 7.4): f = -2a y - b. Exact with
    Fractions (the power rule on the coefficients)."""
    inputs.real(a, "a")
    inputs.real(b, "b")
    constant, linear = (-c for c in polynomial_derivative([0, b, a]))
    return QuadraticForce(linear, constant, magnitude(linear), magnitude(constant))


@dataclass(frozen=True)
class Vertex:
    """The vertex of U = a y^2 + b y (7.8): ``y_shift`` = -b / 2a and ``u_shift`` = -b^2 / 4a;
    ``shift_denominator`` = -b / (a y_shift), the 2 of b / 2a, and ``depth_denominator`` =
    -b^2 / (a u_shift), the 4 of b^2 / 4a."""

    y_shift: Real
    u_shift: Real
    shift_denominator: Real
    depth_denominator: Real


def parabola_vertex(a: Real, b: Real) -> Vertex:
    """Where U = a y^2 + b y is lowest (dU/dy = 0) and how low (7.8): exact with Fractions."""
    inputs.real(a, "a")
    inputs.real(b, "b")
    if a == 0 or b == 0:
        raise ValueError("a parabola (a != 0) with a linear term (b != 0)")
    c0, c1 = polynomial_derivative([0, b, a])  # dU/dy = c0 + c1 y
    y = -c0 / c1
    u = a * y * y + b * y
    return Vertex(y, u, -b / (a * y), -b * b / (a * u))


def quadratic_potential(a: Symbolic, b: Symbolic, y: Symbolic) -> Symbolic:
    """The total potential U(y) = a y^2 + b y of (7.8a): a target's quadratic a y^2 and the
    linear potential b y of gravity. Plain operators (exact, symbolic)."""
    return a * y * y + b * y
