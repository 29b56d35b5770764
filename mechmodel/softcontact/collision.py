"""The soft collision of balls on a line, and of a floor if any (Figs. 7.5-7.7, 8.1).

``soft_collision`` checks its inputs, integrates the collision down a ladder of tolerances
until the energy is kept, and returns the final velocities as ``Estimate`` values whose error
is measured against a tenfold looser run (``SoftCollision``). One run, ``_integrate``: the
balls' energy and time scales (``_Balls``), their equations of motion under the contacts in
force (``_equations``), and the alternation of free flights, where the next touch is found
exactly, and pieces integrated between contact events (``_run_pieces``, with
``softcontact.pieces``).

Units: any consistent set, SI or the book's scaled units (positions m, velocities m/s, masses
kg, the strength k of F = k y^n in N/m^n). The inputs are checked as numbers of any kind; the
integration works in floats.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import NamedTuple

from mechmodel import inputs
from mechmodel.softcontact.pieces import (
    Equations,
    Flags,
    State,
    Tolerance,
    closing_rates,
    ivp_piece,
    ode_piece,
    overlaps,
)
from mechmodel.typing import Estimate, Real


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
_SAFETY = 10  # the tenfold-looser run's change, times this, bounds the error (tested)
_FLOOR = 1e-12  # relative error floor: rounding and event location over a whole run


class _Run(NamedTuple):
    """One run of ``_integrate``: the final velocities, the relative energy drift, the number
    of touches and releases, the time of the last release, and the sampled path (times, and
    the balls' positions at each)."""

    velocities: list[float]
    drift: float
    touches: int
    duration: float
    times: list[float]
    path: list[list[float]]


# --- one run ---------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class _Balls:
    """The balls of one run: their masses (an array), the force law ``strength`` y^``power``,
    and the first contact in play, ``lowest`` (0 with a floor: contact 0 is the floor's, with
    ball 0; else 1)."""

    m: State
    power: float
    strength: float
    lowest: int

    def energy(self, pos: State, vel: State, on: Flags) -> float:
        """Kinetic energy plus the energy k y^(n+1)/(n+1) stored in the contacts ``on``."""
        import numpy as np

        y = np.where(on, np.maximum(overlaps(pos), 0.0), 0.0)
        stored = self.strength * y ** (self.power + 1) / (self.power + 1)
        return float(np.sum(self.m * vel * vel) / 2 + np.sum(stored[self.lowest :]))

    def tolerance(self, speed: float, e0: float, rtol: float, cap_fraction: float) -> Tolerance:
        """The run's tolerances, step cap and time scale for the speed scale ``speed`` and the
        total energy ``e0``."""
        power, strength = self.power, self.strength
        # time scale: the contact time of the lightest ball at that speed
        reach = ((power + 1) * float(self.m.min()) * speed * speed / (2 * strength)) ** (
            1 / (power + 1)
        )
        scale = reach / speed
        # the shortest contact possible: no pair closes faster than twice the top speed the
        # energy allows, 2 sqrt(2 E / m_min), and its reduced mass is at least m_min / 2; such a
        # pair stays in touch for at least 2 y_max / r. Steps are capped at a fraction of that
        # (a quarter at most), so no contact can open and close between two steps unseen.
        fastest = 2 * math.sqrt(2 * e0 / float(self.m.min())) if e0 > 0 else speed
        deepest = ((power + 1) * float(self.m.min()) * fastest**2 / (4 * strength)) ** (
            1 / (power + 1)
        )
        return Tolerance(
            rtol, rtol * 1e-3 * max(reach, speed), 2 * deepest / fastest * cap_fraction, scale
        )


def _equations(mass: list[float], power: float, strength: float, on: list[bool]) -> Equations:
    """Newton's equations of the balls of masses ``mass`` under the contacts ``on`` (a list the
    caller updates in place before each piece): d/dt of (positions, velocities)."""
    n = len(mass)

    def rhs(_t: float, s: State) -> list[float]:
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

    return rhs


def _run_pieces(
    rhs: Equations,
    on: list[bool],
    state: State,
    active: Flags,
    lowest: int,
    tol: Tolerance,
    method: str,
) -> tuple[float, State, int, list[float], list[list[float]]]:
    """Alternate free flights (no contact in force: the next touch is found exactly) and
    pieces integrated with the contacts ``active`` (updated in place, and copied into ``on``
    for ``rhs``), from time 0 until nothing presses and nothing closes. Returns the end time
    and state, the number of touches and releases, and the sampled times and positions."""
    import numpy as np

    n = len(state) // 2
    t = 0.0
    times, path = [0.0], [list(state[:n])]
    touches = 0
    watched = list(range(lowest, n))
    for _ in range(_MAX_SEGMENTS):
        x, v = state[:n], state[n:]
        y, r = overlaps(x), closing_rates(v)
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
            piece = ode_piece(rhs, t, state, active, watched, tol)
        else:
            piece = ivp_piece(rhs, t, state, active, watched, tol, method)
        t, state = piece.t, piece.state
        times.extend(piece.times)
        path.extend(piece.rows)
        for j in piece.flipped:
            active[j] = not active[j]
            touches += 1
    else:
        raise ArithmeticError("soft collision did not end within the segment limit")
    return t, state, touches, times, path


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
) -> _Run:
    """One run of the piecewise integration; see ``soft_collision``."""
    import numpy as np

    m = np.asarray(masses, float)
    n = len(m)
    x = np.asarray(positions, float).copy()
    v = np.asarray(velocities, float).copy()
    balls = _Balls(m, power, strength, 0 if floor else 1)

    y0, r0 = overlaps(x), closing_rates(v)
    active = (y0 > 0) | ((y0 == 0) & (r0 >= 0))
    active[: balls.lowest] = False
    e0 = balls.energy(x, v, active)
    # speed scale: the largest closing speed or, for balls released pressed together at rest,
    # the speed the stored energy would give the lightest ball
    speed = float(np.max(np.abs(r0))) or math.sqrt(2 * e0 / float(m.min()))
    if speed == 0:  # nothing moves and nothing is stored: nothing happens
        return _Run([float(w) for w in v], 0.0, 0, 0.0, [0.0], [list(x)])
    tol = balls.tolerance(speed, e0, rtol, cap_fraction)
    on = active.tolist()  # the contacts in force during the current piece (set before each)
    rhs = _equations([float(mk) for mk in m], power, strength, on)
    start = np.concatenate((x, v))
    t, state, touches, times, path = _run_pieces(rhs, on, start, active, balls.lowest, tol, method)
    x, v = state[:n], state[n:]
    drift = abs(balls.energy(x, v, active) - e0) / e0 if e0 else 0.0
    return _Run([float(w) for w in v], drift, touches, t, times, path)


# --- the driver ------------------------------------------------------------------------------


def _checked(
    masses: Sequence[Real],
    positions: Sequence[Real],
    velocities: Sequence[Real],
    power: Real,
    strength: Real,
    floor: bool,
    method: str,
) -> None:
    """``ValueError`` unless the inputs describe a collision ``soft_collision`` can run."""
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


def soft_collision(
    masses: Sequence[Real],
    positions: Sequence[Real],
    velocities: Sequence[Real],
    power: Real,
    strength: Real = 1,
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
    _checked(masses, positions, velocities, power, strength, floor, method)
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
        if fine.drift <= _ENERGY_GOAL:
            break
    coarse = _integrate(*args, rtol=rtol * 10, method=method, cap_fraction=cap)
    # error: ten times the change under a tenfold looser tolerance, plus what the energy drift
    # allows and a floor (the embedded error estimate can miss the non-smooth onset of a
    # contact, y^n at y = 0); over 1000 random collisions this bounds the true error with room
    spread = sum(abs(v) for v in fine.velocities) + sum(abs(v) for v in args[2])
    finals = tuple(
        Estimate(float(a), _SAFETY * abs(a - b) + (fine.drift + _FLOOR) * spread)
        for a, b in zip(fine.velocities, coarse.velocities, strict=True)
    )
    return SoftCollision(
        masses=tuple(args[0]),
        velocities=finals,
        energy_error=fine.drift,
        touches=fine.touches,
        duration=fine.duration,
        times=tuple(fine.times),
        positions=tuple(tuple(row[k] for row in fine.path) for k in range(len(masses))),
    )
