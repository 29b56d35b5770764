"""Sensitivity: perturbing a claim's inputs moves its model value (design section 5).

For a fixed sample of modelled claims every referenced input is nudged (integers by one, other
numbers by one part in a thousand). A derived claim must move under at least one of its inputs (a
model returning a remembered number fails), unless its value is a structural zero (a height at
the floor); identities and counts may rightly stay put under small nudges. An input that leaves
a sampled claim unmoved must move some other claim that uses it (a model that ignores an
argument altogether fails); an input may rightly not matter to one claim, such as the ceiling to
the first bang.
"""

from __future__ import annotations

import random
from fractions import Fraction
from typing import Any

import pytest

from reference.calls import (
    ModelCache,
    ModelCallError,
    assumed_args,
    build_args,
    input_at,
    replace_input,
)
from reference.catalog import Catalog
from reference.compare import exact
from reference.schema import Claim
from reference.validate import claim_refs, parsed

pytestmark = pytest.mark.integrity
SAMPLE = 200


def nudged(value: Any) -> Any:
    if isinstance(value, int):
        return value + 1 if value >= 0 else value - 1  # away from zero
    if isinstance(value, Fraction):
        return value * Fraction(1001, 1000)
    return value * 1.001 if value else 1e-3


def _value(value: Any) -> Fraction | None:
    """The exact value of a model result; None where the nudged model gives no number (a
    different kind of answer, which counts as moving)."""
    if value is None or isinstance(value, bool):
        return None
    return exact(value.real if isinstance(value, complex) else value)


class _Probe:
    def __init__(self, catalog: Catalog) -> None:
        self.by_id = catalog.by_id()
        self.cache = ModelCache()

    def moved_inputs(self, claim: Claim) -> tuple[set[str], set[str], Fraction | None]:
        """The inputs whose nudge moves the claim's value, all its inputs, and the value."""
        assert claim.model is not None
        args, inputs = build_args(
            claim.args,
            lambda ident: (self.by_id[ident], parsed(self.by_id[ident])),
            rounded=lambda ident: False,
        )
        args.update(assumed_args(claim.assumptions)[0])
        base = _value(self.cache.picked(claim.id, claim.model, args, claim.pick))
        moved = set()
        for item in inputs:
            changed = replace_input(args, item.path, nudged(input_at(args, item.path)))
            try:
                value = _value(self.cache.picked(claim.id, claim.model, changed, claim.pick))
            except ModelCallError:
                value = None  # the nudge left the model's domain: the input matters
            if value != base:
                moved.add(item.claim_id)
        return moved, {item.claim_id for item in inputs}, base


def test_models_move_with_their_inputs(catalog: Catalog) -> None:
    refs = {c.id: {r for v in c.args.values() for r in claim_refs(v)} for _, c in catalog.claims()}
    # a formula claim's inputs are its symbols, compared at generic points (test_formulas)
    with_inputs = [c for _, c in catalog.claims() if c.model and refs[c.id] and c.kind != "formula"]
    sample = with_inputs
    if len(sample) > SAMPLE:
        sample = random.Random(0).sample(with_inputs, SAMPLE)
    probe = _Probe(catalog)
    still, idle = [], set()
    for claim in sample:
        moved, used, value = probe.moved_inputs(claim)
        if not moved and claim.kind == "derived" and value != 0:
            still.append(claim.id)
        idle |= used - moved
    users = {ident: [c for c in with_inputs if ident in refs[c.id]] for ident in sorted(idle)}
    ignored = [
        ident
        for ident, claims in users.items()
        if not any(ident in probe.moved_inputs(c)[0] for c in claims)
    ]
    assert not still, f"claims whose model ignores all its inputs: {still}"
    assert not ignored, f"inputs that move no claim using them: {ignored}"
