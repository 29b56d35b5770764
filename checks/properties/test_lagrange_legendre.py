"""Laws of the Legendre contact transformation (mechmodel.lagrange.legendre): chapter 12,
(12.10)-(12.13), Figs. 12.3-12.4.

The numerical Legendre transform is checked against sympy's symbolic one, within the
stated error of its bounded scalar search (``SEARCH``).
Floats are compared within 1e-12 of the sum of the magnitudes involved; Fraction results
must be exact. Tolerances shared by the lagrange modules are in ``_lagrange_helpers``.
"""

from __future__ import annotations

from collections.abc import Callable
from fractions import Fraction
from functools import cache

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from checks.properties._lagrange_helpers import FLOOR
from checks.properties.closeness import assert_close, magnitude
from checks.properties.strategies import (
    convex_lagrangian_coefficients,
    exact_masses,
    exact_velocities,
    legendre_slopes,
)
from mechmodel import lagrange

pytestmark = pytest.mark.properties
SEARCH = 1e-9  # relative error allowed to a Legendre value found by a bounded scalar search


def _quartic(a: float, b: float) -> Callable[[float], float]:
    return lambda v: a * v**2 / 2 + b * v**4 / 4


def _hamiltonian(a: float, b: float, p: float) -> lagrange.LegendreResult:
    bound = abs(p) / a + 1  # |L'(v)| >= a |v|, so the contact velocity is inside
    return lagrange.legendre_transform(_quartic(a, b), p, -bound, bound)


@settings(max_examples=50)
@given(convex_lagrangian_coefficients(), legendre_slopes())
@example((1.0, 0.0), 1.6)  # the quadratic L of Fig. 12.3's momentum
def test_legendre_transform_is_an_involution(coefficients: tuple[float, float], v: float) -> None:
    """Transforming L(v) to H(p) = max_v (p v - L) and H back gives L again (12.11a-b):
    the Legendre contact transformation is its own inverse for a convex L (Fig. 12.9)."""
    a, b = coefficients
    top = a * (abs(v) + 1) + b * (abs(v) + 1) ** 3  # |H'(p)| reaches |v| inside [-top, top]
    back = lagrange.legendre_transform(lambda p: _hamiltonian(a, b, p).value, v, -top, top)
    lag = _quartic(a, b)(v)
    assert abs(back.value - lag) <= SEARCH * (abs(lag) + abs(v) * top + 1)


@given(convex_lagrangian_coefficients(), legendre_slopes())
def test_hamiltonian_is_pv_minus_l_at_the_tangent_point(
    coefficients: tuple[float, float], p: float
) -> None:
    """H(p) = p v - L(v) (12.11b) at the velocity v where L has slope p: dL/dv = p there
    (12.10a), the tangent contact of Fig. 12.3."""
    a, b = coefficients
    h = _hamiltonian(a, b, p)
    v = h.argument
    contact = p * v - _quartic(a, b)(v)
    assert_close(h.value, contact, scale=magnitude(h.value, contact, p * v), abs=FLOOR)
    slope = a * v + b * v**3
    assert abs(slope - p) <= 1e-6 * (abs(p) + 1)
    with pytest.raises(ValueError, match="lower < upper"):
        lagrange.legendre_transform(_quartic(a, b), p, v, v)  # an empty search interval


@cache
def _sympy_hamiltonians() -> list[tuple[Callable[..., float], Callable[..., float]]]:
    """H(p) of L = m v^2/2 + c v and of L = m (e^v - 1 - v), derived by sympy: solve
    dL/dv = p for v (one real root each) and put it into p v - L."""
    import sympy

    v, p, m, c = sympy.symbols("v p m c", real=True)
    out = []
    for lag in (m * v**2 / 2 + c * v, m * (sympy.exp(v) - 1 - v)):
        (vp,) = sympy.solve(sympy.Eq(sympy.diff(lag, v), p), v)
        h = sympy.simplify(p * vp - lag.subs(v, vp))
        out.append((sympy.lambdify((m, c, v), lag, "math"), sympy.lambdify((m, c, p), h, "math")))
    return out


@settings(max_examples=50)
@given(
    st.floats(min_value=0.2, max_value=5),
    st.floats(min_value=-2, max_value=2),
    legendre_slopes(),
    st.sampled_from([0, 1]),
)
def test_legendre_transform_matches_sympy(m: float, c: float, p: float, which: int) -> None:
    """The numerical transform agrees with sympy's symbolic H(p) = p v(p) - L(v(p)) for a
    shifted quadratic and an exponential Lagrangian (12.11b)."""
    if which == 1:
        p = max(p, -0.9 * m)  # e^v - 1 > -1: slopes of the exponential L exceed -m
    lag, ham = _sympy_hamiltonians()[which]
    bound = (abs(p) + abs(c)) / m + 5  # beyond the contact velocity of either Lagrangian
    got = lagrange.legendre_transform(lambda v: lag(m, c, v), p, -bound, bound)
    want = ham(m, c, p)
    assert abs(got.value - want) <= SEARCH * (abs(want) + abs(p) * bound + 1)


@given(exact_masses(), exact_velocities())
@example(Fraction(8, 5), Fraction(1))  # Fig. 12.3: L = 1.0 at v = 1.0 with slope p = 1.6
def test_legendre_tangents_meet_the_axes_at_minus_the_transform(m: Fraction, v: Fraction) -> None:
    """The tangent to L = m v^2/2 at v has slope p = dL/dv = m v (12.10a) and meets the L axis
    at L - p v = -H(p), H = p^2/(2m) (12.11b, Fig. 12.3a); the tangent to H at p, of slope
    v = dH/dp, meets the H axis at -L (12.11a, Fig. 12.3b). Exact."""
    lag = lagrange.kinetic_energy([m], [v])
    (p,) = lagrange.momenta([m], [v])
    ham = lagrange.hamiltonian_free([m], [p])
    tangent = lagrange.legendre_tangent(lag, p, v)
    assert (tangent.transform, tangent.intercept) == (ham, -ham)
    back = lagrange.legendre_tangent(ham, v, p)
    assert (back.transform, back.intercept) == (lag, -lag)


# -- formula models: the Legendre pair ---------------------------------------------------------


@given(exact_velocities(), exact_masses())
@example(Fraction(1), Fraction(8, 5))  # Fig. 12.3: v = 1.0, p = 1.6
def test_legendre_pair_is_half_pv_both_ways(v: Fraction, m: Fraction) -> None:
    """For L = m v^2/2 and p = m v: L = v p/2 and H = p v/2 numerically (line 13716), and
    H = p v - L is the Legendre transform (12.11b); exact. A zero velocity, or a p/v that is no
    positive mass, is an error."""
    if v == 0:
        v = Fraction(1)
    p = m * v
    pair = lagrange.quadratic_legendre_pair(v, p)
    assert pair.mass == m
    assert pair.lagrangian == pair.hamiltonian == p * v / 2
    assert pair.hamiltonian == lagrange.legendre_tangent(pair.lagrangian, p, v).transform
    with pytest.raises(ValueError, match="non-zero"):
        lagrange.quadratic_legendre_pair(0, p)
    with pytest.raises(ValueError, match="positive"):
        lagrange.quadratic_legendre_pair(v, -p)
