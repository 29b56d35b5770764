"""Laws of loop integrals and Cauchy's formulas (mechmodel.complexfields.loops and .cauchy):
chapter 10, (10.37)-(10.39), (10.44)-(10.45).

Contour integrals are numerical and carry their own error estimate; a law holds within that
estimate (plus a few units of rounding of the float result).

Shared helpers of the complexfields modules are in ``_complexfields_helpers``.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import example, given, target

from checks.properties.closeness import assert_close
from checks.properties.strategies import gaussian_integers, laurent_terms, loop_circles
from mechmodel import complexfields as cf
from mechmodel.complexfields import cauchy

pytestmark = pytest.mark.properties
EPS = 2.0**-52


# --- loop integrals and the line source (10.37)-(10.39) ---------------------------------------


@pytest.mark.parametrize(("lowest", "highest"), [(-9, 0), (-2, 7)])
def test_the_loop_scan_stays_where_its_rule_is_exact(lowest: int, highest: int) -> None:
    """The 16-node rule (checked on 8 nodes) integrates z^n exactly only for |n + 1| < 8
    (10.39): a scan of the loop integrals beyond that is refused."""
    with pytest.raises(ValueError, match="scan range"):
        cf.nonzero_loop_powers(lowest, highest)


@given(
    laurent_terms().map(lambda ts: [t for t in ts if t[2] >= 0] or [(1.0, 0.0, 0)]), loop_circles()
)
def test_the_loop_integral_of_an_analytic_function_vanishes(
    terms: list[tuple[float, float, int]], circle: tuple[float, float, float]
) -> None:
    """Cauchy's theorem: a polynomial (analytic everywhere) has zero loop integral around any
    circle (10.39)."""
    loop = cf.laurent_loop_integral([list(t) for t in terms], *circle)
    scale = (
        sum(
            abs(complex(re, im)) * (abs(complex(*circle[:2])) + circle[2]) ** k
            for re, im, k in terms
        )
        * 2
        * math.pi
        * circle[2]
    )
    tol = loop.real.error + 1e-12 * scale
    target(abs(complex(loop.real.value, loop.imag.value)) / (scale or 1), label="relative loop")
    assert abs(loop.real.value) <= tol
    assert abs(loop.imag.value) <= tol


@given(laurent_terms(), loop_circles())
@example([(7.0, -3.0, -1)], (0.0, 0.0, 2.0))
def test_a_pole_gives_its_residue(
    terms: list[tuple[float, float, int]], circle: tuple[float, float, float]
) -> None:
    """The loop integral of sum c_k z^k is 2 pi i c_-1 if the circle encloses the pole at the
    origin and zero if it does not (10.39), (10.44). The error estimate of the double-precision
    rule never claims more than double precision: it is at least eps |result|."""
    cx, cy, radius = circle
    loop = cf.laurent_loop_integral([list(t) for t in terms], cx, cy, radius)
    residue = sum(complex(re, im) for re, im, k in terms if k == -1)
    expected = 2j * math.pi * residue if abs(complex(cx, cy)) < radius else 0j
    got = complex(loop.real.value, loop.imag.value)
    size = max(abs(complex(re, im)) for re, im, _ in terms)
    reach = max(abs(complex(cx, cy)) + radius, 1 / max(abs(abs(complex(cx, cy)) - radius), 1e-3))
    tol = loop.real.error + 1e-12 * size * 2 * math.pi * radius * reach**4
    assert abs(got - expected) <= tol
    assert loop.real.error >= EPS * abs(got)


@pytest.mark.parametrize(
    ("centre", "allowed"), [(11.0, True), (10.95, False), (-9.0, True), (-9.1, False)]
)
def test_a_loop_may_pass_no_closer_to_the_pole_than_a_tenth_of_its_radius(
    centre: float, allowed: bool
) -> None:
    """A circle of radius 10 whose edge passes 1 = r/10 from the pole of 1/z is integrated (to
    zero outside, 2 pi i inside: (10.39)); one passing closer is refused."""
    if not allowed:
        with pytest.raises(ValueError, match="too close"):
            cf.laurent_loop_integral([[1, 0, -1]], centre, 0, 10)
        return
    loop = cf.laurent_loop_integral([[1, 0, -1]], centre, 0, 10)
    expected = 2j * math.pi if abs(centre) < 10 else 0j
    assert abs(complex(loop.real.value, loop.imag.value) - expected) <= loop.real.error + 1e-12


@pytest.mark.parametrize("n", range(-9, 8))
def test_only_the_monopole_term_has_a_loop_integral(n: int) -> None:
    """The loop integral of a (z - c)^n around c is 2 pi i a for n = -1 and zero otherwise
    (10.39), (10.45), at 30 digits; by default for the unit source on the unit circle. The
    error estimate is never below the working precision of the result. The rule on 16 nodes
    (and its check on 8) is exact only for |n + 1| < 8: other powers are refused."""
    if not -8 < n + 1 < 8:
        with pytest.raises(ValueError, match=r"power must be in \(-9, 7\)"):
            cf.power_loop_integral(n)
        return
    cases = ((1 + 0j, 0j, 1.0), (-2 + 3j, 0.5 - 1.5j, 0.25), (0.5j, -3 + 1j, 4.0))
    for a, centre, radius in (*cases, (300 - 400j, 0j, 2.0)):
        loop = cf.power_loop_integral(n, a.real, a.imag, centre.real, centre.imag, radius)
        expected = 2j * math.pi * a if n == -1 else 0j
        got = complex(loop.real.value, loop.imag.value)
        assert abs(got - expected) <= loop.real.error + 1e-14 * (1 + abs(a))
        assert loop.real.error >= 10.0**-cf.DIGITS * abs(got)
    unit = cf.power_loop_integral(n)
    got = complex(unit.real.value, unit.imag.value)
    assert abs(got - (2j * math.pi if n == -1 else 0j)) <= unit.real.error + 1e-14


@given(gaussian_integers())
def test_a_line_source_has_flux_2_pi_re_a_and_circulation_minus_2_pi_im_a(
    a: tuple[int, int],
) -> None:
    """Im loop f dz counts the real source (flux) and Re loop f dz the imaginary source
    (vorticity) of f = a/z (10.37)-(10.39), Figs. 10.9-10.10."""
    src = cf.line_source(*a)
    tol = src.flux.error + 1e-13 * (1 + abs(complex(float(a[0]), float(a[1]))))
    assert_close(src.flux.value, 2 * math.pi * float(a[0]), rel=0, abs=tol)
    assert_close(src.circulation.value, -2 * math.pi * float(a[1]), rel=0, abs=tol)
    assert (src.star_numerator_re, src.star_numerator_im) == (a[0], -a[1])
    unit = cf.line_source()  # the unit real source a = q = 1 of Fig. 10.9(a)
    assert_close(unit.flux.value, 2 * math.pi, rel=0, abs=unit.flux.error + 1e-13)
    assert_close(unit.circulation.value, 0, rel=0, abs=unit.circulation.error + 1e-13)


# --- Laurent coefficients and Cauchy's formulas (10.44)-(10.45) -------------------------------


@pytest.mark.parametrize("index", range(-5, 6))
def test_contour_integration_recovers_every_laurent_coefficient(index: int) -> None:
    """a_n = (1/(2 pi i)) loop z^(-n-1) f(z) dz for every n of a test Laurent series (10.44)."""
    check = cf.laurent_coefficient_check(index)
    assert_close(check.two_pi.value, 2 * math.pi, rel=0, abs=check.two_pi.error + 1e-14)
    assert abs(check.residual.value) <= check.residual.error + 1e-14
    assert check.weight_power == -index - 1
    with pytest.raises(ValueError, match="index"):
        cf.laurent_coefficient_check(index + 11 if index < 0 else index - 11)


@pytest.mark.parametrize("order", range(7))
def test_cauchys_derivative_formula_holds_for_every_order(order: int) -> None:
    """f^(n)(a) = (n!/(2 pi i)) loop f(z)/(z - a)^(n+1) dz (10.45), and the kernel power n + 1
    is the only one that works."""
    d = cf.cauchy_derivative(order)
    assert_close(d.two_pi.value, 2 * math.pi, rel=0, abs=d.two_pi.error + 1e-14)
    # the integral is 2 pi/|b - a|^(n+1) while the integrand reaches r^-n/(|b - a| + r) on the
    # circle |z - a| = r: at DIGITS digits, that cancellation bounds the relative precision
    distance, r = abs(cauchy._CAUCHY_POLE - cauchy._CAUCHY_CENTER), cauchy._CAUCHY_RADIUS
    floor = 10.0**-cf.DIGITS * (distance / r) ** order * distance / (distance + r)
    for part, size in ((d.two_pi, 2 * math.pi), (d.numerator, math.factorial(order))):
        assert part.error >= floor * size
    assert_close(d.numerator.value, math.factorial(order), rel=0, abs=d.numerator.error + 1e-12)
    assert_close(d.taylor_numerator.value, 1.0, rel=0, abs=d.taylor_numerator.error + 1e-14)
    assert cf.cauchy_kernel(order).power == order + 1


@pytest.mark.parametrize("index", range(-5, 6))
def test_the_laurent_weight_is_z_to_minus_n_minus_one(index: int) -> None:
    """The loop integral (1/(2 pi i)) loop z^p f dz returns a_n for p = -n - 1 only (10.44)."""
    p = cf.laurent_weight_power(index)
    assert p == -index - 1
    z = complex(0.7, -0.4)
    assert cf.laurent_weight_at(index, z.real, z.imag) == z**p
    with pytest.raises(ValueError, match="index"):
        cf.laurent_weight_power(index + 11)
