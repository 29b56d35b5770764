"""The evaluator's paths on small catalogs of their own: a model's declared numerical error
(``indeterminate``), intervals (corners, or a grid for a model not monotonic), exact inputs
(design 3a), rounded assumptions, and a constant that matches only an older edition."""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Any

import pytest

from mechmodel.typing import Estimate, not_monotonic
from reference import calls, modelling, tables
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
    monkeypatch.setattr(modelling, "resolve", lambda name: func)


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


def evaluated(book: Book, *claims: Claim, progress: bool = False) -> evaluate.Evaluation:
    f = ChapterFile("reference/claims/ch08.toml", "ch08", META, claims, (), ())
    return evaluate.evaluate_catalog(Catalog((f,)), book, progress=progress)


def _rounded_given(ident: str = "ch08.v", printed: str = "2.1") -> Claim:
    return claim(id=ident, printed=printed, kind="given", expect="given", rounded=True)


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
