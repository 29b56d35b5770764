"""Laws of the projectile family and its envelope (mechmodel.lagrange.projectiles):
chapter 12, (12.14)-(12.17), Figs. 12.5-12.6.

Trajectories, the generating function S and its angle derivative, contact points and the
envelope, also found as the highest trajectory over all elevations (a bounded search).

Floats are compared within 1e-12 of the sum of the magnitudes involved, or within the
stated error of a numerical search or central difference; Fraction results must be exact.
Tolerances shared by the lagrange modules are in ``_lagrange_helpers``.
"""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from checks.properties._lagrange_helpers import FLOOR, REL
from checks.properties.closeness import assert_close, magnitude
from checks.properties.strategies import gravities, launch_angles, launch_speeds
from mechmodel import lagrange

pytestmark = pytest.mark.properties


@given(launch_speeds(), launch_angles(), gravities(), st.floats(min_value=-3, max_value=3))
def test_each_trajectory_touches_the_envelope_once_where_the_model_says(
    v0: float, alpha: float, g: float, offset: float
) -> None:
    """y_env(x) - y(x) = (g / 2 v0^2)(x tan a - v0^2/g)^2 >= 0 (from (12.14c) and (12.17)): every
    trajectory lies under the envelope and touches it at exactly one point, x = v0^2/(g tan a)
    (12.16c), where the two curves also share their slope (Figs. 12.5-12.6). The horizontal
    launch never touches it: a ValueError."""
    xc, yc = lagrange.contact_point(v0, alpha, g)
    x = xc * (1 + offset)
    gap = lagrange.envelope_height(x, v0, g) - lagrange.trajectory_height(x, v0, alpha, g)
    square = g / (2 * v0**2) * (x * math.tan(alpha) - v0**2 / g) ** 2
    scale = v0**2 / g + g * x**2 / v0**2 * (1 + math.tan(alpha) ** 2) + abs(x * math.tan(alpha))
    assert abs(gap - square) <= REL * 10 * scale
    assert gap >= -REL * 10 * scale
    height = lagrange.trajectory_height(xc, v0, alpha, g)
    assert_close(height, yc, scale=magnitude(height, yc, v0**2 / g), abs=FLOOR)
    h = 1e-6 * max(xc, 1e-3)
    slope_gap = (
        lagrange.envelope_height(xc + h, v0, g)
        - lagrange.envelope_height(xc - h, v0, g)
        - lagrange.trajectory_height(xc + h, v0, alpha, g)
        + lagrange.trajectory_height(xc - h, v0, alpha, g)
    ) / (2 * h)
    assert abs(slope_gap) <= 1e-6 * (1 + math.tan(alpha) + g * xc / v0**2)
    with pytest.raises(ValueError, match="horizontal"):  # y = -g x^2/2v0^2 stays below it
        lagrange.contact_point(v0, 0.0, g)


@given(launch_speeds(), launch_angles(), gravities(), st.floats(min_value=0, max_value=5))
@example(2.0, 0.0, 9.8, 1.0)  # a horizontal launch: y = -g x^2 / (2 v0^2)
def test_positions_lie_on_the_trajectory_curve(v0: float, alpha: float, g: float, t: float) -> None:
    """Eliminating t from x(t), y(t) (12.14a-b) gives y(x) (12.14c), whose form the symbolic
    derivation fixes: y = x tan a - g x^k / (d v0^j cos^l a)."""
    fam = lagrange.projectile_family()
    x, y = lagrange.trajectory_position(t, v0, alpha, g)
    height = lagrange.trajectory_height(x, v0, alpha, g)
    assert_close(y, height, scale=magnitude(y, height, v0 * t, g * t**2), abs=FLOOR)
    formula = x * math.tan(alpha) - g * x**fam.x_power / (
        float(fam.quadratic_denominator) * v0**fam.v0_power * math.cos(alpha) ** fam.cos_power
    )
    assert_close(formula, y, scale=magnitude(formula, y, v0 * t, g * t**2), abs=FLOOR)


def test_projectile_family_is_the_books_algebra() -> None:
    """The symbolic derivation gives (12.14)-(12.17): y = v0 sin(a) t - g t^2/2,
    y = x tan a - g x^2/(2 v0^2 cos^2 a), d(cos^-2 a)/da = 2 sin a/cos^3 a,
    1/cos^2 = 1 + tan^2, tan a = v0^2/(g x), y_env = v0^2/(2g) - g x^2/(2 v0^2), and only the
    horizontal trajectory shares the envelope's shape."""
    fam = lagrange.projectile_family()
    assert (fam.time_coefficient, fam.time_power) == (Fraction(1, 2), 2)
    assert (fam.quadratic_denominator, fam.x_power, fam.v0_power, fam.cos_power) == (
        Fraction(2),
        2,
        2,
        2,
    )
    assert (fam.secant_derivative_coefficient, fam.secant_derivative_cos_power) == (Fraction(2), 3)
    assert (fam.secant_tan_constant, fam.secant_tan_power, fam.tan_derivative_cos_power) == (
        Fraction(1),
        2,
        2,
    )
    assert (fam.contact_tan_v0_power, fam.contact_tan_square_v0_power) == (2, 4)
    assert (fam.envelope_constant_denominator, fam.envelope_constant_v0_power) == (Fraction(2), 2)
    assert fam.envelope_shape_angle == 0


# -- formula models: the trajectory family and its envelope ------------------------------------


@given(launch_speeds(), launch_angles(), gravities(), st.floats(min_value=0, max_value=5))
def test_generating_solution_vanishes_on_the_trajectory(
    v0: float, alpha: float, g: float, t: float
) -> None:
    """S(v0, a : x, y) (12.15) is zero at every point (x(t), y(t)) of the trajectory (12.14a-b)
    and grows by one for each unit the point lies lower."""
    x, y = lagrange.trajectory_position(t, v0, alpha, g)
    scale = abs(y) + v0 * t + g * t * t
    assert abs(lagrange.generating_solution(x, y, v0, alpha, g)) <= 1e-12 * (scale + 1)
    below = lagrange.generating_solution(x, y - 1, v0, alpha, g)
    assert abs(below - 1) <= 1e-12 * (scale + 1)


@given(
    launch_speeds(),
    st.floats(min_value=-1.4, max_value=1.4),
    gravities(),
    st.floats(min_value=-3, max_value=3),
)
def test_angle_derivative_is_the_slope_of_s_in_the_angle(
    v0: float, alpha: float, g: float, u: float
) -> None:
    """dS/da (12.16b) agrees with a central difference of S in the angle, at x in units of the
    reach v0^2/g; it is zero at the contact abscissa of the angle (12.16c)."""
    x = u * v0 * v0 / g
    h = 1e-5
    numeric = (
        lagrange.generating_solution(x, 0, v0, alpha + h, g)
        - lagrange.generating_solution(x, 0, v0, alpha - h, g)
    ) / (2 * h)
    exact_slope = lagrange.generating_angle_derivative(x, v0, alpha, g)
    size = (abs(x) + g * x * x / v0**2) / math.cos(alpha) ** 4
    assert abs(numeric - exact_slope) <= 1e-6 * (size + 1)
    if abs(alpha) > 0.05:
        xc = lagrange.contact_distance(v0, alpha, g)
        d = lagrange.generating_angle_derivative(xc, v0, alpha, g)
        assert abs(d) <= 1e-9 * (abs(xc) + g * xc * xc / v0**2) / math.cos(alpha) ** 4


@given(launch_speeds(), gravities(), st.floats(min_value=0.05, max_value=20))
@example(1.0, 1.0, 1.0)  # the 45-degree path touches the envelope at its landing point
def test_contact_slope_and_abscissa_are_inverse(v0: float, g: float, u: float) -> None:
    """The trajectory of slope tan a = contact_tangent(x) touches the envelope at x: its
    contact abscissa is x again, its height there is the envelope's, and dS/da vanishes
    (12.16c). Both signs of x."""
    for x in (u * v0 * v0 / g, -u * v0 * v0 / g):
        tan = lagrange.contact_tangent(x, v0, g)
        alpha = math.atan(tan)
        assert_close(lagrange.contact_distance(v0, alpha, g), x, rel=1e-12, abs=FLOOR)
        y = lagrange.trajectory_height(x, v0, alpha, g)
        assert abs(y - lagrange.envelope_by_maximum(x, v0, g)) <= 1e-10 * (
            v0 * v0 / g + g * x * x / v0**2
        )
    with pytest.raises(ValueError, match="x = 0"):
        lagrange.contact_tangent(0.0, v0, g)
    with pytest.raises(ValueError, match="horizontal"):
        lagrange.contact_distance(v0, 0.0, g)


@given(
    launch_speeds(),
    gravities(),
    st.floats(min_value=0.01, max_value=3),
    st.sampled_from([1, -1]),
    launch_angles(),
)
@example(1.0, 1.0, 0.0, 1, 0.7)  # x = 0: the top of the vertical launch, v0^2/(2g)
def test_envelope_by_maximum_bounds_every_trajectory(
    v0: float, g: float, u: float, sign: int, alpha: float
) -> None:
    """The highest point over all elevations at an abscissa lies above every trajectory there
    (also one launched backwards) and on the parabola v0^2/(2g) - g x^2/(2 v0^2) (12.17), at
    x from 1/100 to 3 reaches v0^2/g on either side, and at x = 0 (the vertical launch)."""
    x = sign * u * v0 * v0 / g
    top = lagrange.envelope_by_maximum(x, v0, g)
    scale = v0 * v0 / g + g * x * x / v0**2
    for a in (alpha, -alpha):
        assert lagrange.trajectory_height(x, v0, a, g) <= top + 1e-12 * scale
    assert abs(top - lagrange.envelope_height(x, v0, g)) <= 1e-12 * scale
