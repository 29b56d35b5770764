"""Complex derivatives, potentials and fields in the plane (chapter 10, (10.25)-(10.56)).

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

The submodules, each re-exported here (the catalog names ``complexfields.function``):

- ``derivatives``: polynomials in x, y and z, z*; d/dz, d/dz*, div, curl (10.31)-(10.32),
  the laminar field (Fig. 10.7) and the chain rule at a point (10.25), (10.31)-(10.34).
- ``potentials``: potentials of analytic fields, the power rule and its inverse, the factors
  of (10.34), (10.46)-(10.47), fields and potentials at a point (10.35), (10.38), (10.44)-(10.45).
- ``sources``: non-analytic fields k (z*)^n, their sources and the split fL* + fT*
  (10.46)-(10.56).
- ``loops``: loop integrals and the line source (10.37)-(10.39), (10.44), as ``Estimate``.
- ``cauchy``: Laurent coefficients and Cauchy's formulas by contour integration (10.44)-(10.45).
- ``multipoles``: dipoles, 4-poles and 2^order-poles, level lines (10.40)-(10.44).
- ``maps``: the stereographic map of Fig. 10.15 (w = 1/z).
- ``_quadrature`` and ``_common``: the trapezoid rule on a circle and shared input checks.
"""

from __future__ import annotations

from mechmodel.complexfields._quadrature import DIGITS, LAURENT_POINTS, MONOMIAL_POINTS, POINTS
from mechmodel.complexfields.cauchy import (
    CauchyDerivative,
    CauchyKernel,
    LaurentCoefficientCheck,
    cauchy_derivative,
    cauchy_kernel,
    laurent_coefficient_check,
    laurent_weight_at,
    laurent_weight_power,
)
from mechmodel.complexfields.derivatives import (
    Z_OF_XY,
    ZSTAR,
    ZSTAR_OF_XY,
    ChainRule,
    ComplexPolyView,
    CoordinateInverse,
    LaminarField,
    PlanePoint,
    PolyView,
    X,
    Y,
    chain_rule_derivatives,
    complex_view,
    conjugate_linear_field,
    conjugate_potential_derivative,
    coordinates_from_z,
    curl_of_z_vector,
    curl_z,
    d_dz,
    d_dzstar,
    divergence,
    gradient,
    inverse_coordinates,
    phasor_pair_square,
    poly_view,
    zpoly_to_xy,
)
from mechmodel.complexfields.loops import (
    LineSource,
    LoopIntegral,
    LoopPowers,
    laurent_loop_integral,
    line_source,
    nonzero_loop_powers,
    power_loop_integral,
)
from mechmodel.complexfields.maps import (
    StereographicLengths,
    StereographicPoint,
    stereographic_image_radius,
    stereographic_lengths,
    stereographic_preimage_radius,
    stereographic_projection,
)
from mechmodel.complexfields.multipoles import (
    DipolePair,
    MultipoleTerm,
    QuadrupoleRelations,
    dipole_level_radius,
    dipole_pair,
    dipole_pair_at,
    dipole_pair_field,
    laurent_term_of_multipole,
    level_line_angle,
    line_multipole_at,
    line_multipole_polar,
    multipole_field,
    multipole_of_laurent_term,
    multipole_pole_count,
    multipole_sources,
    multipole_term_at,
    potential_term_poles,
    quadrupole_relations,
)
from mechmodel.complexfields.potentials import (
    AnalyticPotential,
    FactorPair,
    FieldPoint,
    LaurentTerm,
    PotentialFieldCoefficients,
    PowerAntiderivative,
    SourceFactors,
    analytic_polynomial_at,
    complementary_potential_factor,
    exceptional_power,
    inverted_laurent_potential_at,
    laurent_derivative,
    laurent_potential_at,
    plot_field,
    potential_factor_sum,
    potential_field_coefficients,
    potential_parts,
    power_antiderivative,
    power_field_at,
    power_field_polar,
    power_field_potential,
    source_field_factors,
)
from mechmodel.complexfields.sources import (
    NonAnalyticField,
    SourcePoint,
    conjugate_power_field,
    conjugate_power_field_at,
)

__all__ = [
    "DIGITS",
    "LAURENT_POINTS",
    "MONOMIAL_POINTS",
    "POINTS",
    "ZSTAR",
    "ZSTAR_OF_XY",
    "Z_OF_XY",
    "AnalyticPotential",
    "CauchyDerivative",
    "CauchyKernel",
    "ChainRule",
    "ComplexPolyView",
    "CoordinateInverse",
    "DipolePair",
    "FactorPair",
    "FieldPoint",
    "LaminarField",
    "LaurentCoefficientCheck",
    "LaurentTerm",
    "LineSource",
    "LoopIntegral",
    "LoopPowers",
    "MultipoleTerm",
    "NonAnalyticField",
    "PlanePoint",
    "PolyView",
    "PotentialFieldCoefficients",
    "PowerAntiderivative",
    "QuadrupoleRelations",
    "SourceFactors",
    "SourcePoint",
    "StereographicLengths",
    "StereographicPoint",
    "X",
    "Y",
    "analytic_polynomial_at",
    "cauchy_derivative",
    "cauchy_kernel",
    "chain_rule_derivatives",
    "complementary_potential_factor",
    "complex_view",
    "conjugate_linear_field",
    "conjugate_potential_derivative",
    "conjugate_power_field",
    "conjugate_power_field_at",
    "coordinates_from_z",
    "curl_of_z_vector",
    "curl_z",
    "d_dz",
    "d_dzstar",
    "dipole_level_radius",
    "dipole_pair",
    "dipole_pair_at",
    "dipole_pair_field",
    "divergence",
    "exceptional_power",
    "gradient",
    "inverse_coordinates",
    "inverted_laurent_potential_at",
    "laurent_coefficient_check",
    "laurent_derivative",
    "laurent_loop_integral",
    "laurent_potential_at",
    "laurent_term_of_multipole",
    "laurent_weight_at",
    "laurent_weight_power",
    "level_line_angle",
    "line_multipole_at",
    "line_multipole_polar",
    "line_source",
    "multipole_field",
    "multipole_of_laurent_term",
    "multipole_pole_count",
    "multipole_sources",
    "multipole_term_at",
    "nonzero_loop_powers",
    "phasor_pair_square",
    "plot_field",
    "poly_view",
    "potential_factor_sum",
    "potential_field_coefficients",
    "potential_parts",
    "potential_term_poles",
    "power_antiderivative",
    "power_field_at",
    "power_field_polar",
    "power_field_potential",
    "power_loop_integral",
    "quadrupole_relations",
    "source_field_factors",
    "stereographic_image_radius",
    "stereographic_lengths",
    "stereographic_preimage_radius",
    "stereographic_projection",
    "zpoly_to_xy",
]
