"""Model calls for claims: argument values, the call cache and the box of input roundings.

``args`` values are numbers, lists, strings "p/q" (a Fraction) or ``{ claim = ID }``: that claim's
value, in SI where it has a physical unit, as printed where it is ``scaled`` or ``1``. Inputs that
are rounded (referenced derived or identity claims, givens with ``rounded = true``) span a box
[v - h, v + h]; the model evaluated at the box's corners gives the claim's input interval.
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

from reference.models import follow, resolve
from reference.numbers import Printed
from reference.schema import Claim, ClaimRef
from reference.tables import NO_CONVERSION, unit_factor

MAX_ROUNDED_INPUTS = 10  # 2^10 corners at most; beyond that no interval is computed
_FRACTION_ARG = re.compile(r"-?\d+/\d+")


class ModelCallError(Exception):
    """A model raised, or its result could not be read; names the claim and the field."""

    def __init__(self, claim_id: str, field: str, message: str) -> None:
        self.claim_id, self.field = claim_id, field
        super().__init__(f"{claim_id}: field '{field}': {message}")


@dataclass(frozen=True)
class Input:
    """A referenced claim's value in ``args``: where it sits, whose it is, and whether it is
    rounded (then ``half_width`` is its half-width in the units the model receives)."""

    path: tuple[str | int, ...]
    claim_id: str
    rounded: bool
    half_width: Any


def input_value(claim: Claim, printed: Printed) -> Any:
    """A referenced claim's value as a model input.

    As printed (an ``int`` when integral, a ``Fraction`` for an exact fraction, else a float) for
    ``scaled`` and ``1``; a float in SI for a physical unit.
    """
    value = printed.value
    if claim.unit in NO_CONVERSION:
        if value.denominator == 1:
            return int(value)
        if printed.exact and not printed.irrational:
            return value
        return float(value)
    return float(value) * unit_factor(claim.unit)


def input_half_width(claim: Claim, printed: Printed) -> Any:
    """The half-width of a referenced value in the units the model receives it in."""
    h = printed.half_width
    if claim.unit in NO_CONVERSION:
        return float(h)
    return float(h) * unit_factor(claim.unit)


def is_rounded(claim: Claim) -> bool:
    """Whether a referenced claim's printed value is a rounded number."""
    return claim.kind in ("derived", "identity") or (claim.kind == "given" and claim.rounded)


def build_args(
    raw: dict[str, Any], lookup: Callable[[str], tuple[Claim, Printed]]
) -> tuple[dict[str, Any], list[Input]]:
    """Concrete keyword arguments for a model, and the referenced inputs among them."""
    inputs: list[Input] = []

    def convert(value: Any, path: tuple[str | int, ...]) -> Any:
        if isinstance(value, ClaimRef):
            ref, printed = lookup(value.claim)
            rounded = is_rounded(ref) and bool(printed.half_width)
            inputs.append(Input(path, ref.id, rounded, input_half_width(ref, printed)))
            return input_value(ref, printed)
        if isinstance(value, list):
            return [convert(item, (*path, i)) for i, item in enumerate(value)]
        if isinstance(value, str) and _FRACTION_ARG.fullmatch(value):
            p, q = value.split("/")
            return Fraction(int(p), int(q))
        return value

    args = {name: convert(value, (name,)) for name, value in raw.items()}
    return args, inputs


def replace_input(args: dict[str, Any], path: tuple[str | int, ...], value: Any) -> dict[str, Any]:
    """A copy of ``args`` with the value at ``path`` replaced."""
    out = {k: list(v) if isinstance(v, list) else v for k, v in args.items()}
    target: Any = out
    for step in path[:-1]:
        target[step] = list(target[step])
        target = target[step]
    target[path[-1]] = value
    return out


def input_at(args: dict[str, Any], path: tuple[str | int, ...]) -> Any:
    """The value at ``path`` in ``args``."""
    value: Any = args
    for step in path:
        value = value[step]
    return value


def corners(args: dict[str, Any], rounded: list[Input]) -> Iterator[dict[str, Any]]:
    """The model's arguments at every corner of the box of input roundings."""
    for signs in itertools.product((-1, 1), repeat=len(rounded)):
        out = args
        for sign, r in zip(signs, rounded, strict=True):
            out = replace_input(out, r.path, input_at(out, r.path) + sign * r.half_width)
        yield out


def _freeze(value: Any) -> Any:
    if isinstance(value, list | tuple):
        return tuple(_freeze(v) for v in value)
    if isinstance(value, dict):
        return tuple(sorted((k, _freeze(v)) for k, v in value.items()))
    return (type(value).__name__, value)


class ModelCache:
    """Each model call evaluated once per run, keyed on the model and its arguments."""

    def __init__(self) -> None:
        self._results: dict[Any, Any] = {}
        self.calls = 0

    @staticmethod
    def key(model: str, args: dict[str, Any]) -> Any:
        """The cache key of a call: the model and its arguments, with their types."""
        return (model, _freeze(args))

    def call(self, claim_id: str, model: str, args: dict[str, Any]) -> Any:
        key = self.key(model, args)
        if key not in self._results:
            func = resolve(model)
            self.calls += 1
            try:
                self._results[key] = func(**args)
            except (ValueError, TypeError, ArithmeticError) as err:
                shown = ", ".join(f"{k}={v!r}" for k, v in args.items())
                raise ModelCallError(
                    claim_id, "model", f"{model}({shown}) raised {type(err).__name__}: {err}"
                ) from err
        return self._results[key]

    def picked(self, claim_id: str, model: str, args: dict[str, Any], pick: str) -> Any:
        """The part of the model's result that ``pick`` names."""
        result = self.call(claim_id, model, args)
        try:
            return follow(result, pick)
        except ValueError as err:
            raise ModelCallError(claim_id, "pick", str(err)) from err
