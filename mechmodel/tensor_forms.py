"""Tensor forms of momentum and energy for n bodies on a line ((3.9)-(3.14), chapter 3).

The inertia matrix M = diag(m_1, ..., m_n) of (3.9a) turns velocity vectors into momenta: the
total momentum is V_COM.M.V and the kinetic energy V.M.V/2. A collision's energies split into
these forms: KE = V_IN.M.V_IN/2, the cross term V_FIN.M.V_IN, and the crunch energy KE - IE
(3.11)-(3.14); the energy ellipse is the form x^2/a^2 + y^2/b^2 = 1 (3.15). Units: masses and
velocities in whatever units the inputs carry (the book's scaled ones or SI); exact for
``Fraction`` inputs. ``collisions.collision_tensor_forms`` builds these for a two-body collision.
"""

from __future__ import annotations

from dataclasses import dataclass

from mechmodel import inputs
from mechmodel.typing import Matrix, Real, Vector


def inertia_tensor(masses: Vector) -> tuple[tuple[Real, ...], ...]:
    """The diagonal inertia matrix M of (3.9a): M_jj = m_j, M_jk = 0 for j != k."""
    for i, m in enumerate(masses):
        inputs.mass(m, f"masses[{i}]")
    return tuple(
        tuple(m if j == k else 0 * m for k in range(len(masses))) for j, m in enumerate(masses)
    )


def inertia_coefficient_count(n: int) -> int:
    """How many inertia coefficients M_jk a full inertia matrix of dimension ``n`` >= 1 holds
    (the upgrade of (3.9a) to (3.9b)): counted over the rows of the n x n ``inertia_tensor``."""
    size = inputs.count(n, "n", minimum=1)
    return sum(len(row) for row in inertia_tensor([1] * size))


def _check_matrix(inertia: Matrix, n: int) -> None:
    if len(inertia) != n or any(len(row) != n for row in inertia):
        raise ValueError(f"the inertia matrix must be {n} x {n} to match the velocity vectors")
    for j, row in enumerate(inertia):
        for k, x in enumerate(row):
            inputs.real(x, f"inertia[{j}][{k}]")


def tensor_form(u: Vector, inertia: Matrix, v: Vector) -> Real:
    """The tensor form u . M . v = sum_jk u_j M_jk v_k of (3.11a)-(3.12b).

    V_COM . M . V_IN is V_COM P_Total (3.11a); V . M . V / 2 the kinetic energy (3.12c).
    """
    if len(u) != len(v) or not u:
        raise ValueError("u and v must be vectors of one length")
    _check_matrix(inertia, len(u))
    for i, (a, b) in enumerate(zip(u, v, strict=True)):
        inputs.real(a, f"u[{i}]")
        inputs.real(b, f"v[{i}]")
    return sum(u[j] * inertia[j][k] * v[k] for j in range(len(u)) for k in range(len(v)))


def ellipse_tensor_form(x: Real, y: Real, a: Real, b: Real) -> Real:
    """The tensor form r . M . r of (3.15) for r = (x, y) and the ellipse tensor
    M = diag(1/a^2, 1/b^2) of radii a, b > 0: 1 on the ellipse, as (3.7b)."""
    inputs.positive(a, "a")
    inputs.positive(b, "b")
    zero = 0 * a
    tensor = ((1 / (a * a), zero), (zero, 1 / (b * b)))
    return tensor_form((x, y), tensor, (x, y))


@dataclass(frozen=True)
class TensorForms:
    """The quadratic forms of (3.11)-(3.14) for inertia M and velocities IN, FIN and COM.

    With V_COM = (V_IN + V_FIN)/2 (the T-symmetry (3.4)) and a transpose-symmetric M,
    ``ke_from_com`` = V_COM.P - V_FIN.M.V_IN/2 equals ``ke_in`` (3.12a); the Ka-runch energy
    V_COM.P/2 splits as ``quarter_in + quarter_cross`` (3.13) and the crunch energy KE - IE is
    ``quarter_in - quarter_cross`` (3.14).
    """

    inertia: tuple[tuple[Real, ...], ...]
    v_in: tuple[Real, ...]
    v_fin: tuple[Real, ...]
    v_com: tuple[Real, ...]

    def _form(self, u: Vector, v: Vector) -> Real:
        return tensor_form(u, self.inertia, v)

    @property
    def com_momentum(self) -> Real:
        """V_COM . M . V_IN = V_COM P_Total (3.11a, b)."""
        return self._form(self.v_com, self.v_in)

    @property
    def com_momentum_fin(self) -> Real:
        """V_COM . M . V_FIN, equal to ``com_momentum`` when momentum is conserved (3.11a)."""
        return self._form(self.v_com, self.v_fin)

    @property
    def half_com_momentum(self) -> Real:
        """V_COM P_Total / 2, the Ka-runch energy IE of (3.13)."""
        return self.com_momentum / 2

    @property
    def cross(self) -> Real:
        """V_FIN . M . V_IN (3.12b)."""
        return self._form(self.v_fin, self.v_in)

    @property
    def cross_transposed(self) -> Real:
        """V_IN . M . V_FIN, equal to ``cross`` for a transpose-symmetric M (3.12b)."""
        return self._form(self.v_in, self.v_fin)

    @property
    def half_cross(self) -> Real:
        """V_FIN . M . V_IN / 2, subtracted in (3.12c)."""
        return self.cross / 2

    @property
    def ke_from_com(self) -> Real:
        """V_COM P_Total - V_FIN . M . V_IN / 2, line 1 of (3.12a, c)."""
        return self.com_momentum - self.half_cross

    @property
    def ke_in(self) -> Real:
        """Kinetic energy V_IN . M . V_IN / 2 (3.12c)."""
        return self._form(self.v_in, self.v_in) / 2

    @property
    def ke_fin(self) -> Real:
        """Kinetic energy V_FIN . M . V_FIN / 2 (3.12c)."""
        return self._form(self.v_fin, self.v_fin) / 2

    @property
    def ie(self) -> Real:
        """Kinetic energy at the COM point, V_COM . M . V_COM / 2 (the IE of (3.13))."""
        return self._form(self.v_com, self.v_com) / 2

    @property
    def quarter_in(self) -> Real:
        """V_IN . M . V_IN / 4 (3.13)."""
        return self._form(self.v_in, self.v_in) / 4

    @property
    def quarter_cross(self) -> Real:
        """V_FIN . M . V_IN / 4 (3.13)."""
        return self.cross / 4

    @property
    def crunch(self) -> Real:
        """KE - IE = V_IN.M.V_IN/4 - V_FIN.M.V_IN/4, the crunch energy (3.14)."""
        return self.quarter_in - self.quarter_cross


def tensor_energy_forms(
    inertia: Matrix,
    v_in: Vector,
    v_fin: Vector,
    v_com: Vector,
) -> TensorForms:
    """The tensor forms (3.11)-(3.14) of inertia matrix M (any n x n) and velocity vectors
    V_IN, V_FIN, V_COM (the book's (60, 10), (40, 90), (50, 50) for Fig. 3.1)."""
    n = len(v_in)
    if not n or len(v_fin) != n or len(v_com) != n:
        raise ValueError("V_IN, V_FIN and V_COM must be vectors of one length")
    _check_matrix(inertia, n)
    for name, vec in (("v_in", v_in), ("v_fin", v_fin), ("v_com", v_com)):
        for i, x in enumerate(vec):
            inputs.real(x, f"{name}[{i}]")
    return TensorForms(
        tuple(tuple(row) for row in inertia), tuple(v_in), tuple(v_fin), tuple(v_com)
    )
