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
"""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import mpmath

from mechmodel import fields, inputs
from mechmodel.algebra import polynomial_derivative

DIGITS = 40  # mpmath working precision (significant digits) for e and compound interest


def _fraction(value: mpmath.mpf) -> Fraction:
    """The exact rational value of an mpmath number: no digit of its precision is lost."""
    mantissa, exponent = mpmath.mpf(value).man_exp
    return Fraction(int(mantissa)) * Fraction(2) ** int(exponent)


def _mp(value: Any) -> mpmath.mpf:
    """An mpmath number from an int, float, Fraction or mpmath number (at the current dps)."""
    if isinstance(value, Fraction):
        return mpmath.mpf(value.numerator) / value.denominator
    return mpmath.mpf(value)


# ----------------------------------------------------------------------------------------------
# The exponential series (10.5)-(10.6)


def exp_series_term(x: Any, k: Any, *, exact: bool = False) -> Any:
    """The k-th term x^k / k! of the exponential series (10.5b)."""
    inputs.real(x, "x")
    k = inputs.count(k, "k")
    if exact:
        x = Fraction(x)
    return x**k / math.factorial(k)


def exp_partial_sum(x: Any, order: Any, *, exact: bool = False) -> Any:
    """Partial sum of e^x to precision order ``order``: sum_{k=0}^{order} x^k / k! (10.6)."""
    order = inputs.count(order, "order")
    return sum(exp_series_term(x, k, exact=exact) for k in range(order + 1))


def euler_number() -> mpmath.mpf:
    """Euler's growth constant e = lim (1 + 1/m)^m (10.1), (10.4), to ``DIGITS`` digits."""
    with mpmath.workdps(DIGITS):
        return +mpmath.e


def exponential(x: Any) -> mpmath.mpf:
    """e^x for a real x, to ``DIGITS`` digits (the function equal to its own slope, (10.1))."""
    inputs.real(x, "x")
    with mpmath.workdps(DIGITS):
        return mpmath.exp(_mp(x))


def exp_pi_multiple(multiple: Any) -> mpmath.mpf:
    """The real pi-exponential e^(multiple * pi), e.g. e^(-pi) of the text after (10.20)."""
    inputs.real(multiple, "multiple")
    with mpmath.workdps(DIGITS):
        return mpmath.exp(_mp(multiple) * mpmath.pi)


def pascal_triangle(rows: Any) -> list[list[int]]:
    """Rows n = 0..rows of Pascal's triangle built by Pascal's rule alone: every entry is the sum
    of the one or two entries above it, the pinnacle B00 = 1 (Table 1 of chapter 10)."""
    rows = inputs.count(rows, "rows")
    triangle = [[1]]
    for _ in range(rows):
        above = triangle[-1]
        triangle.append([a + b for a, b in zip([0, *above], [*above, 0], strict=True)])
    return triangle


def _leading_coefficient(values: list[Fraction]) -> Fraction:
    """Leading coefficient of the polynomial of degree len(values) - 1 through the points
    (j, values[j]), j = 0, 1, ... (Lagrange interpolation, exact)."""
    n = len(values)
    total = Fraction(0)
    for i, y in enumerate(values):
        denominator = 1
        for j in range(n):
            if j != i:
                denominator *= i - j
        total += Fraction(y) / denominator
    return total


def exp_series_coefficient(power: Any) -> Fraction:
    """Coefficient of (r t)^k in e^(r t), from the binomial limit (10.4)-(10.5a).

    In (1 + r t/n)^n the term (r t)^k has the coefficient B(n, k) / n^k; as n grows only the
    leading n^k of B(n, k) survives, so the coefficient is the leading coefficient of B(n, k) as a
    polynomial in n ("huge n makes n(n-1) cancel n^2"). The B(n, k) are counted with Pascal's
    rule, not with factorials; the result is the exact Fraction 1/k!.
    """
    k = inputs.count(power, "power")
    triangle = pascal_triangle(k)
    counts = [Fraction(row[k]) if k < len(row) else Fraction(0) for row in triangle]
    return _leading_coefficient(counts)


def inverse_factorial(value: Any) -> int:
    """The j with j! = value (the smallest such j, so 1 gives 0); ``ValueError`` if none."""
    target = Fraction(value)
    j, f = 0, 1
    while f < target:
        j += 1
        f *= j
    if f != target:
        raise ValueError(f"{value!r} is not a factorial")
    return j


def exp_series_factorial(power: Any) -> int:
    """The j of the denominator j! of the (r t)^k term of the e-series (10.5a): the inverse
    factorial of 1 / ``exp_series_coefficient(k)`` (it is k)."""
    k = inputs.count(power, "power")
    return inverse_factorial(1 / exp_series_coefficient(k))


def exp_series_correct_decimals(x: Any, order: Any) -> int:
    """Decimal places to which the order-``order`` partial sum of e^x is correct: the largest d
    with |partial sum - e^x| < 10^-d / 2 ("5-figure accuracy" of (10.6))."""
    order = inputs.count(order, "order")
    with mpmath.workdps(DIGITS):
        error = abs(_mp(exp_partial_sum(Fraction(x), order, exact=True)) - exponential(x))
        d = 0
        while error < mpmath.mpf(10) ** (-(d + 1)) / 2:
            d += 1
        return d


def exp_series_additions(order: Any) -> int:
    """Additions needed for the order-``order`` partial sum: one fewer than its terms (10.6)."""
    order = inputs.count(order, "order")
    terms = [exp_series_term(1, k, exact=True) for k in range(order + 1)]
    return len(terms) - 1


def exp_series_term_count(order: Any) -> int:
    """Number of terms of the order-``order`` partial sum of the e-series: k = 0..order."""
    order = inputs.count(order, "order")
    return len(range(order + 1))


def exp_remainder_bound(x: Any, order: Any) -> Any:
    """Lagrange bound on |e^x - partial sum to ``order``|: |x|^(o+1)/(o+1)! e^max(x, 0).

    For x > 0 the next term alone is not a bound (all later terms are positive); the factor
    e^x covers them. For x <= 0 the series alternates and the next term bounds the error.
    """
    order = inputs.count(order, "order")
    inputs.real(x, "x")
    with mpmath.workdps(DIGITS):
        next_term = _mp(abs(x)) ** (order + 1) / math.factorial(order + 1)
        return next_term * (exponential(x) if x > 0 else 1)


def exp_series_polynomial(rate: Any, time: Any, order: Any) -> Any:
    """The e-series (10.5a) of e^(r t) cut after its (r t)^``order`` term: sum_k c_k (r t)^k,
    the coefficients c_k those of the binomial limit (``exp_series_coefficient``: counted with
    Pascal's rule, not with factorials). Plain operators: symbols give an expression."""
    order = inputs.count(order, "order")
    x = rate * time
    return sum((exp_series_coefficient(k) * x**k for k in range(order + 1)), 0)


def exp_series_polynomial_rate(rate: Any, time: Any, order: Any) -> Any:
    """The time rate d/dt of ``exp_series_polynomial`` (10.9): the power rule (10.8b) applied
    term by term to that polynomial in t, whose coefficients are c_k r^k."""
    order = inputs.count(order, "order")
    coefficients = [exp_series_coefficient(k) * rate**k for k in range(order + 1)]
    return sum((c * time**k for k, c in enumerate(polynomial_derivative(coefficients))), 0)


def exp_to_log_rotation() -> float:
    """The quarter turn that carries the graph of y = e^x onto the log potential U = -ln y
    (Fig. 10.1: "rotate your y = e^x graph by 90 degrees"). Each candidate rotation by j * 90
    degrees is applied to points (x, e^x); the one whose images satisfy Y = -ln X is returned as
    a magnitude in radians (it is clockwise)."""
    quarter = math.pi / 2
    samples = [-1 + j / 4 for j in range(9)]
    for j in (1, -1, 2, 3, -3):
        found = True
        for x in samples:
            z = unit_phasor(j * quarter) * complex(x, math.exp(x))
            if z.real <= 0 or abs(z.imag + math.log(z.real)) > 2**-40:
                found = False
                break
        if found:
            return abs(j) * quarter
    raise ValueError("no quarter turn maps y = e^x onto U = -ln y")


def _log_potential_slope(y: Any) -> mpmath.mpf:
    """dU/dy of U(y) = -ln y by a symmetric difference quotient at high precision."""
    with mpmath.workdps(DIGITS):
        h = mpmath.mpf(10) ** (-(DIGITS // 3))
        yy = _mp(Fraction(y))
        return (-mpmath.log(yy + h) + mpmath.log(yy - h)) / (2 * h)


def log_potential_force(y: Any) -> float:
    """The force F(y) = -dU/dy of the log potential U(y) = -ln y (Fig. 10.1b, c), from the
    slope of U by a difference quotient at high precision (it is 1/y)."""
    inputs.positive(y, "y")
    return float(-_log_potential_slope(y))


def log_potential_normal_angle(y: Any) -> float:
    """Angle (radians) between the hypotenuse of the force triangle (base F(y), altitude 1) and
    the tangent (1, dU/dy) of U = -ln y at y (Fig. 10.1c: "hypotenuse is 90 degrees to U(y)")."""
    inputs.positive(y, "y")
    slope = float(_log_potential_slope(y))
    force = -slope
    hypotenuse = complex(force, 1)  # base F across, altitude 1 up
    tangent = complex(1, slope)
    return abs(cmath.phase(hypotenuse / tangent))


# ----------------------------------------------------------------------------------------------
# Interest: simple, compound (10.3) and continuous


def interest_rate(rate: Any) -> Any:
    """A yearly interest rate r as a pure number (r = 0.03 is 3% a year): the claim's unit
    (percent) writes it the way the text does."""
    return inputs.real(rate, "rate")


def simple_interest(rate: Any, time: Any, principal: Any) -> Any:
    """Simple interest: p(t) = (1 + r t) p(0), r per year, t in years, p in dollars."""
    for value, name in ((rate, "rate"), (time, "time"), (principal, "principal")):
        inputs.real(value, name)
    return (1 + rate * time) * principal


def compound_period(periods: Any, time: Any = 1, elapsed: Any = 1) -> Any:
    """End of the ``elapsed``-th of ``periods`` equal compounding periods of ``time`` years:
    elapsed t/m (the half-period t/2, the 1/3rd-period t/3, 2t/3, ...)."""
    m = inputs.count(periods, "periods", minimum=1)
    inputs.real(time, "time")
    return Fraction(elapsed) * Fraction(time) / m


def compound_factor(rate: Any, periods: Any, time: Any = 1) -> Any:
    """The growth factor of one compounding period, 1 + r t/m (exact for int and Fraction)."""
    m = inputs.count(periods, "periods", minimum=1)
    inputs.real(rate, "rate")
    inputs.real(time, "time")
    if isinstance(rate, int | Fraction) and isinstance(time, int | Fraction):
        return 1 + Fraction(rate) * Fraction(time) / m
    return 1 + rate * time / m


def compound_growth(rate: Any, periods: Any, time: Any = 1, principal: Any = 1) -> Fraction:
    """Compound interest p_(1/m)(t) = (1 + r t/m)^m p(0) (10.3), to ``DIGITS`` digits.

    Computed as p(0) exp(m log1p(r t/m)) in mpmath: floating point loses the digits of
    1 + 1/m from m = 1e6 on and exact fractions are hopeless at m = 1e9. Returned as the exact
    Fraction of that 40-digit number, so that no digit is lost on the way to the comparison
    (a float would not tell m = 1e9 from m = 1e9 + 1).
    """
    m = inputs.count(periods, "periods", minimum=1)
    for value, name in ((rate, "rate"), (time, "time"), (principal, "principal")):
        inputs.real(value, name)
    with mpmath.workdps(DIGITS):
        step = _mp(Fraction(rate) * Fraction(time) / m)
        return _fraction(_mp(Fraction(principal)) * mpmath.exp(m * mpmath.log1p(step)))


def compound_growth_exact(rate: Any, periods: Any, time: Any = 1, principal: Any = 1) -> Fraction:
    """(1 + r t/m)^m p(0) as an exact Fraction for rational inputs (the book's 9/4, 64/27...)."""
    m = inputs.count(periods, "periods", minimum=1)
    return compound_factor(Fraction(rate), m, Fraction(time)) ** m * Fraction(principal)


def continuous_growth(rate: Any, time: Any = 1, principal: Any = 1) -> mpmath.mpf:
    """The limit of compounding ever more often: p(0) e^(r t) (10.4), to ``DIGITS`` digits."""
    for value, name in ((rate, "rate"), (time, "time"), (principal, "principal")):
        inputs.real(value, name)
    with mpmath.workdps(DIGITS):
        return _mp(Fraction(principal)) * exponential(Fraction(rate) * Fraction(time))


def compound_solid_figures(rate: Any, periods: Any, time: Any = 1, after: Any = 0) -> int:
    """The "solid figures" of compound interest (10.3): the leading significant digits of
    (1 + r t/m)^m (truncated, not rounded) that it shares with the limit e^(r t), less the first
    ``after`` figures (those of the "2.71" the text counts beyond)."""
    after = inputs.count(after, "after")
    with mpmath.workdps(DIGITS):
        value = _mp(compound_growth(rate, periods, time))
        limit = continuous_growth(rate, time)
        scale = mpmath.mpf(10) ** (DIGITS // 2 - int(mpmath.floor(mpmath.log10(limit))))
        a = str(int(mpmath.floor(value * scale)))
        b = str(int(mpmath.floor(limit * scale)))
    same = 0
    while same < min(len(a), len(b)) and a[same] == b[same]:
        same += 1
    return same - after


# ----------------------------------------------------------------------------------------------
# Binomials and Pascal's triangle


def factorial(n: Any) -> int:
    """n! = n (n-1) ... 2 1, with 0! = 1."""
    n = inputs.count(n, "n")
    return math.factorial(n)


def binomial(n: Any, k: Any) -> int:
    """Binomial coefficient B(n, k) = n!/(k!(n-k)!) from factorials (the formula after (9));
    0 outside 0 <= k <= n."""
    n = inputs.count(n, "n")
    k = inputs.integer(k, "k")
    if not 0 <= k <= n:
        return 0
    return factorial(n) // (factorial(k) * factorial(n - k))


def binomial_pq(p: Any, q: Any) -> int:
    """B^n_(p,q) = n!/(p! q!) with n = p + q: the ways to pick p x's and q y's (x^p y^q)."""
    p = inputs.count(p, "p")
    q = inputs.count(q, "q")
    return binomial(p + q, p)


def binomial_complement(n: Any, k: Any) -> int:
    """The other count of a two-way choice: n - k (tails when k of n tosses are heads)."""
    n = inputs.count(n, "n")
    k = inputs.count(k, "k")
    if k > n:
        raise ValueError(f"k = {k} exceeds n = {n}")
    return n - k


def card_deck_size(x_cards: Any, y_cards: Any) -> int:
    """Cards in a deck of ``x_cards`` x-cards and ``y_cards`` y-cards."""
    return inputs.count(x_cards, "x_cards") + inputs.count(y_cards, "y_cards")


def binomial_expansion(power: Any) -> list[int]:
    """Coefficients of (x + y)^n, x^n first, by multiplying (x + y) n times: the "table of
    product terms" of (1)-(5) (each factor adds its row shifted by one power of y)."""
    n = inputs.count(power, "power")
    coefficients = [1]
    for _ in range(n):
        times_x = [*coefficients, 0]
        times_y = [0, *coefficients]
        coefficients = [a + b for a, b in zip(times_x, times_y, strict=True)]
    return coefficients


def binomial_terms(x: Any, y: Any, n: Any, first: Any, last: Any, end: str = "x") -> Any:
    """The sum of the terms B(n, k) x^(n-k) y^k of (x + y)^n for k = ``first`` .. ``last`` (the
    binomial series after (10.4)), the coefficients from ``binomial_expansion``; ``end = "y"``
    counts the terms from the y^n end instead: k = n - ``last`` .. n - ``first``."""
    n = inputs.count(n, "n")
    first, last = inputs.count(first, "first"), inputs.count(last, "last")
    if end not in ("x", "y"):
        raise ValueError(f"end must be 'x' or 'y', got {end!r}")
    row = binomial_expansion(n)
    ks = range(n - last, n - first + 1) if end == "y" else range(first, last + 1)
    return sum((row[k] * x ** (n - k) * y**k for k in ks if 0 <= k <= n), 0)


def compound_binomial_terms(rate: Any, time: Any, n: Any, last: Any) -> Any:
    """The binomial series of (1 + r t/n)^n (the step from (10.4) to (10.5a)) through its
    (r t/n)^``last`` term: ``binomial_terms`` with x = 1, y = r t/n."""
    return binomial_terms(1, rate * time / n, n, 0, last)


def falling_factorial_leading_term(n: Any, factors: Any) -> Any:
    """The leading term of n(n-1)...(n-k+1), k = ``factors``, as a polynomial in n: the power of
    n that cancels the n^k of (r t/n)^k for huge n (after (10.4)). The product is multiplied
    out factor by factor (coefficient lists, constant term first) and its top term kept."""
    k = inputs.count(factors, "factors")
    coefficients = [1]
    for j in range(k):  # times (n - j)
        shifted = [0, *coefficients]
        scaled = [-j * c for c in coefficients] + [0]
        coefficients = [a + b for a, b in zip(shifted, scaled, strict=True)]
    degree = max(d for d, c in enumerate(coefficients) if c)
    return coefficients[degree] * n**degree


def binomial_box_power(top_power: Any) -> int:
    """Power of the product computed in a multiplication box: the top row (x + y)^n times the
    factor (x + y) on the left is (x + y)^(n + 1); read off the expansion's length."""
    n = inputs.count(top_power, "top_power")
    return len(binomial_expansion(n)) if n >= 0 else 0


def binomial_box_row(x: Any, y: Any, top_power: Any, left: str) -> Any:
    """A row of the multiplication box of (2)-(5): the factor ``left`` (x or y) on the left
    times each term of the top row (x + y)^n (coefficients of ``binomial_expansion``), added
    up. Plain operators: symbols give an expression."""
    if left not in ("x", "y"):
        raise ValueError(f"left must be 'x' or 'y', got {left!r}")
    n = inputs.count(top_power, "top_power")
    factor = x if left == "x" else y
    row = binomial_expansion(n)
    return sum((factor * row[k] * x ** (n - k) * y**k for k in range(n + 1)), 0)


def binomial_box_product(x: Any, y: Any, top_power: Any) -> Any:
    """The product worked out in a multiplication box, (x + y)^n (x + y) of (2)-(5): the x row
    plus the y row (``binomial_box_row``)."""
    return binomial_box_row(x, y, top_power, "x") + binomial_box_row(x, y, top_power, "y")


def pascal_row_length(n: Any) -> int:
    """Number of entries ("spots") of row n of Pascal's triangle."""
    n = inputs.count(n, "n")
    return len(pascal_triangle(n)[n])


def pascal_row_span(n: Any) -> dict[str, int]:
    """Smallest and largest q - p over the entries B_(p,q) of row n = p + q."""
    n = inputs.count(n, "n")
    spots = [n - 2 * p for p in range(len(pascal_triangle(n)[n]))]
    return {"min": min(spots), "max": max(spots)}


def pascal_row_sum(n: Any) -> int:
    """Sum of row n of Pascal's triangle (8): the count of all terms of (x + y)^n."""
    n = inputs.count(n, "n")
    return sum(pascal_triangle(n)[n])


def binomial_term_count(factors: Any) -> int:
    """Terms of the product of ``factors`` factors (x + y) before collecting: x or y from each,
    so 2 * 2 * ... (7)-(8)."""
    n = inputs.count(factors, "factors")
    count = 1
    for _ in range(n):
        count *= len(("x", "y"))
    return count


def integer_power(base: Any, exponent: Any) -> int:
    """base^exponent for integers, by repeated multiplication ((9): 2^2 = 4, ...)."""
    base = inputs.integer(base, "base")
    exponent = inputs.count(exponent, "exponent")
    value = 1
    for _ in range(exponent):
        value *= base
    return value


def falling_factors(n: Any, k: Any) -> list[int]:
    """The factors n (n-1) ... (n-k+1) of n!/(n-k)!, largest first (10!/8! = 10*9)."""
    n = inputs.count(n, "n")
    k = inputs.count(k, "k")
    return [n - j for j in range(k)]


def falling_factors_pq(p: Any, q: Any) -> list[int]:
    """The factors of (p + q)!/q!, largest first: 10!/(2! 8!) = 10 * 9 / 2 (after (9))."""
    return falling_factors(inputs.count(p, "p") + inputs.count(q, "q"), p)


def gaussian_exponent_coefficient(n: Any) -> Fraction:
    """Coefficient c of the Gauss approximation B(n, n/2 + x) / B(n, n/2) ~ e^(-c x^2) of the
    binomial distribution (plotted after (9) for n = 10): the binomial variance n/4 of p about
    n/2 gives c = 1 / (2 n/4) = 2/n."""
    n = inputs.count(n, "n", minimum=1)
    variance = Fraction(n, 4)  # n tosses of p = 1/2: n p (1 - p)
    return 1 / (2 * variance)


def binomial_gaussian(n: Any, deviation: Any) -> dict[str, Any]:
    """Binomial ratio B(n, n/2 + x)/B(n, n/2) and its Gauss approximation e^(-2 x^2/n)."""
    n = inputs.count(n, "n", minimum=1)
    x = inputs.integer(deviation, "deviation")
    centre = n // 2
    ratio = Fraction(binomial(n, centre + x), binomial(n, centre))
    return {"binomial": ratio, "gauss": math.exp(-float(gaussian_exponent_coefficient(n)) * x**2)}


# ----------------------------------------------------------------------------------------------
# Derivatives and the Maclaurin series (10.7)-(10.12)


@dataclass(frozen=True)
class PowerRule:
    """d/dt t^n = ``factor`` t^``power`` (10.8b); ``drop`` = n - power."""

    factor: int
    power: int
    drop: int


def power_rule(power: Any) -> PowerRule:
    """Derivative of t^n from the binomial expansion of ((t + dt)^n - t^n)/dt (10.8a): the only
    term that survives tiny dt is B(n, 1) t^(n-1) dt / dt."""
    n = inputs.count(power, "power")
    if n == 0:
        return PowerRule(0, 0, 0)  # a constant has no slope
    # (t + dt)^n - t^n = sum_{j>=1} B(n, j) t^(n-j) dt^j; divided by dt, only j = 1 survives
    row = binomial_expansion(n)
    return PowerRule(row[1], n - 1, 1)


def power_rule_drop(powers: list[Any], derivative: Any = 1) -> int:
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


def derivative_term(power: Any, derivative: Any) -> DerivativeTerm:
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


def power_increment(t: Any, dt: Any, power: Any) -> Any:
    """The rise x(t + dt) - x(t) of the power curve x = t^n over a step dt ((10.7a), (10.8a)):
    (t + dt)^n expanded with the coefficients of ``binomial_expansion`` (the multiplication
    box), less t^n. Plain operators: symbols give an expression."""
    n = inputs.count(power, "power")
    row = binomial_expansion(n)
    return sum((row[j] * t ** (n - j) * dt**j for j in range(n + 1)), 0) - t**n


def secant_slope(t: Any, dt: Any, power: Any) -> Any:
    """The slope ratio dx/dt of the secant of x = t^n from t to t + dt ((10.7a), (10.8a))."""
    return power_increment(t, dt, power) / dt


def power_derivative(t: Any, power: Any, coefficient: Any = 1) -> Any:
    """The tangent slope d/dt (A t^n) of (10.7b), (10.8b): A times the ``power_rule``'s factor
    times t to its lowered power (the secant slope's limit as dt shrinks)."""
    rule = power_rule(power)
    return coefficient * rule.factor * t**rule.power


def parabola_slope(lam: Any, x: Any) -> Any:
    """Slope dy/dx at ``x`` of the parabola 2 lam y = x^2 of semi-latus rectum ``lam`` (Fig. 9.4,
    checked after (10.7b)): its height ``fields.parabola_height_for_latus`` is a multiple of
    x^2, differentiated by the power rule (``power_derivative``)."""
    return power_derivative(x, 2, coefficient=fields.parabola_height_for_latus(lam, 1))


def nth_difference_quotient(difference: Any, step: Any, order: Any) -> Any:
    """Leibniz's d^n x/dt^n of (10.12b): the n-th difference d^n x of x, divided by the step dt
    once for each of the n difference quotients taken (the d/dt of d/dt of ...): over dt^n."""
    n = inputs.count(order, "order")
    value = difference
    for _ in range(n):
        value = value / step
    return value


def polynomial_rate(coefficients: list[Any], t: Any, derivative: Any = 1) -> Any:
    """The ``derivative``-th time derivative of x(t) = sum_k c_k t^k at t ((10.11c)-(10.11i)):
    ``polynomial_derivative`` applied that many times. Plain operators: symbols give an
    expression."""
    d = inputs.count(derivative, "derivative")
    current = list(coefficients)
    for _ in range(d):
        current = polynomial_derivative(current)
    return sum((c * t**k for k, c in enumerate(current)), 0)


def power_term_rate(t: Any, power: Any, derivative: Any, coefficient: Any = 1) -> Any:
    """The ``derivative``-th derivative of c t^n, the general term of (10.11c)-(10.11i):
    ``derivative_term``'s factor times c times t to the lowered power."""
    term = derivative_term(power, derivative)
    return coefficient * term.factor * t**term.power


def maclaurin_divisor(power: Any) -> int:
    """c_k = x^(k)(0) / D_k: the k-th derivative of c_k t^k at t = 0 is D_k c_k, D_k the product
    of the power-rule factors (10.11); D_2 = 2 gives c2 = a(0)/2."""
    k = inputs.count(power, "power")
    return derivative_term(k, k).factor


def maclaurin_factorial(power: Any) -> int:
    """The j of the 1/j! in c_k = x^(k)(0)/j! (10.11f), (10.12a): the inverse factorial of the
    divisor D_k (it is k)."""
    k = inputs.count(power, "power")
    return inverse_factorial(maclaurin_divisor(k))


def leibniz_denominator(step: Any, order: Any) -> Any:
    """The denominator of Leibniz's d^n x/dt^n (10.12b): what the n-th difference d^n x is
    divided by in ``nth_difference_quotient``, one dt per derivative taken (dt^n)."""
    return 1 / nth_difference_quotient(1, step, order)


def maclaurin_polynomial(derivatives: list[Any], t: Any) -> Any:
    """The Maclaurin series (10.12a) cut after the given derivatives at t = 0 (x(0), v(0), a(0),
    j(0), ...): sum_k x^(k)(0) t^k / D_k, with the divisors D_k of (10.11) found by applying the
    power rule k times (``maclaurin_divisor``). Plain operators: symbols give an expression."""
    return sum((Fraction(1, maclaurin_divisor(k)) * d * t**k for k, d in enumerate(derivatives)), 0)


# ----------------------------------------------------------------------------------------------
# Sine and cosine (10.13)-(10.16)

_SINUSOIDS = ("sin", "cos")


def _kind(kind: str) -> str:
    if kind not in _SINUSOIDS:
        raise ValueError(f"kind must be 'sin' or 'cos', got {kind!r}")
    return kind


@dataclass(frozen=True)
class SinusoidDerivative:
    """d^n/dt^n of sin(w t) or cos(w t) = ``sign`` w^``omega_power`` ``function``(w t), and
    ``value_at_zero``: that derivative at t = 0 for w = 1 (the x(0), v(0), a(0)... of (10.16))."""

    sign: int
    omega_power: int
    function: str
    value_at_zero: int


def sinusoid_derivative(kind: str, order: Any) -> SinusoidDerivative:
    """Differentiate sin or cos ``order`` times with (10.15): d/dt sin w t = w cos w t,
    d/dt cos w t = -w sin w t (each step one more factor w)."""
    function = _kind(kind)
    n = inputs.count(order, "order")
    sign, power = 1, 0
    for _ in range(n):
        if function == "sin":
            function = "cos"
        else:
            function, sign = "sin", -sign
        power += 1
    at_zero = sign * (1 if function == "cos" else 0)  # cos 0 = 1, sin 0 = 0
    return SinusoidDerivative(sign, power, function, at_zero)


def sinusoid_coefficient(kind: str, power: Any) -> Fraction:
    """Maclaurin coefficient c_n = x^(n)(0)/n! of sin t or cos t (w = 1), (10.12), (10.16)."""
    n = inputs.count(power, "power")
    return Fraction(sinusoid_derivative(kind, n).value_at_zero, factorial(n))


def sinusoid_derivative_period(kind: str) -> int:
    """Number of derivatives after which sin or cos repeats: (10.16)'s repeat-after-4 pattern."""
    start = sinusoid_derivative(kind, 0)
    n = 1
    while True:
        d = sinusoid_derivative(kind, n)
        if (d.sign, d.function) == (start.sign, start.function):
            return n
        n += 1


def sinusoid_series_factors(kind: str) -> list[int]:
    """The factors x^(n)(0) of the (w t)^n/n! terms over one period: 0, 1, 0, -1 for sine."""
    return [
        sinusoid_derivative(kind, n).value_at_zero for n in range(sinusoid_derivative_period(kind))
    ]


def sinusoid_powers(kind: str, count: Any) -> list[int]:
    """The first ``count`` powers p with a nonzero coefficient: odd for sine, even for cosine."""
    count = inputs.count(count, "count")
    out: list[int] = []
    p = 0
    while len(out) < count:
        if sinusoid_derivative(kind, p).value_at_zero != 0:
            out.append(p)
        p += 1
    return out


def sinusoid_term_count(kind: str, order: Any) -> int:
    """Number of nonzero terms of the sine or cosine series up to power ``order``."""
    order = inputs.count(order, "order")
    return sum(1 for p in range(order + 1) if sinusoid_derivative(kind, p).value_at_zero)


@dataclass(frozen=True)
class TermCountFormula:
    """Number of terms n = (o + ``offset``)/``divisor`` for the orders o that end on a term."""

    offset: int
    divisor: int


def sinusoid_term_count_formula(kind: str) -> TermCountFormula:
    """Fit n = (o + offset)/divisor to the counted terms of the orders that end on a nonzero
    term ((o+1)/2 for sine, (o+2)/2 for cosine: Fig. 10.4's text)."""
    orders = sinusoid_powers(kind, 3)
    counts = [sinusoid_term_count(kind, o) for o in orders]
    divisor = Fraction(orders[1] - orders[0], counts[1] - counts[0])
    offset = divisor * counts[0] - orders[0]
    for o, n in zip(orders, counts, strict=True):
        if (o + offset) / divisor != n:
            raise ValueError("the term count is not linear in the order")
    return TermCountFormula(int(offset), int(divisor))


def _sinusoid_terms(kind: str, order: int) -> list[tuple[int, int]]:
    """(power, x^(power)(0)) of the nonzero terms up to ``order``."""
    out = []
    for p in range(order + 1):
        c = sinusoid_derivative(kind, p).value_at_zero
        if c:
            out.append((p, c))
    return out


def _sum_terms(terms: list[tuple[int, int]], x: Any) -> Any:
    total: Any = 0
    for p, c in terms:
        total += c * x**p / math.factorial(p)
    return total


def sinusoid_partial_sum(kind: str, x: Any, order: Any) -> Any:
    """Partial sum of the sine or cosine series (10.16) up to power ``order`` at x = w t."""
    inputs.real(x, "x")
    order = inputs.count(order, "order")
    return _sum_terms(_sinusoid_terms(kind, order), x)


def sinusoid_coefficient_in_omega(kind: str, omega: Any, power: Any) -> Any:
    """Maclaurin coefficient c_n = x^(n)(0)/n! of sin(w t) or cos(w t) as a function of w (the
    list after (10.15)): the n-th derivative of (10.15) at t = 0, sign w^n (cos 0) or 0 (sin 0),
    over the divisor D_n of (10.11). Plain operators: a symbol w gives an expression."""
    n = inputs.count(power, "power")
    d = sinusoid_derivative(kind, n)
    return Fraction(d.value_at_zero, maclaurin_divisor(n)) * omega**d.omega_power


def sinusoid_series(kind: str, omega: Any, t: Any, order: Any) -> Any:
    """The sine or cosine series (10.16) of sin(w t) or cos(w t) up to the power ``order``, its
    zero terms included: sum_n x^(n)(0) t^n / D_n with the derivatives x^(n)(0) = sign w^n
    (cos 0) or 0 (sin 0) of (10.15) (``sinusoid_derivative``) and the Maclaurin divisors D_n
    (10.11). Plain operators: symbols give an expression."""
    order = inputs.count(order, "order")
    total: Any = 0
    for n in range(order + 1):
        d = sinusoid_derivative(kind, n)
        total += Fraction(d.value_at_zero, maclaurin_divisor(n)) * omega**d.omega_power * t**n
    return total


def sinusoid_remainder_bound(x: Any, order: Any) -> Any:
    """Lagrange bound |x|^(o+1)/(o+1)! on |sin x - partial sum| and |cos x - partial sum|
    (every derivative of sin and cos is at most 1 in size)."""
    inputs.real(x, "x")
    order = inputs.count(order, "order")
    return abs(x) ** (order + 1) / math.factorial(order + 1)


def sinusoid_max_error(
    kind: str, order: Any, oscillations: Any = 1, samples: int = 2**10 + 1
) -> float:
    """Largest |partial sum - function| over ``oscillations`` full periods centred on t = 0,
    t in [-pi k, pi k] (on ``samples`` points; the error grows toward the ends)."""
    inputs.positive(oscillations, "oscillations")
    order = inputs.count(order, "order")
    reference = math.sin if _kind(kind) == "sin" else math.cos
    terms = _sinusoid_terms(kind, order)
    half = math.pi * oscillations
    points = [half * (2 * j / (samples - 1) - 1) for j in range(samples)]
    return max(abs(_sum_terms(terms, t) - reference(t)) for t in points)


def sinusoid_min_order(kind: str, tolerance: Any, oscillations: Any = 1) -> int:
    """Lowest order o whose partial sum stays within ``tolerance`` (an absolute error, the
    amplitude being 1) over ``oscillations`` full periods centred on t = 0 (Fig. 10.4)."""
    inputs.positive(tolerance, "tolerance")
    order = 0
    while sinusoid_max_error(kind, order, oscillations) > tolerance:
        order += 1
    # report the order of the last nonzero term used (order o and o+1 may give the same sum)
    while order > 0 and sinusoid_derivative(kind, order).value_at_zero == 0:
        order -= 1
    return order


def sinusoid_min_terms(kind: str, tolerance: Any, oscillations: Any = 1) -> int:
    """Nonzero terms of the lowest-order partial sum within ``tolerance`` (see above)."""
    return sinusoid_term_count(kind, sinusoid_min_order(kind, tolerance, oscillations))


# ----------------------------------------------------------------------------------------------
# Euler's formula, phasors and complex products (10.17)-(10.30)


def imaginary_unit_power(k: Any) -> complex:
    """i^k by repeated multiplication by i = sqrt(-1) (exact in floating point)."""
    k = inputs.count(k, "k")
    value = complex(1, 0)
    for _ in range(k):
        value = complex(-value.imag, value.real)  # times i
    return value


def imaginary_unit_period() -> int:
    """The smallest k > 0 with i^k = 1: the repeat-after-4 pattern of the powers of i."""
    k = 1
    while imaginary_unit_power(k) != 1:
        k += 1
    return k


def euler_series(theta: Any, order: Any) -> complex:
    """Partial sum of e^(i theta) = sum_k (i theta)^k / k! to ``order`` (10.17)."""
    inputs.real(theta, "theta")
    order = inputs.count(order, "order")
    return sum(imaginary_unit_power(k) * theta**k / math.factorial(k) for k in range(order + 1))


def unit_phasor(angle: Any = 0, pi_multiple: Any = 0) -> complex:
    """e^(i phi) = cos phi + i sin phi (10.17) for phi = angle + pi_multiple * pi (radians)."""
    inputs.real(angle, "angle")
    inputs.real(pi_multiple, "pi_multiple")
    phi = float(angle) + float(pi_multiple) * math.pi
    return complex(math.cos(phi), math.sin(phi))


def phasor_divisor(
    numerator_re: Any, numerator_im: Any, angle: Any, angle_sign: Any = 1, sign: Any = 1
) -> complex:
    """The d of e^(i s phi) = sign (a + i b)/d: d = sign (a + i b) / e^(i s phi)
    ((10.21): e^(i pi/4) = (1 + i)/sqrt 2). Real where the identity holds."""
    z = complex(float(numerator_re), float(numerator_im)) * float(sign)
    return z / unit_phasor(float(angle) * float(angle_sign))


def opposite_phasor_angle(angle: Any = 0, pi_multiple: Any = 0, exponent_sign: Any = -1) -> float:
    """The angle psi in [0, 2 pi) with -e^(s i psi) = e^(i phi), s = ``exponent_sign`` (-1 or +1):
    the "-e^(-i 3pi/4)" and "-e^(+i 5pi/4)" forms of e^(i pi/4) in (10.21). Radians."""
    if exponent_sign not in (-1, 1):
        raise ValueError(f"exponent_sign must be -1 or +1, got {exponent_sign!r}")
    phi = float(angle) + float(pi_multiple) * math.pi
    target = -unit_phasor(phi)  # e^(s i psi) = -e^(i phi)
    psi = cmath.phase(target) * exponent_sign
    return psi % (2 * math.pi)


def clockwise_angle(angle: Any = 0, pi_multiple: Any = 0) -> float:
    """The clockwise angle psi in [0, 2 pi) with e^(-i psi) = e^(i phi) (e^(i5pi/4) = e^(-i3pi/4),
    Fig. 10.5a). Radians."""
    phi = float(angle) + float(pi_multiple) * math.pi
    return cmath.phase(unit_phasor(phi).conjugate()) % (2 * math.pi)


def phasor_modulus(x: Any, y: Any) -> float:
    """The modulus r = A = |psi| of the phasor with Cartesian parts psi_x = ``x``, psi_y = ``y``
    (the polar form of (10.19b), Fig. 10.5): the radius of x + i y in polar coordinates."""
    inputs.real(x, "x")
    inputs.real(y, "y")
    return cmath.polar(complex(float(x), float(y)))[0]


def phasor_quarter_cycle() -> float:
    """Fraction s of a cycle by which Re psi runs behind Im psi for psi = A e^(-i w t)
    (the "gonna-be" of Fig. 10.5b): Re psi(t + s T) = Im psi(t), i.e. e^(-2 pi i s) = -i."""
    target = complex(0, -1)  # Im psi = Re(-i psi)
    return (-cmath.phase(target) / (2 * math.pi)) % 1


@dataclass(frozen=True)
class PhasorDerivative:
    """d^n/dt^n x(0) e^(-i w t) = ``factor`` w^``omega_power`` x(t) (10.22)."""

    factor: complex
    omega_power: int


def phasor_derivative(order: Any) -> PhasorDerivative:
    """Differentiate e^(-i w t) ``order`` times: each derivative multiplies by -i w (10.22b)."""
    n = inputs.count(order, "order")
    factor, power = complex(1, 0), 0
    for _ in range(n):
        factor = factor * complex(0, -1)
        power += 1
    return PhasorDerivative(factor, power)


def phasor_rate(omega: Any, x: Any, order: Any) -> Any:
    """The ``order``-th time derivative of x(t) = x(0) e^(-i w t) as a multiple of x(t)
    ((10.22b), (10.23a)): the ``phasor_derivative`` factor times w^power times x."""
    d = phasor_derivative(order)
    f = d.factor  # a power of -i: real (+-1, kept an exact int) for an even order
    factor = int(f.real) if f.imag == 0 and f.real.is_integer() else f
    return factor * omega**d.omega_power * x


def unit_circle_radius(samples: Any = 12) -> float:
    """Largest |e^(i theta)| over ``samples`` angles around the circle: 1 (Fig. 10.5a)."""
    n = inputs.count(samples, "samples", minimum=1)
    return max(abs(unit_phasor(2 * math.pi * j / n)) for j in range(n))


def rotate(x: Any, y: Any, angle: Any) -> tuple[float, float]:
    """The 2-D rotation of (x, y) by ``angle`` as the complex product e^(i phi)(x + i y)
    (10.27a): (x cos phi - y sin phi, x sin phi + y cos phi)."""
    z = unit_phasor(angle) * complex(float(x), float(y))
    return z.real, z.imag
