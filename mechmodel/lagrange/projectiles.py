"""Projectile families of one speed, their contact points and envelope: (12.14)-(12.17),
Figs. 12.5-12.6 (the volcanoes of Io, the atomic fountain).

Trajectories y(t) and y(x) of launch speed v0 and elevation a in uniform gravity g (12.14), the
contact generating function S(v0, a : x, y) = -y + y(x) (12.15) and its angle derivative
(12.16b) from an exact polynomial, the contact slope and abscissa where dS/da = 0 (12.16c), the
envelope y_env = v0^2/(2g) - g x^2/(2 v0^2) (12.17) by formula and as the highest trajectory over
all elevations (scipy), and the exponents and coefficients of the family derived in exact
algebra. Lengths in m, speeds in m/s, g in m/s^2, angles in radians.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from typing import cast

from mechmodel import inputs
from mechmodel.algebra import Laurent
from mechmodel.lagrange._common import _lib
from mechmodel.lagrange.calculus import angle_derivative
from mechmodel.typing import Real


def trajectory_position(time: Real, speed: Real, angle: Real, gravity: Real) -> tuple[float, float]:
    """(x, y) at time t of a projectile launched from the origin at speed v0 and elevation
    angle alpha in uniform gravity g (12.14a-b): (v0 cos(a) t, v0 sin(a) t - g t^2/2), m."""
    inputs.real(time, "time")
    inputs.positive(speed, "speed")
    inputs.real(angle, "angle")
    inputs.positive(gravity, "gravity")
    lib = _lib(angle)
    return speed * lib.cos(angle) * time, speed * lib.sin(angle) * time - gravity * time**2 / 2


def trajectory_height(x: Real, speed: Real, angle: Real, gravity: Real) -> float:
    """Height y(x) = x tan(a) - g x^2 / (2 v0^2 cos^2 a) of the trajectory (12.14c), m."""
    inputs.real(x, "x")
    inputs.positive(speed, "speed")
    inputs.real(angle, "angle")
    inputs.positive(gravity, "gravity")
    lib = _lib(angle)
    c = lib.cos(angle)
    if c == 0:
        raise ValueError("a vertical launch has no y(x)")
    return x * lib.tan(angle) - gravity * x**2 / (2 * speed**2 * c**2)


def envelope_height(x: Real, speed: Real, gravity: Real) -> Real:
    """Height of the envelope of all trajectories of speed v0 (12.17):
    y_env(x) = v0^2/(2g) - g x^2/(2 v0^2), m. Exact for ``int`` and ``Fraction``."""
    inputs.real(x, "x")
    inputs.positive(speed, "speed")
    inputs.positive(gravity, "gravity")
    return speed**2 / (2 * gravity) - gravity * x**2 / (2 * speed**2)


def contact_point(speed: Real, angle: Real, gravity: Real) -> tuple[Real, Real]:
    """Where the trajectory of elevation a touches the envelope (12.16c):
    x = v0^2 / (g tan a), y = y_env(x). ``ValueError`` for a = 0 (the horizontal launch never
    touches it) or a vertical one."""
    inputs.positive(speed, "speed")
    inputs.real(angle, "angle")
    inputs.positive(gravity, "gravity")
    t = _lib(angle).tan(angle)
    if t == 0:
        raise ValueError("the horizontal trajectory never contacts the envelope")
    x = speed**2 / (gravity * t)
    return x, envelope_height(x, speed, gravity)


def _generating_polynomial() -> Laurent:
    """S(v0, a : x, y) = -y + y(x) (12.15) as a Laurent polynomial in x, y, g, v0 and
    c = cos a, s = sin a: y'' = -g integrated twice from y'(0) = v0 s, y(0) = 0, and the time
    t = x/(v0 c) of x(t) = v0 c t put in (12.14)."""
    g, v0, x = (Laurent.var(n) for n in ("g", "v0", "x"))
    height_t = ((-g).integrate("t") + v0 * Laurent.var("s")).integrate("t")
    height_x = height_t.substitute("t", x / (v0 * Laurent.var("c")))
    return height_x - Laurent.var("y")


# _INEXACT_TERMS: the cast to float of a polynomial in the cosine c and sine s of the angle at
# these values: every term but -y holds c or s, a float (an mpmath number for an mpmath angle,
# which mechmodel's mpmath branches treat as a float), so the exact sum is a float.


def _fountain_values(x: Real, y: Real, speed: Real, angle: Real, gravity: Real) -> dict[str, Real]:
    inputs.real(x, "x")
    inputs.real(y, "y")
    inputs.positive(speed, "speed")
    inputs.real(angle, "angle")
    inputs.positive(gravity, "gravity")
    lib = _lib(angle)
    c = lib.cos(angle)
    if c == 0:
        raise ValueError("a vertical launch has no trajectory y(x)")
    return {"x": x, "y": y, "g": gravity, "v0": speed, "c": c, "s": lib.sin(angle)}


def generating_solution(x: Real, y: Real, speed: Real, angle: Real, gravity: Real) -> float:
    """The contact generating function S(v0, a : x, y) = -y + y(x) of (12.15) at the point
    (x, y), m: zero on the trajectory of speed v0 and elevation a, positive below it. From the
    exact polynomial of ``_generating_polynomial``."""
    values = _fountain_values(x, y, speed, angle, gravity)
    return cast(float, _generating_polynomial().evaluate_real(values))  # _INEXACT_TERMS


def _angle_slope() -> Laurent:
    """dS/da (12.16b) of the generating polynomial, reduced with sin^2 = 1 - cos^2."""
    return angle_derivative(_generating_polynomial(), "c", "s")


def generating_angle_derivative(x: Real, speed: Real, angle: Real, gravity: Real) -> float:
    """dS/da of the generating function (12.16b) at x for the elevation a, m/rad: the exact
    angle derivative (cos' = -sin, sin' = cos) of the polynomial S, evaluated. It vanishes
    where the trajectory of elevation a touches the envelope of the family."""
    values = _fountain_values(x, 0, speed, angle, gravity)
    return cast(float, _angle_slope().evaluate_real(values))  # _INEXACT_TERMS


def contact_tangent(x: Real, speed: Real, gravity: Real) -> Real:
    """tan a of the trajectory that touches the envelope at the abscissa x (12.16c): dS/da
    times cos^3 a is A c + B s with A, B free of the angle, so dS/da = 0 where
    tan a = s/c = -A/B, evaluated at x, v0 and g. ``ValueError`` at x = 0."""
    inputs.real(x, "x")
    inputs.positive(speed, "speed")
    inputs.positive(gravity, "gravity")
    form = (_angle_slope() * Laurent.var("c", 3)).reduce_trig("c", "s")
    cos_part = form.part("s", 0)
    sin_part = form.part("s", 1) / Laurent.var("s")
    a, b = cos_part / Laurent.var("c"), sin_part
    if any(dict(k).get(n, 0) for k in (*a.terms, *b.terms) for n in ("c", "s")):
        raise ValueError("dS/da is not of the form (A cos a + B sin a)/cos^3 a")
    values = {"x": x, "g": gravity, "v0": speed}
    denominator = b.evaluate_real(values)
    if denominator == 0:
        raise ValueError("no trajectory touches the envelope at x = 0")
    return -a.evaluate_real(values) / denominator


def contact_distance(speed: Real, angle: Real, gravity: Real) -> float:
    """The abscissa x where the trajectory of elevation a touches the envelope (12.16c): dS/da
    is A x + B x^2 with A, B functions of the angle, zero at x = 0 and at x = -A/B.
    ``ValueError`` for a horizontal launch (it never touches the envelope)."""
    values = _fountain_values(0, 0, speed, angle, gravity)
    slope = _angle_slope()
    linear = slope.part("x", 1) / Laurent.var("x")
    quadratic = slope.part("x", 2) / Laurent.var("x", 2)
    if slope != linear * Laurent.var("x") + quadratic * Laurent.var("x", 2):
        raise ValueError("dS/da is not of the form A x + B x^2")
    b = quadratic.evaluate_real(values)
    a = linear.evaluate_real(values)
    if b == 0:
        raise ValueError("the horizontal trajectory never contacts the envelope")
    return cast(float, -a / b)  # _INEXACT_TERMS


def envelope_by_maximum(x: Real, speed: Real, gravity: Real) -> float:
    """Height of the envelope of all trajectories of speed v0 at the abscissa x (12.17), m,
    found without its formula: the highest y(x) of (12.14c) over all elevations, by a bounded
    scalar search in the angle (at x = 0 the highest point of the vertical launch, by a search
    in time). y(x) is a concave quadratic in tan a, so the maximum is unique, and the value is
    insensitive to the error of the angle to second order: the relative error is about
    (1e-8 v0^2/(g x))^2, below 1e-12 for |x| > 1e-2 v0^2/g. Floats."""
    from scipy.optimize import minimize_scalar

    inputs.real(x, "x")
    inputs.positive(speed, "speed")
    inputs.positive(gravity, "gravity")
    x, v0, g = float(x), float(speed), float(gravity)
    if x == 0:
        up = math.pi / 2
        end = 1.0
        while trajectory_position(end, v0, up, g)[1] > 0:  # a time after the landing
            end *= 2
        result = minimize_scalar(
            lambda t: -trajectory_position(t, v0, up, g)[1],
            bounds=(0.0, end),
            method="bounded",
            options={"xatol": 1e-13 * end},
        )
        return float(trajectory_position(float(result.x), v0, up, g)[1])
    edge = math.nextafter(math.pi / 2, 0.0)
    result = minimize_scalar(
        lambda a: -trajectory_height(x, v0, a, g),
        bounds=(-edge, edge),
        method="bounded",
        options={"xatol": 1e-13},
    )
    return float(trajectory_height(x, v0, float(result.x), g))


@dataclass(frozen=True)
class ProjectileFamily:
    """Coefficients and exponents of the trajectory family and its envelope, derived
    symbolically ((12.14)-(12.17)). Denominators are given as positive numbers and powers of a
    denominator as positive exponents, as the book prints them."""

    time_coefficient: Fraction  # y(t) = v0 sin(a) t - time_coefficient g t^time_power
    time_power: int
    quadratic_denominator: (
        Fraction  # y(x) = x tan a - g x^x_power / (den v0^v0_power cos^cos_power)
    )
    x_power: int
    v0_power: int
    cos_power: int
    tan_derivative_cos_power: int  # d tan a / da = 1 / cos^k a
    secant_derivative_coefficient: Fraction  # d cos^-2 a / da = coef sin a / cos^k a
    secant_derivative_cos_power: int
    secant_tan_constant: Fraction  # 1/cos^2 = constant + tan^power
    secant_tan_power: int
    contact_tan_v0_power: int  # tan a = v0^k / (g x) at the contact point (12.16c)
    contact_tan_square_v0_power: int  # tan^2 a = v0^k / (g^2 x^2)
    envelope_constant_denominator: Fraction  # y_env = v0^k / (den g) - ...
    envelope_constant_v0_power: int
    envelope_quadratic_denominator: Fraction  # ... - g x^k / (den v0^j)
    envelope_x_power: int
    envelope_v0_power: int
    envelope_shape_angle: float  # the a whose trajectory has the envelope's shape


def projectile_family() -> ProjectileFamily:
    """Derive (12.14)-(12.17) in exact algebra.

    y'' = -g integrated twice from y'(0) = v0 sin a, y(0) = 0 gives y(t); t = x/(v0 cos a)
    from x(t) eliminates the time. S = -y + y(x) is differentiated in a (cos' = -sin,
    sin' = cos, sin^2 = 1 - cos^2). Written with T = tan a, where 1/cos^2 = 1 + T^2, S is
    quadratic in T; dS/dT = 0 is linear in T and gives the contact slope T(x), which put back
    into y gives the envelope. The envelope's x^2 term equals a trajectory's only where
    cos^2 a = 1: the horizontal launch.
    """
    g, v0, x = (Laurent.var(n) for n in ("g", "v0", "x"))
    c, s, tan = Laurent.var("c"), Laurent.var("s"), Laurent.var("T")
    # (12.14b): integrate y'' = -g twice
    velocity = (-g).integrate("t") + v0 * s
    height_t = velocity.integrate("t")
    gravity_term = height_t.part("t", 2)
    # (12.14c): eliminate t = x / (v0 cos a)
    height_x = height_t.substitute("t", x / (v0 * c))
    quad = height_x.part("x", 2)
    # (12.16b): d/da of the two terms of y(x)
    slope_term = height_x.part("x", 1) / x  # tan a = s/c
    d_tan = angle_derivative(slope_term, "c", "s")
    secant2 = Laurent.var("c", -2)
    d_secant2 = angle_derivative(secant2, "c", "s")
    # 1/cos^2 in powers of tan: the power k for which 1/cos^2 - tan^k reduces to a constant
    tan_ratio = s / c
    k_sec = next(
        k for k in range(1, 5) if (secant2 - (tan_ratio**k).reduce_trig("c", "s")).is_constant()
    )
    sec_constant = Laurent.rational((secant2 - (tan_ratio**k_sec).reduce_trig("c", "s")).value())
    # S in T: y(x) = x T - g x^2 (1 + T^2) / (2 v0^2)
    quad_no_cos = quad * Laurent.var("c", 2)
    height_tan = x * tan + quad_no_cos * (sec_constant + tan**k_sec)
    d_s = height_tan.diff("T")  # linear in T: a + b T
    a_part, b_part = d_s.part("T", 0), d_s.part("T", 1) / tan
    contact_tan = -a_part / b_part
    envelope = height_tan.substitute("T", contact_tan)
    env_const = envelope.part("x", 0)
    env_quad = envelope.part("x", 2)
    env_x2, traj_x2 = (
        Laurent.rational(env_quad.only_coefficient()),
        Laurent.rational(quad_no_cos.only_coefficient()),
    )
    shape_ratio = env_x2 / traj_x2  # = cos^2 a
    return ProjectileFamily(
        time_coefficient=-Laurent.rational(gravity_term.only_coefficient()),
        time_power=gravity_term.power("t"),
        quadratic_denominator=1 / abs(Laurent.rational(quad.only_coefficient())),
        x_power=quad.power("x"),
        v0_power=-quad.power("v0"),
        cos_power=-quad.power("c"),
        tan_derivative_cos_power=-d_tan.power("c"),
        secant_derivative_coefficient=Laurent.rational(d_secant2.only_coefficient()),
        secant_derivative_cos_power=-d_secant2.power("c"),
        secant_tan_constant=sec_constant,
        secant_tan_power=k_sec,
        contact_tan_v0_power=contact_tan.power("v0"),
        contact_tan_square_v0_power=(contact_tan**2).power("v0"),
        envelope_constant_denominator=1 / Laurent.rational(env_const.only_coefficient()),
        envelope_constant_v0_power=env_const.power("v0"),
        envelope_quadratic_denominator=1 / abs(Laurent.rational(env_quad.only_coefficient())),
        envelope_x_power=env_quad.power("x"),
        envelope_v0_power=-env_quad.power("v0"),
        envelope_shape_angle=math.acos(math.sqrt(float(shape_ratio))),
    )
