"""Bang counts and states of a ball pair under a ceiling in O(1): the rotation picture (chapter 5).

How many bangs ``mechmodel.bangs.sequences.ceiling_sequence`` makes, and the velocities after
its first n bangs, without simulating them: in mass-scaled velocities (5.6) each bang is a
reflection and each double bang a rotation by -2 phi (5.12)-(5.13), phi = atan(sqrt(m2/m1)).
Floats where a count is far from a boundary, mpmath near one, the exact sequence at a true tie.
Velocities in the units of the inputs (the book's scaled units); angles in radians.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

from mechmodel import inputs
from mechmodel.bangs.sequences import BALLS, CEILING, BangKind, ceiling_sequence
from mechmodel.typing import Real, not_monotonic

# -- the rotation picture: counts and states in O(1) (chapter 5) -------------------------------
# In mass-scaled velocities V = (v1 sqrt(m1), v2 sqrt(m2)) (5.6) both bangs are reflections that
# keep |V|: a ball bang across the collision line v1 = v2, at angle phi = atan(sqrt(m2/m1)), a
# ceiling bang across the V1 axis; a double bang turns V by -2 phi (5.12). With alpha the polar
# angle of V in (-pi, pi], a ball bang is possible iff alpha lies in (phi - pi, phi) (v1 > v2) and
# a ceiling bang iff alpha lies in (0, pi) (v2 > 0). From a ball bang at angle a the k-th ball
# bang happens iff a - 2 k phi > phi - pi and the k-th ceiling bang iff a - 2 k phi > 2 phi - pi:
# the counts are ceilings of A = (a - phi + pi)/(2 phi) and A - 1/2, computed in floats where
# they are far from a whole number and with mpmath near one.
_TIE_MARGIN = 1e-9  # relative distance from a whole number below which floats are not trusted


@dataclass(frozen=True)
class BangCount:
    """How many bangs a ball pair under a ceiling makes, from the rotation picture.

    ``first`` is the kind of the first bang (None when no bang can happen).
    """

    ball_bangs: int
    ceiling_bangs: int
    first: BangKind | None

    @property
    def total(self) -> int:
        """All bangs of the sequence."""
        return self.ball_bangs + self.ceiling_bangs


def _angles(m1: Real, m2: Real, v1: Real, v2: Real, *, precise: bool) -> tuple[Real, Real]:
    """(phi, alpha): the collision line's angle and the state's polar angle in V space."""
    if precise:
        import mpmath

        def to_mp(x: Any) -> Any:  # a Real or an mpmath number (mpmath is untyped)
            return (
                mpmath.mpf(x.numerator) / x.denominator
                if hasattr(x, "denominator")
                else (mpmath.mpf(x))
            )

        m1, m2, v1, v2 = (to_mp(x) for x in (m1, m2, v1, v2))
        return mpmath.atan(mpmath.sqrt(m2 / m1)), mpmath.atan2(
            v2 * mpmath.sqrt(m2), v1 * mpmath.sqrt(m1)
        )
    m1, m2, v1, v2 = (float(x) for x in (m1, m2, v1, v2))
    return math.atan(math.sqrt(m2 / m1)), math.atan2(v2 * math.sqrt(m2), v1 * math.sqrt(m1))


@not_monotonic
def bang_count(m1: Real, m2: Real, v1: Real, v2: Real) -> BangCount:
    """How many bangs ``ceiling_sequence`` makes, in O(1): no bang is simulated.

    The rotation picture (5.12)-(5.13) of the comment above. Where a count's boundary falls
    within a relative 1e-9 of a whole number the angles are recomputed with mpmath at enough
    digits (more for a wide mass ratio or a wide spread of the speeds); a true tie (a later
    state exactly on a boundary: v1 = v2 or v2 = 0 after some bangs) is settled by simulating
    the inputs' exact rational values. The first bang's kind is decided exactly on the given
    velocities. The counts are those of the inputs' exact values: they agree with
    ``ceiling_sequence`` (the reference) run exactly, and with a float run wherever its
    rounding decides no bang (near a boundary, 2 v_com - v1 can lose a tiny velocity).
    """
    inputs.mass(m1, "m1")
    inputs.mass(m2, "m2")
    inputs.real(v1, "v1")
    inputs.real(v2, "v2")
    if v1 == 0 and v2 == 0:
        return BangCount(0, 0, None)
    # enough digits for the mass ratio and for the velocities' spread (a v2 of 1e-300 beside a
    # v1 of 1 moves a boundary by 1e-300)
    speeds = [abs(float(v)) for v in (v1, v2) if v]
    spread = math.log10(max(speeds)) - math.log10(min(speeds)) if all(speeds) else 0.0
    digits = 30 + int(abs(math.log10(float(m1) / float(m2))) + spread)
    for precise in (False, True):
        counts = _count_at(m1, m2, v1, v2, precise=precise, digits=digits)
        if counts is not None:
            return counts
    # a true tie: the exact values of the inputs are simulated without rounding
    sequence = ceiling_sequence(*(_exact(x) for x in (m1, m2, v1, v2)))
    balls = sum(b.kind == BALLS for b in sequence.bangs)
    first = sequence.bangs[0].kind if sequence.bangs else None
    return BangCount(balls, sequence.count - balls, first)


def _exact(x: Real) -> Real:
    """The exact rational value of an int, float, Fraction or Decimal; other numbers as given."""
    try:
        return Fraction(x)
    except TypeError:
        return x


def _count_at(
    m1: Real, m2: Real, v1: Real, v2: Real, *, precise: bool, digits: int
) -> BangCount | None:
    """The counts at float or mpmath precision, or None if a boundary is too close to call."""
    import mpmath

    with mpmath.workdps(digits):
        phi, alpha = _angles(m1, m2, v1, v2, precise=precise)
        pi = mpmath.pi if precise else math.pi
        half = mpmath.mpf(1) / 2 if precise else 0.5
        margin = mpmath.mpf(10) ** (10 - digits) if precise else _TIE_MARGIN
        # which bang comes first is decided on the velocities themselves, exactly: the angles
        # of a state on a boundary (v1 = v2, v2 = 0) can round to either side
        ceiling_first = 0
        first: BangKind
        if v1 > v2:
            first, start = BALLS, alpha
        elif v2 > 0:
            first, start, ceiling_first = CEILING, -alpha, 1
            if not v1 > -v2:  # after the ceiling bang the balls do not close
                return BangCount(0, 1, first)
        else:
            return BangCount(0, 0, None)
        big_a = (start - phi + pi) / (2 * phi)
        big_b = big_a - half
        for x in (big_a, big_b):
            if abs(x - round(x)) <= margin * max(1, abs(x)):
                return None
        ceil = mpmath.ceil if precise else math.ceil
        balls, ceilings = int(ceil(big_a)), int(ceil(big_b))
        return BangCount(balls, max(0, ceilings) + ceiling_first, first)


def state_after_bangs(m1: Real, m2: Real, v1: Real, v2: Real, n: int) -> tuple[float, float]:
    """(v1, v2) after the first ``n`` bangs of ``ceiling_sequence``, in O(1) (floats).

    Each ball bang reflects the V-space angle across phi (alpha -> 2 phi - alpha), each ceiling
    bang across 0 (alpha -> -alpha); |V| is kept. ``ValueError`` past the sequence's end.
    """
    n = inputs.count(n, "n")
    count = bang_count(m1, m2, v1, v2)
    if n > count.total:
        raise ValueError(f"the sequence has {count.total} bangs, fewer than {n}")
    phi, alpha = _angles(m1, m2, v1, v2, precise=False)
    radius = math.hypot(float(v1) * math.sqrt(float(m1)), float(v2) * math.sqrt(float(m2)))
    if count.first == CEILING and n >= 1:
        alpha, n = -alpha, n - 1
    alpha -= 2 * phi * (n // 2)  # each double bang (ball, then ceiling) turns by -2 phi
    if n % 2:
        alpha = 2 * phi - alpha
    return (
        radius * math.cos(alpha) / math.sqrt(float(m1)),
        radius * math.sin(alpha) / math.sqrt(float(m2)),
    )
