"""The evaluator's paths on small catalogs of their own: a model's inputs. Derived inputs exact
or rounded (design 3a), rounded and exact givens, rounded assumptions."""

from __future__ import annotations

import math

import pytest

from checks._evaluate_helpers import claim, fake_model, run
from reference.book import Book


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


@pytest.mark.parametrize(("ulps", "interval"), [(16, None), (17, [-0.05, 0.05])])
def test_a_derived_input_within_sixteen_ulps_of_its_model_is_exact(
    book: Book, monkeypatch: pytest.MonkeyPatch, ulps: int, interval: list[float] | None
) -> None:
    """A model's 0.5 off by the 16 ulps of float arithmetic is the printed 0.5 exactly: a
    claim using it gets no interval from it; 17 ulps off, it is a rounded input."""
    off = 0.5 + ulps * math.ulp(0.5)
    fake_model(monkeypatch, lambda v=None: off if v is None else v - off)
    half = claim(id="ch08.h", printed="0.5", kind="derived", expect="verified", model="t.x")
    using = claim(
        id="ch08.u",
        printed="0.0",
        kind="derived",
        expect="verified",
        model="t.x",
        args={"v": {"claim": "ch08.h"}},
    )
    result = run(book, half, using)["ch08.u"]
    assert result.interval == (None if interval is None else pytest.approx(interval, abs=1e-9))


def test_a_rounded_assumption_keeps_its_decimals(
    book: Book, monkeypatch: pytest.MonkeyPatch
) -> None:
    """An assumption "2.5" is passed as 2.5, and one "24" as the int 24."""
    fake_model(monkeypatch, lambda speed, n: speed * n if isinstance(n, int) else -1.0)
    c = claim(
        id="ch08.a",
        printed="60",
        kind="derived",
        expect="verified",
        model="t.x",
        assumptions={
            "speed": {"value": "2.5", "rounded": True, "reason": "r"},
            "n": {"value": "24", "reason": "r"},
        },
    )
    result = run(book, c)["ch08.a"]
    assert result.model_value == 60.0
    assert result.interval == pytest.approx([2.45 * 24, 2.55 * 24])
