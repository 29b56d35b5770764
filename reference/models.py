"""Calling mechmodel for a claim: resolving ``model``, binding ``args``, following ``pick``.

A claim's ``model`` is ``module.function`` inside ``mechmodel``. Its result may be a number, a
sequence or a dataclass; ``pick`` is a path of names and ``[index]`` into it ("velocities[2]",
"bangs[10].v1"); empty for a scalar. A model declares facts about itself with attributes the
evaluator reads through ``mechmodel.typing``: ``@not_monotonic`` (no input interval over a box of
roundings), and an ``Estimate`` result carries its own numerical error.
"""

from __future__ import annotations

import importlib
import inspect
import re
from collections.abc import Callable
from typing import Any

_PICK = re.compile(r"\.?([A-Za-z_]\w*)|\[(-?\d+)\]")


class PickError(ValueError):
    """``pick`` does not lead anywhere in the model's result."""


def resolve(name: str) -> Callable[..., Any]:
    """The mechmodel function called ``module.function``; ``LookupError`` if there is none.

    A module's public functions are those its ``__all__`` lists, or, without one, those
    defined in mechmodel: its own and those it re-exports from the shared layer
    (``fields.line_angle`` from ``numeric``); a name it imports from elsewhere
    (``collisions.dataclass``, ``operators.math``) is not a model."""
    module_name, _, func_name = name.partition(".")
    try:
        module = importlib.import_module(f"mechmodel.{module_name}")
    except ModuleNotFoundError as err:
        raise LookupError(f"no module mechmodel.{module_name}") from err
    func = getattr(module, func_name, None)
    public = getattr(module, "__all__", None)
    if public is not None:
        exported = func_name in public
    else:
        home = getattr(func, "__module__", None) or ""
        exported = home == "mechmodel" or home.startswith("mechmodel.")
    if func is None or not callable(func) or func_name.startswith("_") or not exported:
        raise LookupError(f"mechmodel.{module_name} has no public function {func_name!r}")
    return func


def check_signature(func: Callable[..., Any], names: list[str]) -> str | None:
    """Why keyword arguments ``names`` cannot call ``func``, or None if they can."""
    try:
        inspect.signature(func).bind(**dict.fromkeys(names))
    except TypeError as err:
        return str(err)
    return None


def pick_steps(path: str) -> list[str | int]:
    """The steps of a pick path; ``ValueError`` if it is not names and [index]."""
    steps: list[str | int] = []
    pos = 0
    while pos < len(path):
        m = _PICK.match(path, pos)
        if not m or (pos == 0 and path.startswith(".")):
            raise ValueError(f"cannot read pick path {path!r} at {path[pos:]!r}")
        steps.append(m[1] if m[1] is not None else int(m[2]))
        pos = m.end()
    return steps


def follow(result: Any, path: str) -> Any:
    """The part of ``result`` that ``path`` names."""
    value = result
    for step in pick_steps(path):
        try:
            if isinstance(step, int) or isinstance(value, dict):
                value = value[step]
            else:
                value = getattr(value, step)
        except (AttributeError, IndexError, KeyError, TypeError) as err:
            raise PickError(f"pick {path!r}: no {step!r} in {type(value).__name__}") from err
    return value
