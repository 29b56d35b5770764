"""One stretch of a soft collision with a fixed set of contacts, ended at a touch or release.

Between two contact events the right-hand side of Newton's equations is smooth, so each
stretch (a "piece") is integrated by the 8th-order Dormand-Prince method (DOP853) until a
watched overlap changes sign: an active contact releasing or an open one touching (Figs.
7.5-7.7, 8.1). Two ways: ``ode_piece``, Hairer's Fortran DOP853 through
``scipy.integrate.ode``, which checks the overlaps after every step (``_Watch``) and locates the
crossing by Newton's method on the true trajectory (``_locate``), each iterate a fresh step from
the last one before it; and ``ivp_piece``, one of scipy's ``solve_ivp`` methods with its event
location, the event's state redone as a step. Here live too the overlaps of the contacts (the
floor's, contact 0, is -x_0; that of balls j-1 and j is x_(j-1) - x_j) and their rates.

A state is one float array: the n balls' positions, then their velocities (any consistent
units, as in ``softcontact.collision``).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Protocol, TypeAlias

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

State: TypeAlias = "npt.NDArray[np.float64]"  # positions of the n balls, then their velocities
Flags: TypeAlias = "npt.NDArray[np.bool_]"  # one per contact: in force or not
Equations: TypeAlias = Callable[[float, "npt.NDArray[np.float64]"], list[float]]

_MAX_STEPS = 1_000_000  # steps of one Fortran run, a guard against a runaway integration
_NEWTON_STEPS = 30  # 1 to 3 locate a touch or release (2,360 events measured); bisection guards
_EPS = 2.0**-52  # the spacing of doubles at 1
_ODE_FAILURES = {
    -1: "input is not consistent",
    -2: "more steps needed",
    -3: "step size becomes too small",
    -4: "problem is probably stiff",
}


@dataclass(frozen=True)
class Tolerance:
    """One run's accuracy: relative and absolute tolerance, the step cap, and the time scale
    (a first step of a thousandth of it; no piece runs longer than 10^4 of it)."""

    rtol: float
    atol: float
    step_cap: float
    scale: float


@dataclass
class Piece:
    """One stretch of integration with a fixed set of contacts: where it ended, the contacts
    that touched or released there (none if it ran out of time), and its sampled path."""

    t: float
    state: State
    flipped: list[int]
    times: list[float]
    rows: list[list[float]]


# --- contacts: overlaps and their rates ------------------------------------------------------


def _gap(j: int, s: State) -> float:
    """Overlap of contact j in state s (positions, then velocities): the floor's (j = 0) is
    -x_0, that of balls j-1 and j is x_(j-1) - x_j; positive while they press."""
    return -s[0] if j == 0 else s[j - 1] - s[j]


def _signed_gap(j: int, s: State, side: float) -> float:
    """Contact j's overlap in state s for spotting a touch or release: an overlap of exactly 0
    counts as still on ``side`` (the sign before the event: +1 for a contact in force, -1 for
    one open), so that touching at the start of a piece is not an event."""
    y = _gap(j, s)
    return y if y != 0 else side * 1e-300


def _gap_rate(j: int, s: State, n: int) -> float:
    """Time derivative of contact j's overlap in state s of n balls."""
    return -s[n] if j == 0 else s[n + j - 1] - s[n + j]


def overlaps(pos: State) -> State:
    """The overlaps of all contacts at positions ``pos``: the floor's, then each pair's."""
    import numpy as np

    return np.concatenate(([-pos[0]], pos[:-1] - pos[1:]))


def closing_rates(vel: State) -> State:
    """The time derivatives of ``overlaps`` at velocities ``vel``: positive while closing."""
    import numpy as np

    return np.concatenate(([-vel[0]], vel[:-1] - vel[1:]))


# --- solve_ivp's pieces ----------------------------------------------------------------------


@dataclass(frozen=True)
class _Event:
    """solve_ivp's terminal event of contact j: its overlap, signed as seen from ``side``
    (``_signed_gap``), crossing zero away from that side."""

    j: int
    side: float
    terminal: bool = True

    @property
    def direction(self) -> int:
        return -1 if self.side > 0 else 1

    def __call__(self, _t: float, s: State) -> float:
        return _signed_gap(self.j, s, self.side)


def ivp_piece(
    rhs: Equations,
    t: float,
    state: State,
    active: Flags,
    watched: list[int],
    tol: Tolerance,
    method: str,
) -> Piece:
    """Integrate with scipy's ``solve_ivp`` until a watched contact touches or releases."""
    from scipy.integrate import solve_ivp

    n = len(state) // 2
    sol = solve_ivp(
        rhs,
        (t, t + 1e4 * tol.scale),
        state,
        rtol=tol.rtol,
        atol=tol.atol,
        events=[_Event(j, 1.0 if active[j] else -1.0) for j in watched],
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
    return Piece(
        end_t,
        end,
        [j for j, hit in zip(watched, sol.t_events, strict=True) if len(hit)],
        [float(s) for s in sol.t[1:]],
        [list(col[:n]) for col in sol.y.T[1:]],
    )


# --- the Fortran DOP853's pieces -------------------------------------------------------------


class _Solver(Protocol):
    """What ``_dop853`` returns, a ``scipy.integrate.ode`` (scipy has no type information)."""

    t: float
    y: State

    def set_solout(self, solout: Callable[[float, State], int]) -> object: ...

    def set_initial_value(self, y: State, t: float) -> object: ...

    def integrate(self, t: float) -> State: ...

    def get_return_code(self) -> int: ...


def _dop853(rhs: Equations, tol: Tolerance, first_step: float) -> _Solver:
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


def _run_dop853(solver: _Solver, t: float, state: State, until: float) -> None:
    """Run ``solver`` (a ``_dop853``) from (t, state) to ``until`` (or until its solout stops
    it)."""
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


class _Watch:
    """The solout of a Fortran run: after every step it checks the watched overlaps for a sign
    change (an active contact released, an inactive one touching) and stops the run at the
    first step over which one changed. It keeps the last step before that (``last``: time,
    state, signed overlaps), the contacts that changed (``stop``) and the sampled path."""

    def __init__(self, watched: list[int], side: dict[int, float], t: float, state: State):
        self.watched = watched
        self.side = side  # per contact, the sign of its overlap before the event
        self.n = len(state) // 2
        self.last: tuple[float, State, list[float]] = (t, state, self.signed(state))
        self.stop: list[list[int]] = []
        self.times: list[float] = []
        self.rows: list[list[float]] = []

    def signed(self, s: State) -> list[float]:
        return [_signed_gap(j, s, self.side[j]) for j in self.watched]

    def across(self, j: int, y: float) -> bool:
        return y * self.side[j] < 0

    def __call__(self, tk: float, yk: State) -> int:
        if tk == self.last[0]:
            return 0  # the call at the start
        now = self.signed(yk)
        hits = [
            j
            for j, before, y in zip(self.watched, self.last[2], now, strict=True)
            if self.across(j, y) and not self.across(j, before)  # a crossing, not a start across
        ]
        if hits:
            self.stop.append(hits)
            return -1
        self.last = (tk, yk.copy(), now)
        self.times.append(tk)
        self.rows.append(list(yk[: self.n]))
        return 0


def _state_at(rhs: Equations, tol: Tolerance, ta: float, ya: State, when: float) -> State:
    """The state at time ``when`` >= ta, by one fresh step of the Fortran DOP853 from
    (ta, ya): a step's end, not an interpolant's."""
    if when <= ta:
        return ya
    step = _dop853(rhs, tol, when - ta)
    _run_dop853(step, ta, ya, when)
    result: State = step.y.copy()
    return result


def _locate(
    rhs: Equations,
    tol: Tolerance,
    j: int,
    side: float,
    start: tuple[float, State],
    end: tuple[float, State],
) -> tuple[float, int, State]:
    """When and where contact j, whose overlap had the sign ``side`` at the step's ``start``
    (time, state) and the other sign at its ``end``, touches or releases: the crossing is
    estimated from a cubic through both ends, then found by Newton's method on the true
    trajectory, each iterate a fresh integration from the step's start (``_state_at``)."""
    (ta, ya), (tb, yb) = start, end
    n = len(ya) // 2
    h = tb - ta
    g0, g1 = _gap(j, ya), _gap(j, yb)
    u = _hermite_root(g0, g1, _gap_rate(j, ya, n) * h, _gap_rate(j, yb, n) * h)
    when, low, high = ta + u * h, ta, tb
    for _ in range(_NEWTON_STEPS):
        s = _state_at(rhs, tol, ta, ya, when)
        y, rate = _gap(j, s), _gap_rate(j, s, n)
        if y * side < 0:  # across
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
            return when, j, s
        if not low < follow < high:  # outside the bracket, or back at an end: bisect
            follow = (low + high) / 2
        when = follow
    raise ArithmeticError(f"soft collision: contact {j}'s touch or release not located")


def ode_piece(
    rhs: Equations, t: float, state: State, active: Flags, watched: list[int], tol: Tolerance
) -> Piece:
    """Integrate with the Fortran DOP853 until a watched contact touches or releases.

    After every step the watched overlaps are checked for a sign change (``_Watch``). The
    first step over which one changed is taken apart: each crossing is located within it
    (``_locate``), so that the state at the event comes from a step, not from an interpolant;
    the piece ends at the earliest.
    """
    n = len(state) // 2
    side = {j: 1.0 if active[j] else -1.0 for j in watched}  # the sign before the event
    watch = _Watch(watched, side, t, state)
    solver = _dop853(rhs, tol, tol.scale * 1e-3)
    solver.set_solout(watch)
    _run_dop853(solver, t, state, t + 1e4 * tol.scale)
    if not watch.stop:
        return Piece(float(solver.t), solver.y.copy(), [], watch.times, watch.rows)
    start = watch.last[0], watch.last[1]
    end = float(solver.t), solver.y.copy()
    roots = [_locate(rhs, tol, j, side[j], start, end) for j in watch.stop[0]]
    first = min(when for when, _, _ in roots)
    at = next(s for when, _, s in roots if when == first)
    return Piece(
        first,
        at,
        [j for when, j, _ in roots if when == first],
        [*watch.times, first],
        [*watch.rows, list(at[:n])],
    )
