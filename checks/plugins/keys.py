"""What the plugins keep on ``config.stash`` for the session, and share."""

from __future__ import annotations

from collections import Counter

import pytest

from reference.book import Book
from reference.catalog import Catalog
from reference.evaluation import Evaluation
from reference.scan import ScanResult
from reports.background import BackgroundReport

BOOK = pytest.StashKey[Book | None]()
NO_BOOK = pytest.StashKey[str]()  # why there is no book, for the skips
CATALOG = pytest.StashKey[Catalog]()
EVALUATION = pytest.StashKey[Evaluation]()
SCAN = pytest.StashKey[ScanResult]()
REPORT = pytest.StashKey[BackgroundReport]()
SELECTED = pytest.StashKey[set[str]]()  # the claims whose tests this session runs
WORKER_VERDICTS = pytest.StashKey[Counter[str]]()
WORKER_ERRORS = pytest.StashKey[int | None]()
