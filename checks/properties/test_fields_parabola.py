"""Laws of the parabola and the power-law forces (mechmodel.fields.parabola): chapter 9,
Figs. 9.1-9.4.

Floats are compared within 1e-12 of the sum of the magnitudes involved (a few ulps more where a
square root or a trigonometric function of a large phase intervenes, as said); Fraction inputs
must give exact equality.
"""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import assume, example, given
from hypothesis import strategies as st

from checks.properties.closeness import assert_close
from checks.properties.strategies import fraction_coefficients, rationals, slopes
from mechmodel import fields

pytestmark = pytest.mark.properties
REL = 1e-12


# --- the parabola: focus, directrix, kites (Figs. 9.1, 9.3, 9.4) ------------------------------


@given(fraction_coefficients(), slopes())
def test_parabola_points_are_as_far_from_focus_as_from_directrix(a: Fraction, x: float) -> None:
    """Every point of y = a x^2 is equally far from the focus and the directrix (Fig. 9.3b)."""
    geo = fields.parabola_geometry(float(a))
    to_focus = geo.focal_radius(x)
    to_directrix = geo.directrix_distance(x)
    assert_close(to_focus, to_directrix, rel=4 * REL, scale=to_focus + to_directrix)


@given(fraction_coefficients())
def test_parabola_lengths_are_exact(a: Fraction) -> None:
    """x^2 = 4 p y = 2 lambda y: lambda = 2p is the half-width at the focus, the tip's radius of
    curvature and the focus-directrix distance; the slope there is 1 (Figs. 9.3, 9.4)."""
    geo = fields.parabola_geometry(a)
    p, lam = geo.focal_height, geo.semi_latus_rectum
    assert lam == 2 * p == geo.focus_to_directrix == geo.tip_radius_of_curvature
    assert geo.height(lam) == p  # the latus rectum's ends are level with the focus
    assert geo.latus_end_slope == 1
    assert geo.focal_factor == 4
    assert geo.latus_factor == 2
    assert geo.directrix_height == -p


@given(fraction_coefficients(), slopes())
def test_force_triangle_altitude_is_constant(a: Fraction, x: float) -> None:
    """Each force triangle of U = a x^2 has the altitude 1/(2a) = lambda, and its hypotenuse is
    normal to the tangent (Fig. 9.1a); its base, the scaled force, is -x."""
    assume(abs(x) > 1e-6)
    tri = fields.force_triangle(float(a), x)
    assert_close(tri.altitude, 1 / (2 * float(a)), rel=4 * REL, scale=tri.altitude)
    assert_close(tri.base, -x, rel=4 * REL, scale=abs(x))
    slope = 2 * float(a) * x  # the tangent's direction (1, slope) is normal to the hypotenuse
    assert_close(
        tri.base + tri.altitude * slope,
        0.0,
        scale=abs(float(tri.base)) + abs(float(tri.altitude) * slope),
    )


@given(fraction_coefficients(), rationals(-10, 10, 12))
@example(Fraction(3), Fraction(0))  # the vertex: no force, no slope
def test_force_triangles_are_exact_and_alike_at_the_vertex(a: Fraction, x: Fraction) -> None:
    """On U = a x^2 the Hooke force is F = -dU/dx = -2 a x, minus the central difference
    quotient (exact for a parabola), and every force triangle has the scale and the altitude
    1/(2a) and the base -x, the vertex's too as the limit of its neighbours' (Fig. 9.1a)."""
    tri = fields.force_triangle(a, x)
    h = Fraction(1, 7)
    assert tri.force == -(a * (x + h) ** 2 - a * (x - h) ** 2) / (2 * h)
    assert tri.scale == tri.altitude == 1 / (2 * a)
    assert tri.base == -x


@given(fraction_coefficients(), rationals(-10, 10, 12))
@example(Fraction(3), Fraction(0))  # the tip, where the normal is the axis itself
def test_every_normal_meets_the_axis_lambda_above_its_point(a: Fraction, x: Fraction) -> None:
    """The normal at any point of y = a x^2 crosses the axis lambda = 1/(2a) higher up, the
    constant vertical of the tangent-kites of Fig. 9.4: the rise is x over the tangent's slope,
    a central difference quotient (exact for a parabola); at the tip, its limit lambda."""
    geo = fields.parabola_geometry(a)
    h = Fraction(1, 7)
    tangent = (geo.height(x + h) - geo.height(x - h)) / (2 * h)
    rise = geo.semi_latus_rectum if x == 0 else x / tangent
    assert geo.subnormal(x) == rise == 1 / (2 * a)


@given(fraction_coefficients(), st.integers(min_value=0, max_value=6), rationals(-10, 10, 12))
@example(Fraction(3), 1, Fraction(0))  # a linear potential pushes at the origin too
@example(Fraction(3), 0, Fraction(1))  # a constant potential does not push at all
def test_power_law_force_is_minus_the_slope(a: Fraction, n: int, x: Fraction) -> None:
    """F = -dU/dx of U = a x^n (Force = -Slope, (6.9); Hooke's F = -2x of Fig. 9.1b): x F = -n U
    exactly, as the power rule has it, and F is minus the complex-step slope of U; a power below
    1 has an infinite force at x = 0, a ValueError."""
    n = max(n, 1) if x == 0 else n
    force = fields.power_law_force(a, n, x)
    assert x * force == -n * a * x**n
    step = 1e-30
    expected = -(float(a) * (float(x) + step * 1j) ** n).imag / step
    assert_close(float(force), expected, scale=abs(expected) + float(a))
    if x == 0:
        assert force == (-a if n == 1 else 0)
        with pytest.raises(ValueError, match="infinite"):
            fields.power_law_force(a, Fraction(1, 2), x)


@given(fraction_coefficients(), fraction_coefficients())
def test_similar_triangles_square_exactly(x: Fraction, unit: Fraction) -> None:
    """The two-step construction of Fig. 9.1a gives y = x^2 / unit exactly (y = x^2 for the
    default unit 1)."""
    assert fields.parabola_point(x, unit) == x * x / unit
    assert fields.parabola_point(x) == x * x


@given(slopes())
@example(1.0)  # y = x and y = -x
@example(0.0)  # the axis: its normal is vertical, with no slope
def test_normal_lines_are_perpendicular(slope: float) -> None:
    """The lines y = s x and y = -x/s meet at 90 degrees (Fig. 9.2); a horizontal line's normal
    has no slope."""
    if slope == 0:
        with pytest.raises(ValueError, match="vertical"):
            fields.normal_slope(slope)
        return
    assume(abs(slope) > 1e-6)
    normal = fields.normal_slope(slope)
    assert_close(fields.angle_between_lines(slope, normal), math.pi / 2, rel=4 * REL, scale=1.0)


@given(slopes(), slopes())
@example(10.0, -10.0)  # steep lines either side of the vertical: an acute angle between them
def test_angle_between_lines_is_the_acute_angle_of_their_directions(s1: float, s2: float) -> None:
    """Lines of slopes s1 and s2 meet at the acute angle whose tangent is |s2 - s1| / |1 + s1 s2|
    (the cross and dot products of their directions (1, s1) and (1, s2)): 0 to 90 degrees, the
    90-degree marks of Fig. 9.2 for y = s x and y = -x/s."""
    expected = math.atan2(abs(s2 - s1), abs(1 + s1 * s2))
    assert_close(fields.angle_between_lines(s1, s2), expected, rel=4 * REL, scale=1.0)


@given(slopes())
def test_tangent_bisects_focal_radius_and_drop_line(slope: float) -> None:
    """At the point of slope s, the angle between focal radius and drop line is twice the angle
    between tangent and drop line (the reflection law of Figs. 9.3b, 9.4, 9.7)."""
    x = slope / 2  # on y = x^2 the slope 2x is s
    geo = fields.parabola_geometry(1)
    to_focus = math.atan2(geo.focal_height - geo.height(x), -x)  # direction to the focus
    drop = -math.pi / 2
    angle = abs(math.remainder(to_focus - drop, 2 * math.pi))
    assert_close(angle, fields.focal_drop_angle(abs(slope)), rel=1e-9, scale=math.pi)


# --- the formulas of chapter 9 as the book writes them: parabola by p or lambda ---------------


@given(fraction_coefficients(), st.integers(min_value=0, max_value=6), rationals(-10, 10, 12))
@example(Fraction(1), 2, Fraction(3))  # Fig. 9.1b: the Hooke line of U = x^2 has slope -2
def test_force_slope_is_the_power_rule_again(a: Fraction, n: int, x: Fraction) -> None:
    """The slope of F = -dU/dx for U = a x^n: x dF/dx = (n - 1) F (F goes as x^(n-1)),
    exactly; for the oscillator n = 2 it is the constant -2a of the straight Hooke line."""
    if x == 0:
        x = Fraction(1, 3)
    slope = fields.power_law_force_slope(a, n, x)
    assert x * slope == (n - 1) * fields.power_law_force(a, n, x)
    assert fields.power_law_force_slope(a, 2, x) == -2 * a


@given(fraction_coefficients())
@example(Fraction(1, 4))  # y = x^2: p = 1/4, lambda = 1/2
def test_parabola_by_focus_and_by_latus_agree(p: Fraction) -> None:
    """The parabola whose focus is p above its tip is the one of half-width lambda = 2p at the
    focus (Figs. 9.3-9.4): exactly; its tip is p below the focus and p above the directrix,
    the points lambda across are at the focus's height, and the tip's radius of curvature is
    lambda."""
    by_focus = fields.parabola_for_focus(p)
    assert by_focus.focal_height == p
    assert fields.parabola_for_latus(by_focus.semi_latus_rectum) == by_focus
    lam = by_focus.semi_latus_rectum
    assert by_focus.height(lam) == by_focus.focal_height == by_focus.tip_to_directrix
    assert by_focus.tip_radius_of_curvature == lam


@given(st.floats(min_value=0.01, max_value=100), st.floats(min_value=-10, max_value=10))
def test_parabola_slope_and_its_point_of_slope_one(p: float, x: float) -> None:
    """The slope of the parabola of focal height p is the derivative of its height (a central
    difference agrees); it is 1 at the end of the latus rectum, level with the focus, whose
    focal radius is then horizontal: its distance from the focus is its distance x across."""
    h = 1e-6 * max(abs(x), p)
    height = fields.parabola_height_for_focus
    difference = (height(p, x + h) - height(p, x - h)) / (2 * h)
    slope = fields.parabola_slope_for_focus(p, x)
    assert math.isclose(slope, difference, rel_tol=1e-6, abs_tol=1e-9 * (1 + abs(x) / p))
    point = fields.parabola_unit_slope_point(p)
    assert math.isclose(fields.parabola_slope_for_focus(p, point.x), 1, rel_tol=4 * REL)
    assert math.isclose(height(p, point.x), p, rel_tol=4 * REL)
    assert math.isclose(point.focal_distance, point.x, rel_tol=4 * REL)


@given(st.floats(min_value=0.01, max_value=100), st.floats(min_value=-30, max_value=30))
def test_the_equidistant_point_is_on_the_parabola(p: float, x: float) -> None:
    """The point found from the definition (as far from the focus as from the directrix) is
    at the height 4 p y = x^2 gives, and of the parabola of semi-latus rectum 2p."""
    y = fields.equidistant_height(p, x)
    assert math.isclose(math.hypot(x, y - p), y + p, rel_tol=1e-12)
    assert math.isclose(y, fields.parabola_height_for_focus(p, x), rel_tol=1e-9, abs_tol=1e-12 * p)
    latus = fields.equidistant_height_for_latus(2 * p, x)
    assert math.isclose(latus, y, rel_tol=1e-12, abs_tol=1e-15 * p)
