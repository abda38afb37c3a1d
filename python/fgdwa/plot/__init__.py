"""Pictures, drawn with matplotlib (Agg) from what the runs recorded, never by
simulating again: an episode's figure and the pieces other figures share
(``episode``), its animated GIF (``animation``), the figures of experiments
(``experiments``), the failed runs of a benchmark (``failures``), a fuzzy
controller's control surfaces (``fuzzy``) and a bag replay's commands
(``replay``).
"""

from fgdwa.plot.animation import write_gif
from fgdwa.plot.episode import draw_world, footprint_patch, plot_episode, save_figure, world_legend
from fgdwa.plot.experiments import FigureJob, draw_figures, experiment_figures
from fgdwa.plot.failures import failures_figure, plot_failures
from fgdwa.plot.fuzzy import plot_control_surfaces
from fgdwa.plot.replay import plot_replay

__all__ = [
    "FigureJob",
    "draw_figures",
    "draw_world",
    "experiment_figures",
    "failures_figure",
    "footprint_patch",
    "plot_control_surfaces",
    "plot_episode",
    "plot_failures",
    "plot_replay",
    "save_figure",
    "world_legend",
    "write_gif",
]
