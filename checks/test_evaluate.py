"""The evaluator's paths that the catalog may not exercise yet: a model's declared numerical
error (``indeterminate``), a model declared not monotonic (no input interval), and a constant
that matches only an older edition (``dated``)."""

from __future__ import annotations

from types import SimpleNamespace
from typing import Any

import pytest

from reference import calls
from reference import evaluation as evaluate
from reference.book import Book
from reference.catalog import Catalog, ChapterFile
from reference.schema import Claim, Meta

META = Meta.model_validate(
    {"chapter": "8", "title": "t", "lines": [6510, 6935], "complete": False, "schema": 1}
)


def claim(**fields: Any) -> Claim:
    base = {"line": 6562, "quote": "q", "quantity": "q", "unit": "scaled"}
    return Claim.model_validate({**base, **fields})


def run(book: Book, *claims: Claim) -> dict[str, evaluate.EvaluatedClaim]:
    f = ChapterFile("reference/claims/ch08.toml", "ch08", META, claims, (), ())
    return evaluate.evaluate_catalog(Catalog((f,)), book).by_id()


def fake_model(monkeypatch: pytest.MonkeyPatch, func: Any) -> None:
    monkeypatch.setattr(calls, "resolve", lambda name: func)
    monkeypatch.setattr(evaluate, "resolve", lambda name: func)


def test_a_verdict_that_changes_within_the_model_error_is_indeterminate(
    book: Book, monkeypatch: pytest.MonkeyPatch
) -> None:
    fake_model(monkeypatch, lambda: SimpleNamespace(value=3.6153, error=0.002))
    c = claim(id="ch08.x", printed="3.62", kind="derived", expect="verified", model="towers.x")
    result = run(book, c)["ch08.x"]
    assert (result.verdict, result.model_error) == ("indeterminate", 0.002)


def test_a_small_model_error_keeps_the_verdict(book: Book, monkeypatch: pytest.MonkeyPatch) -> None:
    fake_model(monkeypatch, lambda: SimpleNamespace(value=3.6153, error=1e-6))
    c = claim(id="ch08.x", printed="3.62", kind="derived", expect="verified", model="towers.x")
    assert run(book, c)["ch08.x"].verdict == "verified"


def test_a_model_declared_not_monotonic_gets_no_interval(
    book: Book, monkeypatch: pytest.MonkeyPatch
) -> None:
    def count(v: float) -> int:
        return round(10 * v)

    count.monotonic = False  # type: ignore[attr-defined]
    fake_model(monkeypatch, count)
    given = claim(id="ch08.v", printed="2.1", kind="given", expect="given", rounded=True)
    c = claim(
        id="ch08.n",
        printed="21",
        kind="count",
        expect="verified",
        model="bangs.x",
        args={"v": {"claim": "ch08.v"}},
    )
    result = run(book, given, c)["ch08.n"]
    assert result.interval is None
    assert "not monotonic" in (result.interval_note or "")


def test_a_rounded_given_makes_an_interval(book: Book, monkeypatch: pytest.MonkeyPatch) -> None:
    fake_model(monkeypatch, lambda v: 1.5 * v + 0.5)
    given = claim(id="ch08.v", printed="2.1", kind="given", expect="given", rounded=True)
    c = claim(
        id="ch08.y",
        printed="3.62",
        kind="derived",
        expect="rounding",
        model="towers.x",
        args={"v": {"claim": "ch08.v"}},
    )
    result = run(book, given, c)["ch08.y"]
    assert result.interval == pytest.approx([3.575, 3.725])
    assert (result.verdict, result.rounding_reason) == ("rounding", "input-rounding")
    assert result.interval_wide  # 0.15 is more than 10 h = 0.05


def test_an_exact_given_makes_no_interval(book: Book, monkeypatch: pytest.MonkeyPatch) -> None:
    fake_model(monkeypatch, lambda v: 1.5 * v + 0.5)
    given = claim(id="ch08.v", printed="2.1", kind="given", expect="given")
    c = claim(
        id="ch08.y",
        printed="3.62",
        kind="derived",
        expect="erratum",
        model="towers.x",
        args={"v": {"claim": "ch08.v"}},
        correct="3.65",
        diagnosis={"kind": "arithmetic", "note": "n"},
    )
    result = run(book, given, c)["ch08.y"]
    assert (result.interval, result.verdict, result.correct_agrees) == (None, "erratum", True)


def test_an_older_edition_of_a_constant_is_diagnosed_dated(book: Book) -> None:
    c = claim(
        id="ch08.g",
        printed="6.672E-11",
        kind="constant",
        expect="erratum",
        constant="gravitational-constant",
        unit="1",
        correct="6.674E-11",
        diagnosis={"kind": "dated", "note": "n"},
    )
    result = run(book, c)["ch08.g"]
    assert result.verdict == "erratum"
    assert result.diagnosis is not None
    assert (result.diagnosis["auto"] or "").startswith("dated: matches CODATA 1973")


def test_a_model_that_raises_names_the_claim(book: Book, monkeypatch: pytest.MonkeyPatch) -> None:
    def broken() -> float:
        raise ValueError("m1 must be positive, got -1")

    fake_model(monkeypatch, broken)
    c = claim(id="ch08.z", printed="3.62", kind="derived", expect="verified", model="towers.x")
    with pytest.raises(
        calls.ModelCallError, match=r"ch08\.z: field 'model': .*m1 must be positive"
    ):
        run(book, c)
