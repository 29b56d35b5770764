"""Sensitivity: perturbing a claim's inputs moves its model value (design section 5).

For a fixed sample of modelled claims, every referenced input is nudged (integers by one, other
numbers by one part in a thousand). Each claim must move under at least one of its inputs, and
each referenced input must move at least one claim that uses it: a model that ignores an
argument, or returns a remembered number, fails.
"""

from __future__ import annotations

import random
from collections import defaultdict
from fractions import Fraction
from typing import Any

import pytest

from reference.calls import ModelCache, build_args, input_at, replace_input
from reference.catalog import Catalog
from reference.compare import exact
from reference.validate import parsed

pytestmark = pytest.mark.integrity
SAMPLE = 200


def nudged(value: Any) -> Any:
    if isinstance(value, int):
        return value + 1
    if isinstance(value, Fraction):
        return value * Fraction(1001, 1000)
    return value * 1.001 if value else 1e-3


def test_models_move_with_their_inputs(catalog: Catalog) -> None:
    by_id = catalog.by_id()
    claims = [c for _, c in catalog.claims() if c.model]
    if len(claims) > SAMPLE:
        claims = random.Random(0).sample(claims, SAMPLE)
    cache = ModelCache()
    still: list[str] = []
    moved_by: dict[str, set[str]] = defaultdict(set)
    used: set[str] = set()
    for claim in claims:
        assert claim.model is not None
        args, inputs = build_args(claim.args, lambda ident: (by_id[ident], parsed(by_id[ident])))
        args.update(claim.assumptions)
        base = exact(cache.picked(claim.id, claim.model, args, claim.pick))
        moved = False
        for item in inputs:
            used.add(item.claim_id)
            changed = replace_input(args, item.path, nudged(input_at(args, item.path)))
            if exact(cache.picked(claim.id, claim.model, changed, claim.pick)) != base:
                moved = True
                moved_by[item.claim_id].add(claim.id)
        if inputs and not moved:
            still.append(claim.id)
    assert not still, f"claims whose model ignores all its inputs: {still}"
    assert not [i for i in used if not moved_by[i]], "inputs that move no claim"
