"""Towers of balls dropped onto the floor (chapter 8).

The balls fall together at speed ``v_drop``, the heaviest at the bottom, and every collision is
independent and elastic (Fig. 8.1(b): finite gaps between the balls).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from mechmodel import inputs
from mechmodel.collisions import Collision, collide


@dataclass(frozen=True)
class Tower:
    """A tower's ball-ball bangs, bottom first, and its balls' final velocities.

    ``rebound`` is ball 1's velocity just after the floor bounce; ``bangs[k]`` is Bang(k+2)
    between balls k+1 and k+2 (the book's Bang(2)12, Bang(3)23, ...), with its velocities before
    and after; ``velocities[k]`` is ball k+1's final velocity.
    """

    masses: tuple[Any, ...]
    rebound: Any
    bangs: tuple[Collision, ...]
    velocities: tuple[Any, ...]


def independent_tower(masses: Sequence[Any], v_drop: Any = 1) -> Tower:
    """Final velocities of an N-ball tower with independent collisions (Fig. 8.1(b), Fig. 8.2).

    Ball 1 rebounds elastically from the floor at +v_drop and meets ball 2, still falling at
    -v_drop (Bang(2)12); ball 2 leaves with its new velocity and meets ball 3, still falling
    (Bang(3)23); and so on up. Ball k's final velocity is the one it leaves its bang with ball
    k+1 with; the top ball's is the tower's launch speed. Later bangs between balls that may
    catch up again are not part of this construction. Exact with Fraction inputs.
    """
    if len(masses) < 1:
        raise ValueError("a tower needs at least one ball")
    for i, m in enumerate(masses):
        inputs.mass(m, f"masses[{i}]")
    inputs.positive(v_drop, "v_drop")
    rebound = rising = collide(math.inf, masses[0], 0, -v_drop).v2
    bangs = []
    for lower, upper in itertools.pairwise(masses):
        bangs.append(collide(lower, upper, rising, -v_drop))
        rising = bangs[-1].v2
    finals = (*(bang.v1 for bang in bangs), rising)
    return Tower(tuple(masses), rebound, tuple(bangs), finals)
