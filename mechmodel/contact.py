"""Contact forces: superball geometry, stopping targets and soft collisions (chapter 7).

- The dent of a ball pressed a depth x into a flat wall (Fig. 7.1): the flat's radius
  r = sqrt(x (2R - x)) (7.1a), the sagitta x ~ r^2 / 2R (7.1b), a balloon's force P pi r^2
  (7.2) and the dent's volume (7.4).
- Stopping a falling daredevil (Figs. 7.3-7.4): a constant-force target (kiddy-pool or
  trampoline) and a linear-force target (a Hooke potential), with their forces, potentials and
  work; the parabola's shift under a constant force (7.8).
- The soft-contact collision integrator: balls (and a floor) that interact only while they
  overlap, with the repulsion F = k y^n of the overlap y (Figs. 7.5-7.7, 8.1). It integrates
  Newton's equations with the 8th-order Dormand-Prince method (DOP853) and stops at every touch
  and release, so that the right-hand side is smooth on each piece; between contacts the balls
  fly freely and the next touch is found exactly. Results carry their numerical error
  (``Estimate``).

Units: SI or the book's scaled units, consistently. Geometry and targets take floats, ints and
Fractions (exact where only + - * / are used); the integrator works in floats.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from mechmodel import inputs
from mechmodel.algebra import polynomial_derivative, polynomial_integral
from mechmodel.numeric import complex_step_derivative
from mechmodel.typing import Estimate

# --- the dent: Fig. 7.1, (7.1)-(7.4) ---------------------------------------------------------


def flat_spot_radius(radius: Any, depth: Any) -> float:
    """Radius r of the flat a ball of radius R shows when pressed a depth x flat (7.1a).

    Thales: r is the geometric mean of the depth x and the rest of the diameter, 2R - x.
    """
    inputs.positive(radius, "radius")
    inputs.real(depth, "depth")
    if not 0 <= depth <= 2 * radius:
        raise ValueError("the depth must lie between 0 and the diameter 2R")
    return math.sqrt(depth * (radius + radius - depth))


def flat_area_slope(radius: Any, depth: Any) -> float:
    """d(r^2)/dx of the flat's squared radius at depth x: 2R - 2x; at x = 0 the 2 of
    r^2 ~ 2 R x (7.1a), and of the sagitta x ~ r^2 / 2R (7.1b)."""
    inputs.positive(radius, "radius")
    inputs.real(depth, "depth")
    return complex_step_derivative(lambda x: x * (radius + radius - x), depth)


def flat_radius_shallow(radius: Any, depth: Any) -> float:
    """Radius of the flat of a shallow dent, x << R, to leading order in x (7.1a).

    r^2 = x (2R - x) vanishes at first contact; its leading term is the slope d(r^2)/dx there
    times x (``flat_area_slope``), so r ~ sqrt(x d(r^2)/dx|0): the sqrt(2 R x) of (7.1a).
    """
    inputs.positive(radius, "radius")
    inputs.real(depth, "depth")
    if depth < 0:
        raise ValueError("the depth must not be negative")
    return math.sqrt(flat_area_slope(radius, 0) * depth)


def sagitta_small_flat(radius: Any, flat_radius: Any) -> Any:
    """Depth x of the dent whose flat has a small radius r << R, to leading order: the bow
    formula of (7.1b). Inverting r^2 = x (2R - x) at first order in x, x ~ r^2 / (d(r^2)/dx at
    x = 0), where ``flat_area_slope`` gives the slope."""
    inputs.positive(radius, "radius")
    inputs.real(flat_radius, "flat_radius")
    return flat_radius * flat_radius / flat_area_slope(radius, 0)


def flat_area(radius: Any, depth: Any) -> float:
    """Area pi r^2 of the flat at depth x, the integrand of the dent's volume (7.4): the flat's
    radius from Thales (``flat_spot_radius``), squared."""
    r = flat_spot_radius(radius, depth)
    return math.pi * r * r


def sagitta(radius: Any, flat_radius: Any) -> float:
    """Depth x of the dent whose flat has radius r, exactly: R - sqrt(R^2 - r^2) (7.1b).

    For r << R this is r^2 / 2R, the bow (sagitta) formula of thin lenses.
    """
    inputs.positive(radius, "radius")
    inputs.real(flat_radius, "flat_radius")
    if not 0 <= flat_radius <= radius:
        raise ValueError("the flat's radius must lie between 0 and R")
    return radius - math.sqrt(radius * radius - flat_radius * flat_radius)


def balloon_force(pressure: Any, radius: Any, depth: Any) -> float:
    """Force of a balloon of pressure P pressed a depth x flat, P pi r^2 (7.2), N."""
    inputs.positive(pressure, "pressure")
    r = flat_spot_radius(radius, depth)
    return pressure * math.pi * r * r


def balloon_stiffness(pressure: Any, radius: Any, depth: Any) -> float:
    """Spring constant dF/dx of the balloon at depth x, N/m: at x = 0, 2 pi P R (7.2)."""
    inputs.positive(pressure, "pressure")
    inputs.positive(radius, "radius")
    inputs.real(depth, "depth")
    return complex_step_derivative(lambda x: pressure * math.pi * x * (radius + radius - x), depth)


def balloon_force_shallow(pressure: Any, radius: Any, depth: Any) -> float:
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

    volume: Any
    quadratic_power: Any
    cubic_power: Any
    cubic_denominator: Any
    small_dent_power: float
    whole_ball: Any
    whole_ball_power: float


def _dent_polynomial(radius: Any) -> list[Any]:
    """pi r(x)^2 / pi = x (2R - x) = 2R x - x^2, coefficients by power of x."""
    return [0, radius + radius, -1]


def _dent_volume_over_pi(radius: Any, depth: Any) -> Any:
    return polynomial_integral(_dent_polynomial(radius), depth)


def dent_volume(radius: Any, depth: Any) -> DentVolume:
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


def dent_volume_shallow(radius: Any, depth: Any) -> float:
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


def whole_ball_volume(radius: Any) -> float:
    """Volume of the whole ball by the dent integral (7.4): the dent as deep as the diameter,
    V(2R), which the book checks against the ball's volume."""
    inputs.positive(radius, "radius")
    return dent_volume(radius, radius + radius).volume


def _local_power(f: Any, x: float) -> float:
    """d ln f / d ln x by the complex step (f analytic and positive at x)."""
    return x * complex_step_derivative(f, x) / float(f(x))


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

    force: Any
    potential_slope: Any
    energy: Any


def constant_force_target(fall_height: Any, stop_distance: Any) -> ConstantTarget:
    """The constant target stopping a fall from ``fall_height`` within ``stop_distance``."""
    inputs.positive(fall_height, "fall_height")
    inputs.positive(stop_distance, "stop_distance")
    force = fall_height / stop_distance  # work F d = energy M g h, per unit weight
    return ConstantTarget(force=force, potential_slope=-force, energy=fall_height)


def stopping_force_reduction(fall_height: Any, distance_before: Any, distance_after: Any) -> Any:
    """Factor by which the stopping force falls when the stopping distance grows (Fig. 7.3c)."""
    before = constant_force_target(fall_height, distance_before).force
    return before / constant_force_target(fall_height, distance_after).force


def deceleration(force_per_weight: Any, g: Any) -> Any:
    """Deceleration, m/s^2, of a body pushed by ``force_per_weight`` times its weight (30 g)."""
    inputs.positive(force_per_weight, "force_per_weight")
    inputs.real(g, "g")
    return force_per_weight * abs(g)


def work_of_constant_force(force: Any, distance: Any) -> Any:
    """Work (area under F vs. y) of a constant force over a distance, F d (7.5a)."""
    inputs.real(force, "force")
    inputs.real(distance, "distance")
    return force * distance


def ramp_work(force: Any, distance: Any) -> Any:
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
    energy: float
    total_stop: float


def linear_target(quadratic: Any, fall_height: Any, fall_height_m: Any) -> LinearTarget:
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

    slope: Any
    constant: Any
    slope_magnitude: Any
    constant_magnitude: Any


def quadratic_potential_force(a: Any, b: Any) -> QuadraticForce:
    """Force of the total potential u = a y^2 + b y (Fig. 7.4): f = -2a y - b. Exact with
    Fractions (the power rule on the coefficients)."""
    inputs.real(a, "a")
    inputs.real(b, "b")
    constant, linear = (-c for c in polynomial_derivative([0, b, a]))
    return QuadraticForce(linear, constant, abs(linear), abs(constant))


@dataclass(frozen=True)
class Vertex:
    """The vertex of U = a y^2 + b y (7.8): ``y_shift`` = -b / 2a and ``u_shift`` = -b^2 / 4a;
    ``shift_denominator`` = -b / (a y_shift), the 2 of b / 2a, and ``depth_denominator`` =
    -b^2 / (a u_shift), the 4 of b^2 / 4a."""

    y_shift: Any
    u_shift: Any
    shift_denominator: Any
    depth_denominator: Any


def parabola_vertex(a: Any, b: Any) -> Vertex:
    """Where U = a y^2 + b y is lowest (dU/dy = 0) and how low (7.8): exact with Fractions."""
    inputs.real(a, "a")
    inputs.real(b, "b")
    if a == 0 or b == 0:
        raise ValueError("a parabola (a != 0) with a linear term (b != 0)")
    c0, c1 = polynomial_derivative([0, b, a])  # dU/dy = c0 + c1 y
    y = -c0 / c1
    u = a * y * y + b * y
    return Vertex(y, u, -b / (a * y), -b * b / (a * u))


def quadratic_potential(a: Any, b: Any, y: Any) -> Any:
    """The total potential U(y) = a y^2 + b y of (7.8a): a target's quadratic a y^2 and the
    linear potential b y of gravity. Plain operators (exact, symbolic)."""
    return a * y * y + b * y


# --- the soft-contact integrator: Figs. 7.5-7.7, 8.1 -----------------------------------------


@dataclass(frozen=True)
class SoftCollision:
    """The outcome of a soft collision of balls on a line (and a floor, if any).

    ``velocities[k]`` is ball k's final velocity (ball 0 lowest), an ``Estimate`` with its error
    bound (see ``soft_collision``); ``energy_error`` the relative
    drift of the total energy over the run (kinetic plus the contacts' k y^(n+1)/(n+1));
    ``touches`` the number of contact events; ``duration`` the time from the start to the last
    release; ``times`` and ``positions`` (one row per ball) sample the trajectory for plots.
    """

    masses: tuple[float, ...]
    velocities: tuple[Estimate, ...]
    energy_error: float
    touches: int
    duration: float
    times: tuple[float, ...] = field(repr=False)
    positions: tuple[tuple[float, ...], ...] = field(repr=False)


# "DOP853-ode" is Hairer's Fortran DOP853 through scipy.integrate.ode: the same 8th-order
# Dormand-Prince method as solve_ivp's "DOP853", stepped in compiled code (benchmarks/
# soft_contact.py compares them all). The others are scipy's solve_ivp methods.
INTEGRATORS = ("DOP853-ode", "DOP853", "RK45", "Radau", "LSODA")
# (rtol, step cap as a fraction of the shortest contact): tried in turn until the energy drift
# is within _ENERGY_GOAL. Near a release the force y^n (n not an integer) has derivatives that
# grow like y^(n-k), so the embedded error estimate can pass a long step into the edge of a
# contact; the energy, conserved exactly, shows it, and a tighter run repairs it.
_LADDER = ((1e-13, 1 / 4), (3e-14, 1 / 4), (3e-14, 1 / 32))
_ENERGY_GOAL = 1e-11
_MAX_SEGMENTS = 10_000
_MAX_STEPS = 1_000_000  # steps of one Fortran run, a guard against a runaway integration
_NEWTON_STEPS = 30  # 1 to 3 locate a touch or release (2,360 events measured); bisection guards
_EPS = 2.0**-52  # the spacing of doubles at 1
_SAFETY = 10  # the tenfold-looser run's change, times this, bounds the error (tested)
_FLOOR = 1e-12  # relative error floor: rounding and event location over a whole run
_ODE_FAILURES = {
    -1: "input is not consistent",
    -2: "more steps needed",
    -3: "step size becomes too small",
    -4: "problem is probably stiff",
}


@dataclass(frozen=True)
class _Tolerance:
    """One run's accuracy: relative and absolute tolerance, the step cap, and the time scale
    (a first step of a thousandth of it; no piece runs longer than 10^4 of it)."""

    rtol: float
    atol: float
    step_cap: float
    scale: float


@dataclass
class _Piece:
    """One stretch of integration with a fixed set of contacts: where it ended, the contacts
    that touched or released there (none if it ran out of time), and its sampled path."""

    t: float
    state: Any
    flipped: list[int]
    times: list[float]
    rows: list[list[float]]


def _gap(j: int, s: Any) -> float:
    """Overlap of contact j in state s (positions, then velocities): the floor's (j = 0) is
    -x_0, that of balls j-1 and j is x_(j-1) - x_j; positive while they press."""
    return -s[0] if j == 0 else s[j - 1] - s[j]


def _signed_gap(j: int, s: Any, side: float) -> float:
    """Contact j's overlap in state s for spotting a touch or release: an overlap of exactly 0
    counts as still on ``side`` (the sign before the event: +1 for a contact in force, -1 for
    one open), so that touching at the start of a piece is not an event."""
    y = _gap(j, s)
    return y if y != 0 else side * 1e-300


def _gap_rate(j: int, s: Any, n: int) -> float:
    """Time derivative of contact j's overlap in state s of n balls."""
    return -s[n] if j == 0 else s[n + j - 1] - s[n + j]


def _ivp_piece(
    rhs: Any, t: float, state: Any, active: Any, watched: list[int], tol: _Tolerance, method: str
) -> _Piece:
    """Integrate with scipy's ``solve_ivp`` until a watched contact touches or releases."""
    from scipy.integrate import solve_ivp

    def make_event(j: int, side: float) -> Any:
        def event(_t: float, s: Any) -> float:
            return _signed_gap(j, s, side)

        event.terminal = True
        event.direction = -1 if side > 0 else 1
        return event

    n = len(state) // 2
    sol = solve_ivp(
        rhs,
        (t, t + 1e4 * tol.scale),
        state,
        rtol=tol.rtol,
        atol=tol.atol,
        events=[make_event(j, 1.0 if active[j] else -1.0) for j in watched],
        max_step=tol.step_cap,
        first_step=tol.scale * 1e-3,
        method=method,
    )
    if sol.status < 0:
        raise ArithmeticError(f"soft collision integration failed: {sol.message}")
    end_t, end = float(sol.t[-1]), sol.y[:, -1].copy()
    if sol.status == 1 and len(sol.t) > 2 and end_t > sol.t[-2]:
        # the event's state comes from the dense-output interpolant, which is less accurate
        # than a step: redo the last stretch as a step that lands exactly on the event
        redo = solve_ivp(
            rhs,
            (float(sol.t[-2]), end_t),
            sol.y[:, -2],
            method=method,
            rtol=tol.rtol,
            atol=tol.atol,
            first_step=end_t - float(sol.t[-2]),
        )
        end = redo.y[:, -1].copy()
    return _Piece(
        end_t,
        end,
        [j for j, hit in zip(watched, sol.t_events, strict=True) if len(hit)],
        [float(s) for s in sol.t[1:]],
        [list(col[:n]) for col in sol.y.T[1:]],
    )


def _dop853(rhs: Any, tol: _Tolerance, first_step: float) -> Any:
    """scipy's Fortran DOP853 integrator for ``rhs`` at the run's tolerances."""
    from scipy.integrate import ode

    return ode(rhs).set_integrator(
        "dop853",
        rtol=tol.rtol,
        atol=tol.atol,
        max_step=tol.step_cap,
        first_step=first_step,
        nsteps=_MAX_STEPS,
    )


def _run_dop853(solver: Any, t: float, state: Any, until: float) -> None:
    """Run ``solver`` from (t, state) to ``until`` (or until its solout stops it)."""
    import warnings

    solver.set_initial_value(state, t)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)  # scipy warns, then reports the code
        solver.integrate(until)
    code = solver.get_return_code()
    if code < 0:
        raise ArithmeticError(
            f"soft collision integration failed: {_ODE_FAILURES.get(code, f'code {code}')}"
        )


def _hermite_root(g0: float, g1: float, d0: float, d1: float) -> float:
    """The first zero in [0, 1] of the cubic with values g0, g1 and slopes d0, d1 at 0 and 1
    (per unit of the interval): where a gap that changed sign over a step is estimated to
    cross zero, from the two ends' positions and velocities alone."""
    import numpy as np

    cubic = [2 * g0 - 2 * g1 + d0 + d1, -3 * g0 + 3 * g1 - 2 * d0 - d1, d0, g0]
    inside = [r.real for r in np.roots(cubic) if abs(r.imag) < 1e-9 and 0 <= r.real <= 1]
    return min(inside) if inside else g0 / (g0 - g1)


def _ode_piece(
    rhs: Any, t: float, state: Any, active: Any, watched: list[int], tol: _Tolerance
) -> _Piece:
    """Integrate with the Fortran DOP853 until a watched contact touches or releases.

    After every step the watched overlaps are checked for a sign change (an active contact
    released, an inactive one touching). The first step over which one changed is taken apart:
    the crossing is estimated from a cubic through both ends, then found by Newton's method on
    the true trajectory, each iterate a fresh integration from the step's start, so that the
    state at the event comes from a step, not from an interpolant.
    """
    n = len(state) // 2
    side = {j: 1.0 if active[j] else -1.0 for j in watched}  # the sign before the event

    def signed(j: int, s: Any) -> float:
        return _signed_gap(j, s, side[j])

    def across(j: int, y: float) -> bool:
        return y * side[j] < 0

    last = [t, state, [signed(j, state) for j in watched]]
    stop: list[Any] = []
    times: list[float] = []
    rows: list[list[float]] = []

    def solout(tk: float, yk: Any) -> int:
        if tk == last[0]:
            return 0  # the call at the start
        now = [signed(j, yk) for j in watched]
        hits = [
            j
            for j, before, y in zip(watched, last[2], now, strict=True)
            if across(j, y) and not across(j, before)  # a crossing, not a start already across
        ]
        if hits:
            stop.append(hits)
            return -1
        last[:] = [tk, yk.copy(), now]
        times.append(tk)
        rows.append(list(yk[:n]))
        return 0

    solver = _dop853(rhs, tol, tol.scale * 1e-3)
    solver.set_solout(solout)
    _run_dop853(solver, t, state, t + 1e4 * tol.scale)
    if not stop:
        return _Piece(float(solver.t), solver.y.copy(), [], times, rows)
    ta, ya = last[0], last[1]
    tb, yb = float(solver.t), solver.y.copy()

    def state_at(when: float) -> Any:
        if when <= ta:
            return ya
        step = _dop853(rhs, tol, when - ta)
        _run_dop853(step, ta, ya, when)
        return step.y.copy()

    h = tb - ta
    roots = []
    for j in stop[0]:
        g0, g1 = _gap(j, ya), _gap(j, yb)
        u = _hermite_root(g0, g1, _gap_rate(j, ya, n) * h, _gap_rate(j, yb, n) * h)
        when, low, high = ta + u * h, ta, tb
        for _ in range(_NEWTON_STEPS):
            s = state_at(when)
            y, rate = _gap(j, s), _gap_rate(j, s, n)
            if across(j, y):
                high = when
            elif y != 0:
                low = when
            follow = when - y / rate if rate else (low + high) / 2
            # done when the overlap is zero to the rounding of the positions it is the
            # difference of, or Newton cannot move the time by more than its own rounding, or
            # the bracket has shrunk to a few roundings of the time (there the integrations'
            # rounding noise can outweigh the overlap, and Newton may hop between the ends)
            resolution = 4 * _EPS * (abs(s[0]) if j == 0 else abs(s[j - 1]) + abs(s[j]))
            rounding = 2 * _EPS * abs(when)
            if abs(y) <= resolution or abs(follow - when) <= rounding or high - low <= 4 * rounding:
                break
            if not low < follow < high:  # outside the bracket, or back at an end: bisect
                follow = (low + high) / 2
            when = follow
        else:
            raise ArithmeticError(f"soft collision: contact {j}'s touch or release not located")
        roots.append((when, j, s))
    first = min(when for when, _, _ in roots)
    end = next(s for when, _, s in roots if when == first)
    return _Piece(
        first,
        end,
        [j for when, j, _ in roots if when == first],
        [*times, first],
        [*rows, list(end[:n])],
    )


def _integrate(
    masses: Sequence[float],
    positions: Sequence[float],
    velocities: Sequence[float],
    power: float,
    strength: float,
    floor: bool,
    rtol: float,
    method: str,
    cap_fraction: float,
) -> tuple[list[float], float, int, float, list[float], list[list[float]]]:
    """One run of the piecewise integration; see ``soft_collision``."""
    import numpy as np

    m = np.asarray(masses, float)
    n = len(m)
    x = np.asarray(positions, float).copy()
    v = np.asarray(velocities, float).copy()
    lowest = 0 if floor else 1  # contact 0 is the floor's (with ball 0), if there is a floor

    def overlaps(pos: Any) -> Any:
        return np.concatenate(([-pos[0]], pos[:-1] - pos[1:]))

    def rates(vel: Any) -> Any:
        return np.concatenate(([-vel[0]], vel[:-1] - vel[1:]))

    def energy(pos: Any, vel: Any, on: Any) -> float:
        y = np.where(on, np.maximum(overlaps(pos), 0.0), 0.0)
        stored = strength * y ** (power + 1) / (power + 1)
        return float(np.sum(m * vel * vel) / 2 + np.sum(stored[lowest:]))

    y0, r0 = overlaps(x), rates(v)
    active = (y0 > 0) | ((y0 == 0) & (r0 >= 0))
    active[:lowest] = False
    e0 = energy(x, v, active)
    # speed scale: the largest closing speed or, for balls released pressed together at rest,
    # the speed the stored energy would give the lightest ball
    speed = float(np.max(np.abs(r0))) or math.sqrt(2 * e0 / float(m.min()))
    if speed == 0:  # nothing moves and nothing is stored: nothing happens
        return [float(w) for w in v], 0.0, 0, 0.0, [0.0], [list(x)]
    # time scale: the contact time of the lightest ball at that speed
    reach = ((power + 1) * float(m.min()) * speed * speed / (2 * strength)) ** (1 / (power + 1))
    scale = reach / speed
    # the shortest contact possible: no pair closes faster than twice the top speed the energy
    # allows, 2 sqrt(2 E / m_min), and its reduced mass is at least m_min / 2; such a pair stays
    # in touch for at least 2 y_max / r. Steps are capped at a fraction of that (a quarter at
    # most), so no contact can open and close between two steps unseen.
    fastest = 2 * math.sqrt(2 * e0 / float(m.min())) if e0 > 0 else speed
    deepest = ((power + 1) * float(m.min()) * fastest**2 / (4 * strength)) ** (1 / (power + 1))
    tol = _Tolerance(
        rtol, rtol * 1e-3 * max(reach, speed), 2 * deepest / fastest * cap_fraction, scale
    )

    mass = [float(mk) for mk in m]
    on = active.tolist()  # the contacts in force during the current piece (set before each)

    def rhs(_t: float, s: Any) -> list[float]:
        # plain floats, one list: for a few balls this is several times faster than numpy
        rates = s.tolist()
        acc = [0.0] * n
        if on[0] and rates[0] < 0:
            acc[0] = strength * (-rates[0]) ** power  # the floor pushes ball 0 up
        for j in range(1, n):
            if on[j]:
                overlap = rates[j - 1] - rates[j]
                if overlap > 0:
                    f = strength * overlap**power
                    acc[j - 1] -= f  # contact j pushes ball j-1 down and ball j up
                    acc[j] += f
        rates[:n] = rates[n:]  # d(position)/dt = velocity
        rates[n:] = [a / mk for a, mk in zip(acc, mass, strict=True)]
        return rates

    t, state = 0.0, np.concatenate((x, v))
    times, path = [0.0], [list(x)]
    touches = 0
    watched = list(range(lowest, n))
    for _ in range(_MAX_SEGMENTS):
        x, v = state[:n], state[n:]
        y, r = overlaps(x), rates(v)
        closing = (r > 0) & (np.arange(n) >= lowest)
        if not closing.any() and not (active & (y > 0)).any():
            break  # nothing presses and nothing closes (balls touching at rest stay so)
        if not active.any():
            waits = np.where(closing, -y / np.where(closing, r, 1.0), np.inf)
            j = int(np.argmin(waits))
            wait = max(float(waits[j]), 0.0)
            x = x + v * wait
            t += wait
            state = np.concatenate((x, v))
            active[j] = True
            touches += 1
            times.append(t)
            path.append(list(x))
            continue
        on[:] = active.tolist()
        if method == "DOP853-ode":
            piece = _ode_piece(rhs, t, state, active, watched, tol)
        else:
            piece = _ivp_piece(rhs, t, state, active, watched, tol, method)
        t, state = piece.t, piece.state
        times.extend(piece.times)
        path.extend(piece.rows)
        for j in piece.flipped:
            active[j] = not active[j]
            touches += 1
    else:
        raise ArithmeticError("soft collision did not end within the segment limit")
    x, v = state[:n], state[n:]
    drift = abs(energy(x, v, active) - e0) / e0 if e0 else 0.0
    return [float(w) for w in v], drift, touches, t, times, path


def soft_collision(
    masses: Sequence[Any],
    positions: Sequence[Any],
    velocities: Sequence[Any],
    power: Any,
    strength: Any = 1,
    floor: bool = False,
    method: str = "DOP853-ode",
) -> SoftCollision:
    """Collide balls on a line that repel with F = strength * y^power while they overlap by y.

    ``positions`` are the balls' positions with their sizes taken out: balls k and k+1 touch
    when x_k = x_(k+1) and overlap by x_k - x_(k+1) when that is positive; ball 0 is the lowest.
    With ``floor`` an infinitely massive floor at x = 0 touches ball 0 when x_0 = 0 and pushes
    with the same law. No other force acts (no gravity during the contact, no friction), so the
    energy, and without a floor the momentum, are conserved; the run ends when nothing overlaps
    and no pair (nor ball 0 and the floor) is closing. Power laws with power >= 1 are supported
    (the force and its first derivative are continuous within each contact). The run is made at
    a relative tolerance of 1e-13 and, while the energy drifts by more than 1e-11 (relative),
    again with tighter tolerances and shorter steps; the velocities' errors are ten times the
    change under a tenfold looser tolerance, plus the energy drift and a floor of 1e-12, both
    times the speeds involved. ``method`` is one of ``INTEGRATORS``: the default "DOP853-ode",
    Hairer's Fortran DOP853 (8th-order Dormand-Prince) through ``scipy.integrate.ode``, with
    each touch and release located by Newton's method on the true trajectory, or one of scipy's
    ``solve_ivp`` methods ("DOP853", "RK45", "Radau", "LSODA") with its event location. The
    Fortran DOP853 reaches this accuracy in a third to a half of the time of the next fastest
    (benchmarks/soft_contact.py compares them).
    """
    if method not in INTEGRATORS:
        raise ValueError(f"method must be one of {INTEGRATORS}, got {method!r}")
    if len(masses) < 1 or len(masses) != len(positions) or len(masses) != len(velocities):
        raise ValueError("give one position and one velocity per mass")
    if len(masses) < 2 and not floor:
        raise ValueError("one ball alone has nothing to collide with")
    for i, m in enumerate(masses):
        inputs.mass(m, f"masses[{i}]")
    for i, (p, v) in enumerate(zip(positions, velocities, strict=True)):
        inputs.real(p, f"positions[{i}]")
        inputs.real(v, f"velocities[{i}]")
    inputs.real(power, "power")
    if power < 1:
        raise ValueError(f"power must be at least 1, got {power!r}")
    inputs.positive(strength, "strength")
    if floor and positions[0] < 0:
        raise ValueError("ball 0 starts below the floor")
    args = (
        [float(m) for m in masses],
        [float(p) for p in positions],
        [float(v) for v in velocities],
        float(power),
        float(strength),
        bool(floor),
    )
    for rtol, cap in _LADDER:
        fine = _integrate(*args, rtol=rtol, method=method, cap_fraction=cap)
        if fine[1] <= _ENERGY_GOAL:
            break
    coarse = _integrate(*args, rtol=rtol * 10, method=method, cap_fraction=cap)
    # error: ten times the change under a tenfold looser tolerance, plus what the energy drift
    # allows and a floor (the embedded error estimate can miss the non-smooth onset of a
    # contact, y^n at y = 0); over 1000 random collisions this bounds the true error with room
    spread = sum(abs(v) for v in fine[0]) + sum(abs(v) for v in args[2])
    finals = tuple(
        Estimate(float(a), _SAFETY * abs(a - b) + (fine[1] + _FLOOR) * spread)
        for a, b in zip(fine[0], coarse[0], strict=True)
    )
    return SoftCollision(
        masses=tuple(args[0]),
        velocities=finals,
        energy_error=fine[1],
        touches=fine[2],
        duration=fine[3],
        times=tuple(fine[4]),
        positions=tuple(tuple(row[k] for row in fine[5]) for k in range(len(masses))),
    )
