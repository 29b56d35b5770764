"""Mutation run: does the test suite notice when mechmodel, or the judge, is wrong?

Copies the project into a temporary directory (one copy per job), changes one small thing in one
module at a time (swap + and -, * and /, flip a comparison, flip a sign, nudge a constant, drop a
factor 2, swap two returned values), and runs the tests that exercise it against the copy with a
per-mutant timeout. A mutant is killed when the tests fail. Before the sample it checks that the
unmutated copy passes and that a mutant that must be killed is killed (so the tests really import
the copy). ``--only`` retries chosen mutants of the sample, as the run prints them.

``--package mechmodel`` (the default) mutates the reference physics and runs the claim tests, the
input and sensitivity tests and the mutated module's properties. ``--package reference`` mutates
the judge (``JUDGE``: compare, numbers, tokens, calls, modelling, evaluation, evaluated) and runs
``JUDGE_TESTS``; with ``--count 0`` every site is tried, not a sample.

    python benchmarks/mutants.py [--package mechmodel|reference] [--count 150] [--seed 0]
                                 [--timeout 120] [--jobs 2] [--module series]
                                 [--only 'mechmodel/x.py:12 swap Add'] [--book PATH]

Not part of the default test run.
"""

from __future__ import annotations

import argparse
import ast
import os
import queue
import random
import shutil
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterator
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
TREE = ("mechmodel", "reference", "reports", "checks", "conftest.py", "pyproject.toml")
TESTS = (
    "checks/test_claims.py",
    "checks/test_mechmodel_inputs.py",
    "checks/test_sensitivity.py",
)  # and the property module of the mutated mechmodel module
JUDGE = ("compare", "numbers", "tokens", "calls", "modelling", "evaluation", "evaluated")
JUDGE_TESTS = (
    "checks/test_claims.py",
    "checks/test_comparison.py",
    "checks/test_verdict_rules.py",
    "checks/test_tokens.py",
    "checks/test_evaluate_models.py",
    "checks/test_evaluate_inputs.py",
    "checks/test_evaluate_intervals.py",
    "checks/test_evaluate_units.py",
    "checks/test_formulas.py",
    "checks/test_power.py",
    "checks/test_restatements.py",
    "checks/test_integrity.py",
    "checks/test_exclusions.py",
    "checks/test_catalog_errors.py",
    "checks/properties/test_judge.py",
)
SANITY = {
    "mechmodel": "mechmodel/collisions.py:0 swap Add",
    "reference": "reference/compare.py:0 swap Add",
}  # a mutant each run must kill
OPERATOR_SWAPS: dict[type[ast.operator], type[ast.operator]] = {
    ast.Add: ast.Sub, ast.Sub: ast.Add, ast.Mult: ast.Div, ast.Div: ast.Mult,
}  # fmt: skip
COMPARE_SWAPS: dict[type[ast.cmpop], type[ast.cmpop]] = {
    ast.Lt: ast.LtE, ast.LtE: ast.Lt, ast.Gt: ast.GtE, ast.GtE: ast.Gt,
}  # fmt: skip


@dataclass(frozen=True)
class Mutant:
    """One change: the file, the line, what kind, and which site of that kind in the file."""

    path: str
    line: int
    kind: str
    index: int

    def __str__(self) -> str:
        return f"{self.path}:{self.line} {self.kind}"


def _nudgeable(value: object) -> bool:
    """Ints (nudged by +1) and nonzero floats (by 1%): a float 0.0 times 1.01 is no change."""
    return type(value) is int or (type(value) is float and value != 0.0)


def _sites(tree: ast.AST) -> Iterator[tuple[str, ast.AST]]:
    for node in ast.walk(tree):
        if isinstance(node, ast.BinOp) and type(node.op) in OPERATOR_SWAPS:
            yield f"swap {type(node.op).__name__}", node
            for side in (node.left, node.right):
                if isinstance(side, ast.Constant) and side.value == 2:
                    yield "drop factor 2", node
        elif isinstance(node, ast.Compare) and type(node.ops[0]) in COMPARE_SWAPS:
            yield f"flip {type(node.ops[0]).__name__}", node
        elif isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
            yield "drop minus", node
        elif isinstance(node, ast.Constant) and _nudgeable(node.value):
            yield "nudge constant", node
        elif (
            isinstance(node, ast.Return)
            and isinstance(node.value, ast.Tuple)
            and len(node.value.elts) >= 2
        ):
            yield "swap returned values", node


def _mutate(kind: str, node: ast.AST) -> ast.AST:
    if kind.startswith("swap") and isinstance(node, ast.BinOp):
        return ast.BinOp(node.left, OPERATOR_SWAPS[type(node.op)](), node.right)
    if kind == "drop factor 2" and isinstance(node, ast.BinOp):
        left_two = isinstance(node.left, ast.Constant) and node.left.value == 2
        return node.right if left_two else node.left
    if kind.startswith("flip") and isinstance(node, ast.Compare):
        flipped = COMPARE_SWAPS[type(node.ops[0])]()
        return ast.Compare(node.left, [flipped, *node.ops[1:]], node.comparators)
    if kind == "drop minus" and isinstance(node, ast.UnaryOp):
        return node.operand
    if kind == "nudge constant" and isinstance(node, ast.Constant):
        value = node.value
        if isinstance(value, int | float):  # what _nudgeable lets through
            return ast.Constant(value + 1 if isinstance(value, int) else value * 1.01)
    if (
        kind == "swap returned values"
        and isinstance(node, ast.Return)
        and isinstance(node.value, ast.Tuple)
    ):
        elts = list(node.value.elts)
        elts[0], elts[1] = elts[1], elts[0]
        return ast.Return(ast.Tuple(elts, ast.Load()))
    raise ValueError(kind)


# modules whose properties live with the topic they came out of
TOPIC_OF = {"tensor_forms": "collisions", "softcontact": "contact"}


def topic(path: str) -> str:
    """A mutated module's topic, whose properties are ``checks/properties/test_<topic>.py`` and
    ``test_<topic>_*.py`` (``property_modules``): ``mechmodel/series.py`` and
    ``mechmodel/series/sums.py`` are both ``series``; ``TOPIC_OF`` names the exceptions."""
    name = Path(Path(path).parts[1]).stem
    return TOPIC_OF.get(name, name)


def property_modules(root: Path, mutated: str) -> list[Path]:
    """The property modules of a mutated mechmodel module's topic: ``test_<topic>.py`` and,
    where the topic's tests are split like its package, every ``test_<topic>_*.py``."""
    folder = root / "checks" / "properties"
    name = topic(mutated)
    return sorted([*folder.glob(f"test_{name}.py"), *folder.glob(f"test_{name}_*.py")])


def enumerate_mutants(root: Path, package: str = "mechmodel") -> list[Mutant]:
    """Every mutation site of ``package``: all its modules for mechmodel, the judge's for
    reference."""
    paths = sorted((root / package).rglob("*.py"))  # a topic split into a subpackage too
    if package == "reference":
        paths = [root / "reference" / f"{name}.py" for name in JUDGE]
    out = []
    for path in paths:
        if path.name == "__init__.py":
            continue
        tree = ast.parse(path.read_text(encoding="utf-8"))
        counts: dict[str, int] = {}
        for kind, node in _sites(tree):
            index = counts.get(kind, 0)
            counts[kind] = index + 1
            out.append(Mutant(str(path.relative_to(root)), getattr(node, "lineno", 0), kind, index))
    return out


def apply(root: Path, mutant: Mutant, source: str) -> None:
    tree = ast.parse(source)
    nodes = [n for k, n in _sites(tree) if k == mutant.kind]
    target = nodes[mutant.index]
    replacement = _mutate(mutant.kind, target)
    for parent in ast.walk(tree):
        for name, value in ast.iter_fields(parent):
            if value is target:
                setattr(parent, name, replacement)
            elif isinstance(value, list) and any(v is target for v in value):
                setattr(parent, name, [replacement if v is target else v for v in value])
    (root / mutant.path).write_text(ast.unparse(ast.fix_missing_locations(tree)) + "\n")


def run_tests(root: Path, book: str, timeout: float, mutated: str | None = None) -> str:
    """ "killed", "survived" or "timeout": the tests of the copy for the mutated file (a
    mechmodel module: the claim, input and sensitivity tests and its property module; a judge
    module: ``JUDGE_TESTS``); when None, all of them."""
    env = {**os.environ, "CI": "true", "BANGCHECK_BOOK": book, "PYTHONDONTWRITEBYTECODE": "1"}
    if mutated is not None and mutated.startswith("reference/"):
        tests = list(JUDGE_TESTS)
    else:
        tests = list(TESTS)
        if mutated is None:
            tests += ["checks/properties", *JUDGE_TESTS]
        else:
            tests += [str(path.relative_to(root)) for path in property_modules(root, mutated)]
    pytest = [sys.executable, "-m", "pytest", "-x", "-q", "-p", "no:cacheprovider"]
    command = [*pytest, f"--book={book}", *dict.fromkeys(tests)]
    try:
        done = subprocess.run(
            command, cwd=root, env=env, capture_output=True, timeout=timeout, check=False
        )
    except subprocess.TimeoutExpired:
        return "timeout"
    # pytest's usage error: on the unmutated copy a harness problem (a missing test file); under a
    # mutant the suite refusing to start, as it does for a catalog the mutated judge calls
    # invalid or a book it calls wrong: the mutant is noticed, so killed
    if done.returncode == 5 or (done.returncode == 4 and mutated is None):
        raise SystemExit(f"pytest could not run {tests} (exit {done.returncode}): {done.stderr!r}")
    return "survived" if done.returncode == 0 else "killed"


def copy_tree(root: Path) -> None:
    """The project's tree, without caches or report output, into ``root``."""
    for name in TREE:
        source = ROOT / name
        if source.is_dir():
            shutil.copytree(
                source, root / name, ignore=shutil.ignore_patterns("__pycache__", "out")
            )
        else:
            shutil.copy2(source, root / name)


def try_mutant(root: Path, mutant: Mutant, book: str, timeout: float) -> str:
    """Apply ``mutant`` in the copy at ``root``, run its tests, undo it; the outcome."""
    path = root / mutant.path
    original = path.read_text(encoding="utf-8")
    apply(root, mutant, original)
    try:
        return run_tests(root, book, timeout, mutant.path)
    finally:
        path.write_text(original, encoding="utf-8")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--package", choices=sorted(SANITY), default="mechmodel")
    parser.add_argument("--count", type=int, default=150, help="sample size; 0: every site")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--timeout", type=float, default=120)
    parser.add_argument("--module", help="sample the sites of this module only")
    parser.add_argument("--jobs", type=int, default=1, help="mutants tried at once (one copy each)")
    parser.add_argument(
        "--only",
        action="append",
        default=[],
        help='try just this mutant of the sample, as printed: "mechmodel/x.py:12 swap Add"',
    )
    parser.add_argument("--book", default=os.environ.get("BANGCHECK_BOOK"))
    args = parser.parse_args()
    if not args.book:
        sys.exit("give --book PATH or set BANGCHECK_BOOK")
    book = str(Path(args.book).resolve())
    with tempfile.TemporaryDirectory(prefix="bangcheck-mutants-") as tmp:
        roots = [Path(tmp) / f"copy{k}" for k in range(max(args.jobs, 1))]
        for root in roots:
            copy_tree(root)
        root = roots[0]
        if run_tests(root, book, args.timeout) != "survived":
            sys.exit("the unmutated copy fails its tests: fix that first")
        where, kind = SANITY[args.package].split(" ", 1)
        sanity = Mutant(where.split(":")[0], 0, kind, 0)
        if try_mutant(root, sanity, book, args.timeout) != "killed":
            sys.exit("the sanity mutant survived: are the tests importing the copy?")
        mutants = enumerate_mutants(root, args.package)
        if args.module:
            mutants = [m for m in mutants if topic(m.path) == args.module]
        count = len(mutants) if args.count == 0 else min(args.count, len(mutants))
        sample = random.Random(args.seed).sample(mutants, count)
        if args.only:
            sample = [m for m in sample if str(m) in args.only]
            unknown = set(args.only) - {str(m) for m in sample}
            if unknown:
                sys.exit(f"not in the sample: {sorted(unknown)}")
        print(f"{len(mutants)} mutation sites; sample of {len(sample)} (seed {args.seed})")
        free: queue.Queue[Path] = queue.Queue()
        for copy in roots:
            free.put(copy)

        def attempt(mutant: Mutant) -> str:
            copy = free.get()
            try:
                return try_mutant(copy, mutant, book, args.timeout)
            finally:
                free.put(copy)

        tally: dict[str, int] = {}
        survivors = []
        start = time.perf_counter()
        with ThreadPoolExecutor(max_workers=len(roots)) as pool:
            for i, (mutant, outcome) in enumerate(
                zip(sample, pool.map(attempt, sample), strict=True), start=1
            ):
                tally[outcome] = tally.get(outcome, 0) + 1
                if outcome == "survived":
                    survivors.append(mutant)
                print(f"[{i}/{len(sample)}] {outcome:<8} {mutant}", file=sys.stderr)
        killed = tally.get("killed", 0) + tally.get("timeout", 0)
        print(
            f"killed {killed} of {len(sample)} ({100 * killed / len(sample):.1f}%): "
            f"{tally}; {time.perf_counter() - start:.0f} s with {len(roots)} job(s)"
        )
        for mutant in survivors:
            print(f"survived: {mutant}")


if __name__ == "__main__":
    main()
