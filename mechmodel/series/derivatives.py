"""Derivatives by the power rule and the Maclaurin series (chapter 10, (10.7)-(10.12)).

The power rule d/dt t^n = n t^(n-1) is read off the binomial expansion of (t + dt)^n (10.8);
applied d times it gives the factors of (10.11c)-(10.11i), whose product is the Maclaurin
divisor D_k = k! of (10.12a). Secant and tangent slopes, polynomial rates, Leibniz's d^n x/dt^n
and the Maclaurin polynomial are written in plain operators: they take ``Symbolic`` arguments,
and a formula claim calls them with sympy symbols. Integers and Fractions stay exact.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction

from mechmodel import fields, inputs
from mechmodel.algebra import polynomial_derivative
from mechmodel.series.binomials import binomial_expansion
from mechmodel.series.exp_series import inverse_factorial
from mechmodel.typing import Symbolic


@dataclass(frozen=True)
class PowerRule:
    """d/dt t^n = ``factor`` t^``power`` (10.8b); ``drop`` = n - power."""

    factor: int
    power: int
    drop: int


def power_rule(power: int) -> PowerRule:
    """Derivative of t^n from the binomial expansion of ((t + dt)^n - t^n)/dt (10.8a): the only
    term that survives tiny dt is B(n, 1) t^(n-1) dt / dt."""
    n = inputs.count(power, "power")
    if n == 0:
        return PowerRule(0, 0, 0)  # a constant has no slope
    # (t + dt)^n - t^n = sum_{j>=1} B(n, j) t^(n-j) dt^j; divided by dt, only j = 1 survives
    row = binomial_expansion(n)
    return PowerRule(row[1], n - 1, 1)


def power_rule_drop(powers: Sequence[int], derivative: int = 1) -> int:
    """How much ``derivative`` derivatives lower the power of t^n (the n-1, n-2, ... of (10.8),
    (10.11)); the same for every power in ``powers`` larger than ``derivative``, else an error."""
    d = inputs.count(derivative, "derivative", minimum=1)
    drops = {int(p) - derivative_term(p, d).power for p in powers if int(p) >= d}
    if len(drops) != 1:
        raise ValueError(f"the power drops by {sorted(drops)} over {powers}")
    return drops.pop()


@dataclass(frozen=True)
class DerivativeTerm:
    """The d-th derivative of c t^k is ``factor`` c t^``power``; ``factors`` are the power-rule
    factors (d of them, ascending: (k-d+1) ... k), ``factor`` their product."""

    factors: list[int]
    factor: int
    power: int


def derivative_term(power: int, derivative: int) -> DerivativeTerm:
    """Apply the power rule ``derivative`` times to t^``power`` ((10.11c)-(10.11i))."""
    k = inputs.count(power, "power")
    d = inputs.count(derivative, "derivative")
    factors: list[int] = []
    factor, p = 1, k
    for _ in range(d):
        rule = power_rule(p)
        factors.insert(0, rule.factor)
        factor *= rule.factor
        p = rule.power
        if factor == 0:
            break
    return DerivativeTerm(factors, factor, p if factor else 0)


def power_increment(t: Symbolic, dt: Symbolic, power: int) -> Symbolic:
    """The rise x(t + dt) - x(t) of the power curve x = t^n over a step dt ((10.7a), (10.8a)):
    (t + dt)^n expanded with the coefficients of ``binomial_expansion`` (the multiplication
    box), less t^n. Plain operators: symbols give an expression."""
    n = inputs.count(power, "power")
    row = binomial_expansion(n)
    return sum((row[j] * t ** (n - j) * dt**j for j in range(n + 1)), 0) - t**n


def secant_slope(t: Symbolic, dt: Symbolic, power: int) -> Symbolic:
    """The slope ratio dx/dt of the secant of x = t^n from t to t + dt ((10.7a), (10.8a))."""
    return power_increment(t, dt, power) / dt


def power_derivative(t: Symbolic, power: int, coefficient: Symbolic = 1) -> Symbolic:
    """The tangent slope d/dt (A t^n) of (10.7b), (10.8b): A times the ``power_rule``'s factor
    times t to its lowered power (the secant slope's limit as dt shrinks)."""
    rule = power_rule(power)
    return coefficient * rule.factor * t**rule.power


def parabola_slope(lam: Symbolic, x: Symbolic) -> Symbolic:
    """Slope dy/dx at ``x`` of the parabola 2 lam y = x^2 of semi-latus rectum ``lam`` (Fig. 9.4,
    checked after (10.7b)): its height ``fields.parabola_height_for_latus`` is a multiple of
    x^2, differentiated by the power rule (``power_derivative``)."""
    return power_derivative(x, 2, coefficient=fields.parabola_height_for_latus(lam, 1))


def nth_difference_quotient(difference: Symbolic, step: Symbolic, order: int) -> Symbolic:
    """Leibniz's d^n x/dt^n of (10.12b): the n-th difference d^n x of x, divided by the step dt
    once for each of the n difference quotients taken (the d/dt of d/dt of ...): over dt^n."""
    n = inputs.count(order, "order")
    value = difference
    for _ in range(n):
        value = value / step
    return value


def polynomial_rate(coefficients: Sequence[Symbolic], t: Symbolic, derivative: int = 1) -> Symbolic:
    """The ``derivative``-th time derivative of x(t) = sum_k c_k t^k at t ((10.11c)-(10.11i)):
    ``polynomial_derivative`` applied that many times. Plain operators: symbols give an
    expression."""
    d = inputs.count(derivative, "derivative")
    current: Sequence[Symbolic] = list(coefficients)
    for _ in range(d):
        current = polynomial_derivative(current)
    return sum((c * t**k for k, c in enumerate(current)), 0)


def power_term_rate(
    t: Symbolic, power: int, derivative: int, coefficient: Symbolic = 1
) -> Symbolic:
    """The ``derivative``-th derivative of c t^n, the general term of (10.11c)-(10.11i):
    ``derivative_term``'s factor times c times t to the lowered power."""
    term = derivative_term(power, derivative)
    return coefficient * term.factor * t**term.power


def maclaurin_divisor(power: int) -> int:
    """c_k = x^(k)(0) / D_k: the k-th derivative of c_k t^k at t = 0 is D_k c_k, D_k the product
    of the power-rule factors (10.11); D_2 = 2 gives c2 = a(0)/2."""
    k = inputs.count(power, "power")
    return derivative_term(k, k).factor


def maclaurin_factorial(power: int) -> int:
    """The j of the 1/j! in c_k = x^(k)(0)/j! (10.11f), (10.12a): the inverse factorial of the
    divisor D_k (it is k)."""
    k = inputs.count(power, "power")
    return inverse_factorial(maclaurin_divisor(k))


def leibniz_denominator(step: Symbolic, order: int) -> Symbolic:
    """The denominator of Leibniz's d^n x/dt^n (10.12b): what the n-th difference d^n x is
    divided by in ``nth_difference_quotient``, one dt per derivative taken (dt^n)."""
    return 1 / nth_difference_quotient(1, step, order)


def maclaurin_polynomial(derivatives: Sequence[Symbolic], t: Symbolic) -> Symbolic:
    """The Maclaurin series (10.12a) cut after the given derivatives at t = 0 (x(0), v(0), a(0),
    j(0), ...): sum_k x^(k)(0) t^k / D_k, with the divisors D_k of (10.11) found by applying the
    power rule k times (``maclaurin_divisor``). Plain operators: symbols give an expression."""
    return sum((Fraction(1, maclaurin_divisor(k)) * d * t**k for k, d in enumerate(derivatives)), 0)
