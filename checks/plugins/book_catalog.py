"""The book and the catalog: ``--book`` and ``--catalog``, validated once, and one test per claim.

- ``--book=PATH`` (else ``$BANGCHECK_BOOK``; with a space pytest takes the path for a test
  path). Without a book, tests that read it skip with the reason; under ``CI=true`` or when a
  path is given, a missing or wrong book is an error.
- ``--catalog DIR``: a directory of draft ``chNN.toml`` files instead of the packaged catalog,
  as for the ``bangcheck`` command.
- The catalog is read and validated once, as collection starts (under xdist the controller
  does it while the workers start); an invalid catalog stops the run with one line per problem
  (file, claim id, field), a usage error, with or without a book.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from checks.plugins import keys
from reference.book import Book, BookError, book_path, load_book
from reference.catalog import Catalog, CatalogDirectoryError
from reference.schema import CatalogError
from reference.validate import checked_catalog

IN_CI = os.environ.get("CI", "").lower() == "true"


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption(
        "--book", action="store", default=None, help="path of bang-unit1.txt ($BANGCHECK_BOOK)"
    )
    parser.addoption(
        "--catalog",
        action="store",
        default=None,
        type=Path,
        help="a directory of draft chNN.toml catalog files instead of the packaged catalog",
    )


def _load_book(config: pytest.Config) -> Book | None:
    given = config.getoption("--book") or os.environ.get("BANGCHECK_BOOK")
    if not given:
        reason = "no book given: pass --book PATH or set BANGCHECK_BOOK"
        if IN_CI:
            raise pytest.UsageError(f"CI=true but {reason}")
        config.stash[keys.NO_BOOK] = reason
        return None
    try:
        return load_book(book_path(given))
    except BookError as err:
        raise pytest.UsageError(str(err)) from err


def pytest_configure(config: pytest.Config) -> None:
    config.stash[keys.BOOK] = _load_book(config)


@pytest.hookimpl(tryfirst=True)
def pytest_collection(session: pytest.Session) -> None:
    """Read and validate the catalog before anything is collected; an invalid one stops the
    run. Under xdist the controller, which collects nothing itself, does this while its workers
    start, and a problem is reported by it, once, before any worker runs a test."""
    config = session.config
    try:
        config.stash[keys.CATALOG] = checked_catalog(
            config.stash[keys.BOOK], config.getoption("--catalog")
        )
    except CatalogDirectoryError as err:
        raise pytest.UsageError(str(err)) from err
    except CatalogError as err:
        raise pytest.UsageError(f"the catalog is invalid:\n{err}") from err


def catalog_of(config: pytest.Config) -> Catalog:
    """The validated catalog (read as collection starts)."""
    return config.stash[keys.CATALOG]


def pytest_generate_tests(metafunc: pytest.Metafunc) -> None:
    """One test per catalogued claim, its id the claim id."""
    if "claim_id" in metafunc.fixturenames:
        ids = [claim.id for _, claim in catalog_of(metafunc.config).claims()]
        metafunc.parametrize("claim_id", ids, ids=ids)


@pytest.fixture(scope="session")
def book(pytestconfig: pytest.Config) -> Book:
    """The verified book; skips (outside CI) when no book was given."""
    the_book = pytestconfig.stash.get(keys.BOOK, None)
    if the_book is None:
        pytest.skip(pytestconfig.stash.get(keys.NO_BOOK, "no book"))
    return the_book


@pytest.fixture(scope="session")
def catalog(pytestconfig: pytest.Config) -> Catalog:
    """The packaged catalog, validated against the book when there is one."""
    return catalog_of(pytestconfig)
