"""z and z* as coordinates of the plane: exact polynomials in x, y and in z, z*, the derivatives
d/dz and d/dz* (10.31), divergence, curl and the laminar field of Fig. 10.7 (10.32); and the
same chain rule at a point, with the phasor sum of Fig. 10.6 (10.25), (10.31)-(10.34).

Polynomials are ``mechmodel.algebra.Laurent`` with Gaussian-rational coefficients; the factors
1/2 of the z- and z*-derivatives come from inverting z = x + i y, z* = x - i y exactly
(``inverse_coordinates``), never written in. ``poly_view`` gives a polynomial as the book prints
it. Dimensionless (the book's scaled units).
"""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass
from fractions import Fraction
from functools import cache

from mechmodel import inputs
from mechmodel.algebra import I_UNIT, Gaussian, Laurent
from mechmodel.complexfields._common import _real
from mechmodel.typing import Real

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
    integers over it ((3x^2 + y^2)/2 has denominator 2, numerators x2y0: 3, x0y2: 1); ``size``
    the largest coefficient magnitude (0 for the zero polynomial).
    """

    coefficients: dict[str, Fraction]
    denominator: int
    numerators: dict[str, int]
    size: Fraction


def poly_view(p: Laurent, first: str = "x", second: str = "y") -> PolyView:
    """The printed form of a polynomial in the variables ``first``, ``second`` with real
    coefficients (``ValueError`` if not real)."""
    terms = p.powers(first, second)
    coeffs = {k: c for k, c in sorted(terms.items()) if isinstance(c, Fraction)}
    if len(coeffs) != len(terms):
        raise ValueError("poly_view needs real coefficients: take real_part or imag_part first")
    denominator = math.lcm(*(c.denominator for c in coeffs.values())) if coeffs else 1
    return PolyView(
        coefficients={_name(k, first, second): c for k, c in coeffs.items()},
        denominator=denominator,
        numerators={_name(k, first, second): int(c * denominator) for k, c in coeffs.items()},
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
    return max((max(abs(Fraction(g.re)), abs(Fraction(g.im))) for g in parts), default=Fraction(0))


def conjugate_linear_field(strength_re: Real = 1, strength_im: Real = 0) -> LaminarField:
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


def phasor_pair_square(r1: Real, phi1: Real, r2: Real, phi2: Real, sign: int = 1) -> float:
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


def coordinates_from_z(x: Real, y: Real) -> PlanePoint:
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


def chain_rule_derivatives(dfdx_re: Real, dfdx_im: Real, dfdy_re: Real, dfdy_im: Real) -> ChainRule:
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


def conjugate_potential_derivative(
    dphi_dx: Real, dphi_dy: Real, da_dx: Real, da_dy: Real
) -> complex:
    """dphi*/dz* of the conjugate potential phi* = Phi - i A whose parts have the partial
    derivatives dPhi/dx, dPhi/dy, dA/dx, dA/dy at the point: the chain rule
    (``chain_rule_derivatives``) applied to d(Phi - iA)/dx and d(Phi - iA)/dy, (10.34)."""
    for value, name in ((da_dx, "da_dx"), (da_dy, "da_dy")):
        inputs.real(value, name)
    return chain_rule_derivatives(dphi_dx, -float(da_dx), dphi_dy, -float(da_dy)).dzstar
