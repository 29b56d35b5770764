"""Tolerances shared by the property modules of mechmodel.lagrange (test_lagrange_*.py)."""

from __future__ import annotations

REL = 1e-12
FLOOR = REL * 1e-300  # subnormal magnitudes carry no relative precision: an absolute floor
