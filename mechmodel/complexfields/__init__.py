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

from mechmodel.complexfields._quadrature import (
    DIGITS as DIGITS,
)
from mechmodel.complexfields._quadrature import (
    LAURENT_POINTS as LAURENT_POINTS,
)
from mechmodel.complexfields._quadrature import (
    MONOMIAL_POINTS as MONOMIAL_POINTS,
)
from mechmodel.complexfields._quadrature import (
    POINTS as POINTS,
)
from mechmodel.complexfields.cauchy import (
    CauchyDerivative as CauchyDerivative,
)
from mechmodel.complexfields.cauchy import (
    CauchyKernel as CauchyKernel,
)
from mechmodel.complexfields.cauchy import (
    LaurentCoefficientCheck as LaurentCoefficientCheck,
)
from mechmodel.complexfields.cauchy import (
    cauchy_derivative as cauchy_derivative,
)
from mechmodel.complexfields.cauchy import (
    cauchy_kernel as cauchy_kernel,
)
from mechmodel.complexfields.cauchy import (
    laurent_coefficient_check as laurent_coefficient_check,
)
from mechmodel.complexfields.cauchy import (
    laurent_weight_at as laurent_weight_at,
)
from mechmodel.complexfields.cauchy import (
    laurent_weight_power as laurent_weight_power,
)
from mechmodel.complexfields.derivatives import (
    Z_OF_XY as Z_OF_XY,
)
from mechmodel.complexfields.derivatives import (
    ZSTAR as ZSTAR,
)
from mechmodel.complexfields.derivatives import (
    ZSTAR_OF_XY as ZSTAR_OF_XY,
)
from mechmodel.complexfields.derivatives import (
    ChainRule as ChainRule,
)
from mechmodel.complexfields.derivatives import (
    ComplexPolyView as ComplexPolyView,
)
from mechmodel.complexfields.derivatives import (
    CoordinateInverse as CoordinateInverse,
)
from mechmodel.complexfields.derivatives import (
    LaminarField as LaminarField,
)
from mechmodel.complexfields.derivatives import (
    PlanePoint as PlanePoint,
)
from mechmodel.complexfields.derivatives import (
    PolyView as PolyView,
)
from mechmodel.complexfields.derivatives import (
    X as X,
)
from mechmodel.complexfields.derivatives import (
    Y as Y,
)
from mechmodel.complexfields.derivatives import (
    chain_rule_derivatives as chain_rule_derivatives,
)
from mechmodel.complexfields.derivatives import (
    complex_view as complex_view,
)
from mechmodel.complexfields.derivatives import (
    conjugate_linear_field as conjugate_linear_field,
)
from mechmodel.complexfields.derivatives import (
    conjugate_potential_derivative as conjugate_potential_derivative,
)
from mechmodel.complexfields.derivatives import (
    coordinates_from_z as coordinates_from_z,
)
from mechmodel.complexfields.derivatives import (
    curl_of_z_vector as curl_of_z_vector,
)
from mechmodel.complexfields.derivatives import (
    curl_z as curl_z,
)
from mechmodel.complexfields.derivatives import (
    d_dz as d_dz,
)
from mechmodel.complexfields.derivatives import (
    d_dzstar as d_dzstar,
)
from mechmodel.complexfields.derivatives import (
    divergence as divergence,
)
from mechmodel.complexfields.derivatives import (
    gradient as gradient,
)
from mechmodel.complexfields.derivatives import (
    inverse_coordinates as inverse_coordinates,
)
from mechmodel.complexfields.derivatives import (
    phasor_pair_square as phasor_pair_square,
)
from mechmodel.complexfields.derivatives import (
    poly_view as poly_view,
)
from mechmodel.complexfields.derivatives import (
    zpoly_to_xy as zpoly_to_xy,
)
from mechmodel.complexfields.loops import (
    LineSource as LineSource,
)
from mechmodel.complexfields.loops import (
    LoopIntegral as LoopIntegral,
)
from mechmodel.complexfields.loops import (
    LoopPowers as LoopPowers,
)
from mechmodel.complexfields.loops import (
    laurent_loop_integral as laurent_loop_integral,
)
from mechmodel.complexfields.loops import (
    line_source as line_source,
)
from mechmodel.complexfields.loops import (
    nonzero_loop_powers as nonzero_loop_powers,
)
from mechmodel.complexfields.loops import (
    power_loop_integral as power_loop_integral,
)
from mechmodel.complexfields.maps import (
    StereographicLengths as StereographicLengths,
)
from mechmodel.complexfields.maps import (
    StereographicPoint as StereographicPoint,
)
from mechmodel.complexfields.maps import (
    stereographic_image_radius as stereographic_image_radius,
)
from mechmodel.complexfields.maps import (
    stereographic_lengths as stereographic_lengths,
)
from mechmodel.complexfields.maps import (
    stereographic_preimage_radius as stereographic_preimage_radius,
)
from mechmodel.complexfields.maps import (
    stereographic_projection as stereographic_projection,
)
from mechmodel.complexfields.multipoles import (
    DipolePair as DipolePair,
)
from mechmodel.complexfields.multipoles import (
    MultipoleTerm as MultipoleTerm,
)
from mechmodel.complexfields.multipoles import (
    QuadrupoleRelations as QuadrupoleRelations,
)
from mechmodel.complexfields.multipoles import (
    dipole_level_radius as dipole_level_radius,
)
from mechmodel.complexfields.multipoles import (
    dipole_pair as dipole_pair,
)
from mechmodel.complexfields.multipoles import (
    dipole_pair_at as dipole_pair_at,
)
from mechmodel.complexfields.multipoles import (
    dipole_pair_field as dipole_pair_field,
)
from mechmodel.complexfields.multipoles import (
    laurent_term_of_multipole as laurent_term_of_multipole,
)
from mechmodel.complexfields.multipoles import (
    level_line_angle as level_line_angle,
)
from mechmodel.complexfields.multipoles import (
    line_multipole_at as line_multipole_at,
)
from mechmodel.complexfields.multipoles import (
    line_multipole_polar as line_multipole_polar,
)
from mechmodel.complexfields.multipoles import (
    multipole_field as multipole_field,
)
from mechmodel.complexfields.multipoles import (
    multipole_of_laurent_term as multipole_of_laurent_term,
)
from mechmodel.complexfields.multipoles import (
    multipole_pole_count as multipole_pole_count,
)
from mechmodel.complexfields.multipoles import (
    multipole_sources as multipole_sources,
)
from mechmodel.complexfields.multipoles import (
    multipole_term_at as multipole_term_at,
)
from mechmodel.complexfields.multipoles import (
    potential_term_poles as potential_term_poles,
)
from mechmodel.complexfields.multipoles import (
    quadrupole_relations as quadrupole_relations,
)
from mechmodel.complexfields.potentials import (
    AnalyticPotential as AnalyticPotential,
)
from mechmodel.complexfields.potentials import (
    FactorPair as FactorPair,
)
from mechmodel.complexfields.potentials import (
    FieldPoint as FieldPoint,
)
from mechmodel.complexfields.potentials import (
    LaurentTerm as LaurentTerm,
)
from mechmodel.complexfields.potentials import (
    PotentialFieldCoefficients as PotentialFieldCoefficients,
)
from mechmodel.complexfields.potentials import (
    PowerAntiderivative as PowerAntiderivative,
)
from mechmodel.complexfields.potentials import (
    SourceFactors as SourceFactors,
)
from mechmodel.complexfields.potentials import (
    analytic_polynomial_at as analytic_polynomial_at,
)
from mechmodel.complexfields.potentials import (
    complementary_potential_factor as complementary_potential_factor,
)
from mechmodel.complexfields.potentials import (
    exceptional_power as exceptional_power,
)
from mechmodel.complexfields.potentials import (
    inverted_laurent_potential_at as inverted_laurent_potential_at,
)
from mechmodel.complexfields.potentials import (
    laurent_derivative as laurent_derivative,
)
from mechmodel.complexfields.potentials import (
    laurent_potential_at as laurent_potential_at,
)
from mechmodel.complexfields.potentials import (
    plot_field as plot_field,
)
from mechmodel.complexfields.potentials import (
    potential_factor_sum as potential_factor_sum,
)
from mechmodel.complexfields.potentials import (
    potential_field_coefficients as potential_field_coefficients,
)
from mechmodel.complexfields.potentials import (
    potential_parts as potential_parts,
)
from mechmodel.complexfields.potentials import (
    power_antiderivative as power_antiderivative,
)
from mechmodel.complexfields.potentials import (
    power_field_at as power_field_at,
)
from mechmodel.complexfields.potentials import (
    power_field_polar as power_field_polar,
)
from mechmodel.complexfields.potentials import (
    power_field_potential as power_field_potential,
)
from mechmodel.complexfields.potentials import (
    source_field_factors as source_field_factors,
)
from mechmodel.complexfields.sources import (
    NonAnalyticField as NonAnalyticField,
)
from mechmodel.complexfields.sources import (
    SourcePoint as SourcePoint,
)
from mechmodel.complexfields.sources import (
    conjugate_power_field as conjugate_power_field,
)
from mechmodel.complexfields.sources import (
    conjugate_power_field_at as conjugate_power_field_at,
)
