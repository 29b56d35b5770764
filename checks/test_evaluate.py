"""The evaluator's paths on small catalogs of their own: a model's declared numerical error
(``indeterminate``), intervals (corners, or a grid for a model not monotonic), exact inputs
(design 3a), rounded assumptions, and a constant that matches only an older edition."""

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


def _peak(v: float) -> float:
    return 4 - (v - 2) ** 2  # a maximum at v = 2, the nominal input below


def _peak_claims(**extra: Any) -> tuple[Claim, Claim]:
    given = claim(id="ch08.v", printed="2.0", kind="given", expect="given", rounded=True)
    c = claim(
        id="ch08.top",
        printed="4.00",
        kind="derived",
        expect="verified",
        model="towers.x",
        args={"v": {"claim": "ch08.v"}},
        **extra,
    )
    return given, c


def test_a_model_not_monotonic_gets_its_interval_from_a_grid(
    book: Book, monkeypatch: pytest.MonkeyPatch
) -> None:
    """At an extremum the corners alone give an interval without the nominal value (the three
    intervals the integrity test caught); declared not monotonic, per function or per claim,
    the interval comes from corners, nominal point and grid, and contains it."""
    fake_model(monkeypatch, _peak)
    corners_only = run(book, *_peak_claims())["ch08.top"]
    assert corners_only.interval == pytest.approx([3.9975, 3.9975])
    per_claim = run(book, *_peak_claims(monotonic=False))["ch08.top"]
    assert per_claim.interval == pytest.approx([3.9975, 4.0])
    declared = _peak
    declared.monotonic = False  # type: ignore[attr-defined]
    try:
        per_function = run(book, *_peak_claims())["ch08.top"]
    finally:
        del declared.monotonic  # type: ignore[attr-defined]
    assert per_function.interval == per_claim.interval


def test_a_model_declared_not_monotonic_over_too_many_inputs_says_so(
    book: Book, monkeypatch: pytest.MonkeyPatch
) -> None:
    fake_model(monkeypatch, lambda **v: sum(v.values()))
    givens = [
        claim(id=f"ch08.v{i}", printed="2.1", kind="given", expect="given", rounded=True)
        for i in range(7)
    ]
    c = claim(
        id="ch08.n",
        printed="14.7",
        kind="derived",
        expect="verified",
        model="bangs.x",
        args={f"v{i}": {"claim": f"ch08.v{i}"} for i in range(7)},
        monotonic=False,
    )
    result = run(book, *givens, c)["ch08.n"]
    assert result.interval is None
    assert "not monotonic" in (result.interval_note or "")


def test_a_derived_input_equal_to_its_model_is_exact(
    book: Book, monkeypatch: pytest.MonkeyPatch
) -> None:
    """ΔP = 0 (line 1945) is exact when its model gives exactly 0: a claim using it gets no
    interval from it, and a later claim that would print 2 is an erratum, not input-rounding."""
    fake_model(monkeypatch, lambda v=None: 0 if v is None else 10 * v)
    zero = claim(id="ch08.dp", printed="0", kind="derived", expect="verified", model="towers.x")
    scaled = claim(
        id="ch08.ten-dp",
        printed="2",
        kind="derived",
        expect="erratum",
        model="towers.x",
        args={"v": {"claim": "ch08.dp"}},
        correct="0",
        diagnosis={"kind": "arithmetic", "note": "n"},
    )
    result = run(book, zero, scaled)["ch08.ten-dp"]
    assert (result.interval, result.verdict) == (None, "erratum")


def test_a_derived_input_off_its_model_is_rounded(
    book: Book, monkeypatch: pytest.MonkeyPatch
) -> None:
    fake_model(monkeypatch, lambda v=None: 0.04 if v is None else 10 * v)
    small = claim(id="ch08.dp", printed="0", kind="derived", expect="verified", model="towers.x")
    scaled = claim(
        id="ch08.ten-dp",
        printed="2",
        kind="derived",
        expect="rounding",
        model="towers.x",
        args={"v": {"claim": "ch08.dp"}},
    )
    result = run(book, small, scaled)["ch08.ten-dp"]
    assert result.interval == pytest.approx([-5.0, 5.0])
    assert (result.verdict, result.rounding_reason) == ("rounding", "input-rounding")


def test_a_rounded_assumption_spans_the_box(book: Book, monkeypatch: pytest.MonkeyPatch) -> None:
    fake_model(monkeypatch, lambda speed: speed / 0.44704)  # m/s to mph
    c = claim(
        id="ch08.mph",
        printed="55",
        kind="derived",
        expect="rounding",
        model="towers.x",
        assumptions={"speed": {"value": "24", "rounded": True, "reason": "r"}},
        precision_reason="the book's rounded 24 m/s",
    )
    result = run(book, c)["ch08.mph"]
    assert result.interval == pytest.approx([23.5 / 0.44704, 24.5 / 0.44704])
    assert (result.verdict, result.rounding_reason) == ("rounding", "input-rounding")
    assert (result.assumptions, result.rounded_assumptions) == ({"speed": "24"}, ["speed"])


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


def test_a_model_that_raises_names_the_claim(book: Book, monkeypatch: pytest.MonkeyPatch) -> None:
    def broken() -> float:
        raise ValueError("m1 must be positive, got -1")

    fake_model(monkeypatch, broken)
    c = claim(id="ch08.z", printed="3.62", kind="derived", expect="verified", model="towers.x")
    with pytest.raises(
        calls.ModelCallError, match=r"ch08\.z: field 'model': .*m1 must be positive"
    ):
        run(book, c)
