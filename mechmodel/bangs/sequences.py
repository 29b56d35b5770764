"""Velocity-only bang sequences of two balls under a ceiling (chapter 5, Fig. 5.1, (5.3)-(5.4)).

Ball 1 (mass m1) is below ball 2 (mass m2); a ceiling (an infinite mass at rest) is above
ball 2. From velocities (v1, v2) the balls bang when ball 1 gains on ball 2 and ball 2 bangs the
ceiling when it rises, until neither can happen: the 'game-over' point of (5.13). Only
velocities are followed (no heights or times: those are ``mechmodel.bangs.histories``).
Bang kinds follow the book's labels: ``"01"`` ball 1 off the floor (Bang-1(01)), ``"12"`` ball
1 hits ball 2 (Bang-2(12)), ``"02"`` ball 2 off the ceiling (Bang-3(20), Bang-11(02)).
Velocities positive up, in the units of the inputs; exact with ``Fraction`` inputs.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Final, Literal

from mechmodel import inputs
from mechmodel.bangs.bounces import ceiling_bounce
from mechmodel.collisions import collide
from mechmodel.typing import Real, not_monotonic

BangKind = Literal["01", "12", "02"]
FLOOR: Final = "01"
BALLS: Final = "12"
CEILING: Final = "02"


# -- velocity-only sequences under a ceiling (Fig. 5.1) ---------------------------------------
@dataclass(frozen=True)
class Bang:
    """One bang: ``"12"`` (ball 1 hits ball 2) or ``"02"`` (ball 2 off the ceiling), and the
    velocities (v1, v2) just after it."""

    kind: BangKind
    v1: Real
    v2: Real


@dataclass(frozen=True)
class BangSequence:
    """A sequence of bangs from a starting state to the last possible bang."""

    start: tuple[Real, Real]
    bangs: tuple[Bang, ...]

    @property
    def count(self) -> int:
        """How many bangs the sequence has, to its end."""
        return len(self.bangs)

    @property
    def velocities(self) -> tuple[tuple[Real, Real], ...]:
        """``velocities[k]`` is (v1, v2) after k bangs; ``velocities[0]`` is the start."""
        return (self.start, *((b.v1, b.v2) for b in self.bangs))


def bang_possible(v1: Real, v2: Real, *, floor: bool = False, ceiling: bool = True) -> bool:
    """Whether another bang can still happen to balls moving at (v1, v2).

    Ball 1 catches ball 2 if v1 > v2; ball 2 reaches a ceiling if it rises (v2 > 0); ball 1
    reaches a floor if it falls (v1 < 0). When none holds the sequence is over: the 'game-over'
    point of (5.13) and Exercise 1.5.1, after which the balls drift apart for good.
    """
    inputs.real(v1, "v1")
    inputs.real(v2, "v2")
    return v1 > v2 or (ceiling and v2 > 0) or (floor and v1 < 0)


def ceiling_sequence(m1: Real, m2: Real, v1: Real, v2: Real) -> BangSequence:
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
            bang = Bang(BALLS, hit.v1, hit.v2)
        elif b > 0:
            bang = Bang(CEILING, a, ceiling_bounce(b))
        else:
            break
        bangs.append(bang)
        a, b = bang.v1, bang.v2
    return BangSequence((v1, v2), tuple(bangs))


def velocities_after_bang(m1: Real, m2: Real, v1: Real, v2: Real, bang: int) -> tuple[Real, Real]:
    """(v1, v2) just after Bang-``bang`` of the book's numbering for Fig. 5.1.

    Bang-1 is the floor bounce F that left the balls at (v1, v2) = (1, -1) in (5.13); the ball
    and ceiling bangs of ``ceiling_sequence`` are Bang-2, Bang-3, ... (even bangs (12), odd
    bangs (02), as on p. 5). ``ValueError`` past the last bang of the sequence.
    """
    n = inputs.count(bang, "bang", minimum=1)
    states = ceiling_sequence(m1, m2, v1, v2).velocities
    if n > len(states):
        raise ValueError(f"the sequence ends at Bang-{len(states)}, before Bang-{n}")
    return states[n - 1]


@not_monotonic
def game_over_bang(m1: Real, m2: Real, v1: Real, v2: Real) -> int:
    """The number of the last bang of Fig. 5.1's sequence, counting the floor bounce as Bang-1.

    Without a second floor bounce the sequence (C M)^p ends when no bang can occur (5.13):
    the 'game-over' point of Exercise 1.5.1.
    """
    return 1 + ceiling_sequence(m1, m2, v1, v2).count


def bangs_in_chain(double_bangs: int, floor_bounces: int = 1) -> int:
    """Bangs in a chain of floor bounces followed by ``double_bangs`` (C M) pairs: (5.3)-(5.4).

    The p double-bangs (C M)^p after the floor bounce F make 2 p + 1 bangs in all.
    """
    p = inputs.count(double_bangs, "double_bangs")
    return inputs.count(floor_bounces, "floor_bounces") + 2 * p
