"""The check of an ellipse's semi-axes a, b > 0 shared by the oscillator modules (chapter 11)."""

from __future__ import annotations

from mechmodel import inputs
from mechmodel.typing import Real


def check_semi_axes(a: Real, b: Real) -> None:
    """``ValueError`` unless the semi-axes a and b are positive numbers."""
    inputs.positive(a, "a")
    inputs.positive(b, "b")
