"""Speed without hollowing the tests out: Hypothesis profiles with a floor on examples, and a
garbage collector tuned for the run.

- Hypothesis profiles ``ci`` (the default when ``CI=true``), ``dev`` (the default otherwise) and
  ``thorough``; choose with ``--hypothesis-profile``. No property may ask for fewer than
  ``MIN_EXAMPLES`` (a usage error names it).
- The property tests allocate millions of short-lived objects (Hypothesis's draws): with
  CPython's default thresholds (700, 10, 10) the collector ran 4,600 times in a serial run,
  2.2 s, most of it full collections re-scanning what lives for the whole session. Rarer young
  collections, and what lives for the whole session frozen out of the collector's reach once
  collected and once evaluated (``freeze_long_lived``), cut that to about 0.9 s.
"""

from __future__ import annotations

import gc

import pytest
from hypothesis import settings

from checks.plugins.book_catalog import IN_CI
from checks.plugins.hypothesis_api import settings_of

MIN_EXAMPLES = 50  # the ci profile's floor: speed never hollows a property out
GC_THRESHOLDS = (20_000, 20, 10)

# ci: derandomized and without the example database, whose reads and writes cost more than
# the examples of most properties
settings.register_profile(
    "ci", derandomize=True, deadline=None, max_examples=MIN_EXAMPLES, database=None
)
settings.register_profile("dev", deadline=None, max_examples=MIN_EXAMPLES)
settings.register_profile("thorough", deadline=None, max_examples=MIN_EXAMPLES * 10)
settings.load_profile("ci" if IN_CI else "dev")


def freeze_long_lived() -> None:
    """Move what lives for the whole session (book, catalog, items, evaluation) out of the
    garbage collector's reach, so that no full collection scans it again."""
    gc.collect()
    gc.freeze()


def pytest_configure(config: pytest.Config) -> None:
    del config
    gc.set_threshold(*GC_THRESHOLDS)


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """The floor on examples: no property may ask for fewer than ``MIN_EXAMPLES``."""
    del config
    low = []
    for item in items:
        use = settings_of(getattr(item, "obj", None))
        marked = item.get_closest_marker("properties") is not None
        if marked and use is not None and use.max_examples < MIN_EXAMPLES:
            low.append(f"{item.nodeid}: max_examples={use.max_examples}")
    if low:
        raise pytest.UsageError(
            f"properties below the floor of {MIN_EXAMPLES} examples:\n" + "\n".join(low)
        )
