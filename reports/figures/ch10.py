"""Figures of chapter 10, redrawn from the model (see ``reports.figures``)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from mechmodel.series import (
    binomial_gaussian,
    compound_growth,
    euler_number,
    exp_partial_sum,
    exp_remainder_bound,
    exp_series_term,
    pascal_triangle,
)
from reports.figures import figure, value_of

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from reference.evaluation import EvaluatedClaim


@figure(
    "e-series",
    "Eq. (10.6)",
    (
        "Errors of the partial sums of the e-series (10.5) at rt = 1 against the order o, on a "
        "log scale: the sums close in on e, always within Lagrange's remainder bound e/(o+1)!, "
        "while the next term 1/(o+1)! alone falls just short of the error. Crosses: the book's "
        "printed sums."
    ),
    tuple(f"ch10.e-series.o{o}" for o in range(1, 9)),
)
def _e_series(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    x = value_of(claims, "ch10.e-series.x")
    orders = list(range(0, 13))
    limit = float(euler_number()) if x == 1 else exp_partial_sum(x, 60)
    errors = [abs(limit - exp_partial_sum(x, o)) for o in orders]
    bounds = [float(exp_remainder_bound(x, o)) for o in orders]
    next_terms = [abs(exp_series_term(x, o + 1)) for o in orders]
    fig.set_size_inches(7.6, 4.6)
    fig.set_layout_engine("constrained")
    ax = fig.add_subplot()
    ax.semilogy(orders, errors, "-o", label="$|e - $ partial sum$|$")
    ax.semilogy(orders, bounds, "--", color="C3", label="remainder bound $|x|^{o+1}e^x/(o+1)!$")
    ax.semilogy(orders, next_terms, ":", color="0.4", label="next term $x^{o+1}/(o+1)!$")
    printed = list(range(1, 9))
    ax.semilogy(
        printed,
        [abs(limit - value_of(claims, f"ch10.e-series.o{o}")) for o in printed],
        "x",
        color="k",
        label="book's (10.6), as printed",
    )
    ax.set_xlabel("precision order $o$")
    ax.set_ylabel("error (dimensionless)")
    ax.legend(fontsize="small")


@figure(
    "pascal-gauss",
    "Table 1 and the Gauss-binomial plot of Ch. 10",
    (
        "Row n = 10 of Pascal's triangle over its pinnacle B₅,₅ = 252 (bars: Table 1's numbers;"
        " dots: the model's binomials) against the Gauss curve exp(−x²/5) the text compares it "
        "with, x = p − 5."
    ),
    (*(f"ch10.pascal.B10-{k}" for k in range(11)), "ch10.binomial.gauss.coefficient"),
)
def _pascal_gauss(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    n = int(value_of(claims, "ch10.binomial.coins.tosses"))
    row = pascal_triangle(n)[n]
    peak = row[n // 2]
    xs = [k - n // 2 for k in range(n + 1)]
    printed = [value_of(claims, f"ch10.pascal.B10-{k}") / peak for k in range(n + 1)]
    fig.set_size_inches(7.6, 4.4)
    fig.set_layout_engine("constrained")
    ax = fig.add_subplot()
    ax.bar(xs, printed, width=0.6, color="C0", alpha=0.6, label="Table 1, row $n = 10$, over 252")
    fine = [j / 20 for j in range(-n // 2 * 20, n // 2 * 20 + 1)]
    coefficient = value_of(claims, "ch10.binomial.gauss.coefficient")
    ax.plot(
        fine,
        [math.exp(-coefficient * x * x) for x in fine],
        color="C3",
        label="$e^{-x^2/5}$, the book's Gauss curve",
    )
    ax.plot(
        xs,
        [float(binomial_gaussian(n, x)["binomial"]) for x in xs],
        "o",
        color="k",
        markersize=3,
        label="model $B(10, 5+x)/B(10, 5)$",
    )
    ax.set_xlabel("$x = p - n/2$")
    ax.set_ylabel("$B(10, p)/B(10, 5)$")
    ax.legend(loc="upper left", fontsize="small")


@figure(
    "compound-interest",
    "Eq. (10.3)",
    (
        "Compound interest (1 + 1/m)ᵐ on $1.00 at r = 1 (100% a year) after a year, for the "
        "book's m = 1 … 10⁹ periods: the gap to e shrinks like e/(2m). Dots: the printed "
        "values; line: the model at 40 digits."
    ),
    (
        "ch10.interest.m1.growth",
        "ch10.interest.m4.growth",
        "ch10.interest.m12.growth",
        "ch10.interest.m52.growth",
        "ch10.interest.m365.growth",
        "ch10.interest.m8760.growth",
        *(f"ch10.e-limit.m1e{k}.value" for k in range(3, 10)),
    ),
)
def _compound(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    e = float(euler_number())
    pairs = [
        ("ch10.interest.m1", "ch10.interest.m1.growth"),
        ("ch10.interest.m2", "ch10.interest.m2.growth"),
        ("ch10.interest.m3", "ch10.interest.m3.growth"),
        ("ch10.interest.m4", "ch10.interest.m4.growth"),
        ("ch10.interest.m12", "ch10.interest.m12.growth"),
        ("ch10.interest.m52", "ch10.interest.m52.growth"),
        ("ch10.interest.m365", "ch10.interest.m365.growth"),
        ("ch10.interest.m8760", "ch10.interest.m8760.growth"),
        *((f"ch10.e-limit.m1e{k}", f"ch10.e-limit.m1e{k}.value") for k in range(3, 10)),
    ]
    ms = [value_of(claims, m) for m, _ in pairs]
    printed_gap = [e - value_of(claims, v) for _, v in pairs]
    grid = [10 ** (j / 4) for j in range(0, 37)]
    model_gap = [e - float(compound_growth(1, round(m))) for m in grid]
    fig.set_size_inches(7.6, 4.6)
    fig.set_layout_engine("constrained")
    ax = fig.add_subplot()
    ax.loglog(grid, model_gap, color="C0", label="$e - (1 + 1/m)^m$ (model)")
    ax.loglog(grid, [e / (2 * m) for m in grid], ":", color="0.4", label="$e/(2m)$")
    ax.loglog(ms, printed_gap, "o", color="k", markersize=4, label="$e$ $-$ printed value")
    ax.set_xlabel("compounding periods $m$ per year")
    ax.set_ylabel(r"gap to $e$ (\$)")
    ax.legend(fontsize="small")
