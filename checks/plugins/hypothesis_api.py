"""The two Hypothesis internals the suite relies on, behind one wrapper.

- ``settings_of``: the settings a ``@given`` test runs with (``@settings(...)`` on it, else the
  loaded profile), read from the attribute Hypothesis puts on the test function
  (``_hypothesis_internal_use_settings``); the example floor of ``speed.py`` reads it.
- ``collecting``: receive the run statistics Hypothesis reports once per test through
  ``hypothesis.statistics.collector`` (what its pytest plugin prints with
  ``--hypothesis-show-statistics``); the invariant recorder reads examples and target scores
  from it.

Neither is public API. ``checks/test_hypothesis_api.py`` exercises both on a tiny property, so
that a Hypothesis upgrade that changes them fails there, with ``HypothesisAPIChangedError`` naming
what moved, instead of silently recording nothing or letting a property below the floor pass.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

from hypothesis import settings

_SETTINGS_ATTRIBUTE = "_hypothesis_internal_use_settings"


class HypothesisAPIChangedError(RuntimeError):
    """A Hypothesis internal the suite relies on is not where it was."""


def settings_of(test: object) -> settings | None:
    """The settings of a ``@given`` test; None for anything else (a function Hypothesis did not
    wrap, or an item's missing function)."""
    if not getattr(test, "is_hypothesis_test", False):
        return None
    found = getattr(test, _SETTINGS_ATTRIBUTE, None)
    if not isinstance(found, settings):
        raise HypothesisAPIChangedError(
            f"a @given test no longer carries its settings as {_SETTINGS_ATTRIBUTE}: "
            "update checks/plugins/hypothesis_api.py for this Hypothesis version"
        )
    return found


def _collector() -> Any:
    try:
        from hypothesis.statistics import collector
    except ImportError as err:  # pragma: no cover - only on an incompatible upgrade
        raise HypothesisAPIChangedError(
            "hypothesis.statistics.collector is gone: update checks/plugins/hypothesis_api.py"
        ) from err
    if not (hasattr(collector, "value") and hasattr(collector, "with_value")):
        raise HypothesisAPIChangedError(
            "hypothesis.statistics.collector has no value/with_value: "
            "update checks/plugins/hypothesis_api.py"
        )
    return collector


@contextmanager
def collecting(observer: Callable[[dict[str, Any]], None]) -> Iterator[None]:
    """Within the block, each finished ``@given`` test hands its statistics dictionary to
    ``observer``, and then to whoever listened before (such as Hypothesis's own plugin)."""
    collector = _collector()
    previous = collector.value

    def both(stats: dict[str, Any]) -> None:
        observer(stats)
        if previous is not None:
            previous(stats)

    with collector.with_value(both):
        yield
