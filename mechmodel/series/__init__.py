"""Series, binomials, compound interest, Euler's formula and phasors (chapter 10).

The exponential e^x = sum_k x^k / k! (eq. (10.5)) is born from the binomial limit
(1 + x/n)^n (10.4); the partial sum to order o keeps the terms k = 0..o (the precision order is
the power of the highest term used, (10.6)). Compound interest (1 + r t/m)^m p(0) (10.3) closes
in on p(0) e^(r t). Binomial coefficients B(n, k) = n!/(k!(n-k)!) fill Pascal's triangle
(Table 1 of the chapter); the sine and cosine series (10.16) and Euler's formula
e^(i theta) = cos theta + i sin theta (10.17) follow from the same series, and complex
products are 2-D rotations (10.26)-(10.27).

Types: functions on integers (binomials, factorials, derivative factors) are exact ``int`` or
``Fraction``. Real-valued series accept floats, ``Fraction`` (exact partial sums) and mpmath
numbers. Compound interest and e are computed in mpmath at ``DIGITS`` significant digits, since
(1 + 1/m)^m in floating point loses digits from m = 1e6 on. Phasors are Python ``complex``.
The functions written with plain operators take ``Symbolic`` arguments: the formula claims call
them with sympy symbols and compare the expression they return with the book's.

The submodules, re-exported here (the catalog names them ``series.function``):

- ``exp_series``: the e-series and its partial sums, e and e^x to ``DIGITS`` digits, the
  coefficients 1/k! from the binomial limit, remainder bounds, the series polynomial and its
  rate, the log potential of Fig. 10.1 ((10.1), (10.4)-(10.6), (10.9)).
- ``interest``: simple, compound (10.3) and continuous (10.4) interest, and the figures that
  compound interest shares with e.
- ``binomials``: factorials, binomial coefficients and Pascal's triangle (Table 1), the
  multiplication box of (1)-(9), the binomial series of (1 + r t/n)^n, the Gauss approximation.
- ``derivatives``: the power rule from the binomial expansion, secant and tangent slopes,
  repeated derivatives and the Maclaurin series ((10.7)-(10.12)).
- ``sinusoids``: the sine and cosine series, their derivatives, term counts and errors over a
  number of oscillations ((10.13)-(10.16), Fig. 10.4).
- ``phasors``: the powers of i, Euler's formula, unit phasors and their angles, phasor
  derivatives, rotations as complex products ((10.17)-(10.30), Fig. 10.5).
- ``_common``: the mpmath working precision ``DIGITS`` and the conversions between mpmath
  numbers and fractions that ``exp_series`` and ``interest`` share.
"""

from __future__ import annotations

from mechmodel.series._common import DIGITS as DIGITS
from mechmodel.series.binomials import binomial as binomial
from mechmodel.series.binomials import binomial_box_power as binomial_box_power
from mechmodel.series.binomials import binomial_box_product as binomial_box_product
from mechmodel.series.binomials import binomial_box_row as binomial_box_row
from mechmodel.series.binomials import binomial_complement as binomial_complement
from mechmodel.series.binomials import binomial_expansion as binomial_expansion
from mechmodel.series.binomials import binomial_gaussian as binomial_gaussian
from mechmodel.series.binomials import binomial_pq as binomial_pq
from mechmodel.series.binomials import binomial_term_count as binomial_term_count
from mechmodel.series.binomials import binomial_terms as binomial_terms
from mechmodel.series.binomials import card_deck_size as card_deck_size
from mechmodel.series.binomials import compound_binomial_terms as compound_binomial_terms
from mechmodel.series.binomials import factorial as factorial
from mechmodel.series.binomials import (
    falling_factorial_leading_term as falling_factorial_leading_term,
)
from mechmodel.series.binomials import falling_factors as falling_factors
from mechmodel.series.binomials import falling_factors_pq as falling_factors_pq
from mechmodel.series.binomials import (
    gaussian_exponent_coefficient as gaussian_exponent_coefficient,
)
from mechmodel.series.binomials import integer_power as integer_power
from mechmodel.series.binomials import pascal_row_length as pascal_row_length
from mechmodel.series.binomials import pascal_row_span as pascal_row_span
from mechmodel.series.binomials import pascal_row_sum as pascal_row_sum
from mechmodel.series.binomials import pascal_triangle as pascal_triangle
from mechmodel.series.derivatives import DerivativeTerm as DerivativeTerm
from mechmodel.series.derivatives import PowerRule as PowerRule
from mechmodel.series.derivatives import derivative_term as derivative_term
from mechmodel.series.derivatives import leibniz_denominator as leibniz_denominator
from mechmodel.series.derivatives import maclaurin_divisor as maclaurin_divisor
from mechmodel.series.derivatives import maclaurin_factorial as maclaurin_factorial
from mechmodel.series.derivatives import maclaurin_polynomial as maclaurin_polynomial
from mechmodel.series.derivatives import nth_difference_quotient as nth_difference_quotient
from mechmodel.series.derivatives import parabola_slope as parabola_slope
from mechmodel.series.derivatives import polynomial_rate as polynomial_rate
from mechmodel.series.derivatives import power_derivative as power_derivative
from mechmodel.series.derivatives import power_increment as power_increment
from mechmodel.series.derivatives import power_rule as power_rule
from mechmodel.series.derivatives import power_rule_drop as power_rule_drop
from mechmodel.series.derivatives import power_term_rate as power_term_rate
from mechmodel.series.derivatives import secant_slope as secant_slope
from mechmodel.series.exp_series import euler_number as euler_number
from mechmodel.series.exp_series import exp_partial_sum as exp_partial_sum
from mechmodel.series.exp_series import exp_pi_multiple as exp_pi_multiple
from mechmodel.series.exp_series import exp_remainder_bound as exp_remainder_bound
from mechmodel.series.exp_series import exp_series_additions as exp_series_additions
from mechmodel.series.exp_series import exp_series_coefficient as exp_series_coefficient
from mechmodel.series.exp_series import exp_series_correct_decimals as exp_series_correct_decimals
from mechmodel.series.exp_series import exp_series_factorial as exp_series_factorial
from mechmodel.series.exp_series import exp_series_polynomial as exp_series_polynomial
from mechmodel.series.exp_series import exp_series_polynomial_rate as exp_series_polynomial_rate
from mechmodel.series.exp_series import exp_series_term as exp_series_term
from mechmodel.series.exp_series import exp_series_term_count as exp_series_term_count
from mechmodel.series.exp_series import exp_to_log_rotation as exp_to_log_rotation
from mechmodel.series.exp_series import exponential as exponential
from mechmodel.series.exp_series import inverse_factorial as inverse_factorial
from mechmodel.series.exp_series import log_potential_force as log_potential_force
from mechmodel.series.exp_series import log_potential_normal_angle as log_potential_normal_angle
from mechmodel.series.interest import compound_factor as compound_factor
from mechmodel.series.interest import compound_growth as compound_growth
from mechmodel.series.interest import compound_growth_exact as compound_growth_exact
from mechmodel.series.interest import compound_period as compound_period
from mechmodel.series.interest import compound_solid_figures as compound_solid_figures
from mechmodel.series.interest import continuous_growth as continuous_growth
from mechmodel.series.interest import interest_rate as interest_rate
from mechmodel.series.interest import simple_interest as simple_interest
from mechmodel.series.phasors import PhasorDerivative as PhasorDerivative
from mechmodel.series.phasors import clockwise_angle as clockwise_angle
from mechmodel.series.phasors import euler_series as euler_series
from mechmodel.series.phasors import imaginary_unit_period as imaginary_unit_period
from mechmodel.series.phasors import imaginary_unit_power as imaginary_unit_power
from mechmodel.series.phasors import opposite_phasor_angle as opposite_phasor_angle
from mechmodel.series.phasors import phasor_derivative as phasor_derivative
from mechmodel.series.phasors import phasor_divisor as phasor_divisor
from mechmodel.series.phasors import phasor_modulus as phasor_modulus
from mechmodel.series.phasors import phasor_quarter_cycle as phasor_quarter_cycle
from mechmodel.series.phasors import phasor_rate as phasor_rate
from mechmodel.series.phasors import rotate as rotate
from mechmodel.series.phasors import unit_circle_radius as unit_circle_radius
from mechmodel.series.phasors import unit_phasor as unit_phasor
from mechmodel.series.sinusoids import SinusoidDerivative as SinusoidDerivative
from mechmodel.series.sinusoids import TermCountFormula as TermCountFormula
from mechmodel.series.sinusoids import sinusoid_coefficient as sinusoid_coefficient
from mechmodel.series.sinusoids import (
    sinusoid_coefficient_in_omega as sinusoid_coefficient_in_omega,
)
from mechmodel.series.sinusoids import sinusoid_derivative as sinusoid_derivative
from mechmodel.series.sinusoids import sinusoid_derivative_period as sinusoid_derivative_period
from mechmodel.series.sinusoids import sinusoid_max_error as sinusoid_max_error
from mechmodel.series.sinusoids import sinusoid_min_order as sinusoid_min_order
from mechmodel.series.sinusoids import sinusoid_min_terms as sinusoid_min_terms
from mechmodel.series.sinusoids import sinusoid_partial_sum as sinusoid_partial_sum
from mechmodel.series.sinusoids import sinusoid_powers as sinusoid_powers
from mechmodel.series.sinusoids import sinusoid_remainder_bound as sinusoid_remainder_bound
from mechmodel.series.sinusoids import sinusoid_series as sinusoid_series
from mechmodel.series.sinusoids import sinusoid_series_factors as sinusoid_series_factors
from mechmodel.series.sinusoids import sinusoid_term_count as sinusoid_term_count
from mechmodel.series.sinusoids import sinusoid_term_count_formula as sinusoid_term_count_formula

__all__ = [
    "DIGITS",
    "DerivativeTerm",
    "PhasorDerivative",
    "PowerRule",
    "SinusoidDerivative",
    "TermCountFormula",
    "binomial",
    "binomial_box_power",
    "binomial_box_product",
    "binomial_box_row",
    "binomial_complement",
    "binomial_expansion",
    "binomial_gaussian",
    "binomial_pq",
    "binomial_term_count",
    "binomial_terms",
    "card_deck_size",
    "clockwise_angle",
    "compound_binomial_terms",
    "compound_factor",
    "compound_growth",
    "compound_growth_exact",
    "compound_period",
    "compound_solid_figures",
    "continuous_growth",
    "derivative_term",
    "euler_number",
    "euler_series",
    "exp_partial_sum",
    "exp_pi_multiple",
    "exp_remainder_bound",
    "exp_series_additions",
    "exp_series_coefficient",
    "exp_series_correct_decimals",
    "exp_series_factorial",
    "exp_series_polynomial",
    "exp_series_polynomial_rate",
    "exp_series_term",
    "exp_series_term_count",
    "exp_to_log_rotation",
    "exponential",
    "factorial",
    "falling_factorial_leading_term",
    "falling_factors",
    "falling_factors_pq",
    "gaussian_exponent_coefficient",
    "imaginary_unit_period",
    "imaginary_unit_power",
    "integer_power",
    "interest_rate",
    "inverse_factorial",
    "leibniz_denominator",
    "log_potential_force",
    "log_potential_normal_angle",
    "maclaurin_divisor",
    "maclaurin_factorial",
    "maclaurin_polynomial",
    "nth_difference_quotient",
    "opposite_phasor_angle",
    "parabola_slope",
    "pascal_row_length",
    "pascal_row_span",
    "pascal_row_sum",
    "pascal_triangle",
    "phasor_derivative",
    "phasor_divisor",
    "phasor_modulus",
    "phasor_quarter_cycle",
    "phasor_rate",
    "polynomial_rate",
    "power_derivative",
    "power_increment",
    "power_rule",
    "power_rule_drop",
    "power_term_rate",
    "rotate",
    "secant_slope",
    "simple_interest",
    "sinusoid_coefficient",
    "sinusoid_coefficient_in_omega",
    "sinusoid_derivative",
    "sinusoid_derivative_period",
    "sinusoid_max_error",
    "sinusoid_min_order",
    "sinusoid_min_terms",
    "sinusoid_partial_sum",
    "sinusoid_powers",
    "sinusoid_remainder_bound",
    "sinusoid_series",
    "sinusoid_series_factors",
    "sinusoid_term_count",
    "sinusoid_term_count_formula",
    "unit_circle_radius",
    "unit_phasor",
]
