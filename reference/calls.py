"""Model calls for claims: argument values, the call cache and the box of input roundings.

``args`` values are numbers, lists, strings "p/q" (a Fraction) or ``{ claim = ID }``: that claim's
value, in SI where it has a physical unit, as printed where it is ``scaled`` or ``1``. Inputs that
are rounded (design 3a: referenced claims that are not exact inputs, givens with ``rounded =
true``, rounded assumptions) span a box [v - h, v + h]; the model evaluated at the box's corners
(or, for a model not monotonic over it, on a grid) gives the claim's input interval.
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

from reference.models import follow, resolve
from reference.numbers import Printed, parse_number
from reference.schema import Assumption, Claim, ClaimRef, SymbolRef
from reference.tables import NO_CONVERSION, unit_factor

MAX_ROUNDED_INPUTS = 10  # 2^10 corners at most; beyond that no interval is computed
MAX_GRID_POINTS = 3**6  # a model not monotonic over its box: 729 calls at most
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


def build_args(
    raw: dict[str, Any],
    lookup: Callable[[str], tuple[Claim, Printed]],
    rounded: Callable[[str], bool],
    symbols: Mapping[str, Any] | None = None,
) -> tuple[dict[str, Any], list[Input]]:
    """Concrete keyword arguments for a model, and the referenced inputs among them;
    ``rounded(id)`` says whether a referenced claim is a rounded input (design 3a), and
    ``symbols`` gives a formula claim's ``{ symbol = NAME }`` arguments their values (sympy
    symbols, or numbers at a point)."""
    inputs: list[Input] = []

    def convert(value: Any, path: tuple[str | int, ...]) -> Any:
        if isinstance(value, SymbolRef):
            if symbols is None or value.symbol not in symbols:
                raise KeyError(f"{{ symbol = {value.symbol!r} }} outside a formula claim")
            return symbols[value.symbol]
        if isinstance(value, ClaimRef):
            ref, printed = lookup(value.claim)
            is_rounded = rounded(ref.id) and bool(printed.half_width)
            inputs.append(Input(path, ref.id, is_rounded, input_half_width(ref, printed)))
            return input_value(ref, printed)
        if isinstance(value, list):
            return [convert(item, (*path, i)) for i, item in enumerate(value)]
        if isinstance(value, str) and _FRACTION_ARG.fullmatch(value):
            p, q = value.split("/")
            return Fraction(int(p), int(q))
        return value

    args = {name: convert(value, (name,)) for name, value in raw.items()}
    return args, inputs


def assumed_args(
    assumptions: dict[str, int | float | str | Assumption],
) -> tuple[dict[str, Any], list[Input]]:
    """The assumptions as keyword arguments, and the rounded ones as inputs of the box (an
    assumption ``{ value = "24", rounded = true }`` spans 23.5 to 24.5)."""
    args: dict[str, Any] = {}
    inputs: list[Input] = []
    for name, assumed in assumptions.items():
        if not isinstance(assumed, Assumption):
            args[name] = assumed
            continue
        printed = parse_number(str(assumed.value))
        value = printed.value
        args[name] = int(value) if value.denominator == 1 else float(value)
        if assumed.rounded and printed.half_width:
            inputs.append(Input((name,), f"assumption {name}", True, float(printed.half_width)))
    return args, inputs


def replace_input(
    args: dict[str, Any], path: tuple[str | int, ...], value: object
) -> dict[str, Any]:
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
    yield from box_points(args, rounded, (-1, 1))


def box_points(
    args: dict[str, Any], rounded: list[Input], steps: tuple[float, ...]
) -> Iterator[dict[str, Any]]:
    """The model's arguments at every point of the grid whose coordinates are ``v + s h`` for
    each rounded input (value v, half-width h) and each s in ``steps`` (from -1 to 1)."""
    for signs in itertools.product(steps, repeat=len(rounded)):
        out = args
        for sign, r in zip(signs, rounded, strict=True):
            out = replace_input(out, r.path, input_at(out, r.path) + sign * r.half_width)
        yield out


def grid_steps(count: int) -> tuple[float, ...] | None:
    """The grid for a model not monotonic over its box of ``count`` rounded inputs: corners,
    centre and points between, as many as stay within ``MAX_GRID_POINTS`` model calls; None
    when not even corners and centre fit."""
    for steps in ((-1, -0.5, 0, 0.5, 1), (-1, 0, 1)):
        if len(steps) ** count <= MAX_GRID_POINTS:
            return steps
    return None


def centre(args: dict[str, Any], rounded: list[Input]) -> dict[str, Any]:
    """The model's arguments at the centre of the box (the midpoint of its extreme corners)."""
    out = args
    for r in rounded:
        v = input_at(out, r.path)
        out = replace_input(out, r.path, ((v - r.half_width) + (v + r.half_width)) / 2)
    return out


def _freeze(value: object) -> object:
    """A hashable form of a model argument (lists and dicts as tuples, each value with its
    type's name: 1 and 1.0 are different calls)."""
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
