"""The verdict rules of design section 3a on the real claims they were written for.

Each test takes a claim of the catalog as evaluated this session and judges its printed value,
and a misprint of it, in the claim's own context: what the verdict would have said had the book
been wrong.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import pytest

from reference.book import Book
from reference.compare import judge
from reference.evaluation import Evaluation
from reference.numbers import parse_number
from reference.schema import CatalogError
from reference.validate import checked_catalog, parsed

# under xdist (--dist loadgroup) every test that reads the session's evaluation is in one group
pytestmark = [pytest.mark.integrity, pytest.mark.xdist_group("evaluation")]

CLAIMS = Path(__file__).parents[1] / "reference" / "claims"


def verdict_of(evaluation: Evaluation, ident: str, printed: str, **parse: object) -> str:
    """The verdict ``printed`` would get in claim ``ident``'s context."""
    ctx = evaluation.contexts[ident]
    return judge(parse_number(printed, **parse), ctx).verdict  # type: ignore[arg-type]


def test_a_model_exactly_on_250_rejects_251(evaluation: Evaluation) -> None:
    """P_total = 250 (line 1943) from exact masses and velocities: 251 was "rounding
    (other-way)" and is now an erratum, as is 249."""
    ident = "ch02.suv-vw.p-total"
    assert evaluation.contexts[ident].interval is None
    assert verdict_of(evaluation, ident, "250") == "verified"
    assert verdict_of(evaluation, ident, "251") == "erratum"
    assert verdict_of(evaluation, ident, "249") == "erratum"
    assert "last-digit" in (evaluation.by_id()[ident].catches or [])


def test_exact_inputs_stay_exact(evaluation: Evaluation) -> None:
    """ΔP = 0 (line 1945) is computed from the figure's printed points, each its model's exact
    value: no input interval, so a printed 2 would be an erratum (it had [-2.5, 2.5])."""
    ident = "ch02.suv-vw.runch.momentum-change"
    assert evaluation.by_id()[ident].interval is None
    assert verdict_of(evaluation, ident, "0") == "verified"
    assert verdict_of(evaluation, ident, "2") == "erratum"


def test_one_radian_and_its_degrees_get_one_verdict(evaluation: Evaluation) -> None:
    """ "-σc = –1-radian or –57.3°" (line 1393): the exact one radian and its 57.3 degrees
    are one angle, and one erratum (the -1 had half a radian of slack as a rounded integer)."""
    radians = evaluation.by_id()["ch01.whirl.first-angle-rad"]
    degrees = evaluation.by_id()["ch01.whirl.first-angle-deg"]
    assert (radians.verdict, degrees.verdict) == ("erratum", "erratum")
    assert radians.exact
    assert verdict_of(evaluation, radians.id, "-1") == "verified"  # read as rounded: passes


def test_the_bound_over_9_is_no_input_and_81_is_judged_as_stated(
    evaluation: Evaluation, book: Book, tmp_path: Path
) -> None:
    """ "a boost of over 9.0 ... (V4)2=81" (line 6568): referencing the bound is refused; the
    81 is judged by the "=" it states, against the tower's own (V4)^2 = 94.5."""
    boost = evaluation.by_id()["ch08.tower-7.energy-boost"]
    assert (boost.relation, boost.verdict, boost.correct) == ("=", "erratum", "94")
    assert boost.model_value == pytest.approx((2 * (7 / 4) ** 3 - 1) ** 2)
    text = (CLAIMS / "ch08.toml").read_text(encoding="utf-8")
    old = (
        'model = "towers.energy_boost"\nargs = { velocity = { claim = "ch08.tower-7.top" }, '
        'v_drop = { claim = "ch08.tower-100-30-10.v-drop" } }\npick = "energy_boost"'
    )
    spoilt = text.replace(
        'model = "towers.geometric_tower"\nargs = { n_balls = { claim = '
        '"ch08.tower-3.n-balls" }, ratio = { claim = "ch08.tower-7.ratio" }, '
        'v_drop = { claim = "ch08.tower-100-30-10.v-drop" } }\n'
        'pick = "energy_boost"',
        old,
    )
    assert spoilt != text
    (tmp_path / "ch08.toml").write_text(spoilt.replace('\npick = "energy_boost"', ""), "utf-8")
    with pytest.raises(CatalogError) as raised:
        checked_catalog(book, tmp_path)
    messages = [(p.id, p.field, p.message) for p in raised.value.problems]
    assert any(
        ident == "ch08.tower-7.energy-boost" and field == "args" and "a bound ('>')" in message
        for ident, field, message in messages
    ), messages


def test_a_declared_truncation_is_admitted_and_an_undeclared_one_is_not(
    evaluation: Evaluation,
) -> None:
    """ "√8=2.82…" (line 1739) declares its cut with the ellipsis: rounding (truncation).
    Without the declaration the same value is an erratum, as "0.478" of line 6883 is, whose
    table rounds every other sum."""
    ident = "ch01.arcsec.tangent-decimal"
    c = evaluation.by_id()[ident]
    assert (c.verdict, c.rounding_reason, c.rounding) == ("rounding", "truncation", "truncation")
    undeclared = dataclasses.replace(evaluation.contexts[ident], truncation=False)
    assert judge(parse_number("2.82"), undeclared).verdict == "erratum"
    assert verdict_of(evaluation, ident, "2.83") == "verified"
    assert verdict_of(evaluation, ident, "2.81") == "erratum"  # not a cut of 2.828
    rocket = evaluation.by_id()["ch08.rocket.velocity-3"]
    assert (rocket.verdict, rocket.rounding) == ("erratum", None)
    assert rocket.diagnosis is not None
    assert (rocket.diagnosis["auto"] or "").startswith("last-digit")


def test_a_printed_intermediate_is_referenced(evaluation: Evaluation) -> None:
    """The 55 mph of line 6229 is the printed 24 m/s converted: input-rounding, not a rounding
    "the other way" of the unrounded 54.2 mph; the 84-minute period is twice the rounded 42."""
    mph = evaluation.by_id()["ch07.daredevil.impact-speed-mph"]
    assert (mph.verdict, mph.rounding_reason) == ("rounding", "input-rounding")
    assert mph.interval == pytest.approx([23.5 / 0.44704, 24.5 / 0.44704])
    assert verdict_of(evaluation, mph.id, "56") == "erratum"
    period = evaluation.by_id()["ch09.tunnel.period"]
    assert period.verdict == "verified"
    assert period.interval == pytest.approx([83.0, 85.0])


def test_no_claim_is_rounding_without_a_reason_it_declares_or_an_interval(
    evaluation: Evaluation,
) -> None:
    """``other-way`` is no longer produced; ``truncation`` only where the claim declares it."""
    for c in evaluation:
        if c.verdict == "rounding":
            assert c.rounding_reason in ("input-rounding", "truncation"), c.id
            if c.rounding_reason == "truncation":
                assert c.rounding == "truncation", c.id
                assert c.precision_reason, c.id
            else:
                assert c.interval is not None, c.id


def test_exact_claims_are_printed_integers(evaluation: Evaluation) -> None:
    by_id = evaluation.catalog.by_id()
    for c in evaluation:
        if c.exact:
            printed = parsed(by_id[c.id])
            assert printed.exact, c.id
            assert printed.value.denominator == 1, c.id
