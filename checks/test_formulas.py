"""Formula claims (design 2a): reading the book's formula safely, comparing it with the model's
at generic points, and formula claims in the catalog and its evaluation."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
import sympy

from reference.book import Book
from reference.formulas import (
    FormulaError,
    compare,
    generic_points,
    make_symbol,
    parse_formula,
    unicode_formula,
)
from reference.schema import CatalogError
from reference.validate import checked_catalog

A = make_symbol("A", {"positive": True})
L = make_symbol("L", {"positive": True})
X = make_symbol("x", {"real": True})
P = make_symbol("p", {"positive": True})


@pytest.mark.parametrize(
    "text",
    [
        '__import__("os").system("true")',
        "A.__class__",
        "(lambda: 1)()",
        "A[0]",
        "'A'",
        "B + 1",  # undeclared
        "sqrt(A, x=1)",
        "A if A else 1",
        "A == 1",
        "",
    ],
)
def test_anything_but_a_formula_is_refused_without_running_it(text: str) -> None:
    with pytest.raises(FormulaError):
        parse_formula(text, {"A": A})


def test_a_formula_reads_into_sympy() -> None:
    formula = parse_formula("sqrt(2*g*h)/pi + x**2", {"g": A, "h": L, "x": X})
    assert formula.expr == sympy.sqrt(2 * A * L) / sympy.pi + X**2
    assert formula.literals == ()


def test_the_focus_of_a_x_squared_is_not_at_a_over_4() -> None:
    """The issue's example (line 7077): A/4 equals 1/(4A) only at A = 1; generic points catch
    it, a single point A = 1 would not."""
    points = generic_points({"A": A}, {})
    assert all(point[A] != 1 for point in points)
    assert not compare(parse_formula("A/4", {"A": A}), 1 / (4 * A), points).agrees
    assert compare(parse_formula("1/(4*A)", {"A": A}), 1 / (4 * A), points).agrees
    assert compare(parse_formula("A/4", {"A": A}), 1 / (4 * A), [{A: 1.0}]).agrees


def test_a_decimal_literal_carries_the_precision_of_its_digits() -> None:
    """0.577 L against L/sqrt(3) = 0.57735 L is verified; 0.578 L is not; 0.5774 L is."""
    points = generic_points({"L": L}, {})
    exact = L / sympy.sqrt(3)
    assert compare(parse_formula("0.577*L", {"L": L}), exact, points).agrees
    assert not compare(parse_formula("0.578*L", {"L": L}), exact, points).agrees
    assert compare(parse_formula("0.5774*L", {"L": L}), exact, points).agrees
    assert not compare(parse_formula("0.5775*L", {"L": L}), exact, points).agrees


def test_a_numeric_model_is_compared_at_the_points() -> None:
    def model(point: dict[sympy.Symbol, float]) -> complex:
        return math.sqrt(point[X] ** 2) / (4 * point[P])  # math: no sympy expression

    points = generic_points({"x": X, "p": P}, {})
    assert compare(parse_formula("Abs(x)/(4*p)", {"x": X, "p": P}), model, points).agrees
    assert not compare(parse_formula("x/(4*p)", {"x": X, "p": P}), model, points).agrees


def test_generic_points_respect_domains_signs_and_are_fixed() -> None:
    t = make_symbol("t", {"real": True})
    n = make_symbol("n", {"positive": True, "integer": True})
    points = generic_points({"t": t, "n": n, "p": P}, {"t": [-1.0, 1.0]})
    assert points == generic_points({"t": t, "n": n, "p": P}, {"t": [-1.0, 1.0]})
    assert all(-1 <= pt[t] <= 1 for pt in points)
    assert all(pt[P] > 0 for pt in points)
    assert all(pt[n] > 0 and float(pt[n]).is_integer() for pt in points)
    assert len({pt[t] for pt in points}) == len(points)  # no two alike


def test_an_integer_symbol_stays_inside_its_domain() -> None:
    n = make_symbol("n", {"positive": True, "integer": True})
    points = generic_points({"n": n}, {"n": [5, 9]})
    assert all(5 <= pt[n] <= 9 and float(pt[n]).is_integer() for pt in points)
    assert len({pt[n] for pt in points}) > 1


def test_an_exact_zero_agrees_with_a_zero_model_but_not_with_a_small_one() -> None:
    n = make_symbol("n", {"positive": True, "integer": True})
    points = generic_points({"n": n}, {"n": [4, 4]})
    falling = n * (n - 1) * (n - 2) * (n - 3) * (n - 4)  # zero at n = 4
    assert compare(
        parse_formula("0", {"n": n}), lambda pt: complex(falling.subs(pt)), points
    ).agrees
    assert compare(parse_formula("0", {"n": n}), lambda pt: 1e-25, points).agrees  # noise
    assert not compare(parse_formula("0", {"n": n}), lambda pt: 1e-6, points).agrees


@pytest.mark.parametrize(
    ("text", "shown"),
    [
        ("omega**2*r", "ω²·r"),
        ("1/(4*A)", "1/(4·A)"),
        ("sqrt(2*g*h)", "√(2·g·h)"),
        ("x**2/(2*lamda)", "x²/(2·λ)"),
        ("m*omega0**-2", "m·ω₀⁻²"),
        ("am3*(x + I*y)**(-2)/(-2) + log((x + I*y))", "a₋₃·z⁻²/(−2)+ln(z)"),
        ("x - m1", "x−m₁"),
        ("exp(I*2*theta)/r**2", "e^(i·2·θ)/r²"),
        ("x**(2*n) + x**(-1) + x**2.5", "x^(2·n)+x⁻¹+x^2.5"),
        ("t**3/factorial(3) + I*theta", "t³/3!+i·θ"),
        ("log(z) + E**x + En*I0", "ln(z)+e^x+En·I₀"),
    ],
)
def test_formulas_are_shown_as_the_book_prints_them(text: str, shown: str) -> None:
    assert unicode_formula(text) == shown


META = """[meta]
chapter = "9"
title = "Geometry and physics of common potential fields"
lines = [6936, 7923]
complete = false
schema = 1
"""
FOCUS = """
[[claim]]
id = "ch09.f.focus"
line = 7077
quote = "y=U=A/4"
quantity = "height of the focus of U = A x^2"
kind = "formula"
expression = "A/4"
symbols = { A = { positive = true } }
tokens = [{ line = 7077, token = "4" }]
model = "fields.parabola_geometry"
args = { a = { symbol = "A" } }
pick = "focal_height"
expect = "erratum"
correct = "1/(4*A)"
diagnosis = { kind = "wrong-formula", note = "n" }
summary = "The focus is at 1/(4A)."
"""


def _draft(tmp_path: Path, text: str) -> Path:
    (tmp_path / "ch09.toml").write_text(META + text, encoding="utf-8")
    return tmp_path


def test_a_formula_claim_is_evaluated(book: Book, tmp_path: Path) -> None:
    from reference.evaluation import evaluate_catalog

    catalog = checked_catalog(book, _draft(tmp_path, FOCUS))
    c = evaluate_catalog(catalog, book, ["9"]).by_id()["ch09.f.focus"]
    assert (c.verdict, c.correct_agrees, c.passed) == ("erratum", True, True)
    data = c.to_json()
    assert (data["value"], data["model_value"], data["printed"]) == (None, None, None)
    assert data["expression"] == "A/4"
    assert data["symbols"] == {
        "A": {
            "positive": True,
            **dict.fromkeys(
                ["real", "negative", "nonnegative", "nonzero", "integer", "complex", "domain"]
            ),
        }
    }
    assert data["class"] == "formula"
    erratum_fields = FOCUS[FOCUS.index('expect = "erratum"') : FOCUS.index("1/(4A).")] + '1/(4A)."'
    right = FOCUS.replace('expression = "A/4"', 'expression = "1/(4*A)"').replace(
        erratum_fields, 'expect = "verified"'
    )
    catalog = checked_catalog(book, _draft(tmp_path, right))
    assert evaluate_catalog(catalog, book, ["9"]).by_id()["ch09.f.focus"].verdict == "verified"


@pytest.mark.parametrize(
    ("old", "new", "field"),
    [
        ('expression = "A/4"', 'expression = "A/4 +"', "expression"),
        ('expression = "A/4"', 'expression = "B/4"', "expression"),
        ('expression = "A/4"', 'expression = "__import__(1)"', "expression"),
        ('correct = "1/(4*A)"', 'correct = "1/(4*A"', "correct"),
        (
            'tokens = [{ line = 7077, token = "4" }]',
            'tokens = [{ line = 7077, token = "5" }]',
            "tokens[0]",
        ),
        ('summary = "The focus is at 1/(4A)."\n', "", "summary"),
        ('kind = "formula"', 'kind = "formula"\nprinted = "4"\nunit = "m"', "unit"),
    ],
)
def test_a_malformed_formula_claim_is_a_catalog_problem(
    book: Book, tmp_path: Path, old: str, new: str, field: str
) -> None:
    assert old in FOCUS
    with pytest.raises(CatalogError) as raised:
        checked_catalog(book, _draft(tmp_path, FOCUS.replace(old, new)))
    assert [(p.id, p.field) for p in raised.value.problems] == [("ch09.f.focus", field)]


def test_expansion_decides_polynomials_and_the_points_decide_the_rest() -> None:
    x = sympy.Symbol("x", real=True)
    symbols = {"x": x}
    points = generic_points(symbols, {})
    poly = compare(parse_formula("(x + 1)**2", symbols), x**2 + 2 * x + 1, points)
    assert (poly.agrees, poly.how) == (True, "symbolic")
    trig = compare(parse_formula("sin(x)**2 + cos(x)**2", symbols), sympy.Integer(1), points)
    assert (trig.agrees, trig.how) == (True, "points")
    wrong = compare(parse_formula("sin(x)**2 - cos(x)**2", symbols), sympy.Integer(1), points)
    assert not wrong.agrees
