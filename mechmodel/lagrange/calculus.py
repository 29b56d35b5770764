"""Calculus on Laurent polynomials (``mechmodel.algebra.Laurent``) of angles and of time.

The derivative in an angle of a polynomial in its cosine and sine (cos' = -sin, sin' = cos,
reduced with sin^2 = 1 - cos^2), used for dS/d(alpha) of the projectile family (12.16b) and the
polar Jacobian (12.26); and the total time derivative by the chain rule (12.7), used for the
polar velocities and the Coriolis term (12.33). Dimensionless: the variables carry the caller's
units.
"""

from __future__ import annotations

from collections.abc import Mapping

from mechmodel.algebra import Laurent


def angle_derivative(p: Laurent, cos: str, sin: str) -> Laurent:
    """d/d(angle) of a polynomial in cos and sin of that angle (chain rule: cos' = -sin,
    sin' = cos), reduced with sin^2 = 1 - cos^2."""
    d = p.diff(cos) * (-Laurent.var(sin)) + p.diff(sin) * Laurent.var(cos)
    return d.reduce_trig(cos, sin)


def time_derivative(p: Laurent, rates: Mapping[str, Laurent]) -> Laurent:
    """Total time derivative sum_k (dP/dx_k) x_k' (the chain rule of (12.7)) where ``rates``
    gives each variable's time derivative as a polynomial."""
    out = Laurent()
    for name, rate in rates.items():
        out = out + p.diff(name) * rate
    return out
