"""Shared numeric helpers: derivatives taken numerically, and the angles of lines and clock hands.

Several chapters take a derivative of a function the model already has: the force -dU/dY of
the isothermal potential (6.11), the growth of the contact radius of (7.1a), the tangent of a
parabola (chapter 9), or the local power of a law (how a bang force scales with the gap,
(6.4)-(6.6)); several turn a slope
into the angle of its line (the 45 degree line of slope 1, Figs. 1.2, 2.1, 9.2) or a number of
hours into the angle of a clock hand (exercise 3 of chapter 1, the phasor clock of Fig. 9.10).
This module holds each of these once.

``complex_step_derivative`` is exact to rounding for functions written with plain operators
(or ``cmath``), since it takes no difference; ``log_slope`` is a central difference in ln x,
good to about 1e-9, for functions that are themselves computed numerically. The angles are
radians; they keep mpmath's precision for mpmath inputs and are floats otherwise.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import SupportsFloat

from mechmodel import inputs
from mechmodel.typing import Real, Scalar

_COMPLEX_STEP = 1e-30  # far below rounding: the complex-step slope is exact to rounding
_LOG_STEP = 1e-4  # step in ln x of the central-difference log-slope


def _is_mp(x: object) -> bool:
    return type(x).__module__.startswith("mpmath")


def complex_step_derivative(f: Callable[[complex], Scalar], x: Real) -> float:
    """df/dx at ``x`` by the complex step, Im f(x + i h) / h.

    ``f`` must be analytic near the real axis and written with plain operators (or ``cmath``),
    so that it accepts a complex argument; the result is exact to rounding.
    """
    return f(float(x) + 1j * _COMPLEX_STEP).imag / _COMPLEX_STEP


def log_slope(f: Callable[[float], SupportsFloat], x: Real) -> float:
    """Local power d ln|f| / d ln x at ``x > 0``: exactly n (to rounding) for f = c x^n.

    A central difference in ln x, so ``f`` may itself be computed numerically (a slope).
    """
    x = float(x)
    up, down = abs(float(f(x * math.exp(_LOG_STEP)))), abs(float(f(x * math.exp(-_LOG_STEP))))
    return (math.log(up) - math.log(down)) / (2 * _LOG_STEP)


def line_angle(slope: Real) -> float:
    """Angle (radians) of a line of slope ``slope`` = dy/dx from the horizontal axis,
    atan(slope), in (-pi/2, pi/2): the slope angle sigma of Fig. 1.2 (line 934: slope 1/1 is the
    45 degree diagonal), the equal-velocity line V2 = V1 of Fig. 2.1, the line y = x of
    Fig. 9.2."""
    inputs.real(slope, "slope")
    if _is_mp(slope):
        import mpmath

        return mpmath.atan(slope)
    return math.atan(slope)


def line_slope(angle: Real) -> float:
    """Slope tan(angle) of a line at ``angle`` radians from the horizontal axis: the inverse of
    ``line_angle``."""
    inputs.real(angle, "angle")
    if _is_mp(angle):
        import mpmath

        return mpmath.tan(angle)
    return math.tan(angle)


def clock_angle(hours: Real, hours_per_turn: int) -> float:
    """Angle (radians) swept by ``hours`` on a clock face of ``hours_per_turn`` equal hours:
    2 pi h / N (exercise 3 of chapter 1, lines 1859-1861: 3 hours of a 12-point clock is 90
    degrees; the phase of the 16-hour phasor clock of Fig. 9.10)."""
    inputs.real(hours, "hours")
    n = inputs.count(hours_per_turn, "hours_per_turn", minimum=1)
    if _is_mp(hours):
        import mpmath

        return 2 * +mpmath.pi * hours / n
    return 2 * math.pi * hours / n
