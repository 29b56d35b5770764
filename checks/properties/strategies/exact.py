"""Exact numbers and exact algebra: the rationals p/q every exact strategy draws
(``rationals``), exact vectors and integer matrices (Appendix 1.A), numbers as the book
prints them (the judge) and Laurent polynomials (mechmodel.algebra)."""

from __future__ import annotations

import math
from fractions import Fraction

from hypothesis import strategies as st

from mechmodel.algebra import Laurent


def rationals(
    low: Fraction | int, high: Fraction | int, max_denominator: int
) -> st.SearchStrategy[Fraction]:
    """An exact p/q in [low, high] with 1 <= q <= max_denominator, unpacked from one drawn
    integer n (q from n mod max_denominator, p from the rest): one draw is a third cheaper than
    two, and ``st.fractions`` draws the same numbers several times more slowly. Shrinking n
    towards 0 gives the least whole number in the range (q = 1)."""
    low, high = Fraction(low), Fraction(high)

    def build(n: int) -> Fraction:
        q, u = n % max_denominator + 1, n // max_denominator
        first, last = math.ceil(low * q), math.floor(high * q)
        return Fraction(first + u % (last - first + 1), q)

    return st.integers(0, max_denominator * 2**31 - 1).map(build)


# --- vectors and matrices (Appendix 1.A), printed numbers (the judge) -------------------------


def exact_vectors3() -> st.SearchStrategy[tuple[Fraction, Fraction, Fraction]]:
    """An exact 3-vector with rational components p/q, |p| <= 50, q <= 12."""
    comp = st.builds(Fraction, st.integers(-50, 50), st.integers(1, 12))
    return st.tuples(comp, comp, comp)


def exact_plane_vectors() -> st.SearchStrategy[tuple[Fraction, Fraction]]:
    """An exact plane vector with rational components p/q, |p| <= 50, q <= 12."""
    comp = st.builds(Fraction, st.integers(-50, 50), st.integers(1, 12))
    return st.tuples(comp, comp)


def levi_civita_index_quads() -> st.SearchStrategy[tuple[int, int, int, int]]:
    """Four Cartesian indices (i, j, m, n), each 1, 2 or 3."""
    index = st.integers(min_value=1, max_value=3)
    return st.tuples(index, index, index, index)


def exact_square_matrices() -> st.SearchStrategy[list[list[int]]]:
    """An exact n x n integer matrix, n from 1 to 4, entries -9 to 9."""
    return st.integers(min_value=1, max_value=4).flatmap(
        lambda n: st.lists(
            st.lists(st.integers(-9, 9), min_size=n, max_size=n), min_size=n, max_size=n
        )
    )


def printed_decimals() -> st.SearchStrategy[str]:
    """A number as the book prints it: a sign or none, digits with the point anywhere (or no
    point), from "0" to "-98765.4321", never with a leading zero before other digits."""

    def build(sign: bool, digits: str, point: int) -> str:
        digits = digits.lstrip("0") or "0"
        place = min(point, len(digits))
        text = digits if place == 0 else f"{digits[:-place] or '0'}.{digits[-place:]}"
        return f"-{text}" if sign and text.strip("0.") else text

    return st.builds(
        build,
        st.booleans(),
        st.text(alphabet="0123456789", min_size=1, max_size=9),
        st.integers(0, 6),
    )


# --- exact algebra (mechmodel.algebra) ---------------------------------------------------------


def laurent_polynomials() -> st.SearchStrategy[Laurent]:
    """A Laurent polynomial in x and y of one to four terms c x^i y^j, c from -3 to 3, i and j
    from -2 to 3 (negative powers included)."""
    term = st.tuples(st.integers(-3, 3), st.integers(-2, 3), st.integers(-2, 3))
    return st.lists(term, min_size=1, max_size=4).map(
        lambda terms: sum(
            (Laurent.term(c, x=i, y=j) for c, i, j in terms),
            Laurent(),
        )
    )
