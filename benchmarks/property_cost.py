"""Where the property suite's time goes: the tests' own bodies (the models and the assertions)
against Hypothesis's engine and the strategies that draw the inputs.

Runs ``checks/properties`` once, serially, under the ci profile (the default run's settings),
wrapping each property's inner test to time its bodies. The remainder of each test's call time
is Hypothesis's: generating and recording every example, seeding and restoring the random
generators around it, and our strategies' draws. Prints the totals, the cost per example, and
the properties that cost most in each part.

Run from the project root:  python benchmarks/property_cost.py [--book PATH] [--top 12]
Not collected by the default pytest run (testpaths = checks).
"""

from __future__ import annotations

import argparse
import functools
import os
import sys
import time
from collections import Counter, defaultdict
from collections.abc import Callable, Generator
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parents[1]


class PropertyClock:
    """A pytest plugin: per property, the call time and the time inside its bodies."""

    def __init__(self) -> None:
        self.call: defaultdict[str, float] = defaultdict(float)  # seconds per property
        self.body: defaultdict[str, float] = defaultdict(float)
        self.examples: Counter[str] = Counter()

    def _timed(self, name: str, inner: Callable[..., Any]) -> Callable[..., Any]:
        @functools.wraps(inner)
        def timed(*args: Any, **kwargs: Any) -> Any:
            start = time.perf_counter()
            try:
                return inner(*args, **kwargs)
            finally:
                self.body[name] += time.perf_counter() - start
                self.examples[name] += 1

        return timed

    def pytest_collection_modifyitems(self, items: list[pytest.Item]) -> None:
        wrapped: set[int] = set()
        for item in items:
            handle = getattr(getattr(item, "obj", None), "hypothesis", None)
            if handle is not None and id(handle) not in wrapped:
                wrapped.add(id(handle))
                handle.inner_test = self._timed(_name(item), handle.inner_test)

    @pytest.hookimpl(wrapper=True)
    def pytest_runtest_call(self, item: pytest.Item) -> Generator[None]:
        start = time.perf_counter()
        try:
            return (yield)
        finally:
            if getattr(getattr(item, "obj", None), "hypothesis", None) is not None:
                self.call[_name(item)] += time.perf_counter() - start


def _name(item: pytest.Item) -> str:
    return f"{Path(str(item.path)).stem}::{item.obj.__name__}"  # type: ignore[attr-defined]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--book", default=os.environ.get("BANGCHECK_BOOK"))
    parser.add_argument("--top", type=int, default=12)
    args = parser.parse_args()
    if not args.book:
        sys.exit("give --book PATH or set BANGCHECK_BOOK")
    os.environ["CI"] = "true"  # the ci profile, as in the default run
    os.chdir(ROOT)
    clock = PropertyClock()
    code = pytest.main(
        ["-q", "-n", "0", "-p", "no:cacheprovider", f"--book={args.book}", "checks/properties"],
        plugins=[clock],
    )
    call, body = sum(clock.call.values()), sum(clock.body.values())
    examples = sum(clock.examples.values())
    engine = call - body
    print(f"\n{len(clock.call)} properties, {examples} examples (pytest exit code {code})")
    print(f"call time {call:.2f} s: bodies {body:.2f} s, Hypothesis and strategies {engine:.2f} s")
    per = 1e3 / examples
    print(f"per example: bodies {per * body:.2f} ms, the rest {per * engine:.2f} ms")
    for title, cost in (
        ("Hypothesis and strategies", lambda k: clock.call[k] - clock.body[k]),
        ("bodies", lambda k: clock.body[k]),
    ):
        print(f"\ncostliest in {title} (s, examples):")
        for name in sorted(clock.call, key=cost, reverse=True)[: args.top]:
            print(f"  {cost(name):6.3f}  {clock.examples[name]:4d}  {name}")
    sys.exit(code)


if __name__ == "__main__":
    main()
