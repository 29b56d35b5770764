"""Gravity inside and outside a uniform Earth (chapter 9).

Inside a uniform Earth of radius R the field grows linearly with the distance from the centre
(Fig. 9.7), F = -m g x / R, so a body in a straight tunnel oscillates harmonically with angular
frequency sqrt(g / R), the same as a circular orbit grazing the surface (Fig. 9.8). SI units in,
SI out (or any consistent units). Floats; mpmath numbers also work through ``sqrt`` of mpmath.
"""

from __future__ import annotations

import math
from typing import Any

from mechmodel import inputs


def circular_orbit_speed(g: Any, radius: Any) -> float:
    """Speed of a circular orbit at the surface, v0 = sqrt(g R) (eq. (9.7b))."""
    inputs.positive(g, "g")
    inputs.positive(radius, "radius")
    return math.sqrt(g * radius)


def tunnel_period(g: Any, radius: Any) -> float:
    """Period of a full oscillation through any straight tunnel, 2 pi sqrt(R / g) (eq. (9.8)).

    It does not depend on the chord: every tunnel is a harmonic oscillator with the same
    frequency sqrt(g / R).
    """
    inputs.positive(g, "g")
    inputs.positive(radius, "radius")
    return 2 * math.pi * math.sqrt(radius / g)


def tunnel_transit_time(g: Any, radius: Any) -> float:
    """Time to fall through a tunnel to the far end, half a period: pi sqrt(R / g) (Fig. 9.8)."""
    return tunnel_period(g, radius) / 2
