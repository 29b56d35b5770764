"""Figures of chapter 10, redrawn from the model (see ``reports.figures``)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from mechmodel.series import exp_partial_sum
from reports.figures import figure, value_of

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from reference.evaluation import EvaluatedClaim


@figure(
    "e-series",
    "(10.6)",
    "Partial sums of the e-series (10.5) at r t = 1 against the order o: each term adds "
    "1/o! and the sums close in on e.",
    tuple(f"ch10.e-series.o{o}" for o in range(1, 9)),
)
def _e_series(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    x = value_of(claims, "ch10.e-series.x")
    orders = list(range(0, 11))
    sums = [exp_partial_sum(x, o) for o in orders]
    limit = exp_partial_sum(x, 40)
    ax = fig.add_subplot()
    ax.semilogy(orders, [abs(limit - s) for s in sums], "-o", label="|e - partial sum|")
    ax.set_xlabel("precision order o")
    ax.set_ylabel("error")
    ax.legend(fontsize="small")
