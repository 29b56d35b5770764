"""Laws of the shared numeric helpers (mechmodel.numeric): derivatives, line and clock angles.

Floats are compared within 1e-12 of the magnitudes involved; the central-difference log-slope
within its declared 1e-9.
"""

from __future__ import annotations

import cmath
import math
from fractions import Fraction

import mpmath
import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from checks.properties.closeness import assert_close
from checks.properties.strategies import force_powers, gaps, positive_quantities, velocities
from mechmodel import numeric

pytestmark = pytest.mark.properties
FLOOR = 1e-300  # below this, subnormal products carry no relative precision: an absolute floor
POWER = 1e-9  # a local power from a central difference in ln x


@given(st.floats(min_value=-5, max_value=5), st.floats(min_value=0.1, max_value=10))
def test_the_complex_step_takes_exact_derivatives(x: float, k: float) -> None:
    """d/dx of k x^3 is 3 k x^2 and of e^(k x) is k e^(k x), to rounding: the complex step
    takes no difference, so nothing cancels (the force -dU/dY of (6.11))."""
    cubic = numeric.complex_step_derivative(lambda u: k * u**3, x)
    step_term = k * 1e-59  # the step's own -k h^2, h = 1e-30: far below rounding
    assert_close(cubic, 3 * k * x * x, scale=4 * 3 * k * x * x, abs=step_term)
    growth = numeric.complex_step_derivative(lambda u: cmath.exp(k * u), x)
    assert_close(growth, k * math.exp(k * x), scale=4 * k * math.exp(k * x))


@given(positive_quantities(), force_powers(), gaps())
@example(2.0, -1.0, 1.0)  # the isothermal 1/Y law of (6.4)
def test_the_log_slope_is_the_local_power(c: float, n: float, x: float) -> None:
    """d ln f / d ln x of f = c x^n is n, whatever c and x (how a force scales with the gap,
    (6.4)-(6.6))."""
    assert_close(numeric.log_slope(lambda u: c * u**n, x), n, rel=POWER, scale=1 + abs(n))


@given(velocities())
@example(1.0)  # the 45 degree line of Fig. 2.1, line 2420
def test_line_angle_and_slope_are_inverse(slope: float) -> None:
    """tan(atan(s)) = s: the 45° line has slope 1 (Figs. 1.2, 2.1, line 2420); an angle lies in
    (-pi/2, pi/2); with mpmath the angle keeps its precision."""
    angle = numeric.line_angle(slope)
    assert -math.pi / 2 <= angle <= math.pi / 2
    assert math.isclose(numeric.line_slope(angle), slope, rel_tol=1e-12, abs_tol=FLOOR)
    with mpmath.workdps(40):
        precise = numeric.line_angle(mpmath.mpf(slope))
        assert abs(mpmath.tan(precise) - slope) <= mpmath.mpf(10) ** -35 * (1 + abs(slope))
    assert numeric.line_angle(1) == math.pi / 4


@given(st.integers(min_value=0, max_value=48), st.integers(min_value=1, max_value=48))
@example(3, 12)  # exercise 3 of chapter 1: 3 hours of the 12-point clock is 90°
@example(4, 16)  # a quarter of the 16-hour phasor clock of Fig. 9.10
def test_a_clock_angle_is_the_fraction_of_a_turn(hours: int, per_turn: int) -> None:
    """h hours of an N-hour clock sweep 2 pi h/N; N hours are the whole turn; an hour count
    that is not a whole number of hours per turn is refused."""
    angle = numeric.clock_angle(hours, per_turn)
    assert_close(angle, 2 * math.pi * float(Fraction(hours, per_turn)))
    assert_close(numeric.clock_angle(per_turn, per_turn), 2 * math.pi)
    with pytest.raises(ValueError, match="hours_per_turn"):
        numeric.clock_angle(hours, per_turn + 0.5)  # type: ignore[arg-type]  # on purpose
