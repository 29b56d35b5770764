"""The soft-contact collision integrator (chapters 7-8: Figs. 7.5-7.7, 8.1).

Balls on a line (and a floor, if any) interact only while they overlap, with the repulsion
F = k y^n of the overlap y (the contact forces of chapter 7, ``contact``). Newton's equations
are integrated with the 8th-order Dormand-Prince method (DOP853), stopping at every touch and
release, so that the right-hand side is smooth on each piece; between contacts the balls fly
freely and the next touch is found exactly. Results carry their numerical error
(``Estimate``).

- ``collision``: ``soft_collision`` and its result ``SoftCollision``: the inputs, the ladder of
  tolerances, the error estimate, and one run of the integration.
- ``pieces``: one stretch between contact events, integrated by the Fortran DOP853 (each touch
  or release located by Newton's method) or by a ``solve_ivp`` method (``INTEGRATORS``).

``contact`` re-exports ``soft_collision``, ``SoftCollision`` and ``INTEGRATORS``.
"""

from __future__ import annotations

from mechmodel.softcontact.collision import INTEGRATORS, SoftCollision, soft_collision

__all__ = ["INTEGRATORS", "SoftCollision", "soft_collision"]
