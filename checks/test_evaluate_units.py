"""The evaluator's paths on small catalogs of their own: units and constants. Values, intervals,
errors and centres restated or printed in another unit, constants judged within h plus twice
their uncertainty, a constant that matches only an older edition, and exact data."""

from __future__ import annotations

import pytest

from checks._evaluate_helpers import _rounded_given, claim, evaluated, fake_model, run
from mechmodel.typing import Estimate
from reference import evaluation as evaluate
from reference import tables
from reference.book import Book


def test_an_older_edition_of_a_constant_is_dated(book: Book) -> None:
    """6.672E-11 misses today's G and matches the CODATA 1973 edition: dated, naming it; the
    claim passes only when it names that edition."""
    c = claim(
        id="ch08.g",
        printed="6.672E-11",
        kind="constant",
        expect="dated",
        edition="CODATA 1973",
        constant="gravitational-constant",
        unit="1",
        correct="6.674E-11",
    )
    result = run(book, c)["ch08.g"]
    assert (result.verdict, result.matched_edition, result.passed) == (
        "dated",
        "CODATA 1973",
        True,
    )
    assert result.diagnosis is not None
    assert (result.diagnosis["auto"] or "").startswith("dated: matches CODATA 1973")
    wrong = run(book, c.model_copy(update={"edition": "CODATA 2010"}))["ch08.g"]
    assert (wrong.verdict, wrong.passed) == ("dated", False)
    today = run(book, c.model_copy(update={"printed": "6.674E-11"}))["ch08.g"]
    assert today.verdict == "verified"


def test_a_complex_value_restated_in_another_unit_converts_its_imaginary_part_too(
    book: Book, monkeypatch: pytest.MonkeyPatch
) -> None:
    """1 + 0.0003i km is real to the 0.05 km of "1.0"; restated as "1000.0" m its imaginary
    part is 0.3 m, six times h."""
    fake_model(monkeypatch, lambda: complex(1000.0, 0.3))  # metres
    km = claim(id="ch08.km", printed="1.0", unit="km", kind="derived", expect="verified")
    km = km.model_copy(update={"model": "towers.x"})
    fine = claim(id="ch08.m", printed="1000.0", unit="m", kind="derived", expect="erratum")
    coarse = claim(id="ch08.m0", printed="1000", unit="m", kind="derived", expect="verified")
    results = run(
        book,
        km,
        fine.model_copy(update={"restates": "ch08.km"}),
        coarse.model_copy(update={"restates": "ch08.km"}),
    )
    assert [results[i].verdict for i in ("ch08.km", "ch08.m", "ch08.m0")] == [
        "verified",
        "erratum",
        "verified",
    ]


def test_a_restatement_in_another_unit_converts_value_interval_error_and_centre(
    book: Book, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A value restated in km from a claim in m: its model value, input interval, declared
    error and centre are all in km."""
    fake_model(monkeypatch, lambda v: Estimate(1500 * v + 500, 0.002))
    metres = claim(
        id="ch08.m",
        printed="3650",
        unit="m",
        kind="derived",
        expect="verified",
        model="towers.x",
        args={"v": {"claim": "ch08.v"}},
    )
    km = claim(id="ch08.km", printed="3.65", unit="km", kind="derived", expect="verified")
    result = evaluated(book, _rounded_given(), metres, km.model_copy(update={"restates": "ch08.m"}))
    c = result.by_id()["ch08.km"]
    assert (c.verdict, c.rounding_reason) == ("verified", None)
    assert c.model_value == pytest.approx(3.65)
    assert c.interval == pytest.approx([3.575, 3.725])
    assert c.model_error == pytest.approx(2e-6)
    assert float(result.centres["ch08.km"]) == pytest.approx(3.65)


def test_a_model_error_restated_in_another_unit_is_converted(
    book: Book, monkeypatch: pytest.MonkeyPatch
) -> None:
    """3615.3 m +- 2 mm: the restated "3.62" km is verified, 2e-6 km changing nothing."""
    fake_model(monkeypatch, lambda: Estimate(3615.3, 0.002))
    metres = claim(
        id="ch08.m", printed="3615", unit="m", kind="derived", expect="verified", model="towers.x"
    )
    km = claim(id="ch08.km", printed="3.62", unit="km", kind="derived", expect="verified")
    results = run(book, metres, km.model_copy(update={"restates": "ch08.m"}))
    assert results["ch08.km"].verdict == "verified"
    assert results["ch08.km"].model_error == pytest.approx(2e-6)


def _constant(monkeypatch: pytest.MonkeyPatch) -> None:
    """A radius known today as 6371.0088 +- 0.010 km (u in m: 10), and in an older edition as
    6378.2 +- 0.020 km."""
    radius = tables.Constant(
        key="test-radius",
        value=6.3710088e6,
        unit="m",
        uncertainty=10.0,
        exact=False,
        source="s",
        edition="today",
        codata=None,
        derived=None,
        older=(tables.Edition("old survey", 6.3782e6, 20.0),),
    )
    monkeypatch.setattr(evaluate, "constants", lambda: {"test-radius": radius})


@pytest.mark.parametrize(
    ("printed", "expected", "edition"),
    [
        ("6371.03", "verified", None),  # 2.1 u off: within h + 2u
        ("6371.04", "erratum", None),  # 3.1 u off
        ("6378.24", "dated", "old survey"),  # 2 u of the old edition off
        ("6378.26", "erratum", None),  # 3 u of the old edition off
    ],
)
def test_a_constant_is_judged_within_h_plus_twice_its_uncertainty(
    book: Book,
    monkeypatch: pytest.MonkeyPatch,
    printed: str,
    expected: str,
    edition: str | None,
) -> None:
    """A constant printed in km, its table in m: today's value and the older edition's are
    converted, each within h plus twice its own standard uncertainty."""
    _constant(monkeypatch)
    c = claim(
        id="ch08.r",
        printed=printed,
        kind="constant",
        unit="km",
        constant="test-radius",
        expect=expected,
    )
    result = run(book, c)["ch08.r"]
    assert (result.verdict, result.matched_edition) == (expected, edition)


def test_a_model_error_is_converted_to_the_printed_unit(
    book: Book, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A model in SI declares 1 cm of error on 3615.3 m: printed in km that is 1e-5 km, which
    leaves "3.62" verified."""
    fake_model(monkeypatch, lambda: Estimate(3615.3, 0.01))
    c = claim(
        id="ch08.km", printed="3.62", unit="km", kind="derived", expect="verified", model="t.x"
    )
    result = run(book, c)["ch08.km"]
    assert result.verdict == "verified"
    assert result.model_error == pytest.approx(1e-5)


def test_an_exact_whole_datum_printed_whole_admits_no_rounding(book: Book) -> None:
    """5,280 feet to the mile is exact: its tolerance is 0, not half a foot."""
    c = claim(
        id="ch08.ft",
        printed="5,280",
        kind="constant",
        unit="1",
        constant="feet-per-mile",
        expect="verified",
    )
    result = run(book, c)["ch08.ft"]
    assert (result.verdict, result.tolerance) == ("verified", 0.0)
    rounded = run(book, c.model_copy(update={"printed": "5,280.0"}))["ch08.ft"]
    assert (rounded.verdict, rounded.tolerance) == ("verified", 0.05)
