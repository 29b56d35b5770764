"""The property suite's one closeness check: its tolerance and what a failure says."""

from __future__ import annotations

from fractions import Fraction

import mpmath
import pytest

from checks.properties.closeness import assert_close, largest, magnitude


def test_the_default_scale_is_the_magnitudes_involved() -> None:
    assert_close(1.0, 1.0 + 1e-12)  # within 1e-12 * (1 + 1)
    with pytest.raises(AssertionError):
        assert_close(1.0, 1.0 + 3e-12)


def test_a_given_scale_replaces_the_magnitudes() -> None:
    assert_close(0.0, 1e-13, scale=1.0)
    with pytest.raises(AssertionError):
        assert_close(0.0, 1e-13, scale=0.01)
    assert_close(1e-300, 0.0, scale=0.0, abs=1e-300)  # the absolute floor alone


def test_rel_zero_makes_abs_the_whole_tolerance() -> None:
    assert_close(5.0, 5.5, rel=0, abs=0.5)
    with pytest.raises(AssertionError):
        assert_close(5.0, 5.5, rel=0, abs=0.4)


def test_exact_and_mpmath_numbers_and_nan() -> None:
    assert_close(Fraction(1, 3), Fraction(1, 3), rel=0)
    assert_close(mpmath.mpf(2), 2.0)
    with pytest.raises(AssertionError):
        assert_close(float("nan"), 1.0, rel=0, abs=1e9)


def test_sequences_compare_entry_by_entry_and_name_the_entry() -> None:
    assert_close(((1.0, 0.0), (0.0, 1.0)), ((1.0, 1e-13), (0.0, 1.0)), scale=1.0)
    with pytest.raises(AssertionError, match=r"at \[1\]\[0\]"):
        assert_close(((1.0, 0.0), (0.0, 1.0)), ((1.0, 0.0), (1e-6, 1.0)), scale=1.0)
    with pytest.raises(AssertionError, match="different shapes"):
        assert_close((1.0, 2.0), (1.0, 2.0, 3.0))


def test_a_failure_reports_both_values_the_difference_and_the_tolerance() -> None:
    with pytest.raises(AssertionError) as failure:
        assert_close(1.5, 1.0, rel=0.1, abs=0.01, scale=2.0)
    message = str(failure.value)
    for part in ("actual 1.5", "expected 1.0", "difference 0.5", "tolerance 0.21", "scale 2.0"):
        assert part in message


def test_magnitude_and_largest() -> None:
    assert magnitude(-2, 3, (1, -5)) == 10  # a sequence counts by its largest entry
    assert largest(((1, -7), (2, 3)), (4,)) == 7
