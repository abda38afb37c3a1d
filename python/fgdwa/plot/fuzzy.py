"""Control surfaces of a two-input fuzzy controller (:mod:`fgdwa.fuzzy`): beta(I, D)
and delta(I, D) for the paper's."""

from __future__ import annotations

import numbers
from pathlib import Path
from typing import Mapping, Optional, Union

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from fgdwa._core import FgdwaError, MamdaniEngine, paper_fuzzy_controller  # noqa: E402
from fgdwa.fuzzy import engine_from_dict  # noqa: E402
from fgdwa.plot.episode import save_figure  # noqa: E402
from fgdwa.file_limits import short_repr

# Axis labels for the paper's variable names.
_PAPER_LABELS = {
    "I": "obstacle density I",
    "D": "path deviation D [m]",
    "beta": "beta (weight of dist)",
    "delta": "delta (weight of similarity)",
}


def _as_engine(engine_or_preset: Union[MamdaniEngine, Mapping, str]) -> MamdaniEngine:
    if isinstance(engine_or_preset, MamdaniEngine):
        return engine_or_preset
    if isinstance(engine_or_preset, Mapping):
        return engine_from_dict(engine_or_preset)
    if engine_or_preset == "paper":
        return paper_fuzzy_controller()
    raise FgdwaError(f"engine: expected a MamdaniEngine, a configuration mapping or 'paper', "
                     f"got {short_repr(engine_or_preset)}")


def plot_control_surfaces(engine_or_preset: Union[MamdaniEngine, Mapping, str] = "paper",
                          path: Optional[Union[str, Path]] = None, *, kind: str = "surface", points: int = 61,
                          labels: Optional[Mapping[str, str]] = None):
    """One panel per output over the grid of a two-input engine: beta(I, D) and
    delta(I, D) for the paper's controller.

    engine_or_preset: a MamdaniEngine, a configuration mapping, or 'paper'.
    kind: 'surface' (3-D) or 'heatmap' (colour map with contour lines).
    points: grid points along each input axis. labels: axis text by variable name.
    Saves a PNG to `path` when given (and closes the figure); returns the figure."""
    engine = _as_engine(engine_or_preset)
    if len(engine.inputs) != 2:
        raise FgdwaError(f"engine: control surfaces need exactly 2 inputs, this one has {len(engine.inputs)}")
    if kind not in ("surface", "heatmap"):
        raise FgdwaError(f"kind = {short_repr(kind)}: must be 'surface' or 'heatmap'")
    if isinstance(points, bool) or not isinstance(points, numbers.Integral) or points < 2:
        raise FgdwaError(f"points = {short_repr(points)}: must be an integer >= 2")
    text = {**_PAPER_LABELS, **(labels or {})}
    x_var, y_var = engine.inputs
    xs = np.linspace(x_var.lo, x_var.hi, int(points))
    ys = np.linspace(y_var.lo, y_var.hi, int(points))
    grid_x, grid_y = np.meshgrid(xs, ys)
    values = engine.evaluate_grid(grid_x, grid_y)

    n = len(engine.outputs)
    fig = plt.figure(figsize=(6.2 * n, 5.0))
    for k, out in enumerate(engine.outputs):
        z = values[out.name]
        title = f"{out.name}({x_var.name}, {y_var.name})"
        if kind == "surface":
            ax = fig.add_subplot(1, n, k + 1, projection="3d")
            surface = ax.plot_surface(grid_x, grid_y, z, cmap="viridis", vmin=out.lo, vmax=out.hi,
                                      linewidth=0, antialiased=True)
            ax.set_zlim(out.lo, out.hi)
            ax.view_init(elev=28, azim=-130)
            # The z label would fall outside the panel at this view: the title and colour bar say it.
            fig.colorbar(surface, ax=ax, shrink=0.6, pad=0.1, label=text.get(out.name, out.name))
        else:
            ax = fig.add_subplot(1, n, k + 1)
            mesh = ax.pcolormesh(grid_x, grid_y, z, cmap="viridis", vmin=out.lo, vmax=out.hi, shading="auto")
            lines = ax.contour(grid_x, grid_y, z, levels=8, colors="white", linewidths=0.6)
            ax.clabel(lines, fontsize=7, fmt="%.2f")
            fig.colorbar(mesh, ax=ax, label=text.get(out.name, out.name))
        ax.set_xlabel(text.get(x_var.name, x_var.name))
        ax.set_ylabel(text.get(y_var.name, y_var.name))
        ax.set_title(title)
    fig.tight_layout()
    if path is not None:
        save_figure(fig, path)
    return fig
