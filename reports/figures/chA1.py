# ruff: noqa: N999  (the module is named for the chapter key "A1", as the catalog file chA1.toml)
"""Figures of Appendix 1.A, redrawn from the model (see ``reports.figures``)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from mechmodel.vectors import area_ratios, heron_area_squared, plane_cross
from reports.figures import figure, value_of

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from reference.evaluation import EvaluatedClaim


@figure(
    "cross-product-areas",
    "Fig. 1.A.2",
    "The parallelogram of A = (3,1) and B = (1,2) and its A+B and A-B triangles. Their areas, "
    "found by Heron's formula from the side lengths alone, are |A x B| = 5 and half of it: the "
    "1/2 of 'Area = 1/2 base altitude = 1/2 |A x B|'.",
    ("chA1.area.triangle",),
)
def _areas(fig: Figure, claims: dict[str, EvaluatedClaim]) -> None:
    a, b = (3, 1), (1, 2)
    ratios = area_ratios(a, b)
    half = value_of(claims, "chA1.area.triangle")
    cross = plane_cross(a, b)
    s, d = (a[0] + b[0], a[1] + b[1]), (a[0] - b[0], a[1] - b[1])
    panels = [
        ("parallelogram", [(0, 0), a, s, b], ratios.parallelogram),
        ("A+B triangle", [(0, 0), a, s], ratios.sum_triangle),
        ("A-B triangle", [(0, 0), a, d], ratios.difference_triangle),
    ]
    for k, (title, corners, ratio) in enumerate(panels):
        ax = fig.add_subplot(1, 3, k + 1)
        xs = [p[0] for p in corners] + [corners[0][0]]
        ys = [p[1] for p in corners] + [corners[0][1]]
        ax.fill(xs, ys, alpha=0.25, color=f"C{k}")
        ax.plot(xs, ys, color=f"C{k}")
        ax.annotate("", a, (0, 0), arrowprops={"arrowstyle": "->"})
        ax.annotate("", b, (0, 0), arrowprops={"arrowstyle": "->", "color": "0.4"})
        area = float(heron_area_squared(*corners[:3])) ** 0.5 * (2 if k == 0 else 1)
        ax.set_title(f"{title}\nHeron {area:g} = {float(ratio):g} |AxB|", fontsize="x-small")
        ax.set_aspect("equal")
        ax.set_xlim(-0.5, 4.5)
        ax.set_ylim(-1.5, 3.5)
        ax.tick_params(labelsize="xx-small")
    fig.suptitle(f"|A x B| = {cross}; book's triangle share {half:g}", fontsize="small")
