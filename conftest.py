"""pytest driver for bangcheck: an index of the suite's plugins (``checks/plugins/``).

- ``book_catalog``: ``--book PATH`` (else ``$BANGCHECK_BOOK``; without one, tests that read the
  book skip with the reason, except under ``CI=true``) and ``--catalog DIR``; the catalog read
  and validated once as collection starts (an invalid one is a usage error, one line per
  problem); one test per claim; the ``book`` and ``catalog`` fixtures.
- ``caches``: the evaluation, the whole book's scan and one report, computed once per session
  (``evaluation``, ``whole_scan``, ``report_dir``); the report built in the background of a
  serial run.
- ``speed``: Hypothesis profiles ``ci`` (the default when ``CI=true``), ``dev`` and
  ``thorough`` (``--hypothesis-profile``) with a floor of 50 examples per property, and the
  garbage collector tuned for the run.
- ``summary``: the verdict counts at the end of the terminal summary.
- ``invariants``: what the property suite checked, recorded in ``.bangcheck/properties.json`` at
  the rootdir for the report.
- ``hypothesis_api`` (not a plugin): the two Hypothesis internals the suite relies on, behind
  one wrapper that ``checks/test_hypothesis_api.py`` keeps honest across upgrades.
"""

from __future__ import annotations

import pytest

from checks.plugins.invariants import InvariantRecorder

pytest_plugins = [
    "checks.plugins.book_catalog",  # listed before the plugins that import it
    "checks.plugins.speed",
    "checks.plugins.caches",
    "checks.plugins.summary",
]


def pytest_configure(config: pytest.Config) -> None:
    config.pluginmanager.register(InvariantRecorder(config), "bangcheck-invariants")
