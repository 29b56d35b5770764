# ruff: noqa: N999  (the module is named for the chapter key "A1", as the catalog file chA1.toml)
"""Figures of Appendix 1.A, redrawn from the model (see ``reports.figures``)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from mechmodel.planar import cross
from mechmodel.vectors import area_ratios, heron_area_squared
from reports.figures import figure, value_of

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from reference.evaluation import EvaluatedClaim


@figure(
    "cross-product-areas",
    "Fig. 1.A.2",
    (
        "The parallelogram of A = (3, 1) and B = (1, 2) and its A+B and A−B triangles "
        "(dimensionless units), their areas found by Heron's formula from the side lengths "
        "alone: |A × B| = 5 and half of it, the ½ of 'Area = ½ base altitude = ½ |A × B|'."
    ),
    ("chA1.area.triangle",),
)
def _areas(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    a, b = (3, 1), (1, 2)
    ratios = area_ratios(a, b)
    half = value_of(claims, "chA1.area.triangle")
    cross_ab = cross(a, b)
    s, d = (a[0] + b[0], a[1] + b[1]), (a[0] - b[0], a[1] - b[1])
    panels = [
        ("parallelogram", [(0, 0), a, s, b], ratios.parallelogram),
        (r"$\mathbf{A}+\mathbf{B}$ triangle", [(0, 0), a, s], ratios.sum_triangle),
        (r"$\mathbf{A}-\mathbf{B}$ triangle", [(0, 0), a, d], ratios.difference_triangle),
    ]
    fig.set_size_inches(10.5, 3.7)
    fig.set_layout_engine("constrained", w_pad=0.1)
    for k, (title, corners, ratio) in enumerate(panels):
        ax = fig.add_subplot(1, 3, k + 1)
        xs = [p[0] for p in corners] + [corners[0][0]]
        ys = [p[1] for p in corners] + [corners[0][1]]
        ax.fill(xs, ys, alpha=0.25, color=f"C{k}")
        ax.plot(xs, ys, color=f"C{k}")
        for tip, name, colour in ((a, "A", "k"), (b, "B", "0.4")):
            ax.annotate(
                "", tip, (0, 0), arrowprops={"arrowstyle": "->", "color": colour, "lw": 1.3}
            )
            ax.annotate(
                rf"$\mathbf{{{name}}}$",
                tip,
                textcoords="offset points",
                xytext=(4, -10) if name == "A" else (-12, 2),
                color=colour,
            )
        area = float(heron_area_squared(*corners[:3])) ** 0.5 * (2 if k == 0 else 1)
        share = rf"{float(ratio):g}\,|\mathbf{{A}}\times\mathbf{{B}}|"
        ax.set_title(f"{title}: area {area:g} = ${share}$", fontsize="medium")
        ax.set_aspect("equal")
        ax.set_xlim(-0.5, 4.5)
        ax.set_ylim(-1.5, 3.5)
        ax.set_xlabel("$x$")
        ax.set_ylabel("$y$")
    ax.text(
        0.97,
        0.04,
        rf"$|\mathbf{{A}}\times\mathbf{{B}}| = {cross_ab}$; the book's share ${half:g}$",
        transform=ax.transAxes,
        ha="right",
        fontsize="small",
    )
