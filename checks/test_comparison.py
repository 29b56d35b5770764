"""Printed values, verdicts, relations, intervals and the automatic diagnosis (design section 3)."""

from __future__ import annotations

import math
from fractions import Fraction

import pytest

from reference.compare import Context, Edition, exact, in_order_of, judge
from reference.diagnose import diagnose
from reference.numbers import NumberFormatError, parse_number


def verdict(printed: str, model: float, **kw: object) -> tuple[str, str | None]:
    """The verdict of ``printed`` against ``model`` in a context of ``kw`` (Context fields)."""
    j = judge(parse_number(printed), Context(exact(model), **kw))  # type: ignore[arg-type]
    return j.verdict, j.reason


def relation(rel: str, printed: str, model: float, **kw: object) -> str:
    """The verdict of the relation ``rel`` (model REL printed)."""
    ctx = Context(exact(model), relation=rel, **kw)  # type: ignore[arg-type]
    return judge(parse_number(printed), ctx).verdict


# -- printed values: value and half-width from the digits ---------------------------------------


@pytest.mark.parametrize(
    ("printed", "value", "half"),
    [
        ("7,250", Fraction(7250), Fraction(1, 2)),
        ("60", Fraction(60), Fraction(1, 2)),
        ("0.0100", Fraction(1, 100), Fraction(5, 100000)),
        ("−7.071", Fraction(-7071, 1000), Fraction(5, 10000)),
        ("6.4E6", Fraction(6400000), Fraction(50000)),
        ("6.282 E6", Fraction(6282000), Fraction(500)),
        ("1.67·10-27", Fraction(167, 10**29), Fraction(5, 10**30)),
        ("2·10-27", Fraction(2, 10**27), Fraction(5, 10**28)),
        ("9·10+9", Fraction(9 * 10**9), Fraction(5 * 10**8)),
        ("64.2%", Fraction(642, 10), Fraction(5, 100)),
        ("45°", Fraction(45), Fraction(1, 2)),
        (".5", Fraction(1, 2), Fraction(5, 100)),
        ("1.5^2", Fraction(9, 4), 2 * Fraction(3, 2) * Fraction(5, 100)),  # d(b^2) = 2 b db
        ("6.28^2e6", Fraction(628**2 * 100), 2 * Fraction(628, 100) * Fraction(5, 1000) * 10**6),
    ],
)
def test_printed_precision_comes_from_its_digits(
    printed: str, value: Fraction, half: Fraction
) -> None:
    """h, and the unit of rounding (a truncation's step, the digits of the automatic
    diagnosis) twice h, for every form: a caret's h is its base's, propagated."""
    p = parse_number(printed)
    assert (p.value, p.half_width, p.exact) == (value, half, False)
    assert p.quantum == 2 * half


@pytest.mark.parametrize(
    ("printed", "value"),
    [
        ("30/10", Fraction(3)),
        ("1/720", Fraction(1, 720)),
        ("(2/3)·10-27", Fraction(2, 3 * 10**27)),
        ("10-25", Fraction(1, 10**25)),
        ("60^2", Fraction(3600)),
        ("10^-25", Fraction(1, 10**25)),
    ],
)
def test_exact_forms(printed: str, value: Fraction) -> None:
    p = parse_number(printed)
    assert (p.value, p.exact, p.half_width) == (value, True, Fraction(0))


@pytest.mark.parametrize(
    ("printed", "value"),
    [
        ("π/3", math.pi / 3),
        ("2π/3", 2 * math.pi / 3),
        ("5π", 5 * math.pi),
        ("180/π", 180 / math.pi),
        ("√3/2", math.sqrt(3) / 2),
        ("√8", math.sqrt(8)),
        ("1/√2", 1 / math.sqrt(2)),
        ("2√2", 2 * math.sqrt(2)),
    ],
)
def test_pi_and_root_forms_are_exact(printed: str, value: float) -> None:
    p = parse_number(printed)
    assert p.exact
    assert p.irrational
    assert verdict(printed, value) == ("verified", None)
    assert verdict(printed, value * (1 + 1e-9)) == ("erratum", None)


def test_sigfigs_widen_the_half_width() -> None:
    p = parse_number("9,000,000,000", sigfigs=1)
    assert p.half_width == 5 * 10**8
    assert judge(p, Context(exact(8.98755e9))).verdict == "verified"
    assert judge(parse_number("9,000,000,000"), Context(exact(8.98755e9))).verdict == "erratum"
    assert parse_number("1", sigfigs=1).half_width == Fraction(1, 2)
    with pytest.raises(NumberFormatError, match="printed zero"):
        parse_number("0.0", sigfigs=1)


def test_an_exact_integer_has_no_half_unit_of_slack() -> None:
    """ "-1 radian" names exactly one radian (line 1393): read as exact, -0.5708 rad is an
    erratum, as the same angle printed -57.3° is; read as a rounded integer it would pass."""
    model = 1 - math.pi / 2
    assert parse_number("-1", exact=True).half_width == 0
    assert judge(parse_number("-1", exact=True), Context(exact(model))).verdict == "erratum"
    assert judge(parse_number("-1"), Context(exact(model))).verdict == "verified"
    assert judge(parse_number("-57.3°"), Context(exact(math.degrees(model)))).verdict == ("erratum")
    assert judge(parse_number("-1", exact=True), Context(exact(-1.0))).verdict == "verified"
    with pytest.raises(NumberFormatError, match="only a printed integer"):
        parse_number("-1.0", exact=True)


@pytest.mark.parametrize("bad", ["", "-", "abc", "1/0", "3..2", "E6"])
def test_unreadable_numbers_raise(bad: str) -> None:
    with pytest.raises(NumberFormatError):
        parse_number(bad)


# -- verdicts of "=" ----------------------------------------------------------------------------


def test_tie_at_half_a_unit_is_inside() -> None:
    assert verdict("0.13", 0.125) == ("verified", None)
    assert verdict("0.12", 0.125) == ("verified", None)


def test_float_just_below_a_half_still_rounds() -> None:
    assert verdict("5.8", 5.749999999999999) == ("verified", None)


def test_the_float_slack_is_a_billionth_of_h() -> None:
    """Inside is |model - printed| <= h (1 + 1e-9): half a billionth of h past it still rounds,
    one and a half billionths past it do not."""
    h = 0.05
    assert verdict("5.8", 5.75 - 0.5e-9 * h) == ("verified", None)
    assert verdict("5.8", 5.75 - 1.5e-9 * h) == ("erratum", None)
    # the edge itself is inside (a model may return an exact Fraction)
    edge = Fraction("5.75") - Fraction(5, 100) * Fraction(1, 10**9)
    assert verdict("5.8", edge) == ("verified", None)  # type: ignore[arg-type]


def test_an_exact_form_admits_sixteen_ulps() -> None:
    """A printed fraction is exact: the model's float may be off by the 16 ulps of a few
    operations, not 17."""
    ulp = math.ulp(0.5)
    assert verdict("1/2", 0.5 + 16 * ulp) == ("verified", None)
    assert verdict("1/2", 0.5 + 17 * ulp) == ("erratum", None)


def test_trailing_zeros_count() -> None:
    assert verdict("0.0100", 0.01002936) == ("verified", None)
    assert verdict("0.0100", 0.01009) == ("erratum", None)
    assert verdict("0.0100", 0.00991) == ("erratum", None)
    assert verdict("0.010", 0.01009) == ("verified", None)


def test_against_an_exact_model_a_value_one_unit_off_is_an_erratum() -> None:
    """No rounding "the other way" (design 3a): a model sitting exactly on "250" (line 1943)
    rejects 251, and 0.5 past h is as wrong as 5 units past it."""
    assert verdict("250", 250) == ("verified", None)
    assert verdict("251", 250) == ("erratum", None)
    assert verdict("249", 250) == ("erratum", None)
    assert verdict("2.71806", 2.7180544) == ("erratum", None)


def test_a_declared_truncation_is_admitted_and_an_undeclared_one_is_not() -> None:
    e6 = 1 + 1 + 1 / 2 + 1 / 6 + 1 / 24 + 1 / 120 + 1 / 720  # 2.7180555...: (10.6)
    assert verdict("2.71805", e6) == ("erratum", None)
    assert verdict("2.71805", e6, truncation=True) == ("rounding", "truncation")
    assert verdict("2.71806", e6, truncation=True) == ("verified", None)
    assert verdict("2.71804", e6, truncation=True) == ("erratum", None)  # cut, not cut again
    assert verdict("-0.62", -0.6267, truncation=True) == ("rounding", "truncation")
    assert verdict("-0.63", -0.6201, truncation=True) == ("erratum", None)  # away from zero
    assert verdict("0.62", -0.6267, truncation=True) == ("erratum", None)  # the sign lost


def test_a_small_value_truncated_to_zero_has_either_sign() -> None:
    """Cut toward zero at the printed digit, 0.07 and -0.07 both print 0.0."""
    assert verdict("0.0", 0.07, truncation=True) == ("rounding", "truncation")
    assert verdict("0.0", -0.07, truncation=True) == ("rounding", "truncation")
    assert verdict("-0.0", -0.07, truncation=True) == ("rounding", "truncation")
    assert verdict("0.0", 0.17, truncation=True) == ("erratum", None)


def test_printed_fraction_is_exact() -> None:
    assert verdict("30/10", 3.0) == ("verified", None)
    assert verdict("1/720", 1 / 720) == ("verified", None)
    assert verdict("30/10", 3.0000001) == ("erratum", None)
    assert verdict("30/10", 3.01) == ("erratum", None)  # no rounding level for exact forms


def test_plus_minus_compares_the_magnitude() -> None:
    assert verdict("±π/3", -math.pi / 3) == ("verified", None)
    assert verdict("±180°", 180.0) == ("verified", None)
    assert verdict("±180°", -178.9) == ("erratum", None)


def test_plus_minus_against_an_input_interval_compares_magnitudes() -> None:
    """ "±a" against a box of model values: the magnitudes the box spans, from 0 where it
    straddles zero or ends at it, else from its smaller end."""
    straddles = (Fraction(-1), Fraction(2))
    assert verdict("±0.5", 1.5, interval=straddles) == ("rounding", "input-rounding")
    assert verdict("±2.5", 1.5, interval=straddles) == ("erratum", None)
    deeper = (Fraction(-2), Fraction(1))  # the larger magnitude at the negative end
    assert verdict("±1.8", 0.5, interval=deeper) == ("rounding", "input-rounding")
    ends_at_zero = (Fraction(-2), Fraction(0))
    assert verdict("±1.0", -1.5, interval=ends_at_zero) == ("rounding", "input-rounding")
    assert verdict("±1.0", 1.5, interval=(Fraction(0), Fraction(2))) == (
        "rounding",
        "input-rounding",
    )
    small = (Fraction(1, 2), Fraction(3, 5))  # away from zero: nothing below 0.5
    assert verdict("±0.52", 0.55, interval=small) == ("rounding", "input-rounding")
    assert verdict("±0.10", 0.55, interval=small) == ("erratum", None)
    negative = (Fraction(-3, 5), Fraction(-1, 2))
    assert verdict("±0.10", -0.55, interval=negative) == ("erratum", None)


def test_input_interval_gives_rounding() -> None:
    # 3.62 from the rounded 2.1 (30/10 tower stage): the model at 2.1 gives 3.65
    box = (exact(3.575), exact(3.725))
    assert verdict("3.62", 3.65, interval=box) == ("rounding", "input-rounding")
    assert verdict("3.62", 3.65) == ("erratum", None)
    assert verdict("3.80", 3.65, interval=box) == ("erratum", None)
    assert verdict("3.73", 3.65, interval=box) == ("rounding", "input-rounding")  # widened by h
    assert verdict("3.74", 3.65, interval=box) == ("erratum", None)
    # widened by h (1 + 1e-9), its ends included (an exact model value can sit on them)
    h = Fraction(5, 1000) * (1 + Fraction(1, 10**9))
    exactly = (Fraction("3.62") + h, Fraction("3.70"))
    assert verdict("3.62", 3.65, interval=exactly) == ("rounding", "input-rounding")
    # widened by h, not more: 1.3 h past the box's end is outside
    assert verdict("3.73", 3.65, interval=(exact(3.575), exact(3.7235))) == ("erratum", None)


def test_a_verdict_that_changes_within_the_model_error_is_indeterminate() -> None:
    assert verdict("3.62", 3.6249, error=exact(1e-6)) == ("verified", None)
    assert verdict("3.62", 3.6249, error=exact(1e-3)) == ("indeterminate", None)
    # model +- error, no further: 3.6240 + 0.0007 still rounds to 3.62 (and 3.6240 + 0.0014
    # would not); likewise below
    assert verdict("3.62", 3.6240, error=exact(7e-4)) == ("verified", None)
    assert verdict("3.62", 3.6160, error=exact(7e-4)) == ("verified", None)


def test_constant_uncertainty_widens_h() -> None:
    two_u = Fraction(2 * 1.5e-15)
    assert verdict("6.674E-11", 6.6743e-11, extra=two_u) == ("verified", None)
    assert verdict("6.672E-11", 6.6743e-11, extra=two_u) == ("erratum", None)


def test_a_dated_value_names_the_matching_edition_closest_to_it() -> None:
    """Three older editions admit 6.6725E-11: the one named is the nearest, not the first or
    the smallest."""
    two_u = exact(4e-14)
    editions = (
        Edition("old", exact(6.6700e-11), two_u),
        Edition("newer", exact(6.6726e-11), two_u),
        Edition("newest", exact(6.6730e-11), two_u),
    )
    j = judge(parse_number("6.6725E-11"), Context(exact(6.6743e-11), editions=editions))
    assert (j.verdict, j.edition) == ("dated", "newer")


def test_count_is_exact() -> None:
    assert verdict("11", 11, exact_only=True) == ("verified", None)
    assert verdict("11", 12, exact_only=True) == ("erratum", None)


# -- relations -----------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("rel", "printed", "model", "expected"),
    [
        ("<", "3.0", 2.9, "verified"),
        ("<", "3.0", 3.0, "erratum"),
        (">", "9.0", 9.4, "verified"),
        (">", "9.0", 8.9, "erratum"),
        (">", "9.0", 9.0, "erratum"),
        ("<=", "3", 3, "verified"),
        ("<=", "3", 4, "erratum"),
        (">=", "3", 2, "erratum"),
        (">=", "3", 3, "verified"),
    ],
)
def test_order_relations(rel: str, printed: str, model: float, expected: str) -> None:
    assert relation(rel, printed, model) == expected


def test_approximate_relation() -> None:
    assert relation("~", "5.8", 5.65, rel_tol=Fraction(5, 100)) == "verified"
    assert relation("~", "5.8", 5.0, rel_tol=Fraction(5, 100)) == "erratum"
    assert relation("~", "4", 5.0, rel_tol=Fraction(1, 4)) == "verified"  # the edge is in
    assert relation("~", "4", 3.0, rel_tol=Fraction(1, 4)) == "verified"
    assert relation("~", "4", 5.01, rel_tol=Fraction(1, 4)) == "erratum"


def test_between() -> None:
    bounds = (parse_number("4"), parse_number("5"))
    assert relation("between", "4", 4.5, bounds=bounds) == "verified"
    assert relation("between", "4", 5.5, bounds=bounds) == "erratum"
    assert relation("between", "4", 4.0, bounds=bounds) == "verified"  # the bounds belong
    assert relation("between", "4", 5.0, bounds=bounds) == "verified"
    assert relation("between", "4", 3.99, bounds=bounds) == "erratum"


def test_order_of_magnitude() -> None:
    assert in_order_of(exact(3.4e-43), Fraction(1, 10**43))
    assert in_order_of(exact(9.9e-44), Fraction(1, 10**43))  # within half a decade
    assert not in_order_of(exact(2e-44), Fraction(1, 10**43))
    assert not in_order_of(exact(1e-42), Fraction(1, 10**43))
    assert in_order_of(exact(math.sqrt(10)), Fraction(10))  # half a decade exactly
    assert in_order_of(Fraction(1), Fraction(3))  # 1 is of order 10^0
    assert in_order_of(Fraction(10), Fraction(80))  # 10^k itself is of order 10^k
    assert not in_order_of(Fraction(0), Fraction(10))  # zero is of no order
    assert in_order_of(Fraction(0), Fraction(0))
    # half a decade, no more: 10^-43.498 is of order 10^-43, 10^-43.502 is not
    assert in_order_of(exact(10**-43.498), Fraction(1, 10**43))
    assert not in_order_of(exact(10**-43.502), Fraction(1, 10**43))


def test_model_value_must_be_finite() -> None:
    with pytest.raises(ValueError, match="not finite"):
        exact(float("nan"))


# -- automatic diagnosis -----------------------------------------------------------------------


@pytest.mark.parametrize(
    ("printed", "correct", "kind"),
    [
        ("-7.071", "7.071", "sign"),
        ("0.77", "0.077", "decimal-shift"),
        ("4,250", "42.50", "decimal-shift"),
        ("3.26", "3.62", "digit-swap"),
        ("3.2", "3.62", "dropped-digit"),
        ("3.662", "3.62", "extra-digit"),
        ("7.24", "3.62", "factor"),
        ("1.81", "3.62", "factor"),
        ("11.37", "3.62", "factor"),
        ("5.03", "3.62", None),
        ("3.63", "3.62", "last-digit"),
        ("0.478", "0.479", "last-digit"),
        ("4", "5", "last-digit"),
        ("4", "6", None),  # a small integer's digits do not pin a ratio of 1/sqrt(2) down
        ("-7.24", "3.62", None),  # a factor with a sign flip is not diagnosed as a factor
    ],
)
def test_automatic_diagnosis(printed: str, correct: str, kind: str | None) -> None:
    found = diagnose(parse_number(printed), parse_number(correct))
    assert (found.kind if found else None) == kind
