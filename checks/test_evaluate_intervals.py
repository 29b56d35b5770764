"""The evaluator's paths on small catalogs of their own: intervals. The box of the rounded
inputs (corners, or a grid for a model not monotonic), its centre, and wide intervals."""

from __future__ import annotations

from fractions import Fraction
from typing import Any

import pytest

from checks._evaluate_helpers import _rounded_given, claim, evaluated, fake_model, run
from mechmodel.typing import not_monotonic
from reference.book import Book
from reference.schema import Claim


def _peak(v: float) -> float:
    return 4 - (v - 2) ** 2  # a maximum at v = 2, the nominal input below


@not_monotonic
def _declared_peak(v: float) -> float:
    return _peak(v)


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
    fake_model(monkeypatch, _declared_peak)
    per_function = run(book, *_peak_claims())["ch08.top"]
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


@pytest.mark.parametrize(("slope", "wide"), [(0.525, True), (0.45, False)])
def test_an_interval_wider_than_ten_h_is_flagged_wide(
    book: Book, monkeypatch: pytest.MonkeyPatch, slope: float, wide: bool
) -> None:
    """The rounded 2.1 spans 0.1: times 0.525 an interval of 10.5 h (h = 0.005 for "1.10")
    is flagged wide, times 0.45 one of 9 h is not."""
    fake_model(monkeypatch, lambda v: slope * (v - 2.1) + 1.1)
    c = claim(
        id="ch08.y",
        printed="1.10",
        kind="derived",
        expect="verified",
        model="towers.x",
        args={"v": {"claim": "ch08.v"}},
    )
    result = run(book, _rounded_given(), c)["ch08.y"]
    assert result.interval == pytest.approx([1.1 - slope * 0.05, 1.1 + slope * 0.05])
    assert (result.verdict, result.interval_wide) == ("verified", wide)


def test_the_centre_of_the_box_is_the_nominal_point(
    book: Book, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The integrity test checks every interval against the model at the box's centre: the
    midpoint of its extreme corners, the nominal inputs, not a corner."""
    fake_model(monkeypatch, lambda v: 1.5 * v + 0.5)
    c = claim(
        id="ch08.y",
        printed="3.65",
        kind="derived",
        expect="verified",
        model="towers.x",
        args={"v": {"claim": "ch08.v"}},
    )
    result = evaluated(book, _rounded_given(), c)
    assert float(result.centres["ch08.y"]) == pytest.approx(3.65)


def test_a_rounded_input_inside_a_list_argument_spans_the_box(
    book: Book, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A referenced claim among a list's items (the tower's masses) is an input of the box like
    any other."""
    fake_model(monkeypatch, lambda masses: masses[0] + masses[1])
    c = claim(
        id="ch08.sum",
        printed="5.1",
        kind="derived",
        expect="verified",
        model="towers.x",
        args={"masses": [{"claim": "ch08.v"}, 3]},
    )
    result = run(book, _rounded_given(), c)["ch08.sum"]
    assert result.interval == pytest.approx([5.05, 5.15])
    assert result.verdict == "verified"


def test_a_model_declared_not_monotonic_is_sampled_at_corners_centre_and_halfway(
    book: Book, monkeypatch: pytest.MonkeyPatch
) -> None:
    """One rounded input (2.0 +- 0.05): the grid is v - h, v - h/2, v, v + h/2, v + h; five
    inputs: corners and centre of each, 3^5 points (5^5 would pass the 729 calls allowed)."""
    seen: list[float] = []

    def model(**v: float) -> float:
        seen.append(v["v0"])
        return sum(v.values())

    def summed(count: int) -> list[Claim]:
        givens = [_rounded_given(f"ch08.v{i}", "2.0") for i in range(count)]
        c = claim(
            id="ch08.n",
            printed=f"{2 * count}.00",
            kind="derived",
            expect="verified",
            model="bangs.x",
            args={f"v{i}": {"claim": f"ch08.v{i}"} for i in range(count)},
            monotonic=False,
        )
        return [*givens, c]

    fake_model(monkeypatch, model)
    run(book, *summed(1))
    assert sorted(set(seen)) == pytest.approx([1.95, 1.975, 2.0, 2.025, 2.05])
    seen.clear()
    result = evaluated(book, *summed(5))
    assert result.model_calls == 3**5 + 1  # and the nominal call (its inputs ints, 2 not 2.0)
    assert sorted(set(seen)) == pytest.approx([1.95, 2.0, 2.05])
    assert result.by_id()["ch08.n"].interval == pytest.approx([9.75, 10.25])
    six = evaluated(book, *summed(6))  # 3^6 = 729 calls: just within the limit
    assert six.model_calls == 3**6 + 1
    assert six.by_id()["ch08.n"].interval == pytest.approx([11.7, 12.3])


def test_an_interval_of_exactly_ten_h_is_not_wide(
    book: Book, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Wide means wider than 10 h: a model stepping by exactly 0.025 either side of 1.10
    spans 10 h = 0.05."""
    step = Fraction(25, 1000)
    fake_model(monkeypatch, lambda v: Fraction(11, 10) + (step if v > 2.1 else -step))
    c = claim(
        id="ch08.y",
        printed="1.10",
        kind="derived",
        expect="rounding",
        model="towers.x",
        args={"v": {"claim": "ch08.v"}},
    )
    result = run(book, _rounded_given(), c)["ch08.y"]
    assert result.interval == [1.075, 1.125]
    assert result.interval_wide is False


@pytest.mark.parametrize("count", [10, 11])
def test_a_monotonic_model_gets_corners_for_ten_rounded_inputs_not_eleven(
    book: Book, monkeypatch: pytest.MonkeyPatch, count: int
) -> None:
    """2^10 = 1024 corners are computed; with 11 rounded inputs the interval is left out and
    the note says why."""
    fake_model(monkeypatch, lambda **v: sum(v.values()))
    givens = [_rounded_given(f"ch08.v{i}", "2.1") for i in range(count)]
    c = claim(
        id="ch08.n",
        printed=f"{2.1 * count:.1f}",
        kind="derived",
        expect="verified",
        model="t.x",
        args={f"v{i}": {"claim": f"ch08.v{i}"} for i in range(count)},
    )
    result = run(book, *givens, c)["ch08.n"]
    if count == 10:
        assert result.interval == pytest.approx([20.5, 21.5])
        assert result.interval_note is None
    else:
        assert result.interval is None
        assert result.interval_note == "11 rounded inputs: too many corners for an interval"
