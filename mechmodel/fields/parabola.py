"""Power laws and the parabola's geometry (chapter 9, Figs. 9.1-9.4).

The parabola U = a x^2 drawn by similar triangles (Fig. 9.1a), the force F = -dU/dx of a power
law (Hooke's F = -2x of Fig. 9.1b) and its force triangle, the staircase of slopes s and -1/s
(Fig. 9.2), and the focus-directrix geometry of y = a x^2: focus p = 1/(4a), semi-latus rectum
lambda = 2p, the square kite of the slope-1 point (Figs. 9.3, 9.4, 9.7). Lengths in any one
unit, angles in radians. Plain operators: Fraction inputs give exact results, and the heights
``parabola_height_for_focus`` and ``parabola_height_for_latus`` take ``Symbolic`` arguments.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass
from typing import overload

from mechmodel import inputs
from mechmodel.fields.inverse_square_laws import power_law_calculus
from mechmodel.numeric import complex_step_derivative, line_angle
from mechmodel.typing import Real, Symbolic


def parabola_point(x: Real, unit: Real = 1) -> Real:
    """Height of the point of the parabola y = x^2 / unit above ``x``, by the two-step
    construction of Fig. 9.1a.

    Go up the vertical line at ``x`` to the 45-degree line (height x), across to the vertical line
    at ``unit``; the line from the origin through (unit, x) has slope x / unit and meets the
    vertical at ``x`` at the height x * x / unit: similar triangles multiply.
    """
    inputs.real(x, "x")
    inputs.positive(unit, "unit")
    slope = x / unit
    return slope * x


def power_law_force(a: Real, n: Real, x: Real) -> Real:
    """Force F(x) = -dU/dx of the power-law potential U(x) = a x^n (Force = -Slope, (6.9)).

    For the oscillator U = x^2 this is Hooke's law F = -2x of Fig. 9.1b.
    """
    inputs.real(a, "a")
    inputs.real(n, "n")
    inputs.real(x, "x")
    if x == 0 and n < 1:
        raise ValueError(f"the force of a x^{n} is infinite at x = 0")
    return -n * a * x ** (n - 1)


def power_law_force_slope(a: Real, n: Real, x: Real) -> Real:
    """Slope dF/dx of the force F = -dU/dx of U(x) = a x^n: the power rule applied twice
    (``power_law_calculus``). For the oscillator U = x^2 it is the constant slope of the Hooke
    line of Fig. 9.1b."""
    inputs.real(a, "a")
    inputs.real(n, "n")
    inputs.real(x, "x")
    first = power_law_calculus(n)  # dU/dx = a n x^(n-1)
    second = power_law_calculus(first.derivative_exponent)
    if x == 0 and second.derivative_exponent < 0 and first.derivative_coefficient != 0:
        raise ValueError(f"the force of a x^{n} has no slope at x = 0")
    if first.derivative_coefficient == 0 or second.derivative_coefficient == 0:
        return 0 * a
    return (
        -a
        * first.derivative_coefficient
        * second.derivative_coefficient
        * x ** (second.derivative_exponent)
    )


@dataclass(frozen=True)
class ForceTriangle:
    """The force triangle of Fig. 9.1a at the point (x, a x^2) of the parabola U = a x^2.

    ``force`` is the Hooke force -2 a x; ``scale`` the factor that makes the force vector equal and
    opposite to the coordinate x; ``base`` the scaled force (= -x) and ``altitude`` the triangle's
    height (constant, whatever x): its hypotenuse is normal to the parabola's tangent.
    """

    force: Real
    scale: Real
    base: Real
    altitude: Real


def force_triangle(a: Real, x: Real) -> ForceTriangle:
    """The force triangle at ``x`` on U = a x^2 (Fig. 9.1a): base F/(2a), altitude 1/(2a)."""
    inputs.positive(a, "a")
    force = power_law_force(a, 2, x)
    scale = -x / force if x != 0 else 1 / (2 * a)
    slope = 2 * a * x  # the tangent's slope: the normal drops 1/slope for each unit across
    base = force * scale
    # the normal through (x, a x^2) runs along (-slope, 1); it crosses the axis after -x across
    altitude = 1 / (2 * a) if slope == 0 else -base / slope
    return ForceTriangle(force, scale, base, altitude)


def normal_slope(slope: Real) -> Real:
    """Slope -1/s of the line normal to a line of slope s (Fig. 9.2: y = s x and y = -x/s)."""
    inputs.real(slope, "slope")
    if slope == 0:
        raise ValueError("a horizontal line has a vertical normal: no slope")
    return -1 / slope


def angle_between_lines(slope1: Real, slope2: Real) -> float:
    """Angle between two lines of the given slopes, radians, in [0, pi/2] (Fig. 9.2's 90-degree
    marks between y = s x and y = -x/s, and between y = x and y = -x)."""
    turn = abs(line_angle(slope1) - line_angle(slope2)) % math.pi
    return min(turn, math.pi - turn)


# --- the parabola: focus, directrix, latus rectum (Figs. 9.3, 9.4, 9.7) ----------------------


@dataclass(frozen=True)
class ParabolaGeometry:
    """Focus-directrix geometry of the parabola y = a x^2 (vertex at the origin).

    ``focal_height`` p = 1/(4a) is the focus above the tip and the directrix as far below it;
    ``semi_latus_rectum`` is the book's lambda = 2p, the half-width at the focus;
    ``focus_to_directrix`` is 2p = lambda; ``tip_to_directrix`` the tip's height above the
    directrix, p; ``tip_radius_of_curvature`` the radius of the osculating
    circle at the tip, also lambda; ``latus_end_slope`` the slope at (lambda, p), where the focal
    radius is horizontal (the square kite of Fig. 9.4); ``focal_factor`` is the 4 of
    x^2 = 4 p y, 1/(a p); ``latus_factor`` the 2 of x^2 = 2 lambda y, 1/(a lambda).
    """

    a: Real
    focal_height: Real
    semi_latus_rectum: Real
    focus_to_directrix: Real
    directrix_height: Real
    tip_to_directrix: Real
    tip_radius_of_curvature: Real
    latus_end_slope: Real
    focal_factor: Real
    latus_factor: Real

    def height(self, x: Real) -> Real:
        """The parabola's height a x^2 at ``x``."""
        return self.a * x * x

    def focal_radius(self, x: Real) -> float:
        """Distance from the point of the parabola above ``x`` to the focus."""
        dy = self.height(x) - self.focal_height
        return math.hypot(x, dy)

    def directrix_distance(self, x: Real) -> Real:
        """Distance from the point of the parabola above ``x`` down to the directrix."""
        return self.height(x) - self.directrix_height

    def subnormal(self, x: Real) -> Real:
        """Rise from the point above ``x`` to where its normal crosses the axis (= lambda)."""
        slope = 2 * self.a * x
        return self.semi_latus_rectum if slope == 0 else x / slope


def parabola_geometry(a: Real) -> ParabolaGeometry:
    """Focus, directrix and latus rectum of y = a x^2 (Figs. 9.3, 9.4; 4 p y = x^2 = 2 lambda y).

    Exact with a ``Fraction`` ``a``; the tip's radius of curvature is (1 + y'^2)^(3/2) / y'' at
    the tip, where y' = 0 and y'' = 2a.
    """
    inputs.positive(a, "a")
    p = 1 / (4 * a)
    lam = 1 / (2 * a)
    directrix = -p
    curvature = 2 * a  # y'' at the tip, where y' = 0
    return ParabolaGeometry(
        a=a,
        focal_height=p,
        semi_latus_rectum=lam,
        focus_to_directrix=p + p,
        directrix_height=directrix,
        tip_to_directrix=0 - directrix,  # the tip is at height 0
        tip_radius_of_curvature=1 / curvature,
        latus_end_slope=2 * a * lam,
        focal_factor=1 / (a * p),
        latus_factor=1 / (a * lam),
    )


# real in, real out (exact with Fractions); a complex x for the complex-step slope
# (parabola_slope_for_focus); sympy symbols for the formula claims
@overload
def parabola_height_for_focus(p: Real, x: Real) -> Real: ...
@overload
def parabola_height_for_focus(p: Real, x: complex) -> complex: ...
@overload
def parabola_height_for_focus(p: Symbolic, x: Symbolic) -> Symbolic: ...
def parabola_height_for_focus(p: Symbolic, x: Symbolic | complex) -> Symbolic | complex:
    """Height y above its tip of the point at ``x`` of the parabola whose focus is ``p`` above
    the tip (Fig. 9.3b): the point as far from the focus (0, p) as from the directrix y = -p,
    x^2 + (y - p)^2 = (y + p)^2, so y = x^2 / (4 p). Plain operators (exact, symbolic)."""
    return x * x / (4 * p)


def parabola_height_for_latus(lam: Symbolic, x: Symbolic) -> Symbolic:
    """Height y above its tip of the point at ``x`` of the parabola of semi-latus rectum
    ``lam`` (the half-width at the focus, Fig. 9.4): the focus is at p = lam / 2, so
    y = x^2 / (4 p) = x^2 / (2 lam)."""
    return parabola_height_for_focus(lam / 2, x)


def equidistant_height(p: float, x: float) -> float:
    """Height y of the point at ``x`` that is as far from the focus (0, p) as from the
    directrix y = -p (the parabola's definition, Fig. 9.3b), found as the root of
    |(x, y) - (0, p)| - (y + p), which is positive at y = 0 and negative far above (it tends
    to -2p): a check of 4 p y = x^2 that does not use it. Floats; p > 0."""
    from scipy.optimize import brentq  # imported where used, as elsewhere: scipy takes 0.3 s

    inputs.positive(p, "p")

    def excess(y: float) -> float:
        return math.hypot(x, y - p) - (y + p)

    if excess(0.0) <= 0:
        return 0.0  # x = 0: the tip
    top = p
    while excess(top) > 0:
        top *= 2
    return float(brentq(excess, 0.0, top, xtol=1e-15, rtol=4 * sys.float_info.epsilon))


def equidistant_height_for_latus(lam: float, x: float) -> float:
    """``equidistant_height`` for the parabola of semi-latus rectum ``lam``: at the focus's
    height the distance to the directrix is 2p, so the points there are 2p across: p = lam/2."""
    return equidistant_height(lam / 2, x)


def parabola_for_focus(p: Real) -> ParabolaGeometry:
    """The focus-directrix geometry of the parabola whose focus is ``p`` above its tip
    (Figs. 9.3-9.4): y = a x^2 with a its height at x = 1 (``parabola_height_for_focus``).
    Exact with a ``Fraction``."""
    inputs.positive(p, "p")
    return parabola_geometry(parabola_height_for_focus(p, 1))


def parabola_for_latus(lam: Real) -> ParabolaGeometry:
    """The geometry of the parabola y = a x^2 whose half-width at the focus is ``lam`` (the
    book's lambda): the points lam across are at the focus's height, a lam^2 = 1/(4a)
    (``parabola_geometry``'s focal height), so a = 1/(2 lam). Exact with a ``Fraction``."""
    inputs.positive(lam, "lam")
    return parabola_geometry(1 / (lam + lam))


def parabola_slope_for_focus(p: Real, x: Real) -> float:
    """Slope dy/dx at ``x`` of the parabola whose focus is ``p`` above its tip, by the complex
    step on its height (``parabola_height_for_focus``): the x/lambda = x/(2p) of Fig. 9.4."""
    inputs.positive(p, "p")
    inputs.real(x, "x")
    return complex_step_derivative(lambda u: parabola_height_for_focus(p, u), x)


@dataclass(frozen=True)
class UnitSlopePoint:
    """The point of slope 1 of a parabola (Figs. 9.4, 9.7): its distance ``x`` across from the
    axis and its distance ``focal_distance`` from the focus."""

    x: float
    focal_distance: float


def parabola_unit_slope_point(p: Real) -> UnitSlopePoint:
    """Where the parabola whose focus is ``p`` above its tip has slope 1: the slope is
    proportional to x (``parabola_slope_for_focus``), so x = 1 / (slope at x = 1); its distance
    from the focus follows from the point's height (``ParabolaGeometry.focal_radius``)."""
    x = 1 / parabola_slope_for_focus(p, 1)
    return UnitSlopePoint(x, parabola_for_focus(p).focal_radius(x))


def focal_drop_angle(slope: Real) -> float:
    """Angle between the focal radius and the vertical drop line to the directrix at the point of
    the parabola whose tangent has slope ``slope``, radians (Figs. 9.4, 9.7).

    The tangent bisects that angle (the reflection law of the parabola): the drop line makes
    pi/2 - atan(slope) with the tangent, so the angle is twice that. Slope 1 gives the right
    angle of the square kite ("twice 45 degrees gives 90").
    """
    return 2 * (math.pi / 2 - line_angle(slope))
