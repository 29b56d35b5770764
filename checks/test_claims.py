"""One test per catalogued claim: its verdict equals its ``expect``.

An unmodeled claim is an expected failure naming its id. For an erratum the model must also agree
with the curator's ``correct``, so that a wrong model cannot pass as an erratum.
"""

from __future__ import annotations

import pytest

from reference.evaluation import EvaluatedClaim, Evaluation

# under xdist (--dist loadgroup) every test that reads the session's evaluation or scan is in
# one group, run by one worker, which evaluates the catalog and scans the book once; the 1,998
# claims are then also one unit of work for the controller to schedule
pytestmark = [pytest.mark.claims, pytest.mark.xdist_group("evaluation")]


def _explain(c: EvaluatedClaim, file: str) -> str:
    interval = f", input interval {c.interval}" if c.interval else ""
    tolerance = f" (tolerance ±{c.tolerance:g}{interval})" if c.tolerance is not None else ""
    return (
        f"{file}: {c.id} (line {c.line}): printed {c.printed!r} vs model {c.model_value!r}"
        f"{tolerance}: verdict {c.verdict}"
        f"{f' [{c.rounding_reason}]' if c.rounding_reason else ''}, expected {c.expect}"
    )


def test_claim(claim_id: str, evaluation: Evaluation) -> None:
    claim = evaluation.by_id()[claim_id]
    file = claim.file
    if claim.verdict == "unmodeled":
        pytest.xfail(f"{claim_id} is unmodeled (no model yet)")
    assert claim.verdict == claim.expect, _explain(claim, file)
    if claim.expect == "erratum":
        assert claim.correct_agrees, (
            f"{file}: {claim_id}: the model ({claim.model_value!r}) does not agree with "
            f"correct = {claim.correct!r} within half a unit of its last digit"
        )
