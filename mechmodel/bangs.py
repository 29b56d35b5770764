"""Sequences of bangs between two balls, the floor and the ceiling (chapters 4-5).

Collisions are independent (the book's "Bang-by-Bang" picture): each bang is an elastic
two-body collision (4.1), completed before the next begins, so only velocities matter. Ball 1
(mass m1) is below ball 2 (mass m2); the ceiling above ball 2 is an infinite mass at rest.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Literal

from mechmodel import inputs
from mechmodel.collisions import collide

BangKind = Literal["12", "02"]


@dataclass(frozen=True)
class Bang:
    """One bang: ``"12"`` (ball 1 hits ball 2) or ``"02"`` (ball 2 off the ceiling), and the
    velocities (v1, v2) just after it."""

    kind: BangKind
    v1: Any
    v2: Any


@dataclass(frozen=True)
class BangSequence:
    """A sequence of bangs from a starting state to the last possible bang."""

    start: tuple[Any, Any]
    bangs: tuple[Bang, ...]

    @property
    def count(self) -> int:
        """How many bangs the sequence has, to its end."""
        return len(self.bangs)

    @property
    def velocities(self) -> tuple[tuple[Any, Any], ...]:
        """``velocities[k]`` is (v1, v2) after k bangs; ``velocities[0]`` is the start."""
        return (self.start, *((b.v1, b.v2) for b in self.bangs))


def ceiling_sequence(m1: Any, m2: Any, v1: Any, v2: Any) -> BangSequence:
    """Bangs of ball 1 against ball 2 and of ball 2 against the ceiling, until neither can occur.

    Fig. 5.1 and (5.4): from (v1, v2) the balls collide when ball 1 gains on ball 2 (v1 > v2), and
    ball 2 bounces off the ceiling when it rises (v2 > 0). The two alternate, since an elastic
    bang leaves the balls separating and a ceiling bang leaves ball 2 falling: the matrix product
    (C M)^p of (5.3). Where both could come first (v1 > v2 > 0) the ball-ball bang is taken
    first. No floor intervenes, so the sequence ends when ball 2 is not rising and ball 1 does
    not gain on it. Exact with Fraction inputs.
    """
    inputs.mass(m1, "m1")
    inputs.mass(m2, "m2")
    a, b = inputs.real(v1, "v1"), inputs.real(v2, "v2")
    bangs: list[Bang] = []
    while True:
        if a > b:
            hit = collide(m1, m2, a, b)
            bang = Bang("12", hit.v1, hit.v2)
        elif b > 0:
            bang = Bang("02", a, collide(m2, math.inf, b, 0).v1)
        else:
            break
        bangs.append(bang)
        a, b = bang.v1, bang.v2
    return BangSequence((v1, v2), tuple(bangs))
