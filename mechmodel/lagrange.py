"""Lagrangian and Hamiltonian mechanics: velocity vs momentum functions (chapter 12).

The kinetic energy written in velocities v is the Lagrangian L(v) = v.M.v/2; in the
quasi-velocities V = R.v (R = M^(1/2), the root-mass matrix) it is the "Estrangian" E(V) = V.V/2,
in momenta p = M.v the Hamiltonian H(p) = p.M^-1.p/2 ((12.1)-(12.9), Fig. 12.1). L and H are
Legendre contact transforms of each other, H(p) = p v - L(v) at p = dL/dv ((12.11)-(12.13),
Figs. 12.3-12.4). A family of projectiles of one speed v0 and all angles has a parabolic
envelope, the "volcanoes of Io" and the atomic fountain ((12.14)-(12.17), Figs. 12.5-12.6). In
polar coordinates the Jacobian, its inverse (the "Kajobian") and the metric give the Lagrangian
L = M (r'^2 + r^2 phi'^2)/2 - U, whose Lagrange equations carry the centrifugal M r phi'^2 and
Coriolis 2 M r r' phi' terms ((12.26)-(12.33)); the Hamiltonian p q' - L is the energy (12.37).
The action S = integral L dt and its phase S/hbar colour the trajectories of Figs. 12.12-12.15.

Three kinds of computation:

- **Exact algebra** for the coefficients and exponents of the formulas the book derives: Laurent
  polynomials in named variables (``mechmodel.algebra.Laurent``), differentiated,
  substituted and, for the cosine and sine of an angle, reduced with sin^2 = 1 - cos^2. Nothing
  is written in: the 1/2 of a trajectory comes from integrating g twice, the 2 of the Coriolis
  term from differentiating M r^2 phi' in time, the envelope from solving dS/d(alpha) = 0.
- **Numbers** for the geometry of the figures (slopes, Legendre tangents, trajectories and their
  envelope, Jacobians, metrics, phases) in plain operators: exact for ``int`` and ``Fraction``
  inputs where no root or trigonometric function is needed, else floats.
- **Numerical transforms**: the Legendre transform of any convex function by a bounded maximum
  (scipy), the envelope of the projectile family as the highest trajectory over all elevations
  (scipy), and the action of a sampled path by the trapezoid rule.

The formula claims of chapter 12 call these with generic numbers: the energy in any scaled
coordinate, the Legendre pair, the generating function S and its angle derivative, the contact
slope and abscissa, the gradient potential of M.v, the polar Lagrangian and forces, the
Hamiltonian of one coordinate and the kinetic energy of a metric (through a Cholesky factor).

Units are SI or the book's scaled units throughout; angles in radians.
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import numpy as np

from mechmodel import inputs
from mechmodel.algebra import Laurent
from mechmodel.ellipse import kinetic_energy, momentum_radius, velocity_radius
from mechmodel.exact import exact_sqrt

# -------------------------------------------------------------------------------------------
# Calculus on Laurent polynomials (mechmodel.algebra) of angles and of time
# -------------------------------------------------------------------------------------------


def angle_derivative(p: Laurent, cos: str, sin: str) -> Laurent:
    """d/d(angle) of a polynomial in cos and sin of that angle (chain rule: cos' = -sin,
    sin' = cos), reduced with sin^2 = 1 - cos^2."""
    d = p.diff(cos) * (-Laurent.var(sin)) + p.diff(sin) * Laurent.var(cos)
    return d.reduce_trig(cos, sin)


def time_derivative(p: Laurent, rates: Mapping[str, Laurent]) -> Laurent:
    """Total time derivative sum_k (dP/dx_k) x_k' (the chain rule of (12.7)) where ``rates``
    gives each variable's time derivative as a polynomial."""
    out = Laurent()
    for name, rate in rates.items():
        out = out + p.diff(name) * rate
    return out


# -------------------------------------------------------------------------------------------
# Kinetic energy in v, V and p: (12.1)-(12.9), Fig. 12.1 (L(v) of free bodies, (12.3), is
# mechmodel.ellipse.kinetic_energy)
# -------------------------------------------------------------------------------------------


def quasi_velocities(masses: Sequence[Any], velocities: Sequence[Any]) -> list[Any]:
    """Mass-scaled velocities V_k = sqrt(m_k) v_k (12.1), the coordinates in which the energy
    ellipse is a circle (Fig. 12.1b); kg^(1/2) m/s."""
    _same_length(masses, velocities)
    return [
        _sqrt(inputs.mass(m)) * inputs.real(v, "velocity")
        for m, v in zip(masses, velocities, strict=True)
    ]


def momenta(masses: Sequence[Any], velocities: Sequence[Any]) -> list[Any]:
    """Momenta p_k = m_k v_k (12.2), kg m/s. Exact for ``int`` and ``Fraction``."""
    _same_length(masses, velocities)
    return [
        inputs.mass(m) * inputs.real(v, "velocity") for m, v in zip(masses, velocities, strict=True)
    ]


def estrangian(quasi: Sequence[Any]) -> Any:
    """E(V) = sum_k V_k^2 / 2 (12.5): the kinetic energy as a function of V."""
    return sum(inputs.real(x, "V") ** 2 for x in quasi) / 2


def hamiltonian_free(masses: Sequence[Any], momenta_: Sequence[Any]) -> Any:
    """H(p) = sum_k p_k^2 / (2 m_k) (12.4): the kinetic energy as a function of momenta."""
    _same_length(masses, momenta_)
    return (
        sum(
            inputs.real(p, "momentum") ** 2 / inputs.mass(m)
            for m, p in zip(masses, momenta_, strict=True)
        )
        / 2
    )


@dataclass(frozen=True)
class RootMassPowers:
    """Powers of the root-mass matrix R = M^(1/2) that map velocities to momenta and back."""

    momentum: int  # p = R^momentum . v, so M = R^momentum
    velocity: int  # v = R^velocity . p, so M^-1 = R^velocity


def root_mass_powers() -> RootMassPowers:
    """(12.9): V = R.v and p = R.V (a second factor sqrt(m): p = m v = sqrt(m) V), so
    M = R^2 and M^-1 = R^-2. Counted by composing the two scalings symbolically."""
    w, v = Laurent.var("w"), Laurent.var("v")
    quasi = w * v  # V = sqrt(m) v
    momentum = w * quasi  # p = sqrt(m) V
    to_momentum = (momentum / v).power("w")
    # v in terms of p: invert p = w^k v
    to_velocity = (v / momentum).power("w")
    return RootMassPowers(momentum=to_momentum, velocity=to_velocity)


def scaled_coordinate_energy(
    masses: Sequence[Any], coordinates: Sequence[Any], scale_power: Any
) -> Any:
    """The kinetic energy of bodies given by their mass-scaled coordinates u_k = m_k^s v_k:
    each velocity is recovered as v_k = u_k m_k^-s and put into L(v) = sum m_k v_k^2/2 (12.3).
    s = 1/2 gives the energy in the quasi-velocities V (12.1), s = 1 in the momenta p (12.2).
    Exact for ``int`` and ``Fraction`` masses when m^s is rational (s = 1); ``scale_power`` is
    a number or a Fraction.
    """
    _same_length(masses, coordinates)
    s = Fraction(scale_power)
    velocities = [
        inputs.real(u, "coordinate") * _power(inputs.mass(m), -s)
        for m, u in zip(masses, coordinates, strict=True)
    ]
    return kinetic_energy(masses, velocities)


@dataclass(frozen=True)
class RootMassMaps:
    """The maps of (12.9) for one body of root mass R = sqrt(m): the momentum p that a unit
    velocity maps to (the mass M) and the velocity v that a unit momentum maps back to
    (the inverse mass M^-1)."""

    mass: Any
    inverse_mass: Any


def root_mass_maps(root_mass: Any) -> RootMassMaps:
    """Compose the root-mass scalings of (12.9) map by map: forward V = R v and p = R V, so a
    unit velocity becomes the momentum R (R 1); back V = p / R and v = V / R, so a unit
    momentum becomes the velocity (1 / R) / R. Exact for ``int`` and ``Fraction``."""
    r = inputs.positive(root_mass, "root_mass")
    if isinstance(r, int):
        r = Fraction(r)
    unit = r**0
    quasi = r * unit  # V = R v at v = 1
    momentum = r * quasi  # p = R V
    back_quasi = unit / r  # V = p / R at p = 1
    velocity = back_quasi / r  # v = V / R
    return RootMassMaps(mass=momentum, inverse_mass=velocity)


@dataclass(frozen=True)
class EllipseSlopes:
    """Slopes (rise over run) of the lines of Fig. 12.1 in the three planes: the collision
    (momentum-conserving) line, the tangent of the energy ellipse at its COM point, and the COM
    bisector (both bodies at the COM velocity), in v (Lagrangian), V (Estrangian) and p
    (Hamiltonian) coordinates. ``*_steepness`` is the magnitude of the collision-line slope
    (the slope triangle drawn on that line)."""

    mass_ratio: Any
    velocity_collision: Any
    velocity_tangent: Any
    velocity_bisector: Any
    quasi_collision: Any
    quasi_tangent: Any
    quasi_bisector: Any
    quasi_steepness: Any
    momentum_collision: Any
    momentum_tangent: Any
    momentum_bisector: Any
    momentum_steepness: Any


def ke_ellipse_slopes(collision_slope: Any) -> EllipseSlopes:
    """The slopes of Fig. 12.1 from the slope -m1/m2 of the collision line in the v1-v2 plane.

    A collision keeps m1 v1 + m2 v2, so it moves (v1, v2) along (m2, -m1); the COM bisector is
    (1, 1). The map to V multiplies the components by sqrt(m_k), the map to p by m_k. The
    tangent of each ellipse at the COM point is normal to the gradient of the energy there
    ((12.10): grad_v L = p, grad_V E = V, grad_p H = v). Exact for a perfect-square ratio.
    """
    inputs.real(collision_slope, "collision_slope")
    ratio = -collision_slope
    inputs.positive(ratio, "mass ratio m1/m2 (minus the collision slope)")
    exact = isinstance(ratio, int | Fraction)
    m1, m2 = (Fraction(ratio), Fraction(1)) if exact else (ratio, 1.0)
    r1, r2 = exact_sqrt(m1), exact_sqrt(m2)

    def slope(dx: Any, dy: Any) -> Any:
        return dy / dx

    def tangent(grad: tuple[Any, Any]) -> Any:
        return slope(grad[1], -grad[0])  # the direction (g2, -g1) is normal to (g1, g2)

    collision_v = (m2, -m1)
    bisector_v = (m2 / m2, m2 / m2)
    com_v = bisector_v  # a COM point: both at the same velocity (any scale)
    grad_l = (m1 * com_v[0], m2 * com_v[1])  # p at the COM point
    com_quasi = (r1 * com_v[0], r2 * com_v[1])  # V at the COM point, grad E = V
    com_p = grad_l
    grad_h = (com_p[0] / m1, com_p[1] / m2)  # v at the COM point, grad H = v
    quasi_collision = slope(r1 * collision_v[0], r2 * collision_v[1])
    momentum_collision = slope(m1 * collision_v[0], m2 * collision_v[1])
    return EllipseSlopes(
        mass_ratio=m1 / m2,
        velocity_collision=slope(*collision_v),
        velocity_tangent=tangent(grad_l),
        velocity_bisector=slope(*bisector_v),
        quasi_collision=quasi_collision,
        quasi_tangent=tangent(com_quasi),
        quasi_bisector=slope(r1 * bisector_v[0], r2 * bisector_v[1]),
        quasi_steepness=abs(quasi_collision),
        momentum_collision=momentum_collision,
        momentum_tangent=tangent(grad_h),
        momentum_bisector=slope(m1 * bisector_v[0], m2 * bisector_v[1]),
        momentum_steepness=abs(momentum_collision),
    )


@dataclass(frozen=True)
class EllipseRadii:
    """Semi-axes of the energy ellipses L(v) = E (velocity radii sqrt(2E/m_k)) and H(p) = E
    (momentum radii sqrt(2 E m_k)), Fig. 12.2."""

    velocity: list[Any]
    momentum: list[Any]


def energy_ellipse_radii(masses: Sequence[Any], energy: Any) -> EllipseRadii:
    """Radii of the L and H ellipses of energy E (Fig. 12.2): L(v) = sum m v^2/2 = E meets the
    v_k axis at sqrt(2E/m_k), H(p) = sum p^2/(2m) = E the p_k axis at sqrt(2E m_k); for each
    axis the H radius is m_k times the L radius."""
    inputs.positive(energy, "energy")
    ms = [inputs.mass(m) for m in masses]
    return EllipseRadii(
        velocity=[velocity_radius(m, energy) for m in ms],
        momentum=[momentum_radius(m, energy) for m in ms],
    )


def ellipse_radius_ratio(mass: Any, energy: Any = 1) -> Any:
    """Ratio of the L(v)-ellipse radius to the H(p)-ellipse radius on one axis for a body of
    mass ``mass`` (Fig. 12.2(d)-(e), where the mass is s times the unit mass): the two radii of
    ``energy_ellipse_radii`` divided, sqrt(2E/m)/sqrt(2Em). Independent of the energy."""
    radii = energy_ellipse_radii([mass], energy)
    return radii.velocity[0] / radii.momentum[0]


# -------------------------------------------------------------------------------------------
# Legendre contact transformation: (12.10)-(12.13), Figs. 12.2-12.4, 12.9
# -------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class QuadraticLegendrePair:
    """The quadratic kinetic energy of one body as L(v) and as H(p), at a velocity v and the
    momentum p it maps to (line 13716): its mass, L and H."""

    mass: Any
    lagrangian: Any
    hamiltonian: Any


def quadratic_legendre_pair(velocity: Any, momentum: Any) -> QuadraticLegendrePair:
    """L and H of the quadratic kinetic energy whose slope dL/dv at ``velocity`` is
    ``momentum``: p = dL/dv = m v (12.10a) fixes the mass m = p / v; then L = m v^2/2 (12.3)
    and H = p^2/(2m) (12.4). Numerically L = H = p v/2 (line 13716) while H = p v - L
    (12.11b). Exact for ``int`` and ``Fraction``; ``ValueError`` where p / v is not a
    positive mass."""
    v = inputs.real(velocity, "velocity")
    p = inputs.real(momentum, "momentum")
    if v == 0:
        raise ValueError("the velocity must be non-zero to fix the mass p / v")
    mass = inputs.mass(p / v, "mass p / v")
    return QuadraticLegendrePair(
        mass=mass,
        lagrangian=kinetic_energy([mass], [v]),
        hamiltonian=hamiltonian_free([mass], [p]),
    )


@dataclass(frozen=True)
class LegendreTangent:
    """The tangent of slope s at the point x of a curve of value f there (Fig. 12.3):
    ``transform`` = s x - f, the Legendre transform (12.11); ``intercept`` = f - s x, where the
    tangent meets the axis x = 0 (minus the transform)."""

    transform: Any
    intercept: Any


def legendre_tangent(value: Any, slope: Any, point: Any) -> LegendreTangent:
    """Legendre geometry of Fig. 12.3: the tangent to L(v) at v (slope p, value L) meets the
    L axis at L - p v = -H, so H(p) = p v - L(v) (12.11b); the same with H(p), slope v and
    point p gives -L (12.11a). Exact for ``int`` and ``Fraction``."""
    for x, name in ((value, "value"), (slope, "slope"), (point, "point")):
        inputs.real(x, name)
    transform = slope * point - value
    return LegendreTangent(transform=transform, intercept=value - slope * point)


@dataclass(frozen=True)
class LegendreStationarity:
    """The first derivatives that vanish at a tangent contact point (12.13)."""

    hamiltonian_velocity_slope: Fraction  # d(p v - L(v))/dv at v = dH/dp (12.13a)
    lagrangian_momentum_slope: Fraction  # d(p v - H(p))/dp at p = dL/dv (12.13b)


def legendre_stationarity() -> LegendreStationarity:
    """For the quadratic L = m v^2/2 and H = p^2/(2m): the secant family p v - L(v) at fixed p
    is extreme where its v-derivative p - m v vanishes, which is at v = dH/dp = p/m; likewise
    v - p/m vanishes at p = dL/dv = m v. Derivatives and substitutions are symbolic."""
    m, v, p = Laurent.var("m"), Laurent.var("v"), Laurent.var("p")
    lagrangian = m * v**2 / 2
    hamiltonian = p**2 / (2 * m)
    h_of_v = (p * v - lagrangian).diff("v").substitute("v", hamiltonian.diff("p"))
    l_of_p = (p * v - hamiltonian).diff("p").substitute("p", lagrangian.diff("v"))
    return LegendreStationarity(
        hamiltonian_velocity_slope=h_of_v.value(), lagrangian_momentum_slope=l_of_p.value()
    )


@dataclass(frozen=True)
class LegendreResult:
    """The Legendre transform F*(s) = max_x (s x - F(x)) and the point x where it is taken."""

    value: float
    argument: float


def legendre_transform(
    function: Callable[[float], float], slope: float, lower: float, upper: float
) -> LegendreResult:
    """Numerical Legendre transform F*(s) = max over x in [lower, upper] of s x - F(x) of a
    convex F ((12.11): H(p) = max_v (p v - L(v)), the tangent of slope p touching L at the
    maximising v, Fig. 12.4a). The maximum is found by a bounded scalar search; the value is
    insensitive to the error of the argument to second order. Floats.
    """
    from scipy.optimize import minimize_scalar

    inputs.real(slope, "slope")
    if not lower < upper:
        raise ValueError("need lower < upper")
    result = minimize_scalar(
        lambda x: function(x) - slope * x,
        bounds=(lower, upper),
        method="bounded",
        options={"xatol": 1e-12 * max(1.0, abs(lower), abs(upper))},
    )
    x = float(result.x)
    return LegendreResult(value=slope * x - function(x), argument=x)


# -------------------------------------------------------------------------------------------
# Projectile families, contact points and their envelope: (12.14)-(12.17), Figs. 12.5-12.6
# -------------------------------------------------------------------------------------------


def trajectory_position(time: Any, speed: Any, angle: Any, gravity: Any) -> tuple[Any, Any]:
    """(x, y) at time t of a projectile launched from the origin at speed v0 and elevation
    angle alpha in uniform gravity g (12.14a-b): (v0 cos(a) t, v0 sin(a) t - g t^2/2), m."""
    inputs.real(time, "time")
    inputs.positive(speed, "speed")
    inputs.real(angle, "angle")
    inputs.positive(gravity, "gravity")
    lib = _lib(angle)
    return speed * lib.cos(angle) * time, speed * lib.sin(angle) * time - gravity * time**2 / 2


def trajectory_height(x: Any, speed: Any, angle: Any, gravity: Any) -> Any:
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


def envelope_height(x: Any, speed: Any, gravity: Any) -> Any:
    """Height of the envelope of all trajectories of speed v0 (12.17):
    y_env(x) = v0^2/(2g) - g x^2/(2 v0^2), m. Exact for ``int`` and ``Fraction``."""
    inputs.real(x, "x")
    inputs.positive(speed, "speed")
    inputs.positive(gravity, "gravity")
    return speed**2 / (2 * gravity) - gravity * x**2 / (2 * speed**2)


def contact_point(speed: Any, angle: Any, gravity: Any) -> tuple[Any, Any]:
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


def _fountain_values(x: Any, y: Any, speed: Any, angle: Any, gravity: Any) -> dict[str, Any]:
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


def generating_solution(x: Any, y: Any, speed: Any, angle: Any, gravity: Any) -> Any:
    """The contact generating function S(v0, a : x, y) = -y + y(x) of (12.15) at the point
    (x, y), m: zero on the trajectory of speed v0 and elevation a, positive below it. From the
    exact polynomial of ``_generating_polynomial``."""
    return _generating_polynomial().evaluate(_fountain_values(x, y, speed, angle, gravity))


def _angle_slope() -> Laurent:
    """dS/da (12.16b) of the generating polynomial, reduced with sin^2 = 1 - cos^2."""
    return angle_derivative(_generating_polynomial(), "c", "s")


def generating_angle_derivative(x: Any, speed: Any, angle: Any, gravity: Any) -> Any:
    """dS/da of the generating function (12.16b) at x for the elevation a, m/rad: the exact
    angle derivative (cos' = -sin, sin' = cos) of the polynomial S, evaluated. It vanishes
    where the trajectory of elevation a touches the envelope of the family."""
    return _angle_slope().evaluate(_fountain_values(x, 0, speed, angle, gravity))


def contact_tangent(x: Any, speed: Any, gravity: Any) -> Any:
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
    denominator = b.evaluate(values)
    if denominator == 0:
        raise ValueError("no trajectory touches the envelope at x = 0")
    return -a.evaluate(values) / denominator


def contact_distance(speed: Any, angle: Any, gravity: Any) -> Any:
    """The abscissa x where the trajectory of elevation a touches the envelope (12.16c): dS/da
    is A x + B x^2 with A, B functions of the angle, zero at x = 0 and at x = -A/B.
    ``ValueError`` for a horizontal launch (it never touches the envelope)."""
    values = _fountain_values(0, 0, speed, angle, gravity)
    slope = _angle_slope()
    linear = slope.part("x", 1) / Laurent.var("x")
    quadratic = slope.part("x", 2) / Laurent.var("x", 2)
    if slope != linear * Laurent.var("x") + quadratic * Laurent.var("x", 2):
        raise ValueError("dS/da is not of the form A x + B x^2")
    b = quadratic.evaluate(values)
    a = linear.evaluate(values)
    if b == 0:
        raise ValueError("the horizontal trajectory never contacts the envelope")
    return -a / b


def envelope_by_maximum(x: Any, speed: Any, gravity: Any) -> float:
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
        return trajectory_position(float(result.x), v0, up, g)[1]
    edge = math.nextafter(math.pi / 2, 0.0)
    result = minimize_scalar(
        lambda a: -trajectory_height(x, v0, a, g),
        bounds=(-edge, edge),
        method="bounded",
        options={"xatol": 1e-13},
    )
    return trajectory_height(x, v0, float(result.x), g)


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
    sec_constant = (secant2 - (tan_ratio**k_sec).reduce_trig("c", "s")).value()
    # S in T: y(x) = x T - g x^2 (1 + T^2) / (2 v0^2)
    quad_no_cos = quad * Laurent.var("c", 2)
    height_tan = x * tan + quad_no_cos * (sec_constant + tan**k_sec)
    d_s = height_tan.diff("T")  # linear in T: a + b T
    a_part, b_part = d_s.part("T", 0), d_s.part("T", 1) / tan
    contact_tan = -a_part / b_part
    envelope = height_tan.substitute("T", contact_tan)
    env_const = envelope.part("x", 0)
    env_quad = envelope.part("x", 2)
    shape_ratio = env_quad.only_coefficient() / quad_no_cos.only_coefficient()  # = cos^2 a
    return ProjectileFamily(
        time_coefficient=-gravity_term.only_coefficient(),
        time_power=gravity_term.power("t"),
        quadratic_denominator=1 / abs(quad.only_coefficient()),
        x_power=quad.power("x"),
        v0_power=-quad.power("v0"),
        cos_power=-quad.power("c"),
        tan_derivative_cos_power=-d_tan.power("c"),
        secant_derivative_coefficient=d_secant2.only_coefficient(),
        secant_derivative_cos_power=-d_secant2.power("c"),
        secant_tan_constant=sec_constant,
        secant_tan_power=k_sec,
        contact_tan_v0_power=contact_tan.power("v0"),
        contact_tan_square_v0_power=(contact_tan**2).power("v0"),
        envelope_constant_denominator=1 / env_const.only_coefficient(),
        envelope_constant_v0_power=env_const.power("v0"),
        envelope_quadratic_denominator=1 / abs(env_quad.only_coefficient()),
        envelope_x_power=env_quad.power("x"),
        envelope_v0_power=-env_quad.power("v0"),
        envelope_shape_angle=math.acos(math.sqrt(float(shape_ratio))),
    )


# -------------------------------------------------------------------------------------------
# Generalized coordinates: polar Jacobian, metric, Lagrangian, forces (12.18)-(12.37)
# -------------------------------------------------------------------------------------------


def coordinate_differential(start: Any, end: Any) -> Any:
    """The differential dq = q_end - q_start between two labelled coordinate lines of a cell
    (Fig. 12.10: the cell between q1 = 100 and q1 = 101 has dq1 = 1). Exact for ``int``."""
    inputs.real(start, "start")
    inputs.real(end, "end")
    return end - start


def polar_jacobian(r: Any, phi: Any) -> list[list[Any]]:
    """Jacobian J[j][m] = dx^j/dq^m of x = r cos phi, y = r sin phi (12.26); its columns are the
    covariant bases E_r, E_phi."""
    inputs.real(r, "r")
    lib = _lib(r, phi)
    c, s = lib.cos(phi), lib.sin(phi)
    return [[c, -r * s], [s, r * c]]


def polar_kajobian(r: Any, phi: Any) -> list[list[Any]]:
    """The inverse ("Kajobian") K[m][j] = dq^m/dx^j of the polar Jacobian (12.26); its rows
    are the contravariant bases E^r, E^phi. ``ValueError`` at the origin."""
    inputs.real(r, "r")
    if r == 0:
        raise ValueError("polar coordinates are singular at r = 0")
    lib = _lib(r, phi)
    c, s = lib.cos(phi), lib.sin(phi)
    return [[c, s], [-s / r, c / r]]


def polar_metric(r: Any, phi: Any = 0) -> list[list[Any]]:
    """Covariant metric g_mn = E_m . E_n = (J^T J)_mn of polar coordinates (12.30b)."""
    j = polar_jacobian(r, phi)
    return [[sum(j[k][m] * j[k][n] for k in range(2)) for n in range(2)] for m in range(2)]


def polar_inverse_metric(r: Any, phi: Any = 0) -> list[list[Any]]:
    """Contravariant metric g^mn = E^m . E^n = (K K^T)^mn of polar coordinates (12.30c)."""
    k = polar_kajobian(r, phi)
    return [[sum(k[m][j] * k[n][j] for j in range(2)) for n in range(2)] for m in range(2)]


_POLAR_RATES = {
    "r": Laurent.var("rd"),
    "rd": Laurent.var("rdd"),
    "pd": Laurent.var("pdd"),
    "c": -Laurent.var("s") * Laurent.var("pd"),
    "s": Laurent.var("c") * Laurent.var("pd"),
}


@dataclass(frozen=True)
class PolarMechanics:
    """Exact results of the polar-coordinate Lagrange mechanics (12.26)-(12.33).

    Variables: r, its rate rd (r'), the angular rate pd (phi'), M the mass. Matrices are given
    entry by entry as coefficients of the power of r shown.
    """

    jacobian_determinant_r_power: int
    metric_rr: Fraction
    metric_rphi: Fraction
    metric_phir: Fraction
    metric_phiphi_coefficient: Fraction
    metric_phiphi_r_power: int
    inverse_metric_rr: Fraction
    inverse_metric_rphi: Fraction
    inverse_metric_phir: Fraction
    inverse_metric_phiphi_coefficient: Fraction
    inverse_metric_phiphi_r_power: int
    kinetic_radial_coefficient: Fraction  # T = coef M r'^2 + ...
    kinetic_angular_coefficient: Fraction  # ... + coef M r^2 phi'^2
    kinetic_angular_rate_power: int
    kinetic_angular_r_power: int
    radial_momentum_coefficient: Fraction  # p_r = coef M r'
    angular_momentum_r_power: int  # p_phi = M r^k phi'
    centrifugal_rate_power: int  # dL/dr = M r phi'^k
    angular_momentum_rate_r_power: int  # dp_phi/dt = M r^k phi'' + ...
    coriolis_coefficient: Fraction  # ... + coef M r r' phi'


def _polar_lagrangian() -> tuple[Laurent, dict[str, Laurent]]:
    """T = M (x'^2 + y'^2)/2 with x = r cos phi, y = r sin phi, in r, r', phi'."""
    r, c, s = Laurent.var("r"), Laurent.var("c"), Laurent.var("s")
    x, y = r * c, r * s
    xd, yd = time_derivative(x, _POLAR_RATES), time_derivative(y, _POLAR_RATES)
    kinetic = (Laurent.var("M") * (xd**2 + yd**2) / 2).reduce_trig("c", "s")
    return kinetic, {"x": x, "y": y}


def polar_mechanics() -> PolarMechanics:
    """Polar Jacobian, metric, Lagrangian, momenta and forces, derived exactly.

    J = d(x, y)/d(r, phi) by differentiation (angle derivatives with cos' = -sin, sin' = cos);
    K = J^-1 by the adjugate over det J (a single term, r); g = J^T J and g^-1 = K K^T, reduced
    with sin^2 = 1 - cos^2 (12.26), (12.30). T = M (x'^2 + y'^2)/2 becomes
    M r'^2/2 + M r^2 phi'^2/2 (12.32); p_r = dL/dr', p_phi = dL/dphi'; the Lagrange equations
    (12.25d) give dp_r/dt = dL/dr = M r phi'^2 - dU/dr (centrifugal) and
    dp_phi/dt = d(M r^2 phi')/dt = M r^2 phi'' + 2 M r r' phi' (Coriolis), (12.33).
    """
    kinetic, xy = _polar_lagrangian()
    cols = [
        [xy[k].diff("r") for k in ("x", "y")],
        [angle_derivative(xy[k], "c", "s") for k in ("x", "y")],
    ]
    jac = [[cols[m][j] for m in range(2)] for j in range(2)]  # jac[j][m] = dx^j/dq^m
    det = (jac[0][0] * jac[1][1] - jac[0][1] * jac[1][0]).reduce_trig("c", "s")
    inv_det = det.monomial_inverse()
    kaj = [
        [(jac[1][1] * inv_det).reduce_trig("c", "s"), (-jac[0][1] * inv_det).reduce_trig("c", "s")],
        [(-jac[1][0] * inv_det).reduce_trig("c", "s"), (jac[0][0] * inv_det).reduce_trig("c", "s")],
    ]
    metric = [
        [
            sum((jac[k][m] * jac[k][n] for k in range(2)), Laurent()).reduce_trig("c", "s")
            for n in range(2)
        ]
        for m in range(2)
    ]
    inverse = [
        [
            sum((kaj[m][j] * kaj[n][j] for j in range(2)), Laurent()).reduce_trig("c", "s")
            for n in range(2)
        ]
        for m in range(2)
    ]
    radial = kinetic.part("rd", 2)
    angular = kinetic.part("pd", 2)
    p_r = kinetic.diff("rd")
    p_phi = kinetic.diff("pd")
    centrifugal = kinetic.diff("r")
    p_phi_rate = time_derivative(p_phi, _POLAR_RATES)
    return PolarMechanics(
        jacobian_determinant_r_power=det.power("r"),
        metric_rr=metric[0][0].value(),
        metric_rphi=metric[0][1].value(),
        metric_phir=metric[1][0].value(),
        metric_phiphi_coefficient=metric[1][1].only_coefficient(),
        metric_phiphi_r_power=metric[1][1].power("r"),
        inverse_metric_rr=inverse[0][0].value(),
        inverse_metric_rphi=inverse[0][1].value(),
        inverse_metric_phir=inverse[1][0].value(),
        inverse_metric_phiphi_coefficient=inverse[1][1].only_coefficient(),
        inverse_metric_phiphi_r_power=inverse[1][1].power("r"),
        kinetic_radial_coefficient=radial.only_coefficient(),
        kinetic_angular_coefficient=angular.only_coefficient(),
        kinetic_angular_rate_power=angular.power("pd"),
        kinetic_angular_r_power=angular.power("r"),
        radial_momentum_coefficient=p_r.only_coefficient(),
        angular_momentum_r_power=p_phi.power("r"),
        centrifugal_rate_power=centrifugal.power("pd"),
        angular_momentum_rate_r_power=p_phi_rate.part("pdd", 1).power("r"),
        coriolis_coefficient=p_phi_rate.part("pdd", 0).only_coefficient(),
    )


@dataclass(frozen=True)
class PolarState:
    """Polar coordinates of a plane motion and their first and second time derivatives."""

    r: float
    phi: float
    rdot: float
    phidot: float
    rddot: float
    phiddot: float


def polar_state(
    position: Sequence[float], velocity: Sequence[float], acceleration: Sequence[float]
) -> PolarState:
    """(r, phi) and their rates from Cartesian position, velocity and acceleration, by the
    Kajobian (12.26): q' = K x', and q'' from differentiating q' = K x' once more."""
    x, y = (inputs.real(v, "position") for v in position)
    vx, vy = velocity
    ax, ay = acceleration
    r = math.hypot(x, y)
    if r == 0:
        raise ValueError("polar coordinates are singular at r = 0")
    phi = math.atan2(y, x)
    rdot = (x * vx + y * vy) / r
    phidot = (x * vy - y * vx) / r**2
    rddot = (vx**2 + vy**2 + x * ax + y * ay) / r - rdot**2 / r
    phiddot = (x * ay - y * ax) / r**2 - 2 * rdot * phidot / r
    return PolarState(r, phi, rdot, phidot, rddot, phiddot)


@dataclass(frozen=True)
class PolarForces:
    """Terms of the polar Lagrange equations (12.33) at one state, from the exact Lagrangian."""

    radial_momentum: float  # p_r = M r'
    angular_momentum: float  # p_phi = M r^2 phi'
    radial_momentum_rate: float  # d p_r / dt = M r''
    centrifugal: float  # dT/dr = M r phi'^2
    angular_momentum_rate: float  # d p_phi / dt = M r^2 phi'' + 2 M r r' phi'
    coriolis: float  # 2 M r r' phi'


def polar_forces(mass: Any, state: PolarState) -> PolarForces:
    """Evaluate the derived polar momenta and forces (12.32)-(12.33) at a state."""
    inputs.mass(mass)
    kinetic, _ = _polar_lagrangian()
    p_r, p_phi = kinetic.diff("rd"), kinetic.diff("pd")
    values = {
        "M": mass,
        "r": state.r,
        "rd": state.rdot,
        "pd": state.phidot,
        "rdd": state.rddot,
        "pdd": state.phiddot,
    }
    p_phi_rate = time_derivative(p_phi, _POLAR_RATES)
    return PolarForces(
        radial_momentum=p_r.evaluate(values),
        angular_momentum=p_phi.evaluate(values),
        radial_momentum_rate=time_derivative(p_r, _POLAR_RATES).evaluate(values),
        centrifugal=kinetic.diff("r").evaluate(values),
        angular_momentum_rate=p_phi_rate.evaluate(values),
        coriolis=p_phi_rate.part("pdd", 0).evaluate(values),
    )


def euler_lagrange_residual(
    mass: Any, state: PolarState, potential_gradient: Sequence[float]
) -> tuple[float, float]:
    """Residuals d/dt(dL/dq') - dL/dq of the polar Lagrange equations (12.25c) for
    L = T - U(r, phi), with (dU/dr, dU/dphi) given: zero along a true motion."""
    f = polar_forces(mass, state)
    du_dr, du_dphi = potential_gradient
    return (
        f.radial_momentum_rate - (f.centrifugal - du_dr),
        f.angular_momentum_rate - (0 - du_dphi),
    )


def polar_hamiltonian(
    mass: Any, r: Any, radial_momentum: Any, angular_momentum: Any, potential: Any = 0
) -> Any:
    """H = p_r^2/(2M) + p_phi^2/(2 M r^2) + U = g^mn p_m p_n /(2M) + U (12.37c), with the
    polar inverse metric diag(1, 1/r^2)."""
    inputs.mass(mass)
    inputs.positive(r, "r")
    g = polar_inverse_metric(r)
    p = (radial_momentum, angular_momentum)
    return sum(g[m][n] * p[m] * p[n] for m in range(2) for n in range(2)) / (2 * mass) + potential


@dataclass(frozen=True)
class QuadraticExtremum:
    """For S(q) = q^2 + b q (line 15831): dS/dq = slope q + constant, zero at ``point``."""

    slope: Fraction
    constant: Fraction
    point: Fraction


def quadratic_extremum(linear_coefficient: Any) -> QuadraticExtremum:
    """dS/dq of S = q^2 + b q by the power rule, and the q where it vanishes (line 15832:
    S = q^2 - 4q gives dS/dq = 2q - 4, zero at q = 2). Exact."""
    b = Fraction(inputs.real(linear_coefficient, "linear_coefficient"))
    q = Laurent.var("q")
    derivative = (q**2 + b * q).diff("q")
    slope, constant = derivative.part("q", 1).only_coefficient(), derivative.part("q", 0).value()
    return QuadraticExtremum(slope=slope, constant=constant, point=-constant / slope)


def gradient_potential(matrix: Sequence[Sequence[Any]], vector: Sequence[Any]) -> Any:
    """The scalar F(v) whose gradient dF/dv^j is M_ij v^i, with F(0) = 0, for a symmetric
    matrix M (line 15022): by the line integral F(v) = integral_0^1 (M.(t v)).v dt, done
    exactly in t. Its q-derivative dF/dq is M_ij v^i dv^j/dq, the step from (12.24) to
    Lagrange's form (12.25a). Exact for ``int`` and ``Fraction``; ``ValueError`` for a matrix
    that is not square and symmetric (then no such F exists).
    """
    n = len(vector)
    if len(matrix) != n or any(len(row) != n for row in matrix):
        raise ValueError("need an n x n matrix and an n-vector")
    for i in range(n):
        for j in range(i):
            if matrix[i][j] != matrix[j][i]:
                raise ValueError("the field M.v has a potential only for a symmetric M")
    t = Laurent.var("t")
    names = {f"v{i}": vector[i] for i in range(n)}
    names.update({f"m{i}_{j}": matrix[i][j] for i in range(n) for j in range(n)})
    field_dot_v = sum(
        (
            Laurent.var(f"m{i}_{j}") * t * Laurent.var(f"v{i}") * Laurent.var(f"v{j}")
            for i in range(n)
            for j in range(n)
        ),
        Laurent(),
    )
    form = field_dot_v.integrate("t").substitute("t", 1)
    total: Any = 0
    for key, c in form.terms.items():  # the Fraction times the values: exact where they are
        term: Any = c
        for name, e in key:
            term = term * names[name] ** e
        total = total + term
    return total


def metric_kinetic_energy(mass: Any, metric: Sequence[Sequence[Any]], rates: Sequence[Any]) -> Any:
    """Kinetic energy of one particle moving at the generalized velocities q' in coordinates
    of covariant metric g (12.31), J or scaled: any Jacobian J with J^T J = g gives the same
    Cartesian speed, so take the Cholesky factor of g (upper triangular, positive diagonal),
    form the Cartesian velocity v = J q' (12.19) and T = M v.v/2 (12.23). ``ValueError`` for a
    metric that is not symmetric and positive definite. Floats."""
    inputs.mass(mass)
    n = len(rates)
    if len(metric) != n or any(len(row) != n for row in metric):
        raise ValueError("need an n x n metric and n rates")
    g = [[float(inputs.real(x, "metric")) for x in row] for row in metric]
    q = [float(inputs.real(x, "rate")) for x in rates]
    if any(g[i][j] != g[j][i] for i in range(n) for j in range(i)):
        raise ValueError("a metric is symmetric")
    factor = [[0.0] * n for _ in range(n)]  # factor[i][j], i <= j: g = factor^T factor
    for i in range(n):
        pivot = g[i][i] - sum(factor[k][i] ** 2 for k in range(i))
        if pivot <= 0:
            raise ValueError("a metric is positive definite")
        diagonal = factor[i][i] = math.sqrt(pivot)
        for j in range(i + 1, n):
            rest = g[i][j] - sum(factor[k][i] * factor[k][j] for k in range(i))
            factor[i][j] = rest / diagonal
    velocity = [sum(factor[i][j] * q[j] for j in range(n)) for i in range(n)]
    return kinetic_energy([mass] * n, velocity)


def polar_lagrangian(
    mass: Any, r: Any, rdot: Any, phidot: Any, potential: Any = 0, phi: Any = 0
) -> Any:
    """L = T - U (12.25b) of a particle at polar (r, phi) moving at rates (r', phi'): the
    Cartesian velocity is J.q' by the polar Jacobian (12.19), (12.26), and
    T = M (vx^2 + vy^2)/2 (12.23). Floats (the Jacobian takes the cosine and sine)."""
    j = polar_jacobian(r, phi)
    velocity = [j[k][0] * rdot + j[k][1] * phidot for k in range(2)]
    return kinetic_energy([mass, mass], velocity) - potential


def polar_terms(
    mass: Any, r: Any, rdot: Any, phidot: Any, rddot: Any = 0, phiddot: Any = 0
) -> PolarForces:
    """The polar momenta and forces of (12.32)-(12.33), ``polar_forces``, at a state given by
    its polar coordinate rates (the angle itself does not enter)."""
    for value, name in ((rdot, "rdot"), (phidot, "phidot"), (rddot, "rddot"), (phiddot, "phiddot")):
        inputs.real(value, name)
    inputs.positive(r, "r")
    return polar_forces(mass, PolarState(r, 0.0, rdot, phidot, rddot, phiddot))


@dataclass(frozen=True)
class PolarGeneralizedForces:
    """dL/dq of the polar Lagrangian L = T - U: the right sides dp_m/dt of (12.25d), (12.33)."""

    radial: Any  # dL/dr = M r phi'^2 - dU/dr
    angular: Any  # dL/dphi = -dU/dphi


def polar_generalized_forces(
    mass: Any, r: Any, rdot: Any, phidot: Any, du_dr: Any, du_dphi: Any = 0
) -> PolarGeneralizedForces:
    """dL/dr and dL/dphi of L = T - U(r, phi) in polar coordinates (12.33): the kinetic part
    differentiated exactly (the centrifugal term of ``polar_terms``), minus the potential's
    gradient (dU/dr, dU/dphi)."""
    inputs.real(du_dr, "du_dr")
    inputs.real(du_dphi, "du_dphi")
    terms = polar_terms(mass, r, rdot, phidot)
    return PolarGeneralizedForces(radial=terms.centrifugal - du_dr, angular=0 - du_dphi)


@dataclass(frozen=True)
class CoordinateHamiltonian:
    """H = p q' - L (12.36a) of L = M g q'^2/2 - U in one generalized coordinate of metric g,
    with the rate q' and the momentum p = dL/dq' (12.25e) that go with it."""

    rate: Any
    momentum: Any
    hamiltonian: Any


def _coordinate_lagrangian() -> Laurent:
    """L = T - U with T = M g q'^2/2 (12.31) for one coordinate, in M, g, qd = q' and U."""
    m, g, qd, u = (Laurent.var(n) for n in ("M", "g", "qd", "U"))
    return m * g * qd**2 / 2 - u


def hamiltonian_of_rate(mass: Any, metric: Any, rate: Any, potential: Any) -> CoordinateHamiltonian:
    """H = p q' - L (12.36a) at the rate q' (12.37a-b): p = dL/dq' by differentiating L
    exactly, then the Legendre form evaluated. Exact for ``int`` and ``Fraction``."""
    inputs.mass(mass)
    inputs.positive(metric, "metric")
    inputs.real(rate, "rate")
    inputs.real(potential, "potential")
    lag = _coordinate_lagrangian()
    momentum = lag.diff("qd")
    values = {"M": mass, "g": metric, "qd": rate, "U": potential}
    p = momentum.evaluate(values)
    return CoordinateHamiltonian(rate=rate, momentum=p, hamiltonian=p * rate - lag.evaluate(values))


def hamiltonian_of_momentum(
    mass: Any, inverse_metric: Any, momentum: Any, potential: Any
) -> CoordinateHamiltonian:
    """H = p q' - L (12.37c) at the momentum p, for the coordinate whose contravariant metric
    is g^11 = ``inverse_metric`` (so g = 1/g^11): p = dL/dq' is linear in q', so q' is p over
    its slope d p/d q'; then H = p q' - L(q'). Exact for ``int`` and ``Fraction``."""
    inputs.mass(mass)
    inputs.positive(inverse_metric, "inverse_metric")
    inputs.real(momentum, "momentum")
    inputs.real(potential, "potential")
    metric = 1 / (Fraction(inverse_metric) if isinstance(inverse_metric, int) else inverse_metric)
    lag = _coordinate_lagrangian()
    p_of_rate = lag.diff("qd")
    if p_of_rate.part("qd", 0).terms:
        raise ValueError("p = dL/dq' has a part free of q'")
    values = {"M": mass, "g": metric, "U": potential}
    rate = momentum / p_of_rate.diff("qd").evaluate(values)
    values["qd"] = rate
    return CoordinateHamiltonian(
        rate=rate, momentum=momentum, hamiltonian=momentum * rate - lag.evaluate(values)
    )


def quadratic_function_slope(point: Any, linear_coefficient: Any) -> Any:
    """dS/dq at q of S(q) = q^2 + b q (line 15832: S = q^2 - 4q), by the power rule on the
    exact polynomial, evaluated at ``point``. Exact for ``int`` and ``Fraction``."""
    b = Fraction(inputs.real(linear_coefficient, "linear_coefficient"))
    inputs.real(point, "point")
    q = Laurent.var("q")
    return (q**2 + b * q).diff("q").evaluate({"q": point})


# -------------------------------------------------------------------------------------------
# Action, phase and Bohr quantization: (12.38)-(12.48), Figs. 12.12-12.15
# -------------------------------------------------------------------------------------------


def action_sum(legs: Sequence[Any]) -> Any:
    """Action accumulated along a path made of legs, J s: the sum of the legs' actions (Fig.
    12.12: 10 to the first wave front and 10 more to the wavelet around it make 20)."""
    return sum(inputs.real(a, "action") for a in legs)


def path_action(lagrangian_values: Sequence[float], times: Sequence[float]) -> float:
    """Action S = integral L dt (12.38) of a sampled path by the trapezoid rule, J s."""
    lv, t = np.asarray(lagrangian_values, float), np.asarray(times, float)
    if lv.shape != t.shape or lv.ndim != 1 or lv.size < 2:
        raise ValueError("need matching 1-D samples of L and t, at least two")
    return float(np.sum((lv[1:] + lv[:-1]) * np.diff(t)) / 2)


def phase_turn() -> float:
    """The phase angle after which e^(i theta) first returns to 1: 2 pi, twice the angle of
    -1 (a full colour circle of Fig. 12.13)."""
    return 2 * cmath.phase(-1)


def bohr_phase(quantum_number: Any) -> float:
    """Phase S_H/hbar of a Bohr-quantized closed loop, 2 pi upsilon (12.45)."""
    n = inputs.count(quantum_number, "quantum_number")
    return phase_turn() * n


def phase_factor(angle: Any) -> complex:
    """The quantum phase factor e^(i angle) (12.42c); 1 after a whole number of turns (12.45)."""
    return cmath.exp(1j * inputs.real(angle, "angle"))


@dataclass(frozen=True)
class PhaseFactorParts:
    real: float
    imag: float


def phase_factor_parts(angle: Any) -> PhaseFactorParts:
    """Real and imaginary parts of e^(i angle): the standing-wave amplitude of a phase."""
    z = phase_factor(angle)
    return PhaseFactorParts(real=z.real, imag=z.imag)


def palette_phase(step: Any, colours: Any) -> float:
    """Phase angle of hue ``step`` on a colour circle of ``colours`` equal hues:
    2 pi step / colours (line 16324: eight hues from red at 0 through pi/4 steps)."""
    k = inputs.count(step, "step")
    n = inputs.count(colours, "colours", minimum=1)
    return phase_turn() * k / n


def palette_amplitude(step: Any, colours: Any) -> float:
    """Real standing-wave amplitude cos(phase) of hue ``step`` (red 1, cyan -1: line 16340)."""
    return phase_factor_parts(palette_phase(step, colours)).real


@dataclass(frozen=True)
class OscillatorPaths:
    """Sampled trajectories of a 2-D isotropic oscillator and their accumulated reduced
    action S_H(t) = integral p . dr (12.46), for phase colouring."""

    times: np.ndarray
    x: np.ndarray  # shape (paths, samples)
    y: np.ndarray
    action: np.ndarray


def oscillator_paths(
    start: Sequence[float],
    speed: float,
    angles: Iterable[float],
    duration: float,
    samples: int = 400,
    omega: float = 1,
    mass: float = 1,
) -> OscillatorPaths:
    """Paths r(t) = r0 cos(w t) + (v0/w) sin(w t) of the oscillator U = M w^2 r^2/2 from one
    point with one speed in several directions (the starlet blast of exercise 1.12.3), and
    S_H = integral p . v dt along each by the trapezoid rule."""
    inputs.positive(speed, "speed")
    inputs.positive(duration, "duration")
    inputs.positive(omega, "omega")
    inputs.mass(mass)
    n = inputs.count(samples, "samples", minimum=2)
    t = np.linspace(0.0, duration, n)
    xs, ys, acts = [], [], []
    for a in angles:
        vx, vy = speed * math.cos(a), speed * math.sin(a)
        x = start[0] * np.cos(omega * t) + vx / omega * np.sin(omega * t)
        y = start[1] * np.cos(omega * t) + vy / omega * np.sin(omega * t)
        ux = -start[0] * omega * np.sin(omega * t) + vx * np.cos(omega * t)
        uy = -start[1] * omega * np.sin(omega * t) + vy * np.cos(omega * t)
        integrand = mass * (ux**2 + uy**2)
        s = np.concatenate([[0.0], np.cumsum((integrand[1:] + integrand[:-1]) * np.diff(t) / 2)])
        xs.append(x)
        ys.append(y)
        acts.append(s)
    return OscillatorPaths(times=t, x=np.array(xs), y=np.array(ys), action=np.array(acts))


# -------------------------------------------------------------------------------------------
# Exercise 1.12.3: the starlet blast
# -------------------------------------------------------------------------------------------


def common_speed(velocities: Sequence[Sequence[Any]]) -> float:
    """The speed |v| shared by all the listed velocity vectors (exercise 1.12.3: fragments
    flying off with one speed in various directions); ``ValueError`` if they differ."""
    speeds = [math.hypot(*(float(inputs.real(c, "component")) for c in v)) for v in velocities]
    if not speeds:
        raise ValueError("no velocities")
    if max(speeds) - min(speeds) > 1e-9 * max(speeds):
        raise ValueError(f"the velocities have different speeds {speeds}")
    return sum(speeds) / len(speeds)


def turning_sequence(
    first: Sequence[Any], second: Sequence[Any], index: Any
) -> tuple[float, float]:
    """The plane vector number ``index`` (0 for ``first``) of the sequence that starts with
    ``first`` and ``second`` and turns (and scales) each next vector from the last as
    ``second`` is turned from ``first``: first * (second / first)^index as complex numbers
    (exercise 1.12.3 lists unit velocities 45 degrees apart). Floats."""
    k = inputs.count(index, "index")
    a = complex(*(float(inputs.real(c, "component")) for c in first))
    b = complex(*(float(inputs.real(c, "component")) for c in second))
    if a == 0:
        raise ValueError("the first vector must be non-zero")
    z = a * (b / a) ** k
    return z.real, z.imag


# -------------------------------------------------------------------------------------------
# helpers
# -------------------------------------------------------------------------------------------


def _same_length(a: Sequence[Any], b: Sequence[Any]) -> None:
    if len(a) != len(b):
        raise ValueError("one velocity (or momentum) per mass")


def _lib(*values: Any) -> Any:
    import mpmath

    return mpmath if any(isinstance(v, mpmath.mpf) for v in values) else math


def _sqrt(x: Any) -> Any:
    return _lib(x).sqrt(x)


def _power(x: Any, e: Fraction) -> Any:
    """x**e: exact for a Fraction x and an integer e, else through float (or mpmath)."""
    if e.denominator == 1:
        return x ** int(e)
    return x ** float(e) if not isinstance(x, Fraction | int) else float(x) ** float(e)
