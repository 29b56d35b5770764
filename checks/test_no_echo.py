"""The model computes, it does not remember (design section 5).

A numeric literal in mechmodel that equals a catalogued printed value is flagged when it has
three or more significant figures, is a non-integer decimal, or is an integer of 100 or more;
powers of ten (10, 1000, 1e-9: scales and tolerances) are never flagged. Unit factors come from
units.toml through the evaluator, so no mechmodel literal equals one (other than 1 and powers of
ten).
"""

from __future__ import annotations

import ast
import math
from fractions import Fraction
from pathlib import Path

import pytest

from reference.catalog import Catalog
from reference.numbers import NumberFormatError
from reference.tables import units
from reference.validate import parsed

ROOT = Path(__file__).parents[1]
ALLOWED: set[Fraction] = {
    Fraction(1, 2),  # the half of 1/2 m v^2 and of every mean: a formula's factor, not a value
    Fraction(1, 4),  # a quarter, as in the quarter turn pi/4 and the 1/4 of areas
}


def literals(source: str) -> list[tuple[int, Fraction, str]]:
    """Every numeric literal of a module: (line, exact value, source text)."""
    lines = source.splitlines()
    out = []
    for node in ast.walk(ast.parse(source)):
        if (
            isinstance(node, ast.Constant)
            and isinstance(node.value, int | float)
            and not isinstance(node.value, bool)
        ):
            if node.end_lineno == node.lineno and node.end_col_offset is not None:
                raw = lines[node.lineno - 1].encode()[node.col_offset : node.end_col_offset]
                text = raw.decode()
            else:
                text = repr(node.value)
            try:
                value = Fraction(text.replace("_", ""))  # the decimal as written, exactly
            except ValueError:
                value = Fraction(node.value)  # hex, octal or binary integers
            out.append((node.lineno, value, text))
    return out


def _power_of_ten(value: Fraction) -> bool:
    def is_pow10(k: int) -> bool:
        return str(k).rstrip("0") == "1"

    n, d = value.numerator, value.denominator
    return (d == 1 and is_pow10(n)) or (n == 1 and is_pow10(d))


def suspicious(value: Fraction, text: str) -> bool:
    """Whether a literal equal to a printed value looks remembered rather than structural:
    powers of ten (scales and tolerances such as 1e-9) and small integers never do."""
    if _power_of_ten(value):
        return False
    digits = text.lower().split("e")[0].replace("_", "").replace(".", "").lstrip("0")
    if value.denominator != 1:
        return True
    if len(digits.rstrip("0")) >= 3:
        return True
    return abs(value.numerator) >= 100


def echoes(source: str, printed: set[Fraction]) -> list[tuple[int, str]]:
    return [
        (line, text)
        for line, value, text in literals(source)
        if value in printed and value not in ALLOWED and suspicious(value, text)
    ]


def printed_values(catalog: Catalog) -> set[Fraction]:
    values = set()
    for _, claim in catalog.claims():
        try:
            value = parsed(claim).value
        except NumberFormatError:  # pragma: no cover - the catalog is validated
            continue
        values |= {value, -value}
    return values


@pytest.mark.integrity
def test_mechmodel_echoes_no_printed_value(catalog: Catalog) -> None:
    printed = printed_values(catalog)
    found = {
        path.name: hits
        for path in sorted((ROOT / "mechmodel").rglob("*.py"))
        if (hits := echoes(path.read_text(encoding="utf-8"), printed))
    }
    assert not found


@pytest.mark.integrity
def test_mechmodel_holds_no_unit_factor() -> None:
    factors = {Fraction(u.si) for u in units().values()}
    factors = {f for f in factors if not math.log10(f).is_integer()}
    found = [
        (path.name, line, text)
        for path in sorted((ROOT / "mechmodel").rglob("*.py"))
        for line, value, text in literals(path.read_text(encoding="utf-8"))
        if value in factors
    ]
    assert not found


def test_the_lint_catches_an_echo() -> None:
    printed = {Fraction("3.62"), Fraction(7250), Fraction(60), Fraction(1000), Fraction(1, 10**9)}
    source = "V3 = 3.62\nKE = 7250\nspeed = 60\nscale = 1000\nhalf = 0.5\ntol = 1e-9\n"
    assert echoes(source, printed) == [(1, "3.62"), (2, "7250")]
