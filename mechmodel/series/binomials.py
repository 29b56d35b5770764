"""Binomials, factorials and Pascal's triangle (chapter 10, (1)-(9) and Table 1).

B(n, k) = n!/(k!(n-k)!) from factorials and, independently, from the multiplication box of
(x + y)^n (each factor (x + y) adds its row shifted by one power of y) and Pascal's rule; the
binomial series of (1 + r t/n)^n on the way from (10.4) to (10.5a); counts of terms, factors
and cards; the Gauss approximation e^(-2 x^2/n) of the binomial ratio. Exact ``int`` and
``Fraction`` throughout; the functions of x and y in plain operators take ``Symbolic``
arguments (a formula claim calls them with sympy symbols).
"""

from __future__ import annotations

import math
from fractions import Fraction

from mechmodel import inputs
from mechmodel.typing import Symbolic


def factorial(n: int) -> int:
    """n! = n (n-1) ... 2 1, with 0! = 1."""
    n = inputs.count(n, "n")
    return math.factorial(n)


def binomial(n: int, k: int) -> int:
    """Binomial coefficient B(n, k) = n!/(k!(n-k)!) from factorials (the formula after (9));
    0 outside 0 <= k <= n."""
    n = inputs.count(n, "n")
    k = inputs.integer(k, "k")
    if not 0 <= k <= n:
        return 0
    return factorial(n) // (factorial(k) * factorial(n - k))


def binomial_pq(p: int, q: int) -> int:
    """B^n_(p,q) = n!/(p! q!) with n = p + q: the ways to pick p x's and q y's (x^p y^q)."""
    p = inputs.count(p, "p")
    q = inputs.count(q, "q")
    return binomial(p + q, p)


def binomial_complement(n: int, k: int) -> int:
    """The other count of a two-way choice: n - k (tails when k of n tosses are heads)."""
    n = inputs.count(n, "n")
    k = inputs.count(k, "k")
    if k > n:
        raise ValueError(f"k = {k} exceeds n = {n}")
    return n - k


def pascal_triangle(rows: int) -> list[list[int]]:
    """Rows n = 0..rows of Pascal's triangle built by Pascal's rule alone: every entry is the sum
    of the one or two entries above it, the pinnacle B00 = 1 (Table 1 of chapter 10)."""
    rows = inputs.count(rows, "rows")
    triangle = [[1]]
    for _ in range(rows):
        above = triangle[-1]
        triangle.append([a + b for a, b in zip([0, *above], [*above, 0], strict=True)])
    return triangle


def card_deck_size(x_cards: int, y_cards: int) -> int:
    """Cards in a deck of ``x_cards`` x-cards and ``y_cards`` y-cards."""
    return inputs.count(x_cards, "x_cards") + inputs.count(y_cards, "y_cards")


def binomial_expansion(power: int) -> list[int]:
    """Coefficients of (x + y)^n, x^n first, by multiplying (x + y) n times: the "table of
    product terms" of (1)-(5) (each factor adds its row shifted by one power of y)."""
    n = inputs.count(power, "power")
    coefficients = [1]
    for _ in range(n):
        times_x = [*coefficients, 0]
        times_y = [0, *coefficients]
        coefficients = [a + b for a, b in zip(times_x, times_y, strict=True)]
    return coefficients


def binomial_terms(
    x: Symbolic, y: Symbolic, n: int, first: int, last: int, end: str = "x"
) -> Symbolic:
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


def compound_binomial_terms(rate: Symbolic, time: Symbolic, n: int, last: int) -> Symbolic:
    """The binomial series of (1 + r t/n)^n (the step from (10.4) to (10.5a)) through its
    (r t/n)^``last`` term: ``binomial_terms`` with x = 1, y = r t/n."""
    return binomial_terms(1, rate * time / n, n, 0, last)


def falling_factorial_leading_term(n: Symbolic, factors: int) -> Symbolic:
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


def binomial_box_power(top_power: int) -> int:
    """Power of the product computed in a multiplication box: the top row (x + y)^n times the
    factor (x + y) on the left is (x + y)^(n + 1); read off the expansion's length."""
    n = inputs.count(top_power, "top_power")
    return len(binomial_expansion(n)) if n >= 0 else 0


def binomial_box_row(x: Symbolic, y: Symbolic, top_power: int, left: str) -> Symbolic:
    """A row of the multiplication box of (2)-(5): the factor ``left`` (x or y) on the left
    times each term of the top row (x + y)^n (coefficients of ``binomial_expansion``), added
    up. Plain operators: symbols give an expression."""
    if left not in ("x", "y"):
        raise ValueError(f"left must be 'x' or 'y', got {left!r}")
    n = inputs.count(top_power, "top_power")
    factor = x if left == "x" else y
    row = binomial_expansion(n)
    return sum((factor * row[k] * x ** (n - k) * y**k for k in range(n + 1)), 0)


def binomial_box_product(x: Symbolic, y: Symbolic, top_power: int) -> Symbolic:
    """The product worked out in a multiplication box, (x + y)^n (x + y) of (2)-(5): the x row
    plus the y row (``binomial_box_row``)."""
    return binomial_box_row(x, y, top_power, "x") + binomial_box_row(x, y, top_power, "y")


def pascal_row_length(n: int) -> int:
    """Number of entries ("spots") of row n of Pascal's triangle."""
    n = inputs.count(n, "n")
    return len(pascal_triangle(n)[n])


def pascal_row_span(n: int) -> dict[str, int]:
    """Smallest and largest q - p over the entries B_(p,q) of row n = p + q."""
    n = inputs.count(n, "n")
    spots = [n - 2 * p for p in range(len(pascal_triangle(n)[n]))]
    return {"min": min(spots), "max": max(spots)}


def pascal_row_sum(n: int) -> int:
    """Sum of row n of Pascal's triangle (8): the count of all terms of (x + y)^n."""
    n = inputs.count(n, "n")
    return sum(pascal_triangle(n)[n])


def binomial_term_count(factors: int) -> int:
    """Terms of the product of ``factors`` factors (x + y) before collecting: x or y from each,
    so 2 * 2 * ... (7)-(8)."""
    n = inputs.count(factors, "factors")
    count = 1
    for _ in range(n):
        count *= len(("x", "y"))
    return count


def integer_power(base: int, exponent: int) -> int:
    """base^exponent for integers, by repeated multiplication ((9): 2^2 = 4, ...)."""
    base = inputs.integer(base, "base")
    exponent = inputs.count(exponent, "exponent")
    value = 1
    for _ in range(exponent):
        value *= base
    return value


def falling_factors(n: int, k: int) -> list[int]:
    """The factors n (n-1) ... (n-k+1) of n!/(n-k)!, largest first (10!/8! = 10*9)."""
    n = inputs.count(n, "n")
    k = inputs.count(k, "k")
    return [n - j for j in range(k)]


def falling_factors_pq(p: int, q: int) -> list[int]:
    """The factors of (p + q)!/q!, largest first: 10!/(2! 8!) = 10 * 9 / 2 (after (9))."""
    return falling_factors(inputs.count(p, "p") + inputs.count(q, "q"), p)


def gaussian_exponent_coefficient(n: int) -> Fraction:
    """Coefficient c of the Gauss approximation B(n, n/2 + x) / B(n, n/2) ~ e^(-c x^2) of the
    binomial distribution (plotted after (9) for n = 10): the binomial variance n/4 of p about
    n/2 gives c = 1 / (2 n/4) = 2/n."""
    n = inputs.count(n, "n", minimum=1)
    variance = Fraction(n, 4)  # n tosses of p = 1/2: n p (1 - p)
    return 1 / (2 * variance)


def binomial_gaussian(n: int, deviation: int) -> dict[str, Fraction | float]:
    """Binomial ratio B(n, n/2 + x)/B(n, n/2) and its Gauss approximation e^(-2 x^2/n)."""
    n = inputs.count(n, "n", minimum=1)
    x = inputs.integer(deviation, "deviation")
    centre = n // 2
    ratio = Fraction(binomial(n, centre + x), binomial(n, centre))
    return {"binomial": ratio, "gauss": math.exp(-float(gaussian_exponent_coefficient(n)) * x**2)}
