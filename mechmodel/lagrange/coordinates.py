"""Generalized coordinates in general: (12.18)-(12.25), (12.31), (12.36)-(12.37), Fig. 12.10.

The differential between two labelled coordinate lines (Fig. 12.10); the potential F(v) whose
gradient is M.v, the step from (12.24) to Lagrange's form (12.25a); the kinetic energy
M q'.g.q'/2 of a metric g through a Cholesky factor (12.31); the Hamiltonian H = p q' - L of one
coordinate at a rate or at a momentum (12.36a), (12.37); and the slope and extremum of the
quadratic S(q) = q^2 + b q (line 15831). SI units or the book's scaled units.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction

from mechmodel import inputs
from mechmodel.algebra import Laurent
from mechmodel.ellipse import kinetic_energy
from mechmodel.typing import Matrix, Real, Symbolic, Vector


def coordinate_differential(start: Real, end: Real) -> Real:
    """The differential dq = q_end - q_start between two labelled coordinate lines of a cell
    (Fig. 12.10: the cell between q1 = 100 and q1 = 101 has dq1 = 1). Exact for ``int``."""
    inputs.real(start, "start")
    inputs.real(end, "end")
    return end - start


@dataclass(frozen=True)
class QuadraticExtremum:
    """For S(q) = q^2 + b q (line 15831): dS/dq = slope q + constant, zero at ``point``."""

    slope: Fraction
    constant: Fraction
    point: Fraction


def quadratic_extremum(linear_coefficient: Real) -> QuadraticExtremum:
    """dS/dq of S = q^2 + b q by the power rule, and the q where it vanishes (line 15832:
    S = q^2 - 4q gives dS/dq = 2q - 4, zero at q = 2). Exact."""
    b = Fraction(inputs.real(linear_coefficient, "linear_coefficient"))
    q = Laurent.var("q")
    derivative = (q**2 + b * q).diff("q")
    slope, constant = (
        Laurent.rational(derivative.part("q", 1).only_coefficient()),
        Laurent.rational(derivative.part("q", 0).value()),
    )
    return QuadraticExtremum(slope=slope, constant=constant, point=-constant / slope)


def gradient_potential(
    matrix: Sequence[Sequence[Symbolic]], vector: Sequence[Symbolic]
) -> Symbolic:
    """The scalar F(v) whose gradient dF/dv^j is M_ij v^i, with F(0) = 0, for a symmetric
    matrix M (line 15022): by the line integral F(v) = integral_0^1 (M.(t v)).v dt, done
    exactly in t. Its q-derivative dF/dq is M_ij v^i dv^j/dq, the step from (12.24) to
    Lagrange's form (12.25a). Exact for ``int`` and ``Fraction``; ``ValueError`` for a matrix
    that is not square and symmetric (then no such F exists).
    """
    n = len(vector)
    if len(matrix) != n or any(len(row) != n for row in matrix):
        raise ValueError("need an n x n matrix and an n-vector")
    for i in range(n):
        for j in range(i):
            if matrix[i][j] != matrix[j][i]:
                raise ValueError("the field M.v has a potential only for a symmetric M")
    t = Laurent.var("t")
    names = {f"v{i}": vector[i] for i in range(n)}
    names.update({f"m{i}_{j}": matrix[i][j] for i in range(n) for j in range(n)})
    field_dot_v = sum(
        (
            Laurent.var(f"m{i}_{j}") * t * Laurent.var(f"v{i}") * Laurent.var(f"v{j}")
            for i in range(n)
            for j in range(n)
        ),
        Laurent(),
    )
    form = field_dot_v.integrate("t").substitute("t", 1)
    total: Symbolic = 0
    for key, c in form.terms.items():  # the Fraction times the values: exact where they are
        term: Symbolic = Laurent.rational(c)
        for name, e in key:
            term = term * names[name] ** e
        total = total + term
    return total


def metric_kinetic_energy(mass: Real, metric: Matrix, rates: Vector) -> float:
    """Kinetic energy of one particle moving at the generalized velocities q' in coordinates
    of covariant metric g (12.31), J or scaled: any Jacobian J with J^T J = g gives the same
    Cartesian speed, so take the Cholesky factor of g (upper triangular, positive diagonal),
    form the Cartesian velocity v = J q' (12.19) and T = M v.v/2 (12.23). ``ValueError`` for a
    metric that is not symmetric and positive definite. Floats."""
    inputs.mass(mass)
    n = len(rates)
    if len(metric) != n or any(len(row) != n for row in metric):
        raise ValueError("need an n x n metric and n rates")
    g = [[float(inputs.real(x, "metric")) for x in row] for row in metric]
    q = [float(inputs.real(x, "rate")) for x in rates]
    if any(g[i][j] != g[j][i] for i in range(n) for j in range(i)):
        raise ValueError("a metric is symmetric")
    factor = [[0.0] * n for _ in range(n)]  # factor[i][j], i <= j: g = factor^T factor
    for i in range(n):
        pivot = g[i][i] - sum(factor[k][i] ** 2 for k in range(i))
        if pivot <= 0:
            raise ValueError("a metric is positive definite")
        diagonal = factor[i][i] = math.sqrt(pivot)
        for j in range(i + 1, n):
            rest = g[i][j] - sum(factor[k][i] * factor[k][j] for k in range(i))
            factor[i][j] = rest / diagonal
    velocity = [sum(factor[i][j] * q[j] for j in range(n)) for i in range(n)]
    return float(kinetic_energy([mass] * n, velocity))  # the velocity is float


@dataclass(frozen=True)
class CoordinateHamiltonian:
    """H = p q' - L (12.36a) of L = M g q'^2/2 - U in one generalized coordinate of metric g,
    with the rate q' and the momentum p = dL/dq' (12.25e) that go with it."""

    rate: Real
    momentum: Real
    hamiltonian: Real


def _coordinate_lagrangian() -> Laurent:
    """L = T - U with T = M g q'^2/2 (12.31) for one coordinate, in M, g, qd = q' and U."""
    m, g, qd, u = (Laurent.var(n) for n in ("M", "g", "qd", "U"))
    return m * g * qd**2 / 2 - u


def hamiltonian_of_rate(
    mass: Real, metric: Real, rate: Real, potential: Real
) -> CoordinateHamiltonian:
    """H = p q' - L (12.36a) at the rate q' (12.37a-b): p = dL/dq' by differentiating L
    exactly, then the Legendre form evaluated. Exact for ``int`` and ``Fraction``."""
    inputs.mass(mass)
    inputs.positive(metric, "metric")
    inputs.real(rate, "rate")
    inputs.real(potential, "potential")
    lag = _coordinate_lagrangian()
    momentum = lag.diff("qd")
    values = {"M": mass, "g": metric, "qd": rate, "U": potential}
    p = momentum.evaluate_real(values)
    return CoordinateHamiltonian(
        rate=rate, momentum=p, hamiltonian=p * rate - lag.evaluate_real(values)
    )


def hamiltonian_of_momentum(
    mass: Real, inverse_metric: Real, momentum: Real, potential: Real
) -> CoordinateHamiltonian:
    """H = p q' - L (12.37c) at the momentum p, for the coordinate whose contravariant metric
    is g^11 = ``inverse_metric`` (so g = 1/g^11): p = dL/dq' is linear in q', so q' is p over
    its slope d p/d q'; then H = p q' - L(q'). Exact for ``int`` and ``Fraction``."""
    inputs.mass(mass)
    inputs.positive(inverse_metric, "inverse_metric")
    inputs.real(momentum, "momentum")
    inputs.real(potential, "potential")
    metric = 1 / (Fraction(inverse_metric) if isinstance(inverse_metric, int) else inverse_metric)
    lag = _coordinate_lagrangian()
    p_of_rate = lag.diff("qd")
    if p_of_rate.part("qd", 0).terms:
        raise ValueError("p = dL/dq' has a part free of q'")
    values = {"M": mass, "g": metric, "U": potential}
    rate = momentum / p_of_rate.diff("qd").evaluate_real(values)
    values["qd"] = rate
    return CoordinateHamiltonian(
        rate=rate, momentum=momentum, hamiltonian=momentum * rate - lag.evaluate_real(values)
    )


def quadratic_function_slope(point: Real, linear_coefficient: Real) -> Real:
    """dS/dq at q of S(q) = q^2 + b q (line 15832: S = q^2 - 4q), by the power rule on the
    exact polynomial, evaluated at ``point``. Exact for ``int`` and ``Fraction``."""
    b = Fraction(inputs.real(linear_coefficient, "linear_coefficient"))
    inputs.real(point, "point")
    q = Laurent.var("q")
    return (q**2 + b * q).diff("q").evaluate_real({"q": point})
