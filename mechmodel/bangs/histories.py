"""Space-time histories of two balls between a floor and a ceiling (chapter 4, Fig. 4.6-4.12).

Event-driven: between bangs the balls move at constant velocity along straight space-time
lines (Fig. 4.6-4.7); each bang (floor, ball-ball, ceiling) is an independent collision (ICM,
Fig. 4.3b). A history records every bang's time, heights (the space-space point y(n) of
Fig. 4.11) and velocities after it (the point v(n)). Heights, times and velocities are in the
units of the inputs (the book's scaled units); exact with ``Fraction`` inputs.
"""

from __future__ import annotations

from dataclasses import dataclass

from mechmodel import inputs
from mechmodel.bangs.bounces import ceiling_bounce, floor_bounce
from mechmodel.bangs.sequences import BALLS, CEILING, FLOOR, BangKind
from mechmodel.collisions import collide
from mechmodel.typing import Real, not_monotonic


# -- space-time histories (Fig. 4.6, 4.7, 4.11, 4.12) ----------------------------------------
@dataclass(frozen=True)
class Event:
    """A bang of a space-time history: Bang-``number`` of ``kind`` at ``time``.

    ``y1``, ``y2`` are the heights of the balls at the bang (the space-space point y(n) of
    Fig. 4.11) and ``v1``, ``v2`` their velocities just after it (the point v(n)).
    """

    number: int
    kind: BangKind
    time: Real
    y1: Real
    y2: Real
    v1: Real
    v2: Real


@dataclass(frozen=True)
class History:
    """Every bang of two balls between a floor and a ceiling, in order, from time 0.

    ``ended`` is True when no further bang can occur (the game-over point); False when the
    history stopped at ``max_bangs``.
    """

    masses: tuple[Real, Real]
    start: tuple[Real, Real, Real, Real]
    bangs: tuple[Event, ...]
    ended: bool

    @property
    def count(self) -> int:
        """How many bangs were recorded."""
        return len(self.bangs)

    def numbers(self, kind: BangKind) -> tuple[int, ...]:
        """The numbers n of the bangs Bang-n of one kind, in order."""
        return tuple(e.number for e in self.bangs if e.kind == kind)

    @property
    def floor_bangs(self) -> tuple[int, ...]:
        """Numbers of the floor bangs (01) of ball 1: Bang-1, Bang-7 in Fig. 4.7."""
        return self.numbers(FLOOR)

    @property
    def ball_bangs(self) -> tuple[int, ...]:
        """Numbers of the bangs (12) between the balls: Bang-2, 4, 6, 9 in Fig. 4.7."""
        return self.numbers(BALLS)

    @property
    def ceiling_bangs(self) -> tuple[int, ...]:
        """Numbers of the ceiling bangs (02) of ball 2: Bang-3, 5, 8 in Fig. 4.7."""
        return self.numbers(CEILING)

    def positions_at(self, t: Real) -> tuple[Real, Real]:
        """Heights (y1, y2) at time ``t`` >= 0 (the space-time paths between bangs)."""
        inputs.real(t, "t")
        if t < 0:
            raise ValueError("t must be >= 0")
        y1, y2, v1, v2 = self.start
        t0: Real = 0
        for e in self.bangs:
            if e.time > t:
                break
            t0, y1, y2, v1, v2 = e.time, e.y1, e.y2, e.v1, e.v2
        return y1 + v1 * (t - t0), y2 + v2 * (t - t0)


@not_monotonic
def bang_history(
    m1: Real,
    m2: Real,
    y1: Real,
    y2: Real,
    v1: Real,
    v2: Real,
    ceiling: Real | None = None,
    floor: Real | None = 0,
    floor_bounces: int | None = None,
    max_bangs: int = 1000,
) -> History:
    """Event-driven history of two point balls between a floor and a ceiling (Fig. 4.6-4.7).

    Ball 1 (mass m1, height y1, velocity v1) is below ball 2 (m2, y2, v2). ``ceiling`` is its
    height (None: no ceiling); ``floor`` the floor's height (None: no floor), open after
    ``floor_bounces`` bounces (None: never; 1 for Exercise 1.4.2's 'floor is open after
    Bang-1'). From time 0 each ball moves in a straight line until the next bang: ball 1 off the
    floor when it falls onto it, the balls when ball 1 catches ball 2, ball 2 off the ceiling
    when it rises to it. Bangs at the same instant are done in the order floor, balls, ceiling.
    Records up to ``max_bangs`` bangs; exact with Fraction inputs.
    """
    inputs.mass(m1, "m1")
    inputs.mass(m2, "m2")
    for value, name in ((y1, "y1"), (y2, "y2"), (v1, "v1"), (v2, "v2")):
        inputs.real(value, name)
    limit = inputs.count(max_bangs, "max_bangs")
    if ceiling is not None:
        inputs.real(ceiling, "ceiling")
    if floor is not None:
        inputs.real(floor, "floor")
    if floor_bounces is not None:
        floor_bounces = inputs.count(floor_bounces, "floor_bounces")
    if y1 > y2:
        raise ValueError("ball 1 must start below ball 2 (y1 <= y2)")
    if floor is not None and y1 < floor:
        raise ValueError("ball 1 must start on or above the floor")
    if ceiling is not None and y2 > ceiling:
        raise ValueError("ball 2 must start on or below the ceiling")

    t: Real = 0
    a, b, u, w = y1, y2, v1, v2
    bangs: list[Event] = []
    bounces = 0
    while len(bangs) < limit:
        floor_open = floor is None or (floor_bounces is not None and bounces >= floor_bounces)
        waits: list[tuple[Real, BangKind]] = []
        if floor is not None and not floor_open and u < 0:
            waits.append(((a - floor) / -u, FLOOR))
        if u > w:
            waits.append(((b - a) / (u - w), BALLS))
        if ceiling is not None and w > 0:
            waits.append(((ceiling - b) / w, CEILING))
        if not waits:
            return History((m1, m2), (y1, y2, v1, v2), tuple(bangs), True)
        dt, kind = min(waits, key=lambda item: item[0])  # ties: first listed wins
        t = t + dt
        a, b = a + u * dt, b + w * dt
        if kind == FLOOR:
            assert floor is not None  # a floor bang needs a floor
            a, u = floor, floor_bounce(u)
            bounces += 1
        elif kind == BALLS:
            b = a  # they meet: the same height
            hit = collide(m1, m2, u, w)
            u, w = hit.v1, hit.v2
        else:
            assert ceiling is not None  # a ceiling bang needs a ceiling
            b, w = ceiling, ceiling_bounce(w)
        bangs.append(Event(len(bangs) + 1, kind, t, a, b, u, w))
    return History((m1, m2), (y1, y2, v1, v2), tuple(bangs), False)
