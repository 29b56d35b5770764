"""Complex derivatives, potentials and fields in the plane (chapter 10, (10.31)-(10.56)).

The book treats a plane vector field F = (Fx, Fy) as the complex function f*(z*) = Fx + i Fy
plotted from a field f(z) (its conjugate), and a complex potential phi = Phi + i A whose
z-derivative is f (10.33): Phi is the scalar potential (F = grad Phi, the mathematician's sign,
no minus) and A the z-component of a vector potential (F = curl A = (dA/dy, -dA/dx)).
Everything here is dimensionless (the book's scaled units).

Three kinds of computation:

- **Exact algebra** for the derived coefficients: polynomials in x, y (or in z, z*) with
  Gaussian-rational coefficients (``mechmodel.algebra.Laurent``). The z- and
  z*-derivatives (10.31) come from inverting the linear map z = x + i y, z* = x - i y, so their
  factors 1/2 are computed, never written in. Results are exact ``Fraction`` or ``int``.
- **Numerical contour integration** (trapezoid rule on a circle, mpmath at 30 digits) for loop
  integrals, Laurent coefficients and Cauchy's formulas (10.39), (10.44)-(10.45). Such results
  are ``Estimate`` values carrying their own error estimate: the difference between the rule
  with N and N/2 points plus a rounding bound.
- **Geometry** of line sources, multipoles and the stereographic map (Figs. 10.9-10.16), in
  floats.
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from fractions import Fraction
from functools import cache
from typing import Any

import mpmath
import numpy as np

from mechmodel import inputs
from mechmodel.algebra import I_UNIT, Gaussian, Laurent
from mechmodel.typing import Estimate

# -------------------------------------------------------------------------------------------
# Polynomials in x, y and in z, z* (the exact algebra is mechmodel.algebra)
# -------------------------------------------------------------------------------------------

ZSTAR = "s"  # the variable z* of a polynomial in z, z* (printed "s" in its view: "z1s2")
X = Laurent.var("x")
Y = Laurent.var("y")
Z_OF_XY = X + Y * I_UNIT  # z = x + i y
ZSTAR_OF_XY = X - Y * I_UNIT  # z* = x - i y


@cache
def _z_zstar_power(a: int, b: int) -> Laurent:
    """z^a z*^b in x, y (cached: the same powers come back often)."""
    return (Z_OF_XY**a) * (ZSTAR_OF_XY**b)


def zpoly_to_xy(p: Laurent) -> Laurent:
    """A polynomial in z, z* rewritten as a polynomial in x, y (z = x + i y, z* = x - i y)."""
    out = Laurent()
    for (a, b), c in p.powers("z", ZSTAR).items():
        out = out + _z_zstar_power(a, b) * c
    return out


def _name(key: tuple[int, ...], first: str, second: str) -> str:
    return f"{first}{key[0]}{second}{key[1]}"


@dataclass(frozen=True)
class PolyView:
    """A real polynomial in x, y as the book prints it: over a common denominator.

    ``coefficients`` maps monomial names ("x1y2" is x y^2, "x0y0" the constant) to exact
    coefficients; ``denominator`` is their least common denominator and ``numerators`` the
    integers over it ((3x^2 + y^2)/2 has denominator 2, numerators x2y0: 3, x0y2: 1).
    ``y_power_of["x1"]`` is the power of y in the only term with x^1 (and ``x_power_of`` the other
    way), ``size`` the largest coefficient magnitude (0 for the zero polynomial).
    """

    coefficients: dict[str, Fraction]
    denominator: int
    numerators: dict[str, int]
    y_power_of: dict[str, int]
    x_power_of: dict[str, int]
    size: Fraction


def poly_view(p: Laurent, first: str = "x", second: str = "y") -> PolyView:
    """The printed form of a polynomial in the variables ``first``, ``second`` with real
    coefficients (``ValueError`` if not real)."""
    terms = p.powers(first, second)
    if any(isinstance(c, Gaussian) for c in terms.values()):
        raise ValueError("poly_view needs real coefficients: take real_part or imag_part first")
    coeffs = dict(sorted(terms.items()))
    denominator = math.lcm(*(c.denominator for c in coeffs.values())) if coeffs else 1
    by_first: dict[int, list[int]] = {}
    by_second: dict[int, list[int]] = {}
    for a, b in coeffs:
        by_first.setdefault(a, []).append(b)
        by_second.setdefault(b, []).append(a)
    return PolyView(
        coefficients={_name(k, first, second): c for k, c in coeffs.items()},
        denominator=denominator,
        numerators={_name(k, first, second): int(c * denominator) for k, c in coeffs.items()},
        y_power_of={f"{first}{a}": bs[0] for a, bs in by_first.items() if len(bs) == 1},
        x_power_of={f"{second}{b}": as_[0] for b, as_ in by_second.items() if len(as_) == 1},
        size=max((abs(c) for c in coeffs.values()), default=Fraction(0)),
    )


@dataclass(frozen=True)
class ComplexPolyView:
    """A complex polynomial split into real and imaginary parts of its coefficients, with the
    common denominator of all of them (z(z*)^2/2 in z, z*: denominator 2)."""

    real: PolyView
    imag: PolyView
    denominator: int


def complex_view(p: Laurent, first: str = "x", second: str = "y") -> ComplexPolyView:
    real, imag = poly_view(p.real_part(), first, second), poly_view(p.imag_part(), first, second)
    return ComplexPolyView(real, imag, math.lcm(real.denominator, imag.denominator))


# -------------------------------------------------------------------------------------------
# (10.31)-(10.32): d/dz, d/dz*, divergence and curl
# -------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class CoordinateInverse:
    """x and y in terms of z and z*: the inverse of z = x + i y, z* = x - i y (10.31).

    ``dx_dz`` ... ``dy_dzstar`` are the partial derivatives (the entries of the inverse
    matrix). The book prints x = (1/2)(z + z*) and y = (1/2i)(z - z*): ``x_coefficient`` is the
    1/2 and ``y_coefficient_times_i`` is i times 1/(2i), again 1/2.
    """

    dx_dz: Gaussian
    dx_dzstar: Gaussian
    dy_dz: Gaussian
    dy_dzstar: Gaussian
    x_coefficient: Fraction
    y_coefficient_times_i: Fraction


def _real(value: Fraction | Gaussian, what: str) -> Fraction:
    g = Gaussian.of(value)
    if g.im != 0:
        raise ArithmeticError(f"{what} should be real, got {g}")
    return g.re


@cache
def inverse_coordinates() -> CoordinateInverse:
    """Invert the linear map (x, y) -> (z, z*) exactly (Cramer's rule), (10.31)."""
    # rows: z = 1 x + i y ; z* = 1 x - i y
    a, b, c, d = Gaussian.of(1), I_UNIT, Gaussian.of(1), -I_UNIT
    det = a * d - b * c
    dx_dz, dx_dzstar = d / det, -b / det
    dy_dz, dy_dzstar = -c / det, a / det
    if dx_dz != dx_dzstar or dy_dz != -dy_dzstar:
        raise ArithmeticError("x must be symmetric and y antisymmetric in z, z*")
    return CoordinateInverse(
        dx_dz,
        dx_dzstar,
        dy_dz,
        dy_dzstar,
        x_coefficient=_real(dx_dz, "dx/dz"),
        y_coefficient_times_i=_real(dy_dz * I_UNIT, "i dy/dz"),
    )


def d_dz(p: Laurent) -> Laurent:
    """z-derivative of a polynomial in x, y, holding z* fixed (10.31)."""
    inv = inverse_coordinates()
    return p.diff("x") * inv.dx_dz + p.diff("y") * inv.dy_dz


def d_dzstar(p: Laurent) -> Laurent:
    """z*-derivative of a polynomial in x, y, holding z fixed (10.31)."""
    inv = inverse_coordinates()
    return p.diff("x") * inv.dx_dzstar + p.diff("y") * inv.dy_dzstar


def divergence(fx: Laurent, fy: Laurent) -> Laurent:
    """2D divergence dFx/dx + dFy/dy of F = (Fx, Fy)."""
    return fx.diff("x") + fy.diff("y")


def curl_z(fx: Laurent, fy: Laurent) -> Laurent:
    """z-component of the curl, dFy/dx - dFx/dy, of F = (Fx, Fy)."""
    return fy.diff("x") - fx.diff("y")


def gradient(phi: Laurent) -> tuple[Laurent, Laurent]:
    """Gradient (dPhi/dx, dPhi/dy) of a scalar potential."""
    return phi.diff("x"), phi.diff("y")


def curl_of_z_vector(a: Laurent) -> tuple[Laurent, Laurent]:
    """Curl of A e_z: (dA/dy, -dA/dx) (10.34)."""
    return a.diff("y"), -a.diff("x")


def _ratio(num: Laurent, den: Laurent) -> Fraction | Gaussian:
    """num / den for polynomials known to be proportional (``ArithmeticError`` otherwise)."""
    if den.is_zero():
        raise ArithmeticError("division by the zero polynomial")
    key, value = next(iter(den.terms.items()))
    ratio = num.terms.get(key, Fraction(0)) / value
    if num != den * ratio:
        raise ArithmeticError("the polynomials are not proportional")
    return ratio


@dataclass(frozen=True)
class LaminarField:
    """The field of f(z) = a z plotted from f*(z*) = a* z* (Fig. 10.7, (10.32)).

    ``dfstar_dz_size``: size of df*/dz (zero: f* depends on z* alone); ``divergence_size``,
    ``curl_size``: sizes of div F and curl F for F = (Re f*, Im f*).
    """

    field_x: PolyView
    field_y: PolyView
    dfstar_dz_size: Fraction
    divergence_size: Fraction
    curl_size: Fraction


def _size(p: Laurent) -> Fraction:
    parts = (Gaussian.of(c) for c in p.terms.values())
    return max((max(abs(g.re), abs(g.im)) for g in parts), default=Fraction(0))


def conjugate_linear_field(strength_re: Any = 1, strength_im: Any = 0) -> LaminarField:
    """f(z) = a z, a = strength_re + i strength_im (exact), and its divergence-free laminar
    plot field F = (Re f*, Im f*) (10.32), Fig. 10.7."""
    a = Gaussian(Fraction(strength_re), Fraction(strength_im))
    f = Z_OF_XY * a
    fstar = f.conjugate_coefficients()
    fx, fy = fstar.real_part(), fstar.imag_part()
    return LaminarField(
        field_x=poly_view(fx),
        field_y=poly_view(fy),
        dfstar_dz_size=_size(d_dz(fstar)),
        divergence_size=_size(divergence(fx, fy)),
        curl_size=_size(curl_z(fx, fy)),
    )


# -------------------------------------------------------------------------------------------
# (10.33)-(10.35), (10.46)-(10.47): potentials and the factors that relate them to fields
# -------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class PotentialFieldCoefficients:
    """dphi*/dz* = c_g grad Phi + c_c curl A for phi* = Phi - i A (10.34), with grad Phi and
    curl A written as complex numbers (dPhi/dx + i dPhi/dy, dA/dy - i dA/dx)."""

    gradient: Fraction
    curl: Fraction


def _as_complex(vx: Laurent, vy: Laurent) -> Laurent:
    return vx + vy * I_UNIT


def potential_field_coefficients() -> PotentialFieldCoefficients:
    """The factors of grad Phi and curl A in dphi*/dz* (10.34), from probes Phi = x (A = 0)
    and A = y (Phi = 0)."""
    zero = Laurent()
    c_grad = _ratio(d_dzstar(X - zero * I_UNIT), _as_complex(*gradient(X)))
    c_curl = _ratio(d_dzstar(zero - Y * I_UNIT), _as_complex(*curl_of_z_vector(Y)))
    return PotentialFieldCoefficients(
        _real(c_grad, "gradient factor"), _real(c_curl, "curl factor")
    )


@dataclass(frozen=True)
class SourceFactors:
    """The factors of the non-analytic definitions (10.46)-(10.47).

    ``source``: k with k df*/dz = div f* + i curl f* (so that s* = rho - i I has rho = div f*
    and I = -curl f*, (10.48)). ``potential``: k with k dphi*/dz* = grad Phi + curl A (so that
    f* = fL* + fT*, (10.49)-(10.50)). ``potential_prefactor`` = 1/potential, the 1/2 of
    phi = (1/2) integral f dz (10.52).
    """

    source: Fraction
    potential: Fraction
    potential_prefactor: Fraction


def source_field_factors() -> SourceFactors:
    """Both factors of (10.46)-(10.47) from probe fields; checked on a second, curling probe."""
    zero = Laurent()
    k_source = _ratio(_as_complex(divergence(X, zero), curl_z(X, zero)), d_dz(X))
    probe_x, probe_y = -Y * X, X * X  # a field with divergence and curl both nonzero
    lhs = d_dz(probe_x + probe_y * I_UNIT) * k_source
    if lhs != _as_complex(divergence(probe_x, probe_y), curl_z(probe_x, probe_y)):
        raise ArithmeticError("the source factor does not hold for a curling field")
    grad_x, grad_y = gradient(X)
    k_potential = _ratio(_as_complex(grad_x, grad_y), d_dzstar(X))
    phi, a = X * Y, X * X * Y  # check: k dphi*/dz* = grad Phi + curl A for another pair
    total = _as_complex(*gradient(phi)) + _as_complex(*curl_of_z_vector(a))
    if d_dzstar(phi - a * I_UNIT) * k_potential != total:
        raise ArithmeticError("the potential factor does not hold for a second probe")
    kp = Fraction(_real(k_potential, "potential factor"))
    return SourceFactors(Fraction(_real(k_source, "source factor")), kp, 1 / kp)


@dataclass(frozen=True)
class LaurentTerm:
    """c z^p."""

    coefficient: Fraction
    power: int


def laurent_derivative(coefficient: Any, power: Any) -> LaurentTerm:
    """d/dz of c z^p: p c z^(p-1) (the power rule); a constant (p = 0) gives zero (10.44)."""
    p = int(power)
    if p != power:
        raise ValueError(f"power must be an integer, got {power!r}")
    return LaurentTerm(Fraction(coefficient) * p, p - 1)


@dataclass(frozen=True)
class PowerAntiderivative:
    """The potential of the power field z^n: z^(n+1) / (n+1) (10.35a), (10.44).

    ``power`` = n + 1 and ``divisor`` = n + 1 (``coefficient`` = 1/divisor; the book prints
    the divisor, e.g. a_{-3} z^-2 / (-2)); ``divisor_magnitude`` its size ("-a / 2z^2");
    ``power_shift`` and ``divisor_shift`` are power - n and divisor - n (the "+1" of
    z^(n+1)/(n+1)); ``inverted_power`` the power of z after w = 1/z is put into w^(n+1).
    """

    field_power: int
    power: int
    divisor: int
    coefficient: Fraction
    divisor_magnitude: int
    power_shift: int
    divisor_shift: int
    inverted_power: int


def power_antiderivative(field_power: Any) -> PowerAntiderivative:
    """Antiderivative of z^n for an integer n != -1, found by inverting the power rule:
    the m with d/dz z^m proportional to z^n, and the factor that makes it exact."""
    n = int(field_power)
    if n != field_power:
        raise ValueError(f"field_power must be an integer, got {field_power!r}")
    m = n - laurent_derivative(1, 0).power  # the power rule lowers the power by one
    slope = laurent_derivative(1, m).coefficient
    if slope == 0:
        raise ValueError("z^-1 has no power-law antiderivative: its potential is ln z (10.38)")
    return PowerAntiderivative(
        field_power=n,
        power=m,
        divisor=int(slope),
        coefficient=1 / slope,
        divisor_magnitude=abs(int(slope)),
        power_shift=m - n,
        divisor_shift=int(slope) - n,
        inverted_power=-m,  # (1/z)^m = z^-m
    )


def exceptional_power(lowest: Any = -6, highest: Any = 6) -> int:
    """The only integer power n in [lowest, highest] whose field z^n has no power-law
    potential (9.38)-(10.38): the one where the power rule gives a zero slope."""
    found = []
    for n in range(int(lowest), int(highest) + 1):
        try:
            power_antiderivative(n)
        except ValueError:
            found.append(n)
    if len(found) != 1:
        raise ArithmeticError(f"expected one exceptional power, found {found}")
    return found[0]


@dataclass(frozen=True)
class AnalyticPotential:
    """phi = a z^(n+1)/(n+1) of the field f = a z^n (n >= 0) expanded in x, y (10.35):
    ``phi`` is Phi = Re phi, ``a`` is A = Im phi, ``field_x``, ``field_y`` the plotted field
    F = (Re f*, Im f*) and ``grad_x`` ... ``curl_y`` the fields grad Phi and curl A."""

    phi: PolyView
    a: PolyView
    field_x: PolyView
    field_y: PolyView
    grad_x: PolyView
    grad_y: PolyView
    curl_x: PolyView
    curl_y: PolyView


def _analytic_polys(
    field_power: Any, strength: Gaussian
) -> tuple[Laurent, Laurent, Laurent, Laurent]:
    """Phi, A, Fx, Fy of f = strength z^n, n >= 0."""
    n = inputs.count(field_power, "field_power")
    anti = power_antiderivative(n)
    phi = (Z_OF_XY**anti.power) * (strength * anti.coefficient)
    fstar = ((Z_OF_XY**n) * strength).conjugate_coefficients()
    return phi.real_part(), phi.imag_part(), fstar.real_part(), fstar.imag_part()


def power_field_potential(
    field_power: Any, strength_re: Any = 1, strength_im: Any = 0
) -> AnalyticPotential:
    """The complex potential of the power field a z^n in x, y (10.35a-c), exact."""
    strength = Gaussian(Fraction(strength_re), Fraction(strength_im))
    big_phi, a, fx, fy = _analytic_polys(field_power, strength)
    gx, gy = gradient(big_phi)
    cx, cy = curl_of_z_vector(a)
    return AnalyticPotential(*(poly_view(p) for p in (big_phi, a, fx, fy, gx, gy, cx, cy)))


@dataclass(frozen=True)
class FactorPair:
    """F = f grad Phi + j curl A for an analytic potential (10.34): given f, the j that
    works, and f + j."""

    j: Fraction
    total: Fraction


def complementary_potential_factor(factor: Any) -> FactorPair:
    """The factor j with F = f grad Phi + j curl A, for the field f(z) = z of Fig. 10.7,
    solved at the point (1, 1) and checked on the whole plane (exact)."""
    f = Fraction(factor)
    big_phi, a, fx, fy = _analytic_polys(1, Gaussian.of(1))
    gx, gy = gradient(big_phi)
    cx, cy = curl_of_z_vector(a)
    at = {"x": 1, "y": 1}  # the point (1, 1)
    j = (fx.evaluate(at) - gx.evaluate(at) * f) / cx.evaluate(at)
    if gx * f + cx * j != fx or gy * f + cy * j != fy:
        raise ArithmeticError("no single j reproduces the field")
    jr = _real(j, "j")
    return FactorPair(jr, f + jr)


def potential_factor_sum() -> Fraction:
    """f + j for every pair with F = f grad Phi + j curl A (10.34): since grad Phi = curl A = F
    for an analytic potential, the sum s with s grad Phi = F (field z, exact)."""
    big_phi, _, fx, _ = _analytic_polys(1, Gaussian.of(1))
    return _real(_ratio(fx, gradient(big_phi)[0]), "f + j")


# -------------------------------------------------------------------------------------------
# Numerical contour integrals (10.39), (10.44)-(10.45)
# -------------------------------------------------------------------------------------------

DIGITS = 30
POINTS = 64  # nodes for the Cauchy formulas (a pole 2.75 away from a contour of radius 0.5)
MONOMIAL_POINTS = 16  # exact for z^p with |p + 1| < 8 (the coarse rule has 8 nodes)
LAURENT_POINTS = 32  # exact for the degree range of the test Laurent series below


@dataclass(frozen=True)
class LoopIntegral:
    """A loop integral of f(z) dz counterclockwise around a circle (10.37): ``imag`` counts the
    real source (flux), ``real`` the imaginary source (vorticity, work around the loop)."""

    real: Estimate
    imag: Estimate


@cache
def _unit_nodes(points: int) -> tuple[Any, ...]:
    """The ``points`` roots of unity exp(2 pi i k / points), at the working precision."""
    with mpmath.workdps(DIGITS):
        return tuple(mpmath.expj(2 * mpmath.pi * k / points) for k in range(points))


def _contour(
    func: Callable[[Any], Any], center: complex, radius: float, points: int
) -> tuple[Any, Any]:
    """Trapezoid rule for the integral of func(z) dz around the circle |z - center| = radius,
    with ``points`` nodes and (for the error estimate) with every other one: (value, error
    estimate). Spectrally accurate for
    functions analytic on an annulus around the circle; exact for Laurent polynomials of
    degree below ``points``."""

    with mpmath.workdps(DIGITS):
        c = mpmath.mpc(center)
        terms = [func(c + radius * e) * (1j * radius * e) for e in _unit_nodes(points)]
        fine = mpmath.fsum(terms) * 2 * mpmath.pi / points
        coarse = mpmath.fsum(terms[::2]) * 4 * mpmath.pi / points  # the rule on every other node
        rounding = mpmath.mpf(10) ** (5 - DIGITS) * (1 + abs(fine))
        return fine, abs(fine - coarse) + rounding


def _float_contour(
    func: Callable[[Any], Any], center: complex, radius: float, points: int
) -> tuple[complex, float]:
    """The same trapezoid rule in double precision (numpy), for decisions that only need to
    tell zero from non-zero or one power from another: (value, error estimate)."""
    nodes = np.exp(2j * np.pi * np.arange(points) / points)
    weighted = func(center + radius * nodes) * (1j * radius * nodes) * (2 * np.pi / points)
    fine = complex(weighted.sum())
    coarse = 2 * complex(weighted[::2].sum())
    rounding = 4 * points * np.finfo(float).eps * float(np.abs(weighted).sum())
    return fine, float(abs(fine - coarse) + rounding)


def _numeric_parts(value: Any, error: Any) -> LoopIntegral:
    err = float(error)
    return LoopIntegral(Estimate(float(value.real), err), Estimate(float(value.imag), err))


def power_loop_integral(
    power: Any,
    strength_re: Any = 1,
    strength_im: Any = 0,
    center_re: Any = 0,
    center_im: Any = 0,
    radius: Any = 1,
) -> LoopIntegral:
    """Loop integral of a (z - c)^p dz around a circle about c (10.39): 2 pi i a for p = -1,
    zero for every other integer power."""
    p = int(power)
    inputs.positive(radius, "radius")
    a = complex(float(strength_re), float(strength_im))
    c = complex(float(center_re), float(center_im))
    if not -MONOMIAL_POINTS // 2 < p + 1 < MONOMIAL_POINTS // 2:
        raise ValueError(
            f"power must be in ({-MONOMIAL_POINTS // 2 - 1}, {MONOMIAL_POINTS // 2 - 1})"
        )
    value, error = _contour(lambda z: a * (z - c) ** p, c, float(radius), MONOMIAL_POINTS)
    return _numeric_parts(value, error)


def laurent_loop_integral(
    terms: list[list[Any]], center_re: Any, center_im: Any, radius: Any, points: int = 2**7
) -> LoopIntegral:
    """Loop integral of f(z) = sum c_k z^k, terms [[re, im, k], ...], around the circle
    |z - c| = radius (10.39), (10.44): 2 pi i c_-1 when the circle encloses the origin, zero
    when it does not (Cauchy's theorem). Trapezoid rule in double precision (numpy); the error
    estimate is the difference from the rule with half the nodes plus a rounding bound. The
    circle must keep clear of the pole at the origin."""
    inputs.positive(radius, "radius")
    c = complex(float(center_re), float(center_im))
    r = float(radius)
    if abs(abs(c) - r) < r / 10:
        raise ValueError("the circle passes too close to the pole at the origin")
    coeffs = [(complex(float(re), float(im)), int(k)) for re, im, k in terms]

    def f(z: Any) -> Any:
        return sum((a * z**k for a, k in coeffs), start=np.zeros_like(z))

    value, error = _float_contour(f, c, r, points)
    return LoopIntegral(Estimate(value.real, error), Estimate(value.imag, error))


@dataclass(frozen=True)
class LineSource:
    """A line source of complex strength a (10.38), Figs. 10.9-10.10: field f(z) = a/z, plotted
    f*(z*) = a*/z*, potential phi = a ln z. ``star_numerator_re``/``_im``: the numerator a* of
    f*; ``flux`` = Im of the loop integral (2 pi Re a, the jump of A around the source),
    ``circulation`` = Re of it (-2 pi Im a, the jump of Phi)."""

    star_numerator_re: float
    star_numerator_im: float
    flux: Estimate
    circulation: Estimate


def line_source(strength_re: Any = 1, strength_im: Any = 0) -> LineSource:
    """Field, plot numerator and loop integrals of the line source a = strength_re + i
    strength_im (a = q real: line charge; a = i J: line current, a vortex)."""
    inputs.real(strength_re, "strength_re")
    inputs.real(strength_im, "strength_im")
    a = complex(float(strength_re), float(strength_im))
    loop = power_loop_integral(-1, strength_re, strength_im)
    star = a.conjugate()
    return LineSource(star.real, star.imag, loop.imag, loop.real)


@dataclass(frozen=True)
class LoopPowers:
    """Which powers z^n have a non-zero loop integral around the origin (10.39), (10.44)."""

    powers: tuple[int, ...]
    field_power: int
    m: int  # multipole index of that term, m = n + 1 (the 2^|m|-pole labelling of (10.44))


def nonzero_loop_powers(lowest: Any = -6, highest: Any = 6) -> LoopPowers:
    """Scan n in [lowest, highest] by numerical contour integration (double precision: only
    zero and non-zero need telling apart)."""
    found = []
    for n in range(int(lowest), int(highest) + 1):
        if not -MONOMIAL_POINTS // 2 < n + 1 < MONOMIAL_POINTS // 2:
            raise ValueError("the scan range must keep |n + 1| below 8")
        value, error = _float_contour(lambda z, n=n: z**n, 0j, 1.0, MONOMIAL_POINTS)
        if abs(value) > 10**3 * error:
            found.append(n)
    if len(found) != 1:
        raise ArithmeticError(f"expected one power with a loop integral, found {found}")
    return LoopPowers(tuple(found), found[0], found[0] + 1)


def _test_laurent_coefficients(lowest: int, highest: int) -> dict[int, complex]:
    """Known, distinct, generic coefficients c_k of a test Laurent series."""
    return {k: complex(1 / (k - lowest + 1), (k % 3) / 7) for k in range(lowest, highest + 1)}


@dataclass(frozen=True)
class LaurentCoefficientCheck:
    """For a_n = (1/(2 pi i)) loop z^(-n-1) f(z) dz (10.44): ``weight_power`` = -n-1, and
    ``two_pi`` = Im of (loop z^(-n-1) f dz) / a_n for a test series with known a_n (the 2 pi of
    the normalizer 2 pi i; its real part is ``residual``)."""

    index: int
    weight_power: int
    two_pi: Estimate
    residual: Estimate


def laurent_coefficient_check(index: Any) -> LaurentCoefficientCheck:
    """Recover a known Laurent coefficient a_index by contour integration (10.44)."""
    n = int(index)
    coeffs = _test_laurent_coefficients(-5, 5)
    if n not in coeffs:
        raise ValueError(f"index must be in [-5, 5], got {n}")

    lowest = min(coeffs)
    ordered = [coeffs[k] for k in sorted(coeffs, reverse=True)]
    weight = -n - 1

    def weighted(z: Any) -> Any:
        total = mpmath.mpc(0)
        for c in ordered:  # Horner: sum c_k z^(k - lowest)
            total = total * z + c
        return total * z ** (lowest + weight)

    value, error = _contour(weighted, 0j, 1.0, LAURENT_POINTS)
    with mpmath.workdps(DIGITS):
        ratio = value / mpmath.mpc(coeffs[n])
        err = float(error / abs(mpmath.mpc(coeffs[n])))
    return LaurentCoefficientCheck(
        n, weight, Estimate(float(ratio.imag), err), Estimate(float(ratio.real), err)
    )


# Cauchy's formulas (10.45) with the test function g(z) = 1/(b - z), analytic inside the
# contour, whose derivatives are known in closed form: g^(n)(a) = n! / (b - a)^(n+1).
_CAUCHY_POLE = 3
_CAUCHY_CENTER = complex(1 / 4, 1 / 8)
_CAUCHY_RADIUS = 1 / 2  # well inside |b - a|: the rule with 32 points is already at 1e-23


def _cauchy_data(order: int, kernel_power: int) -> tuple[Any, Any, Any]:
    """(integral of g/(z-a)^kernel_power dz, its error, g^(order)(a)), at 30 digits."""
    a = _CAUCHY_CENTER

    def integrand(z: Any) -> Any:
        return 1 / ((_CAUCHY_POLE - z) * (z - a) ** kernel_power)

    value, error = _contour(integrand, a, _CAUCHY_RADIUS, POINTS)
    with mpmath.workdps(DIGITS):
        exact = mpmath.factorial(order) / (_CAUCHY_POLE - mpmath.mpc(a)) ** (order + 1)
    return value, error, exact


@dataclass(frozen=True)
class CauchyDerivative:
    """Cauchy's formula f^(n)(a) = (n!/(2 pi i)) loop f(z)/(z-a)^(n+1) dz (10.45), checked
    numerically for a test function: ``two_pi`` = Im(n! I / f^(n)(a)) where I is the loop
    integral, ``numerator`` = Re(2 pi i f^(n)(a) / I) (the n!: 1, 2, 3! = 6 ...),
    ``taylor_numerator`` = Re(a_n n! / f^(n)(a)) with a_n = I/(2 pi i) (the 1 of 1/n!)."""

    order: int
    two_pi: Estimate
    numerator: Estimate
    taylor_numerator: Estimate


def cauchy_derivative(order: Any) -> CauchyDerivative:
    """The n-th Cauchy formula by numerical contour integration (10.45a-c)."""
    n = inputs.count(order, "order")
    value, error, exact = _cauchy_data(n, n + 1)
    with mpmath.workdps(DIGITS):
        rel = error / abs(value)
        k = mpmath.factorial(n) * value / exact
        two_pi_i = 2j * mpmath.pi
        numerator = two_pi_i * exact / value
        taylor = (value / two_pi_i) * mpmath.factorial(n) / exact
        return CauchyDerivative(
            n,
            Estimate(float(k.imag), float(abs(k) * rel)),
            Estimate(float(numerator.real), float(abs(numerator) * rel)),
            Estimate(float(taylor.real), float(abs(taylor) * rel)),
        )


@dataclass(frozen=True)
class CauchyKernel:
    """The power p of (z - a)^p in the n-th Cauchy formula, found by trying p = 1, 2, ...;
    ``shift`` = p - n (the "+1" of (z - a)^(n+1))."""

    order: int
    power: int
    shift: int


def cauchy_kernel(order: Any) -> CauchyKernel:
    """Search the kernel power p for which (n!/(2 pi i)) loop g/(z-a)^p dz = g^(n)(a)."""
    n = inputs.count(order, "order")
    a = _CAUCHY_CENTER
    exact = math.factorial(n) / (_CAUCHY_POLE - a) ** (n + 1)
    matches = []
    for p in range(1, n + 4):
        value, error = _float_contour(
            lambda z, p=p: 1 / ((_CAUCHY_POLE - z) * (z - a) ** p), a, _CAUCHY_RADIUS, POINTS
        )
        guess = math.factorial(n) * value / (2j * math.pi)
        if abs(guess - exact) <= 10**3 * error + 10.0**-12 * abs(exact):
            matches.append(p)
    if len(matches) != 1:
        raise ArithmeticError(f"expected one kernel power, found {matches}")
    return CauchyKernel(n, matches[0], matches[0] - n)


# -------------------------------------------------------------------------------------------
# Multipoles (10.40)-(10.44)
# -------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class DipolePair:
    """Sources +a at z = -D/d and -a at z = +D/d (the book's f_dipole, (10.41)):
    f = a/(z + D/d) - a/(z - D/d) = (c a D) / (z^2 - D^2/k) over a common denominator.
    ``numerator_coefficient`` = c, ``delta_sq_divisor`` = k, ``point_dipole_coefficient`` the
    limit of f/D as D -> 0 times z^2/a (the f_2-pole = -a/z^2)."""

    numerator_coefficient: Fraction
    delta_sq_divisor: Fraction
    point_dipole_coefficient: Fraction


def dipole_pair(position_divisor: Any) -> DipolePair:
    """Combine the two line-source fields exactly, as polynomials in z and the separation D."""
    d = Fraction(position_divisor)
    inputs.positive(d, "position_divisor")
    z, sep = Laurent.var("z"), Laurent.var("D")  # the variable z and the separation D
    plus, minus = z + sep * (1 / d), z - sep * (1 / d)
    numerator = minus - plus  # a/(z + D/d) - a/(z - D/d), a = 1
    denominator = plus * minus
    c = _real(numerator.coefficient(D=1), "numerator")
    if numerator != sep * c or denominator.coefficient(z=2) != 1:
        raise ArithmeticError("unexpected form of the dipole fraction")
    k = -1 / _real(denominator.coefficient(D=2), "D^2 term")
    # f / D = c / (z^2 - D^2/k) -> c / z^2 as D -> 0
    return DipolePair(c, k, c)


def dipole_pair_field(z: complex, separation: float, position_divisor: float = 2) -> complex:
    """The book's f_dipole(z) = a/(z + D/d) - a/(z - D/d) with a = 1, in floats."""
    s = separation / position_divisor
    return 1 / (z + s) - 1 / (z - s)


@dataclass(frozen=True)
class QuadrupoleRelations:
    """(10.43): with f_1 = a/z, f_2 = df_1/dz = -a/z^2 and phi_2 = dphi_1/dz = a/z, the book
    normalizes f_4 = a/z^3. ``field_factor`` = f_4 / (df_2/dz); ``potential_divisor_magnitude``
    is the 2 of phi_4 = -a/(2 z^2) = integral f_4 dz; ``potential_factor`` = phi_4/(dphi_2/dz)."""

    field_factor: Fraction
    potential_divisor_magnitude: int
    potential_factor: Fraction


def quadrupole_relations() -> QuadrupoleRelations:
    """Exact Laurent-monomial algebra for the 4-pole of (10.43), a = 1."""
    f2 = laurent_derivative(1, -1)  # d/dz (a z^-1)
    df2 = laurent_derivative(f2.coefficient, f2.power)
    f4 = LaurentTerm(Fraction(1), -3)
    if df2.power != f4.power:
        raise ArithmeticError("df_2/dz is not a z^-3 field")
    anti = power_antiderivative(f4.power)
    phi2 = LaurentTerm(Fraction(1), -1)  # d/dz (a ln z) = a/z
    dphi2 = laurent_derivative(phi2.coefficient, phi2.power)
    if dphi2.power != anti.power:
        raise ArithmeticError("dphi_2/dz is not a z^-2 potential")
    return QuadrupoleRelations(
        field_factor=f4.coefficient / df2.coefficient,
        potential_divisor_magnitude=anti.divisor_magnitude,
        potential_factor=(f4.coefficient * anti.coefficient) / dphi2.coefficient,
    )


def level_line_angle(field_power: Any, x: Any = 7 / 10, y: Any = 4 / 10) -> Estimate:
    """Angle (radians) between the level lines of Phi and of A of the potential of z^n at
    (x, y), from central differences of phi; 90 degrees for every analytic potential
    (Cauchy-Riemann), Fig. 10.13. Error: the O(h^2) difference error."""
    anti = power_antiderivative(field_power)
    z0 = complex(float(x), float(y))
    if z0 == 0:
        raise ValueError("the point must not be the origin")
    h = 10.0**-5 * max(1.0, abs(z0))

    def phi(z: complex) -> complex:
        return float(anti.coefficient) * z**anti.power

    def grad(part: Callable[[complex], float]) -> tuple[float, float]:
        gx = (part(z0 + h) - part(z0 - h)) / (2 * h)
        gy = (part(z0 + 1j * h) - part(z0 - 1j * h)) / (2 * h)
        return gx, gy

    gp = grad(lambda z: phi(z).real)
    ga = grad(lambda z: phi(z).imag)
    cos_angle = (gp[0] * ga[0] + gp[1] * ga[1]) / (math.hypot(*gp) * math.hypot(*ga))
    return Estimate(math.acos(max(-1.0, min(1.0, cos_angle))), 10.0**-6)


@dataclass(frozen=True)
class MultipoleTerm:
    """The multipole behind a Laurent field term a_n z^n (10.44): a 2^order-pole at the
    origin (n < 0) or at infinity (n >= 0). ``poles`` = 2^order."""

    field_power: int
    order: int
    poles: int
    location: str


def multipole_of_laurent_term(field_power: Any) -> MultipoleTerm:
    """A term z^n with n < 0 is the field of ln z differentiated -(n+1) times (a 2^-(n+1)-pole
    at z = 0); with n >= 0, w = 1/z turns z^n dz into -w^(-n-2) dw, a pole term at w = 0
    (z = infinity) of order n + 1. Each z-derivative doubles the sources."""
    n = int(field_power)
    if n != field_power:
        raise ValueError(f"field_power must be an integer, got {field_power!r}")
    if n < 0:
        order, location = -(n + 1), "origin"
    else:
        w_power = -n - 2  # z^n dz = w^-n (-w^-2 dw)
        order, location = -(w_power + 1), "infinity"
    return MultipoleTerm(n, order, multipole_pole_count(order), location)


def laurent_term_of_multipole(order: Any, location: str) -> int:
    """The field power n of the Laurent term of a 2^order-pole at ``location`` ("origin" or
    "infinity"), by searching the terms of (10.44)."""
    k = inputs.count(order, "order")
    if location not in ("origin", "infinity"):
        raise ValueError(f"location must be 'origin' or 'infinity', got {location!r}")
    found = [
        n
        for n in range(-k - 3, k + 3)
        if (t := multipole_of_laurent_term(n)).order == k and t.location == location
    ]
    if len(found) != 1:
        raise ArithmeticError(f"expected one term, found {found}")
    return found[0]


def multipole_sources(order: Any, spacing: Any = 1 / 64) -> list[tuple[int, Any]]:
    """Point sources (strength, position) of a 2^order-pole built as the book does: a unit
    1-pole, then repeatedly a (-)copy displaced a little (10.41), (10.43). Each step moves in
    a new direction (golden-angle turns) so that no two sources coincide. Floats, or mpmath
    numbers when ``spacing`` is an mpmath number (the sources nearly cancel far away)."""
    k = inputs.count(order, "order")
    sources: list[tuple[int, complex]] = [(1, 0j)]
    turn = math.pi * (3 - math.sqrt(5))
    for step in range(k):
        shift = spacing * cmath.rect(1.0, step * turn)
        sources = sources + [(-q, p + shift) for q, p in sources]
    return sources


def multipole_pole_count(order: Any) -> int:
    """Number of distinct point sources of the 2^order-pole construction."""
    return len({(round(p.real, 12), round(p.imag, 12)) for _, p in multipole_sources(order)})


def multipole_field(z: complex, sources: Iterable[tuple[int, complex]]) -> complex:
    """Field f(z) = sum q/(z - p) of line sources."""
    return sum((q / (z - p) for q, p in sources), start=0j)


# -------------------------------------------------------------------------------------------
# Stereographic projection (Fig. 10.15)
# -------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class StereographicPoint:
    """A point P of a sphere of diameter D standing on the w-plane at its South Pole S and
    touching the z-plane at its North Pole N (Fig. 10.15); theta = angle NOP at the centre O.
    The z-point is where the line from S through P meets the z-plane, the w-point where the
    line from N through P meets the w-plane.

    The ``*_angle_divisor`` fields are theta over the angle read off each printed relation
    (|z| = D tan(theta/2), |w| = D cot(theta/2), SP = D cos(theta/2), NP = D sin(theta/2),
    depth of P below N = D sin^2(theta/2), height above S = D cos^2(theta/2)); the
    ``*_exponent`` fields are the powers in |w| = |z|^p, |z| = |w|^p (true for D = 1),
    depth = NP^p and height = SP^p (in units of D)."""

    z_radius: float
    w_radius: float
    radius: Any
    tan_angle_divisor: float
    cot_angle_divisor: float
    w_exponent: float
    z_exponent: float
    south_chord_angle_divisor: float
    north_chord_angle_divisor: float
    north_depth_exponent: float
    south_height_exponent: float
    north_depth_angle_divisor: float
    south_height_angle_divisor: float


def stereographic_projection(theta: Any, diameter: Any) -> StereographicPoint:
    """Coordinates of the construction of Fig. 10.15 for a point at angle theta (radians)."""
    inputs.positive(diameter, "diameter")
    inputs.real(theta, "theta")
    t, d = float(theta), float(diameter)
    if not 0 < t < math.pi or math.isclose(t, math.pi / 2):
        raise ValueError("theta must be in (0, pi) and not pi/2 (where |z| = |w|)")
    # S at height 0, N at height D, the centre half-way: the radius, exact for exact D
    centre_height = Fraction(diameter) / 2 if isinstance(diameter, int | Fraction) else d / 2
    r = d / 2
    px, py = r * math.sin(t), r + r * math.cos(t)
    z_radius = px * d / py  # line S -> P continued to height D
    w_radius = px * d / (d - py)  # line N -> P continued to height 0
    sp, np_ = math.hypot(px, py), math.hypot(px, d - py)
    depth, height = d - py, py
    return StereographicPoint(
        z_radius=z_radius,
        w_radius=w_radius,
        radius=centre_height,
        tan_angle_divisor=t / math.atan(z_radius / d),
        cot_angle_divisor=t / math.atan(d / w_radius),
        w_exponent=math.log(w_radius) / math.log(z_radius),
        z_exponent=math.log(z_radius) / math.log(w_radius),
        south_chord_angle_divisor=t / math.acos(sp / d),
        north_chord_angle_divisor=t / math.asin(np_ / d),
        north_depth_exponent=math.log(depth / d) / math.log(np_ / d),
        south_height_exponent=math.log(height / d) / math.log(sp / d),
        north_depth_angle_divisor=t / math.asin(math.sqrt(depth / d)),
        south_height_angle_divisor=t / math.acos(math.sqrt(height / d)),
    )


def stereographic_image_radius(z_radius: Any, diameter: Any) -> float:
    """|w| of the image of a z-point at distance |z| from N: project it onto the sphere along
    the line to S, then from N onto the w-plane (Fig. 10.15); equals D^2/|z|."""
    inputs.positive(z_radius, "z_radius")
    inputs.positive(diameter, "diameter")
    d, rho = float(diameter), float(z_radius)
    # the line from S = (0, 0) to (rho, d): points s (rho, d); it meets the sphere
    # x^2 + (y - d/2)^2 = (d/2)^2 where s^2 (rho^2 + d^2) = s d^2
    s = d * d / (rho * rho + d * d)
    px, py = s * rho, s * d
    return px * d / (d - py)


# -------------------------------------------------------------------------------------------
# Non-analytic fields and their sources (10.46)-(10.56)
# -------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class NonAnalyticField:
    """The field f(z, z*) = k (z*)^n and everything (10.46)-(10.56) derive from it.

    ``source_star``: s* = 2 df*/dz (x, y form; ``source_star_z`` in z, z*), ``rho`` = Re s*
    (charge density, div f*) and ``current`` I = -Im s* (current density, -curl f*);
    ``potential_z`` phi = (1/2) integral f dz holding z* fixed, with ``phi`` = Phi and
    ``a`` = A; the longitudinal field fL* = grad Phi, the transverse field fT* = curl A and
    their sum, with div fL* and curl fT*."""

    source_star: ComplexPolyView
    source_star_z: ComplexPolyView
    rho: PolyView
    current: PolyView
    potential_z: ComplexPolyView
    potential_z_powers: dict[str, int]
    phi: PolyView
    a: PolyView
    longitudinal_x: PolyView
    longitudinal_y: PolyView
    transverse_x: PolyView
    transverse_y: PolyView
    total_x: PolyView
    total_y: PolyView
    div_longitudinal: PolyView
    curl_transverse: PolyView


@dataclass(frozen=True)
class _NonAnalyticPolys:
    """The polynomials behind ``NonAnalyticField`` (in x, y unless named ``_z``: in z, z*)."""

    fstar: Laurent
    s_star: Laurent
    s_star_z: Laurent
    phi_z: Laurent
    big_phi: Laurent
    a: Laurent
    longitudinal: tuple[Laurent, Laurent]
    transverse: tuple[Laurent, Laurent]


def _conjugate_power_polys(strength_re: Any, strength_im: Any, power: Any) -> _NonAnalyticPolys:
    """Sources, potentials and fields of f = k (z*)^n as exact polynomials (10.46)-(10.56)."""
    n = inputs.count(power, "power")
    k = Gaussian(Fraction(strength_re), Fraction(strength_im))
    factors = source_field_factors()
    f_z = Laurent.term(k, **{ZSTAR: n})  # in z, z*
    # f* of real x, y: conjugate the coefficients and swap z and z*
    conjugated = f_z.conjugate_coefficients().powers("z", ZSTAR)
    fstar_z = Laurent.from_powers(("z", ZSTAR), {(q, p): c for (p, q), c in conjugated.items()})
    s_star_z = fstar_z.diff("z") * (  # the formal z-derivative, z* held fixed
        factors.source
    )
    fstar = zpoly_to_xy(fstar_z)
    s_star = d_dz(fstar) * factors.source
    if s_star != zpoly_to_xy(s_star_z):
        raise ArithmeticError("the chain-rule and formal z-derivatives disagree")
    phi_z = f_z.integrate("z") * factors.potential_prefactor
    phi = zpoly_to_xy(phi_z)
    big_phi, a = phi.real_part(), phi.imag_part()
    lx, ly = gradient(big_phi)
    tx, ty = curl_of_z_vector(a)
    if lx + tx != fstar.real_part() or ly + ty != fstar.imag_part():
        raise ArithmeticError("fL* + fT* is not the field f*")
    return _NonAnalyticPolys(fstar, s_star, s_star_z, phi_z, big_phi, a, (lx, ly), (tx, ty))


def conjugate_power_field(strength_re: Any, strength_im: Any, power: Any) -> NonAnalyticField:
    """Sources, potentials and fields of f = k (z*)^n, k = strength_re + i strength_im (exact
    for rational k), n >= 0 (10.51)-(10.56)."""
    p = _conjugate_power_polys(strength_re, strength_im, power)
    (lx, ly), (tx, ty) = p.longitudinal, p.transverse
    return NonAnalyticField(
        source_star=complex_view(p.s_star),
        source_star_z=complex_view(p.s_star_z, "z", ZSTAR),
        rho=poly_view(p.s_star.real_part()),
        current=poly_view(-p.s_star.imag_part()),
        potential_z=complex_view(p.phi_z, "z", ZSTAR),
        potential_z_powers={f"z{a}": b for (a, b) in p.phi_z.powers("z", ZSTAR)},
        phi=poly_view(p.big_phi),
        a=poly_view(p.a),
        longitudinal_x=poly_view(lx),
        longitudinal_y=poly_view(ly),
        transverse_x=poly_view(tx),
        transverse_y=poly_view(ty),
        total_x=poly_view(lx + tx),
        total_y=poly_view(ly + ty),
        div_longitudinal=poly_view(divergence(lx, ly)),
        curl_transverse=poly_view(curl_z(tx, ty)),
    )


# -------------------------------------------------------------------------------------------
# Formulas at a point: the quantities that formula claims compare with the book's formulas
# -------------------------------------------------------------------------------------------


def phasor_pair_square(r1: Any, phi1: Any, r2: Any, phi2: Any, sign: Any = 1) -> float:
    """|z + s z'|^2 for the phasors z = r1 e^(i phi1), z' = r2 e^(i phi2) and s = +1 (sum) or
    -1 (difference): the squared length of the parallelogram diagonal, computed as the product
    (z + s z')* (z + s z') of the sum with its conjugate (10.25a-b), Fig. 10.6."""
    for value, name in ((r1, "r1"), (phi1, "phi1"), (r2, "r2"), (phi2, "phi2")):
        inputs.real(value, name)
    s = int(sign)
    if s not in (1, -1) or s != sign:
        raise ValueError(f"sign must be +1 or -1, got {sign!r}")
    w = cmath.rect(float(r1), float(phi1)) + s * cmath.rect(float(r2), float(phi2))
    return (w.conjugate() * w).real


@dataclass(frozen=True)
class PlanePoint:
    """A point (x, y) of the plane."""

    x: float
    y: float


def coordinates_from_z(x: Any, y: Any) -> PlanePoint:
    """x and y rebuilt from z = x + i y and z* = x - i y with the entries of the inverse map
    (``inverse_coordinates``): x = (dx/dz) z + (dx/dz*) z*, y = (dy/dz) z + (dy/dz*) z* (10.31)."""
    inputs.real(x, "x")
    inputs.real(y, "y")
    inv = inverse_coordinates()
    z, zstar = complex(float(x), float(y)), complex(float(x), -float(y))
    rebuilt_x = complex(inv.dx_dz) * z + complex(inv.dx_dzstar) * zstar
    rebuilt_y = complex(inv.dy_dz) * z + complex(inv.dy_dzstar) * zstar
    return PlanePoint(rebuilt_x.real, rebuilt_y.real)


@dataclass(frozen=True)
class ChainRule:
    """``dz`` = df/dz and ``dzstar`` = df/dz* of a function f(x, y) at a point (10.31)."""

    dz: complex
    dzstar: complex


def chain_rule_derivatives(dfdx_re: Any, dfdx_im: Any, dfdy_re: Any, dfdy_im: Any) -> ChainRule:
    """The z- and z*-derivatives of a function f(x, y) whose partial derivatives at the point
    are df/dx = dfdx_re + i dfdx_im and df/dy = dfdy_re + i dfdy_im, by the chain rule
    df/dz = (dx/dz) df/dx + (dy/dz) df/dy (and the same for z*) with the factors of the inverse
    map z = x + iy, z* = x - iy (``inverse_coordinates``), (10.31)-(10.34)."""
    for value, name in (
        (dfdx_re, "dfdx_re"),
        (dfdx_im, "dfdx_im"),
        (dfdy_re, "dfdy_re"),
        (dfdy_im, "dfdy_im"),
    ):
        inputs.real(value, name)
    inv = inverse_coordinates()
    p = complex(float(dfdx_re), float(dfdx_im))
    q = complex(float(dfdy_re), float(dfdy_im))
    return ChainRule(
        dz=complex(inv.dx_dz) * p + complex(inv.dy_dz) * q,
        dzstar=complex(inv.dx_dzstar) * p + complex(inv.dy_dzstar) * q,
    )


def conjugate_potential_derivative(dphi_dx: Any, dphi_dy: Any, da_dx: Any, da_dy: Any) -> complex:
    """dphi*/dz* of the conjugate potential phi* = Phi - i A whose parts have the partial
    derivatives dPhi/dx, dPhi/dy, dA/dx, dA/dy at the point: the chain rule
    (``chain_rule_derivatives``) applied to d(Phi - iA)/dx and d(Phi - iA)/dy, (10.34)."""
    for value, name in ((da_dx, "da_dx"), (da_dy, "da_dy")):
        inputs.real(value, name)
    return chain_rule_derivatives(dphi_dx, -float(da_dx), dphi_dy, -float(da_dy)).dzstar


@dataclass(frozen=True)
class FieldPoint:
    """A complex field and its potential at one point z (10.33): ``field`` f(z); ``plotted``
    the drawn vector F = Fx + i Fy = f*(z*), the conjugate of f; ``potential`` phi(z), whose
    z-derivative is f; ``phi`` = Phi = Re phi (scalar potential) and ``a`` = A = Im phi
    (vector potential)."""

    field: complex
    plotted: complex
    potential: complex
    phi: float
    a: float


def _field_point(field: complex, potential: complex) -> FieldPoint:
    return FieldPoint(field, field.conjugate(), potential, potential.real, potential.imag)


def _point(x: Any, y: Any) -> complex:
    inputs.real(x, "x")
    inputs.real(y, "y")
    z = complex(float(x), float(y))
    if z == 0:
        raise ValueError("the point must not be the origin (a source may sit there)")
    return z


def _polar_point(r: Any, theta: Any) -> complex:
    inputs.positive(r, "r")
    inputs.real(theta, "theta")
    return cmath.rect(float(r), float(theta))


def _strength(strength_re: Any, strength_im: Any) -> complex:
    inputs.real(strength_re, "strength_re")
    inputs.real(strength_im, "strength_im")
    return complex(float(strength_re), float(strength_im))


def _integer(value: Any, name: str) -> int:
    n = int(value)
    if n != value:
        raise ValueError(f"{name} must be an integer, got {value!r}")
    return n


def power_field_at(
    field_power: Any, x: Any, y: Any, strength_re: Any = 1, strength_im: Any = 0
) -> FieldPoint:
    """The power field f = a z^n at z = x + i y, a = strength_re + i strength_im, with its
    potential: a z^(n+1)/(n+1) from the inverted power rule (``power_antiderivative``), or, for
    the one power without a power-law potential, a ln z on the principal branch
    (-pi < theta <= pi), whose z-derivative is a/z (10.35a), (10.38), (10.44)."""
    n = _integer(field_power, "field_power")
    z, a = _point(x, y), _strength(strength_re, strength_im)
    try:
        anti = power_antiderivative(n)
    except ValueError:
        potential = a * cmath.log(z)
    else:
        potential = a * float(anti.coefficient) * z**anti.power
    return _field_point(a * z**n, potential)


def power_field_polar(
    field_power: Any, r: Any, theta: Any, strength_re: Any = 1, strength_im: Any = 0
) -> FieldPoint:
    """``power_field_at`` at the point z = r e^(i theta) (Figs. 10.9-10.14 label their fields
    and potentials in polar form)."""
    z = _polar_point(r, theta)
    return power_field_at(field_power, z.real, z.imag, strength_re, strength_im)


def potential_term_poles(potential_power: Any) -> int:
    """The number of poles 2^order of the multipole behind the potential term a z^m/m, m != 0
    (10.44): its field term is a z^(m-1) (``multipole_of_laurent_term``)."""
    m = _integer(potential_power, "potential_power")
    if m == 0:
        raise ValueError("the m = 0 potential term is a_-1 ln z, not a power")
    return multipole_of_laurent_term(m - 1).poles


def multipole_term_at(
    order: Any, location: str, x: Any, y: Any, strength_re: Any = 1, strength_im: Any = 0
) -> FieldPoint:
    """The Laurent term a z^n of a 2^order-pole at the origin or at infinity (10.44), the
    power n found by ``laurent_term_of_multipole``, with its potential (``power_field_at``)."""
    n = laurent_term_of_multipole(order, location)
    return power_field_at(n, x, y, strength_re, strength_im)


def dipole_pair_at(
    strength: Any, separation: Any, x: Any, y: Any, position_divisor: Any = 2
) -> FieldPoint:
    """The pair of line sources of (10.41): +a at z = -D/d and -a at z = +D/d (the pair whose
    field the book prints, f_dipole = a/(z + D/2) - a/(z - D/2)), at z = x + i y: the field is
    the sum of the sources' fields q/(z - p) (10.40a) and the potential the sum of their
    potentials q ln(z - p) (10.40b), principal branches."""
    inputs.real(strength, "strength")
    inputs.positive(separation, "separation")
    inputs.positive(position_divisor, "position_divisor")
    z, a = _point(x, y), float(strength)
    s = float(separation) / float(position_divisor)
    sources = ((a, -s), (-a, s))
    if any(z == p for _, p in sources):
        raise ValueError("the point must not be a source")
    field = sum((q / (z - p) for q, p in sources), start=0j)
    potential = sum((q * cmath.log(z - p) for q, p in sources), start=0j)
    return _field_point(field, potential)


def line_multipole_at(
    strength: Any, derivatives: Any, x: Any, y: Any, factor: Any = 1
) -> FieldPoint:
    """The k-th z-derivative of the unit line source, k = ``derivatives`` (10.40)-(10.43): the
    field factor * d^k/dz^k (a/z) and the potential factor * d^k/dz^k (a ln z), whose
    z-derivative is that field. Each derivative is the power rule (``laurent_derivative``); the
    derivative of ln z is 1/z. k = 1 is the point dipole f_2-pole = -a/z^2 with
    phi_2-pole = a/z (10.41); the book's 4-pole is k = 2 with the factor 1/2 (10.43)."""
    k = inputs.count(derivatives, "derivatives")
    inputs.real(strength, "strength")
    inputs.real(factor, "factor")
    z = _point(x, y)
    scale = float(strength) * float(factor)
    field = LaurentTerm(Fraction(1), -1)
    for _ in range(k):
        field = laurent_derivative(field.coefficient, field.power)
    if k == 0:
        potential = cmath.log(z)
    else:
        term = LaurentTerm(Fraction(1), -1)  # d/dz ln z
        for _ in range(k - 1):
            term = laurent_derivative(term.coefficient, term.power)
        potential = float(term.coefficient) * z**term.power
    return _field_point(scale * float(field.coefficient) * z**field.power, scale * potential)


def line_multipole_polar(
    strength: Any, derivatives: Any, r: Any, theta: Any, factor: Any = 1
) -> FieldPoint:
    """``line_multipole_at`` at z = r e^(i theta) (the polar labels of Fig. 10.11, (10.42))."""
    z = _polar_point(r, theta)
    return line_multipole_at(strength, derivatives, z.real, z.imag, factor)


def dipole_level_radius(strength: Any, level: Any, theta: Any, part: str) -> float:
    """The distance r along the ray at angle theta where the point-dipole potential
    phi_2-pole = a/z (10.42) has Phi = level (``part`` "phi") or A = level (``part`` "a"):
    on a ray the potential falls off as 1/r (checked at r = 1 and r = 2), so r is the value
    at r = 1 over the level; the level lines are the circles of Fig. 10.11. ``ValueError``
    where the ray does not reach that level (r <= 0)."""
    if part not in ("phi", "a"):
        raise ValueError(f"part must be 'phi' or 'a', got {part!r}")
    inputs.real(level, "level")
    if float(level) == 0:
        raise ValueError("the zero level lines are rays, not circles")
    at_one = getattr(line_multipole_polar(strength, 1, 1, theta), part)
    at_two = getattr(line_multipole_polar(strength, 1, 2, theta), part)
    if not math.isclose(at_two * 2, at_one, rel_tol=1e-12, abs_tol=1e-300):
        raise ArithmeticError("the dipole potential does not fall off as 1/r")
    r = at_one / float(level)
    if not r > 0:
        raise ValueError(f"the ray at theta = {theta} does not reach the level {level}")
    return r


def laurent_potential_at(coefficients: Iterable[Any], lowest: Any, x: Any, y: Any) -> complex:
    """The potential series of (10.44): for the field sum a_n z^n, n = lowest, lowest + 1, ...
    (one real coefficient a_n each), the sum of the potentials of its terms (``power_field_at``:
    a_n z^(n+1)/(n+1), and a_-1 ln z)."""
    start = _integer(lowest, "lowest")
    total = 0j
    for j, c in enumerate(coefficients):
        total += power_field_at(start + j, x, y, c, 0).potential
    return total


def inverted_laurent_potential_at(
    coefficients: Iterable[Any], lowest: Any, x: Any, y: Any
) -> complex:
    """The potential series of (10.44) with z replaced by w = 1/z, at z = x + i y: the series
    ``laurent_potential_at`` evaluated at the point w (Fig. 10.15 maps z to w = 1/z; ln w is
    -ln z off the negative real axis)."""
    w = 1 / _point(x, y)
    return laurent_potential_at(coefficients, lowest, w.real, w.imag)


def analytic_polynomial_at(coefficients: Iterable[Any], x: Any, y: Any) -> complex:
    """f(z) = sum c_k z^k, k = 0, 1, ..., at z = x + i y: a function with no poles, equal to its
    whole Taylor (Maclaurin) series around 0, whose coefficients are c_k = f^(k)(0)/k! (10.45c)."""
    inputs.real(x, "x")
    inputs.real(y, "y")
    z = complex(float(x), float(y))
    total = 0j
    for c in reversed(list(coefficients)):  # Horner
        inputs.real(c, "coefficient")
        total = total * z + float(c)
    return total


@cache
def laurent_weight_power(index: Any) -> int:
    """The power p for which (1/(2 pi i)) loop z^p f(z) dz around the origin returns the
    Laurent coefficient a_index of f (10.44): searched over p = -8 ... 8 by contour integration
    (double precision) of a test series with known, distinct coefficients; the one p that
    recovers a_index."""
    n = _integer(index, "index")
    coeffs = _test_laurent_coefficients(-5, 5)
    if n not in coeffs:
        raise ValueError(f"index must be in [-5, 5], got {n}")
    found = []
    for p in range(-8, 9):

        def weighted(z: Any, p: int = p) -> Any:
            return sum(c * z ** (k + p) for k, c in coeffs.items())

        value, error = _float_contour(weighted, 0j, 1.0, LAURENT_POINTS)
        if abs(value / (2j * math.pi) - coeffs[n]) <= 10**3 * error + 10.0**-12:
            found.append(p)
    if len(found) != 1:
        raise ArithmeticError(f"expected one weight power, found {found}")
    return found[0]


def laurent_weight_at(index: Any, x: Any, y: Any) -> complex:
    """The weight z^p of f(z) in the loop integral that gives a_index (``laurent_weight_power``),
    at z = x + i y."""
    p = laurent_weight_power(index)
    return _point(x, y) ** p


@dataclass(frozen=True)
class SourcePoint:
    """The non-analytic field f = k (z*)^n of (10.51)-(10.56) at one point z = x + i y:
    ``field_star`` f* = fx + i fy; ``source_star`` s* = rho - i I = 2 df*/dz; ``rho`` and
    ``current`` I; ``potential`` phi = Phi + i A = (1/2) integral of f dz at fixed z*; ``phi``,
    ``a``; the longitudinal field fL* = grad Phi and the transverse field fT* = curl A, each
    written Fx + i Fy (``longitudinal``, ``transverse``, and their sum ``total``);
    ``div_longitudinal`` = div fL* and ``curl_transverse`` = curl fT*."""

    field_star: complex
    source_star: complex
    rho: float
    current: float
    potential: complex
    phi: float
    a: float
    longitudinal: complex
    transverse: complex
    total: complex
    div_longitudinal: float
    curl_transverse: float


def conjugate_power_field_at(
    strength_re: Any, strength_im: Any, power: Any, x: Any, y: Any
) -> SourcePoint:
    """``conjugate_power_field``'s exact polynomials evaluated at the point (x, y) (exact for
    rational x, y and k; floats convert exactly)."""
    inputs.real(x, "x")
    inputs.real(y, "y")
    p = _conjugate_power_polys(strength_re, strength_im, power)
    u, v = Fraction(x), Fraction(y)

    def at(poly: Laurent) -> complex:
        return complex(poly.evaluate({"x": u, "y": v}))

    def vector(pair: tuple[Laurent, Laurent]) -> complex:
        return at(pair[0] + pair[1] * I_UNIT)

    source = at(p.s_star)
    (lx, ly), (tx, ty) = p.longitudinal, p.transverse
    potential = at(zpoly_to_xy(p.phi_z))
    return SourcePoint(
        field_star=at(p.fstar),
        source_star=source,
        rho=source.real,
        current=-source.imag,
        potential=potential,
        phi=at(p.big_phi).real,
        a=at(p.a).real,
        longitudinal=vector(p.longitudinal),
        transverse=vector(p.transverse),
        total=vector((lx + tx, ly + ty)),
        div_longitudinal=at(divergence(lx, ly)).real,
        curl_transverse=at(curl_z(tx, ty)).real,
    )


@dataclass(frozen=True)
class StereographicLengths:
    """The lengths of Fig. 10.15 for the point P at the central angle theta on a sphere of
    diameter D (N on the z-plane, S on the w-plane): ``z_radius`` |z| and ``w_radius`` |w| of
    its two images, the chords ``south_chord`` SP and ``north_chord`` NP, P's depth below N
    (``north_depth``), its height above S (``south_height``) and the angle NSP at S between the
    axis and the chord SP (``south_angle``, radians), the angle the figure marks theta/2."""

    z_radius: float
    w_radius: float
    south_chord: float
    north_chord: float
    north_depth: float
    south_height: float
    south_angle: float


def stereographic_lengths(theta: Any, diameter: Any) -> StereographicLengths:
    """The construction of Fig. 10.15 in coordinates: S at the origin, N at height D, P on the
    circle of radius D/2 about the centre at angle theta from N; the line S -> P continued to
    height D gives |z|, the line N -> P continued to height 0 gives |w|."""
    inputs.positive(diameter, "diameter")
    inputs.real(theta, "theta")
    t, d = float(theta), float(diameter)
    if not 0 < t < math.pi:
        raise ValueError("theta must be in (0, pi): P between N and S")
    r = d / 2
    px, py = r * math.sin(t), r + r * math.cos(t)
    return StereographicLengths(
        z_radius=px * d / py,
        w_radius=px * d / (d - py),
        south_chord=math.hypot(px, py),
        north_chord=math.hypot(px, d - py),
        north_depth=d - py,
        south_height=py,
        south_angle=math.atan2(px, py),
    )


def stereographic_preimage_radius(w_radius: Any, diameter: Any) -> float:
    """|z| of the point whose image is at distance |w| from S: project the w-point onto the
    sphere along the line to N, then from S onto the z-plane (Fig. 10.15)."""
    inputs.positive(w_radius, "w_radius")
    inputs.positive(diameter, "diameter")
    d, rho = float(diameter), float(w_radius)
    # the line from N = (0, d) to (rho, 0): points (t rho, d - t d); on the sphere
    # x^2 + (y - d/2)^2 = (d/2)^2 where t^2 (rho^2 + d^2) = t d^2
    t = d * d / (rho * rho + d * d)
    px, py = t * rho, d - t * d
    return px * d / py


# -------------------------------------------------------------------------------------------
# Float helpers for figures and property tests
# -------------------------------------------------------------------------------------------


def plot_field(f: Callable[[complex], complex], z: complex) -> tuple[float, float]:
    """The plotted vector F = (Re f*, Im f*) = (Re f, -Im f) of a field f at z."""
    w = f(z).conjugate()
    return w.real, w.imag


def potential_parts(phi: Callable[[complex], complex], z: complex) -> tuple[float, float]:
    """(Phi, A) = (Re phi, Im phi) at z."""
    w = phi(z)
    return w.real, w.imag
