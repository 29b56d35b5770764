"""Non-analytic fields f = k (z*)^n and their sources (10.46)-(10.56): the source s* = 2 df*/dz
= rho - i I (charge density div f*, current density -curl f*), the potential
phi = (1/2) integral f dz at fixed z*, and the split of the field f* = fL* + fT* into a
longitudinal part grad Phi and a transverse part curl A. Exact polynomials
(``NonAnalyticField``) and their values at a point (``SourcePoint``). Dimensionless.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from fractions import Fraction

from mechmodel import inputs
from mechmodel.algebra import I_UNIT, Gaussian, Laurent
from mechmodel.complexfields.derivatives import (
    ZSTAR,
    ComplexPolyView,
    PolyView,
    complex_view,
    curl_of_z_vector,
    curl_z,
    d_dz,
    divergence,
    gradient,
    poly_view,
    zpoly_to_xy,
)
from mechmodel.complexfields.potentials import source_field_factors
from mechmodel.typing import Real


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


def _conjugate_power_polys(strength_re: Real, strength_im: Real, power: int) -> _NonAnalyticPolys:
    """Sources, potentials and fields of f = k (z*)^n as exact polynomials (10.46)-(10.56)."""
    n = inputs.count(power, "power")
    return _exact_polys(Fraction(strength_re), Fraction(strength_im), n)


@functools.lru_cache(maxsize=64)
def _exact_polys(strength_re: Fraction, strength_im: Fraction, n: int) -> _NonAnalyticPolys:
    """``_conjugate_power_polys`` for an exact k, computed once per (k, n): a field is
    evaluated at many points, and the polynomials' algebra costs milliseconds."""
    k = Gaussian(strength_re, strength_im)
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


def conjugate_power_field(strength_re: Real, strength_im: Real, power: int) -> NonAnalyticField:
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
    strength_re: Real, strength_im: Real, power: int, x: Real, y: Real
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
