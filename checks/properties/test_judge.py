"""The judge's laws: reading printed numbers, rounding, and how verdicts move (design 3, 3a).

Properties of ``reference.numbers``, ``reference.compare`` and ``reference.tokens`` themselves,
as the mechmodel laws are checked in the other modules of this package.
"""

from __future__ import annotations

from decimal import Decimal
from fractions import Fraction

import pytest
from hypothesis import given
from hypothesis import strategies as st

from checks.properties.strategies import printed_decimals
from reference.compare import Context, exact, judge
from reference.numbers import parse_number
from reference.tokens import tokenize_line

pytestmark = pytest.mark.properties


def _unit(text: str) -> Fraction:
    """One unit of the last printed digit."""
    exponent = Decimal(text).as_tuple().exponent
    assert isinstance(exponent, int)
    return Fraction(10) ** exponent


@given(printed_decimals())
def test_a_printed_decimal_is_read_exactly_with_half_a_unit(text: str) -> None:
    """The value is the decimal's own, h half a unit of its last digit (statcheck's rule)."""
    p = parse_number(text)
    assert p.value == Fraction(Decimal(text))
    assert p.half_width == _unit(text) / 2
    assert not p.exact


@given(printed_decimals(), st.floats(-0.4999, 0.4999))
def test_a_model_within_half_a_unit_is_verified(text: str, offset: float) -> None:
    """Rounding law: any model that rounds to the printed digits is verified."""
    model = Fraction(Decimal(text)) + Fraction(offset) * _unit(text)
    assert judge(parse_number(text), Context(model)).verdict == "verified"


@given(printed_decimals(), st.sampled_from([-1, 1]))
def test_one_unit_off_an_exact_model_is_an_erratum(text: str, step: int) -> None:
    """Against an exact model value, the last digit one up or down is an erratum (no rounding
    "the other way", design 3a)."""
    p = parse_number(text)
    verdict = judge(p, Context(p.value + step * _unit(text))).verdict
    assert verdict == "erratum"


@given(printed_decimals(), st.floats(-3, 3), st.floats(0, 5), st.floats(0, 5))
def test_verdicts_are_monotonic_in_what_they_admit(
    text: str, offset: float, widen: float, width: float
) -> None:
    """More uncertainty never turns an admitted value into an erratum: widening h (a
    constant's uncertainty) or the input interval only moves a verdict towards verified."""
    p = parse_number(text)
    unit = _unit(text)
    model = p.value + Fraction(offset) * unit
    rank = {"erratum": 0, "rounding": 1, "verified": 2}
    narrow = judge(p, Context(model)).verdict
    wider = judge(p, Context(model, extra=Fraction(widen) * unit)).verdict
    assert rank[wider] >= rank[narrow]
    box = (model - Fraction(width) * unit, model + Fraction(width) * unit)
    with_box = judge(p, Context(model, interval=box)).verdict
    assert rank[with_box] >= rank[narrow]


@given(printed_decimals(), st.floats(-3, 3))
def test_a_verdict_does_not_depend_on_the_sign(text: str, offset: float) -> None:
    """Judging -printed against -model is judging printed against model."""
    p = parse_number(text)
    model = p.value + Fraction(offset) * _unit(text)
    negative = parse_number(text[1:] if text.startswith("-") else f"-{text}")
    assert judge(p, Context(model)).verdict == judge(negative, Context(-model)).verdict


@given(st.lists(printed_decimals(), min_size=1, max_size=6))
def test_every_token_the_tokenizer_finds_is_read(numbers: list[str]) -> None:
    """A line of numbers between words: each is one token, and each token reads back as the
    value printed."""
    line = "x = " + " and ".join(numbers) + " m."
    tokens = tokenize_line(line, 1)
    assert [t.text for t in tokens] == numbers
    assert [parse_number(t.text).value for t in tokens] == [Fraction(Decimal(n)) for n in numbers]


@given(printed_decimals())
def test_a_float_model_value_is_taken_exactly(text: str) -> None:
    value = float(Decimal(text))
    assert exact(value) == Fraction(value)
