"""Calling a claim's model: its value in the printed unit and its interval over the box of
rounded inputs.

``ModelCalls`` builds a claim's keyword arguments (``reference.calls``), calls its model through
the ``ModelCache`` (once per model and arguments), reads the picked result (an ``Estimate``'s
declared numerical error; a complex number with no imaginary part is real) and divides it by the
unit factor of the printed unit. With rounded inputs (design 3a) it evaluates the model at the
box's corners, or on a grid where the model is not monotonic, and at the box's centre. For a
formula claim (design 2a) it calls the model with sympy symbols. ``reference.evaluation``
judges what it returns.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

import sympy

from mechmodel.typing import Estimate, is_monotonic
from reference.calls import (
    MAX_ROUNDED_INPUTS,
    ModelCache,
    ModelCallError,
    assumed_args,
    box_points,
    build_args,
    centre,
    corners,
    grid_steps,
)
from reference.compare import exact
from reference.models import PickError, follow, resolve
from reference.numbers import Printed
from reference.schema import Claim
from reference.tables import unit_factor

ModelValue = int | float | Fraction | complex  # a model's number, in the printed unit


@dataclass(frozen=True)
class Modelled:
    """What the model said of a claim, in the printed unit: its value, the interval over the
    box of rounded inputs (or why there is none), its declared error, and its value at the
    box's centre."""

    value: ModelValue | None = None
    interval: tuple[Fraction, Fraction] | None = None
    interval_note: str | None = None
    error: Fraction | None = None
    centre: Fraction | None = None


class ModelCalls:
    """The model calls of an evaluation: ``lookup`` gives a referenced claim and its printed
    value, ``is_rounded_input`` whether it is a rounded input (design 3a)."""

    def __init__(
        self,
        cache: ModelCache,
        lookup: Callable[[str], tuple[Claim, Printed]],
        is_rounded_input: Callable[[str], bool],
    ) -> None:
        self.cache = cache
        self.lookup = lookup
        self.is_rounded_input = is_rounded_input

    def call_model(self, claim: Claim) -> Modelled:
        """The model's value in the printed unit, its input interval (or why there is none),
        its declared error and its value at the box's centre."""
        assert claim.model is not None
        args, inputs = build_args(claim.args, self.lookup, self.is_rounded_input)
        assumed, assumed_inputs = assumed_args(claim.assumptions)
        args.update(assumed)
        value, error = self._value_at(claim, args)
        rounded = [i for i in [*inputs, *assumed_inputs] if i.rounded]
        if not rounded:
            return Modelled(value, None, None, error)
        monotonic = claim.monotonic
        if monotonic is None:
            monotonic = is_monotonic(resolve(claim.model))
        if monotonic:
            if len(rounded) > MAX_ROUNDED_INPUTS:
                note = f"{len(rounded)} rounded inputs: too many corners for an interval"
                return Modelled(value, None, note, error)
            points = corners(args, rounded)
        else:
            steps = grid_steps(len(rounded))
            if steps is None:
                note = f"{len(rounded)} rounded inputs of a model not monotonic: no interval"
                return Modelled(value, None, note, error)
            points = box_points(args, rounded, steps)
        reals = [real_part(self._value_at(claim, point)[0]) for point in points]
        middle = real_part(self._value_at(claim, centre(args, rounded))[0])
        return Modelled(value, (min(reals), max(reals)), None, error, middle)

    def _value_at(self, claim: Claim, args: dict[str, Any]) -> tuple[ModelValue, Fraction | None]:
        """The model's picked value at ``args`` in the printed unit, and its declared error."""
        assert claim.model is not None
        raw = self.cache.picked(claim.id, claim.model, args, claim.pick)
        error = None
        if isinstance(raw, Estimate):
            error = raw.error
            raw = raw.value
        factor = unit_factor(claim.unit)
        converted = self._convert(claim, raw, factor)
        return converted, None if error is None else exact(float(error) / factor)

    @staticmethod
    def _convert(claim: Claim, value: Any, factor: float) -> ModelValue:
        """A picked model result as a number in the printed unit (``value`` is whatever the
        model returned: anything that converts to a number is read)."""
        if isinstance(value, bool) or not isinstance(value, int | float | complex | Fraction):
            try:
                value = complex(value) if isinstance(value, complex) else float(value)
            except (TypeError, ValueError) as err:
                raise ModelCallError(
                    claim.id,
                    "pick",
                    f"the model result is a {type(value).__name__}, not a "
                    "number: pick a part of it",
                ) from err
        if isinstance(value, complex) and value.imag == 0:
            value = value.real
        if isinstance(value, float) and not math.isfinite(value):
            raise ModelCallError(claim.id, "model", f"{claim.model} returned {value}")
        if factor == 1:
            return value
        return value / factor

    def formula_model(
        self, claim: Claim, symbols: dict[str, sympy.Symbol]
    ) -> tuple[sympy.Expr | Callable[[Mapping[sympy.Symbol, float]], complex], str | None]:
        """The correct formula: the model called with sympy symbols, if it returns an
        expression; else a function of a point that calls it with numbers."""
        assert claim.model is not None
        func = resolve(claim.model)

        def call(values: Mapping[str, Any]) -> Any:  # symbols or numbers in; a model's result out
            args, _ = build_args(claim.args, self.lookup, self.is_rounded_input, symbols=values)
            return follow(func(**args), claim.pick)

        try:
            result = call(symbols)
        except (TypeError, ValueError, ArithmeticError, AttributeError, PickError):
            result = None
        if isinstance(result, sympy.Basic | int | Fraction):
            expr = sympy.sympify(result)
            return expr, str(expr)

        def at(point: Mapping[sympy.Symbol, float]) -> complex:
            values = {name: point[sym] for name, sym in symbols.items()}
            try:
                return complex(call(values))
            except (TypeError, ValueError, ArithmeticError) as err:
                raise ModelCallError(claim.id, "model", f"{claim.model} raised {err}") from err

        return at, None


def real_part(value: ModelValue) -> Fraction:
    """The exact value of a model number's real part."""
    return exact(value.real if isinstance(value, complex) else value)
