"""Complex potentials phi = Phi + i A of analytic fields f = dphi/dz (10.33)-(10.35), (10.38),
(10.44): the factors relating dphi*/dz* to grad Phi and curl A (10.34), (10.46)-(10.47), the
power rule and its inverse (the potential z^(n+1)/(n+1) of z^n, a ln z for n = -1), the
potentials of power fields in x, y (exact), and the field and potential at a point
(``FieldPoint``: power fields, Laurent and Taylor series (10.44)-(10.45c)), with the float
helpers the figures of Figs. 10.7-10.14 plot. Dimensionless.
"""

from __future__ import annotations

import cmath
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from fractions import Fraction

from mechmodel import inputs
from mechmodel.algebra import I_UNIT, Gaussian, Laurent
from mechmodel.complexfields._common import _integer, _point, _polar_point, _real, _strength
from mechmodel.complexfields.derivatives import (
    Z_OF_XY,
    PolyView,
    X,
    Y,
    curl_of_z_vector,
    curl_z,
    d_dz,
    d_dzstar,
    divergence,
    gradient,
    poly_view,
)
from mechmodel.typing import Real


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


def laurent_derivative(coefficient: Real, power: int) -> LaurentTerm:
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


def power_antiderivative(field_power: int) -> PowerAntiderivative:
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


def exceptional_power(lowest: int = -6, highest: int = 6) -> int:
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
    field_power: int, strength: Gaussian
) -> tuple[Laurent, Laurent, Laurent, Laurent]:
    """Phi, A, Fx, Fy of f = strength z^n, n >= 0."""
    n = inputs.count(field_power, "field_power")
    anti = power_antiderivative(n)
    phi = (Z_OF_XY**anti.power) * (strength * anti.coefficient)
    fstar = ((Z_OF_XY**n) * strength).conjugate_coefficients()
    return phi.real_part(), phi.imag_part(), fstar.real_part(), fstar.imag_part()


def power_field_potential(
    field_power: int, strength_re: Real = 1, strength_im: Real = 0
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


def complementary_potential_factor(factor: Real) -> FactorPair:
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


def power_field_at(
    field_power: int, x: Real, y: Real, strength_re: Real = 1, strength_im: Real = 0
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
    field_power: int, r: Real, theta: Real, strength_re: Real = 1, strength_im: Real = 0
) -> FieldPoint:
    """``power_field_at`` at the point z = r e^(i theta) (Figs. 10.9-10.14 label their fields
    and potentials in polar form)."""
    z = _polar_point(r, theta)
    return power_field_at(field_power, z.real, z.imag, strength_re, strength_im)


def laurent_potential_at(coefficients: Iterable[Real], lowest: int, x: Real, y: Real) -> complex:
    """The potential series of (10.44): for the field sum a_n z^n, n = lowest, lowest + 1, ...
    (one real coefficient a_n each), the sum of the potentials of its terms (``power_field_at``:
    a_n z^(n+1)/(n+1), and a_-1 ln z)."""
    start = _integer(lowest, "lowest")
    total = 0j
    for j, c in enumerate(coefficients):
        total += power_field_at(start + j, x, y, c, 0).potential
    return total


def inverted_laurent_potential_at(
    coefficients: Iterable[Real], lowest: int, x: Real, y: Real
) -> complex:
    """The potential series of (10.44) with z replaced by w = 1/z, at z = x + i y: the series
    ``laurent_potential_at`` evaluated at the point w (Fig. 10.15 maps z to w = 1/z; ln w is
    -ln z off the negative real axis)."""
    w = 1 / _point(x, y)
    return laurent_potential_at(coefficients, lowest, w.real, w.imag)


def analytic_polynomial_at(coefficients: Iterable[Real], x: Real, y: Real) -> complex:
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


def plot_field(f: Callable[[complex], complex], z: complex) -> tuple[float, float]:
    """The plotted vector F = (Re f*, Im f*) = (Re f, -Im f) of a field f at z."""
    w = f(z).conjugate()
    return w.real, w.imag


def potential_parts(phi: Callable[[complex], complex], z: complex) -> tuple[float, float]:
    """(Phi, A) = (Re phi, Im phi) at z."""
    w = phi(z)
    return w.real, w.imag
