"""The evaluator's paths on small catalogs of their own: the model's value. Its declared numerical
error (``indeterminate``), a model that raises, complex and large integer values, a claim between
bounds, the automatic diagnosis, a correct value finer than printed, and the progress lines."""

from __future__ import annotations

import pytest

from checks._evaluate_helpers import claim, evaluated, fake_model, run
from mechmodel.typing import Estimate
from reference import calls
from reference.book import Book


def test_a_verdict_that_changes_within_the_model_error_is_indeterminate(
    book: Book, monkeypatch: pytest.MonkeyPatch
) -> None:
    fake_model(monkeypatch, lambda: Estimate(3.6153, 0.002))
    c = claim(id="ch08.x", printed="3.62", kind="derived", expect="verified", model="towers.x")
    result = run(book, c)["ch08.x"]
    assert (result.verdict, result.model_error) == ("indeterminate", 0.002)


def test_a_small_model_error_keeps_the_verdict(book: Book, monkeypatch: pytest.MonkeyPatch) -> None:
    fake_model(monkeypatch, lambda: Estimate(3.6153, 1e-6))
    c = claim(id="ch08.x", printed="3.62", kind="derived", expect="verified", model="towers.x")
    assert run(book, c)["ch08.x"].verdict == "verified"


def test_a_model_that_raises_names_the_claim(book: Book, monkeypatch: pytest.MonkeyPatch) -> None:
    def broken() -> float:
        raise ValueError("m1 must be positive, got -1")

    fake_model(monkeypatch, broken)
    c = claim(id="ch08.z", printed="3.62", kind="derived", expect="verified", model="towers.x")
    with pytest.raises(
        calls.ModelCallError, match=r"ch08\.z: field 'model': .*m1 must be positive"
    ):
        run(book, c)


def test_a_complex_model_value_must_be_real(book: Book, monkeypatch: pytest.MonkeyPatch) -> None:
    """A complex model value meets a real printed one: its imaginary part must vanish within
    h; a zero imaginary part leaves a real value."""
    fake_model(monkeypatch, lambda im: complex(2.0, im))
    c = claim(id="ch08.c", printed="2.0", kind="derived", expect="verified", model="towers.x")
    real = run(book, c.model_copy(update={"args": {"im": 0.0}}))["ch08.c"]
    assert (real.verdict, real.model_value) == ("verified", 2.0)
    small = run(book, c.model_copy(update={"args": {"im": 0.01}}))["ch08.c"]
    assert (small.verdict, small.model_value) == ("verified", [2.0, 0.01])
    unit = run(book, c.model_copy(update={"args": {"im": 1.0}}))["ch08.c"]
    assert (unit.verdict, unit.model_value) == ("erratum", [2.0, 1.0])


def test_an_imaginary_part_of_exactly_h_is_admitted(
    book: Book, monkeypatch: pytest.MonkeyPatch
) -> None:
    """As for the real part, the edge belongs: 2 + 0.5i against "2" (h = 0.5)."""
    fake_model(monkeypatch, lambda im: complex(2.0, im))
    c = claim(id="ch08.c", printed="2", kind="derived", expect="verified", model="towers.x")
    edge = run(book, c.model_copy(update={"args": {"im": 0.5}}))["ch08.c"]
    past = run(book, c.model_copy(update={"args": {"im": 0.5000001}}))["ch08.c"]
    assert (edge.verdict, past.verdict) == ("verified", "erratum")


def test_a_between_claim_holds_between_its_bounds(
    book: Book, monkeypatch: pytest.MonkeyPatch
) -> None:
    fake_model(monkeypatch, lambda x: x)
    c = claim(
        id="ch08.b",
        printed="4",
        kind="derived",
        expect="verified",
        model="towers.x",
        relation="between",
        bounds=["4", "5"],
    )
    inside = run(book, c.model_copy(update={"args": {"x": 4.5}}))["ch08.b"]
    outside = run(book, c.model_copy(update={"args": {"x": 5.5}}))["ch08.b"]
    assert (inside.verdict, outside.verdict) == ("verified", "erratum")


def test_a_count_returned_as_a_large_int_is_compared_exactly(
    book: Book, monkeypatch: pytest.MonkeyPatch
) -> None:
    """2^64 - 1 grains: an int model value is not rounded to a float (which would be 2^64),
    nor where a claim restates it; a count admits no rounding (tolerance 0)."""
    fake_model(monkeypatch, lambda: 2**64 - 1)
    c = claim(
        id="ch08.n",
        printed="18,446,744,073,709,551,615",
        kind="count",
        unit="1",
        expect="verified",
        model="towers.x",
    )
    result = run(book, c)["ch08.n"]
    assert (result.verdict, result.tolerance) == ("verified", 0.0)
    off = c.model_copy(update={"printed": "18,446,744,073,709,551,616"})
    assert run(book, off)["ch08.n"].verdict == "erratum"
    again = claim(
        id="ch08.again",
        printed="18,446,744,073,709,551,616",
        kind="count",
        unit="1",
        expect="erratum",
        restates="ch08.n",
        correct="18,446,744,073,709,551,615",
        diagnosis={"kind": "arithmetic", "note": "n"},
    )
    restated = run(book, c, again)["ch08.again"]
    assert (restated.verdict, restated.correct_agrees) == ("erratum", True)


@pytest.mark.parametrize(("printed", "model"), [("3.26", 3.6213), ("326", 362.13)])
def test_an_unexpected_erratum_is_diagnosed_against_the_model_at_the_printed_precision(
    book: Book, monkeypatch: pytest.MonkeyPatch, printed: str, model: float
) -> None:
    """A claim expected verified that misses gets the automatic diagnosis from the model
    written to the printed digits: 3.26 for 3.6213 is a digit swap of 3.62, 326 for 362.13
    one of 362."""
    fake_model(monkeypatch, lambda: model)
    c = claim(id="ch08.s", printed=printed, kind="derived", expect="verified", model="towers.x")
    result = run(book, c)["ch08.s"]
    assert result.verdict == "erratum"
    assert result.diagnosis is not None
    assert result.diagnosis["auto"] == "digit-swap: digits 362 printed as 326"


def test_a_correct_value_finer_than_printed_is_exact(
    book: Book, monkeypatch: pytest.MonkeyPatch
) -> None:
    """ "3.9" for 3.625: correct = "3.625" agrees with the model; "3.62", finer than printed,
    is read as exact (design 2a) and does not."""
    fake_model(monkeypatch, lambda: 3.625)
    c = claim(
        id="ch08.e",
        printed="3.9",
        kind="derived",
        expect="erratum",
        model="towers.x",
        correct="3.625",
        diagnosis={"kind": "arithmetic", "note": "n"},
    )
    assert run(book, c)["ch08.e"].correct_agrees is True
    wrong = run(book, c.model_copy(update={"correct": "3.62"}))["ch08.e"]
    assert (wrong.verdict, wrong.correct_agrees, wrong.passed) == ("erratum", False, False)
    # more figures at the same decimals is not finer: "10.5" for "0.5" is read to its h
    fake_model(monkeypatch, lambda: 10.52)
    shifted = c.model_copy(update={"printed": "0.5", "correct": "10.5"})
    assert run(book, shifted)["ch08.e"].correct_agrees is True


def test_progress_counts_the_claims_evaluated(
    book: Book, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """The last progress line comes once every claim is evaluated, not before the last one:
    a run that fails at its third claim never said "3/3"."""

    def model(x: float) -> float:
        if x < 0:
            raise ValueError("x must be positive")
        return x

    fake_model(monkeypatch, model)
    claims = [
        claim(
            id=f"ch08.p{i}",
            printed="3.62",
            kind="derived",
            expect="verified",
            model="towers.x",
            args={"x": 3.62},
        )
        for i in range(3)
    ]
    evaluated(book, *claims, progress=True)
    assert capsys.readouterr().err.splitlines() == ["bangcheck: evaluated 3/3 claims"]
    failing = claims[2].model_copy(update={"args": {"x": -1.0}})
    with pytest.raises(calls.ModelCallError):
        evaluated(book, *claims[:2], failing, progress=True)
    assert "3/3" not in capsys.readouterr().err


def test_progress_every_two_hundred_claims(
    book: Book, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    fake_model(monkeypatch, lambda: 3.62)
    claims = [
        claim(id=f"ch08.p{i}", printed="3.62", kind="derived", expect="verified", model="t.x")
        for i in range(201)
    ]
    evaluated(book, *claims, progress=True)
    assert capsys.readouterr().err.splitlines() == [
        "bangcheck: evaluated 200/201 claims",
        "bangcheck: evaluated 201/201 claims",
    ]
