"""Force, potential energy and action from bangs (chapter 6).

A big ball m1 (or a "monster" wall M1) closes on a tiny ball m2 that bounces to and fro between
it and a fixed wall (Fig. 6.1). Averaged over many bangs the tiny ball acts on m1 like a force
field: the bang rate times the momentum each bang transfers. If a "Robin Hood" in the ceiling
keeps m2's speed fixed (isothermal) the force goes as 1/Y (6.4); if every bang is elastic and
m2 keeps what it gains (adiabatic) it goes as 1/Y^3 (6.5). The module holds those laws, their
potentials (6.6)-(6.11), the two-gas oscillator (6.12), power-law potentials, the period of an
oscillation in a symmetric power-law well, the toss (6.13), and the bang sequences of Figs. 6.4
and 6.5 (the trapped ball and the monster pair).

Conventions: Y is the gap between m1 and the wall (m), positive away from the wall; a force is
the physicist's force on m1, F_phys = -dU/dY (6.9), positive away from the wall; speeds are
magnitudes, velocities are signed. Units are SI or the book's scaled units, consistently.
Functions use plain operators, so Fraction inputs stay exact where only + - * / are involved.
Slopes of analytic functions are taken by the complex step (f(x + i h) has imaginary part
h f'(x) to rounding), so they are as accurate as the function itself; local powers (log-slopes)
of force laws by a central difference in ln x, exact to rounding for a pure power law.
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import TypeVar, cast, overload

from mechmodel import inputs
from mechmodel.algebra import polynomial_integral
from mechmodel.collisions import collide
from mechmodel.numeric import complex_step_derivative, log_slope
from mechmodel.typing import Real, Scalar, Symbolic, Vector

RealOrComplex = TypeVar("RealOrComplex", Real, complex)  # complex under the complex step
_CHEBYSHEV_NODES = 64  # Gauss-Chebyshev nodes of the period integral (exact for the harmonic well)


@overload
def _ln(x: Real) -> float: ...
@overload
def _ln(x: complex) -> complex: ...
def _ln(x: Scalar) -> Scalar:
    """Natural logarithm of a real or complex number (complex for the complex step)."""
    return cmath.log(x) if isinstance(x, complex) else math.log(x)


# --- bang rate and the bounce off a moving wall, (6.1)-(6.3), Fig. 6.2 -----------------------
def bang_period(gap: Real, speed: Real) -> Real:
    """Time between m2's bangs on m1, s: out across the gap Y and back, 2Y / v2 (6.1a).

    m1 is taken as still (v1 << v2): the little ball crosses the gap twice per round trip.
    Exact with Fraction inputs; the 2 of (6.1a) is ``bang_period(1, 1)``.
    """
    inputs.positive(gap, "gap")
    inputs.positive(speed, "speed")
    out = gap / speed
    back = gap / speed
    return out + back


def bang_rate(gap: Real, speed: Real) -> Real:
    """Bangs per second on m1, B = 1 / period = v2 / 2Y (6.1b)."""
    return 1 / bang_period(gap, speed)


def moving_wall_bounce(v_wall: Real, speed: Real) -> Real:
    """Speed of m2 after a head-on bang with a wall (m1 >> m2) closing at ``v_wall`` (6.2).

    m2 arrives at velocity -``speed``; the infinite mass keeps its velocity and m2 leaves at
    v_wall + (v_wall + speed) = speed + 2 v_wall (``collisions.collide`` with an infinite m1).
    """
    inputs.real(v_wall, "v_wall")
    inputs.real(speed, "speed")
    return collide(math.inf, 1, v_wall, -speed).v2


def wall_speed_gain(v_wall: Real, speed: Real) -> Real:
    """Speed m2 gains per bang in units of the wall's speed, (v2FIN - v2) / v1 (6.2).

    The 2 of v2FIN = v2 + 2 v1 and of the monster's "twice its speed (2V1)" (Fig. 6.6a).
    """
    inputs.positive(v_wall, "v_wall")
    return (moving_wall_bounce(v_wall, speed) - speed) / v_wall


def bang_momentum_transfer(m2: Real, speed: Real, v_wall: Real) -> Real:
    """Momentum one bang gives m2 (and takes from m1), kg m/s: m2 v2FIN - (-m2 v2) (6.3).

    = 2 m2 v2 + 2 m2 v1: the coefficients of m2 v2 and of m2 v1 are the transfers at unit
    m2 with (speed, v_wall) = (1, 0) and (0, 1).
    """
    inputs.mass(m2, "m2")
    return m2 * moving_wall_bounce(v_wall, speed) - (-m2 * speed)


def speed_gain_rate(v_wall: Real, rate: Real) -> Real:
    """Rate at which m2's speed grows, m/s^2: the speed one bang with the closing wall adds
    (``moving_wall_bounce``, the same whatever m2's speed) times the bangs per second, ``rate``
    (6.5a): dv2/dt = 2 v1 B."""
    inputs.real(rate, "rate")
    gain = moving_wall_bounce(v_wall, 0)  # m2 met at rest leaves with just the gain
    return gain * rate


def adiabatic_speed_growth(v_wall: Real, speed: Real, gap: Real) -> Real:
    """dv2/dt of m2 between a wall closing at ``v_wall`` and the fixed wall at gap Y, m/s^2:
    the gain per bang at the bang rate of (6.1b), 2 v1 v2 / 2Y (6.5a)-(6.5b)."""
    return speed_gain_rate(v_wall, bang_rate(gap, speed))


def thermal_speed(mass: Real, temperature: Real, boltzmann: Real) -> float:
    """Speed of a one-dimensional gas atom of ``mass`` at ``temperature``, m/s, with the book's
    KE = k T of (6.4): 1/2 m v^2 = k T, v = sqrt(2 k T / m) (the "typical atomic speeds")."""
    inputs.mass(mass, "mass")
    inputs.positive(temperature, "temperature")
    inputs.positive(boltzmann, "boltzmann")
    return math.sqrt(2 * boltzmann * temperature / mass)


# --- force laws: isothermal 1/Y (6.4), adiabatic 1/Y^3 (6.5), their potentials --------------
@dataclass(frozen=True)
class ForceLaw:
    """A bang-force law at one gap: the force on m1 and its local powers.

    ``force`` on m1, N (positive: pushing m1 away from the wall); ``inverse_power`` n of
    F ~ 1/Y^n and ``gap_exponent`` = -n (F ~ Y^p, the p of F = k y^p); ``speed_exponent`` k of
    F ~ v^k for the speed that sets the law (m2's speed, or the v0 of the adiabatic constant
    v0 Y0); ``force_gap_per_energy`` is F Y / KE2, the 2 of F = 2 KE / Y.
    """

    force: Real
    inverse_power: float
    gap_exponent: float
    speed_exponent: float
    force_gap_per_energy: Real


def _law(force: Callable[[Real, Real], Real], gap: Real, speed: Real, energy: Real) -> ForceLaw:
    """ForceLaw of ``force(gap, speed)`` at (gap, speed); ``energy`` is m2's kinetic energy."""
    value = force(gap, speed)
    power = log_slope(lambda y: force(y, speed), gap)
    return ForceLaw(
        force=value,
        inverse_power=-power,
        gap_exponent=power,
        speed_exponent=log_slope(lambda v: force(gap, v), speed),
        force_gap_per_energy=value * gap / energy,
    )


def _isothermal(m2: Real, speed: Real, gap: Real) -> Real:
    """Bang rate times momentum per bang, on a slow m1: 2 m2 v2 times v2 / 2Y."""
    return bang_momentum_transfer(m2, speed, 0) * bang_rate(gap, speed)


def isothermal_force(m2: Real, speed: Real, gap: Real) -> ForceLaw:
    """Isothermal bang force on m1, F = B dP = m2 v2^2 / Y (6.4), and its local powers.

    m2 keeps its speed v2 whatever m1 does (the ceiling's "Robin Hood" holds its energy, the
    temperature, fixed); each bang on the slow m1 transfers 2 m2 v2 at the rate v2 / 2Y.
    """
    inputs.mass(m2, "m2")
    inputs.positive(speed, "speed")
    inputs.positive(gap, "gap")
    energy = m2 * speed * speed / 2
    return _law(lambda y, v: _isothermal(m2, v, y), gap, speed, energy)


def isothermal_force_of_energy(energy: Real, gap: Real, m2: Real = 1) -> Real:
    """Isothermal bang force on m1, N, when m2 has kinetic energy ``energy`` (6.4).

    m2 of any mass ``m2`` moving at the speed that gives it that energy, sqrt(2 KE / m2),
    pushes with bang rate times momentum per bang: the force depends on m2 and v2 only through
    KE (F = 2 KE / Y).
    """
    inputs.positive(energy, "energy")
    inputs.mass(m2, "m2")
    inputs.positive(gap, "gap")
    speed = math.sqrt(2 * energy / m2)
    return _isothermal(m2, speed, gap)


def thermal_kinetic_energy(boltzmann: Real, temperature: Real) -> Real:
    """Mean kinetic energy of an atom moving in one dimension in equilibrium at temperature T,
    J: k T / 2, by equipartition (each quadratic term of the energy, here 1/2 m v^2, holds
    k T / 2 on average), with k Boltzmann's constant."""
    inputs.positive(boltzmann, "boltzmann")
    inputs.positive(temperature, "temperature")
    return boltzmann * temperature / 2


def isothermal_gas_law(boltzmann: Real, temperature: Real, gap: Real) -> Real:
    """F Y of the one-atom gas at temperature T, J: the bang force (6.4) of an atom with the
    thermal kinetic energy, times the gap; the 1-D ideal gas law P V = N k T for N = 1 (the
    product does not depend on the gap)."""
    energy = thermal_kinetic_energy(boltzmann, temperature)
    return isothermal_force_of_energy(energy, gap) * gap


def isothermal_potential(m2: Real, speed: Real, gap: Real) -> Real:
    """Isothermal potential of m1, U = -m2 v2^2 ln Y (6.11), J (zero at Y = 1 unit).

    Its force -dU/dY = m2 v2^2 / Y is the isothermal law (6.4): see
    ``isothermal_potential_force``.
    """
    inputs.mass(m2, "m2")
    inputs.positive(speed, "speed")
    inputs.positive(gap, "gap")
    return -m2 * speed * speed * _ln(gap)


def isothermal_potential_force(m2: Real, speed: Real, gap: Real) -> ForceLaw:
    """The force -dU/dY of the isothermal potential (6.11), with its local powers."""
    inputs.mass(m2, "m2")
    inputs.positive(speed, "speed")
    inputs.positive(gap, "gap")

    def force(y: Real, v: Real) -> float:
        return -complex_step_derivative(lambda g: -m2 * v * v * _ln(g), y)

    return _law(force, gap, speed, m2 * speed * speed / 2)


def adiabatic_speed(v0: Real, y0: Real, gap: Real) -> Real:
    """Speed of m2 once the gap has closed from Y0 to Y, adiabatic (6.5b): v2 = v0 Y0 / Y.

    Each bang adds 2 v1 at the rate v2 / 2Y while Y shrinks at v1 (6.5a): dv2 / v2 = -dY / Y,
    so v2 Y stays constant (the action of Fig. 6.4, see ``trapped_ball``).
    """
    inputs.positive(v0, "v0")
    inputs.positive(y0, "y0")
    inputs.positive(gap, "gap")
    return v0 * y0 / gap


def _adiabatic(m2: Real, v0: Real, y0: Real, gap: Real) -> Real:
    speed = v0 * y0 / gap
    return m2 * speed * speed / gap  # the bang force m2 v2^2 / Y at the current speed


def _adiabatic_potential(m2: Real, v0: Real, y0: Real, gap: RealOrComplex) -> RealOrComplex:
    speed = v0 * y0 / gap
    return m2 * speed * speed / 2  # m2's kinetic energy, lent by m1 (6.7)


def adiabatic_force(m2: Real, v0: Real, y0: Real, gap: Real) -> ForceLaw:
    """Adiabatic bang force on m1 at gap Y, F = m2 v2^2 / Y = m2 (v0 Y0)^2 / Y^3 (6.5b).

    ``speed_exponent`` is the power of v0, hence of the constant v0 Y0 ("const." of (6.5b)).
    """
    inputs.mass(m2, "m2")
    speed = adiabatic_speed(v0, y0, gap)
    return _law(lambda y, v: _adiabatic(m2, v, y0, y), gap, v0, m2 * speed * speed / 2)


def adiabatic_potential(m2: Real, v0: Real, y0: Real, gap: Real) -> Real:
    """m1's potential energy at gap Y, J: m2's kinetic energy 1/2 m2 (v0 Y0 / Y)^2 (6.7)."""
    inputs.mass(m2, "m2")
    adiabatic_speed(v0, y0, gap)
    return _adiabatic_potential(m2, v0, y0, gap)


def adiabatic_potential_force(m2: Real, v0: Real, y0: Real, gap: Real) -> ForceLaw:
    """The force -dU/dY of the adiabatic potential (6.7), with its local powers (6.10).

    "It checks!!": the slope is taken of the potential itself, and equals the bang force (6.5b).
    """
    inputs.mass(m2, "m2")
    speed = adiabatic_speed(v0, y0, gap)

    def force(y: Real, v: Real) -> float:
        return -complex_step_derivative(lambda g: _adiabatic_potential(m2, v, y0, g), y)

    return _law(force, gap, v0, m2 * speed * speed / 2)


def kinetic_energy_factor(m2: Real, v0: Real, y0: Real, gap: Real) -> float:
    """The factor c that makes U = c m2 v2^2 the potential of the adiabatic bang force.

    Bang force (6.5b) over -d(m2 v2^2)/dY: the 1/2 of the kinetic energy that "F = -dU/dY needs"
    (after (6.10)).
    """
    inputs.mass(m2, "m2")
    adiabatic_speed(v0, y0, gap)
    bare = -complex_step_derivative(lambda g: m2 * (v0 * y0 / g) * (v0 * y0 / g), gap)
    return _adiabatic(m2, v0, y0, gap) / bare


# --- two gases: the oscillator (6.12), harmonic period, power-law potentials ---------------
@dataclass(frozen=True)
class OpposedSeries:
    """Taylor coefficients in x of the two opposed isothermal forces on m1 (before (6.12)).

    With unit force constant f: ``left`` of f / (Y + x) (the gas behind m1, its space grown to
    Y + x), ``right`` of f / (Y - x) (the gas ahead, its space shrunk), ``total`` of their
    difference, F_total = f / (Y + x) - f / (Y - x); index = power of x. ``total_magnitudes``
    are the sizes of the total's coefficients (the book prints their minus signs as operators);
    ``spring_per_force_constant`` is k / f = -total[1], the 2 of k = 2f.
    """

    left: tuple[Real, ...]
    right: tuple[Real, ...]
    total: tuple[Real, ...]
    total_magnitudes: tuple[Real, ...]
    spring_per_force_constant: Real


def _reciprocal_series(gap: Real, sign: int, order: int) -> list[Real]:
    """Coefficients of 1 / (gap + sign x) up to x^order: c0 = 1/gap, c_n = -sign c_(n-1)/gap."""
    out: list[Real] = [1 / gap]
    for _ in range(order):
        out.append(-sign * out[-1] / gap)
    return out


def opposed_isothermal_series(order: int, gap: Real = 1) -> OpposedSeries:
    """Expansion of F_total = f/(Y + x) - f/(Y - x) to ``order`` in x, f = 1 (before (6.12)).

    Only odd powers survive ("only x^2, x^4, ... terms cancel"): -2 f x / Y^2 - 2 f x^3 / Y^4 ...
    Exact with Fraction ``gap`` (or integer gap: the coefficients are then Fractions only if the
    gap is a Fraction; an int gap of 1 gives exact integers as floats).
    """
    n = inputs.count(order, "order", minimum=1)
    inputs.positive(gap, "gap")
    left = _reciprocal_series(gap, 1, n)
    right = _reciprocal_series(gap, -1, n)
    total = [a - b for a, b in zip(left, right, strict=True)]
    return OpposedSeries(
        tuple(left), tuple(right), tuple(total), tuple(cast(Real, abs(c)) for c in total), -total[1]
    )


@dataclass(frozen=True)
class OpposedForces:
    """The two opposed isothermal forces on m1 displaced x, as Taylor polynomials in x to a
    given order (before (6.12)): ``left`` of f / (Y + x), ``right`` of f / (Y - x) and
    ``total`` of their difference F_total, each evaluated at x (with the force constant f)."""

    left: Symbolic
    right: Symbolic
    total: Symbolic


def opposed_isothermal_forces(
    force_constant: Symbolic, x: Symbolic, order: int, gap: Real = 1
) -> OpposedForces:
    """The series of ``opposed_isothermal_series`` to ``order``, times f and summed at x.

    Plain operators: sympy symbols for f and x give the polynomials themselves.
    """
    series = opposed_isothermal_series(order, gap)

    def value(coefficients: Vector) -> Symbolic:
        return sum(force_constant * c * x**k for k, c in enumerate(coefficients))

    return OpposedForces(value(series.left), value(series.right), value(series.total))


def opposed_spring_constant(force_constant: Real, gap: Real) -> float:
    """Spring constant of m1 between two isothermal gases of force constant f, N/m.

    Each side pushes with f / (its space), the left one at Y + x and the right one at Y - x;
    k = -dF_total/dx at x = 0, 2 f / Y^2 (6.12).
    """
    inputs.positive(force_constant, "force_constant")
    inputs.positive(gap, "gap")
    f = force_constant
    return -complex_step_derivative(lambda x: f / (gap + x) - f / (gap - x), 0)


def isothermal_spring_constant(m2: Real, speed: Real, gap: Real) -> float:
    """Spring constant of m1 between two isothermal gases, k = -dF_total/dx at x = 0, N/m.

    Each side pushes with f / (its space), f = m2 v2^2 (6.11); k = 2 f / Y^2 (6.12).
    """
    inputs.mass(m2, "m2")
    inputs.positive(speed, "speed")
    inputs.positive(gap, "gap")
    return opposed_spring_constant(m2 * speed * speed, gap)


def hooke_potential(k: Real, x: Real) -> Real:
    """Potential of the linear force F = -k x, U = -integral_0^x F dx = k x^2 / 2 (6.12).

    Integrated term by term, so Fraction inputs give the exact 1/2.
    """
    inputs.real(k, "k")
    inputs.real(x, "x")
    return -polynomial_integral([0, -k], x)


def oscillation_period(mass: Real, strength: Real, power: Real, amplitude: Real) -> float:
    """Period of an oscillation of amplitude A in the symmetric well U = strength |x|^power, s.

    T = 2 integral_{-A}^{A} dx / v(x), v = sqrt(2 (U(A) - U(x)) / m). Writing
    U(A) - U(x) = (A^2 - x^2) w(x) leaves the Chebyshev weight 1 / sqrt(A^2 - x^2), so
    Gauss-Chebyshev quadrature (nodes x_i = A cos((2i - 1) pi / 2n), weights pi / n) gives the
    integral; it is exact for the harmonic well (w constant) and converges fast for smooth wells.
    """
    inputs.mass(mass, "mass")
    inputs.positive(strength, "strength")
    inputs.positive(power, "power")
    inputs.positive(amplitude, "amplitude")
    a, p, k = float(amplitude), float(power), float(strength)
    n = _CHEBYSHEV_NODES
    terms = []
    for i in range(1, n + 1):
        x = a * math.cos((2 * i - 1) * math.pi / (2 * n))
        w = k * (a**p - abs(x) ** p) / (a * a - x * x)
        terms.append(1 / math.sqrt(2 * w / float(mass)))
    return 2 * math.pi / n * math.fsum(terms)


def harmonic_period(omega: Real) -> float:
    """Period of the harmonic oscillator of angular frequency omega, s (after (6.12)).

    A unit mass on the spring k = omega^2: the turning-point integral of
    ``oscillation_period`` for U = k x^2 / 2 (any amplitude: it does not depend on it).
    """
    inputs.positive(omega, "omega")
    return oscillation_period(1, omega * omega / 2, 2, 1)


@dataclass(frozen=True)
class PowerLawPotential:
    """The potential of a power-law force F = k y^p at y (after (6.12)).

    ``potential`` U = -integral F dy = -k y^(p+1) / (p+1), or -k ln y for p = -1 (then the
    potential is logarithmic, like the isothermal (6.11)); ``exponent`` its local power
    d ln|U| / d ln y; ``exponent_gain`` = exponent - p, the 1 of p + 1; ``force`` = -dU/dy (a
    check: it equals k y^p); ``logarithmic`` is True for p = -1.
    """

    potential: Real
    exponent: float
    exponent_gain: float
    force: float
    logarithmic: bool


def _power_potential(k: Real, p: Real, y: RealOrComplex) -> RealOrComplex:
    if p == -1:
        return -k * _ln(y)
    return -k * y ** (p + 1) / (p + 1)


def power_law_potential(strength: Real, power: Real, y: Real) -> PowerLawPotential:
    """Potential of the force F = strength y^power at y > 0 (the list after (6.12))."""
    inputs.real(strength, "strength")
    inputs.real(power, "power")
    inputs.positive(y, "y")
    exponent = log_slope(lambda x: _power_potential(strength, power, x), y)
    return PowerLawPotential(
        potential=_power_potential(strength, power, y),
        exponent=exponent,
        exponent_gain=exponent - power,
        force=-complex_step_derivative(lambda x: _power_potential(strength, power, x), y),
        logarithmic=power == -1,
    )


# --- the toss (6.13) --------------------------------------------------------------------------
def _gravity(g: Real) -> Real:
    """Size of the gravitational acceleration; the book writes g with either sign (up positive:
    g = -9.8)."""
    inputs.real(g, "g")
    if g == 0:
        raise ValueError("g must not be zero")
    return cast(Real, abs(g))  # abs of a Real: mypy joins a union's abs to object


def toss_height(v_floor: Real, g: Real) -> Real:
    """Height a ball launched straight up at ``v_floor`` rises to, m (6.13a): g h = V^2 / 2.

    From the kinematics of constant deceleration: it rises for t = V / g, covering
    V t - g t^2 / 2. Exact with Fraction inputs.
    """
    inputs.real(v_floor, "v_floor")
    gm = _gravity(g)
    speed = cast(Real, abs(v_floor))
    t = speed / gm
    return speed * t - gm * t * t / 2


def toss_height_gain(speed_gain: Real) -> Real:
    """Factor by which the toss height grows when the launch speed grows ``speed_gain``-fold.

    "A 3-fold velocity gain means 3^2 = 9-fold height gain" (after (6.13)).
    """
    inputs.positive(speed_gain, "speed_gain")
    unit = speed_gain / speed_gain  # 1 of the input's type: Fraction inputs stay exact
    return toss_height(speed_gain, unit) / toss_height(unit, unit)


@dataclass(frozen=True)
class Fall:
    """A ball dropped from rest through ``height`` (6.13b): its ``time``, its floor ``speed``
    V = sqrt(2 g h), and ``speed_squared_per_g`` = V^2 / g = 2 h (the 60 of sqrt(60 g))."""

    time: float
    speed: float
    speed_squared_per_g: float


def fall_from_height(height: Real, g: Real) -> Fall:
    """Fall from rest through ``height`` under gravity ``g`` (either sign), no drag (6.13b)."""
    inputs.positive(height, "height")
    gm = float(_gravity(g))
    h = float(height)
    speed = math.sqrt(2 * gm * h)  # energy: 1/2 V^2 = g h per unit mass
    return Fall(time=speed / gm, speed=speed, speed_squared_per_g=speed * speed / gm)


def same_speed(speed: Real) -> Real:
    """A speed the book restates in another unit ("24 meters per sec. or 55 mph", Fig. 7.3),
    SI: the value itself, which the evaluator converts to the printed unit."""
    inputs.real(speed, "speed")
    return speed


def launch_speed(height: Real, g: Real) -> float:
    """Launch speed that tosses a ball to ``height``, V = sqrt(2 g h) (6.13b), m/s."""
    return fall_from_height(height, g).speed


# --- bang sequences: the trapped ball (Fig. 6.4), the monster pair (Fig. 6.5) ----------------
@dataclass(frozen=True)
class TrappedBall:
    """The little ball between a closing big ball and a fixed wall (Fig. 6.4).

    ``speeds[k]`` is its speed after its (k+1)-th bang with the big ball (Bang(1) first);
    ``ranges[k]`` the gap Delta x between big ball and wall when it next hits the wall, and
    ``products[k]`` = ranges[k] * speeds[k], the action Delta x v2 = Delta x Delta v / 2;
    ``times[k]`` the time of that wall bang.
    """

    speeds: tuple[Real, ...]
    ranges: tuple[Real, ...]
    products: tuple[Real, ...]
    times: tuple[Real, ...]


def trapped_ball(v_wall: Real, v_ball: Real, gap: Real, bangs: int) -> TrappedBall:
    """Follow ``bangs`` bangs of the little ball trapped by a big ball closing at ``v_wall``.

    The wall is at x = 0, the little ball starts at x = -``gap`` with velocity ``v_ball``
    (positive: toward the wall) just as the big ball (infinitely heavier, Fig. 6.4), closing at
    ``v_wall``, reaches it; so the big ball must be the faster, ``v_ball < v_wall``. Each bang
    with the big ball is ``collisions.collide`` with an infinite mass, which leaves the little
    ball faster than the big one, 2 v_wall - v; the wall reverses the ball's velocity. Exact
    with Fraction inputs.
    """
    inputs.positive(v_wall, "v_wall")
    inputs.real(v_ball, "v_ball")
    inputs.positive(gap, "gap")
    n = inputs.count(bangs, "bangs", minimum=1)
    if not v_ball < v_wall:
        raise ValueError(
            f"the big ball (v_wall = {v_wall!r}) does not catch the little ball (v_ball = "
            f"{v_ball!r}): v_ball must be less than v_wall"
        )
    t, x_big, velocity = 0 * gap, -gap, v_ball
    speeds, ranges, products, times = [], [], [], []
    for _ in range(n):
        velocity = collide(math.inf, 1, v_wall, velocity).v2
        x_ball = x_big
        dt = -x_ball / velocity  # to the wall at x = 0
        t, x_big = t + dt, x_big + v_wall * dt
        speeds.append(velocity)
        ranges.append(-x_big)
        products.append(-x_big * velocity)
        times.append(t)
        velocity = -velocity  # the wall's bounce
        dt = -x_big / (v_wall - velocity)  # back to meet the big ball
        t, x_big = t + dt, x_big + v_wall * dt
    return TrappedBall(tuple(speeds), tuple(ranges), tuple(products), tuple(times))


def monster_pair(v_monster: Real, v_start: Real, bongs: int) -> tuple[Real, ...]:
    """Velocities of an atom pinged between two monster masses closing at +-V (Fig. 6.5).

    The left monster moves at +V, the right one at -V; an atom moving left (or at rest) is hit
    by the left one, an atom moving right by the right one, each bong being
    ``collisions.collide`` with an infinite mass. Returns the start and the velocity after each
    of ``bongs`` bongs: from 0 the even integers 0, 2, -4, 6, ... (for V = 1).
    """
    inputs.positive(v_monster, "v_monster")
    inputs.real(v_start, "v_start")
    n = inputs.count(bongs, "bongs", minimum=0)
    out = [v_start]
    for _ in range(n):
        v = out[-1]
        wall = v_monster if v <= 0 else -v_monster
        out.append(collide(math.inf, 1, wall, v).v2)
    return tuple(out)
