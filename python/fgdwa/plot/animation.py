"""An animated GIF of one episode: the robot's footprint as it
is, the path driven so far, the rollouts the planner scored (coloured by score)
and the one it chose, the lidar's hits, the detect window, the moving obstacles
and the robot's tracks of them, the global path in force; each with a legend
entry, and above the map the time, the cycle, the navigator's mode and the
fuzzy controller's inputs and weights.

Every frame replays what the episode recorded (``run_episode(record_cycles=True)``):
nothing of the robot's side is simulated again. The map, the legend and the
colour bar are drawn once; each frame restores that picture and draws only what
moves on it (blitting), and all frames share one palette.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.cm import ScalarMappable  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
from matplotlib.colors import Normalize  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Circle, Patch, Wedge  # noqa: E402
from matplotlib import font_manager  # noqa: E402
from matplotlib.font_manager import FontProperties  # noqa: E402
from PIL import Image, ImageDraw, ImageFont  # noqa: E402
from tqdm import tqdm  # noqa: E402

from fgdwa._core import FgdwaError  # noqa: E402
from fgdwa.plot.episode import FAN_COLOURS, MOVER_COLOUR, draw_world, footprint_patch, placed_outline  # noqa: E402
from fgdwa.sim.episode import EpisodeResult  # noqa: E402
from fgdwa.sim.scenario import Scenario, scenario_params, trial_variation  # noqa: E402
from fgdwa.file_limits import short_repr

FRAME_SIZE = (11.2, 6.4)  # inches; 1120 x 640 pixels at the default 100 dpi
STATUS_POINTS = 10  # the status lines' font size
CIRCLE = np.column_stack([np.cos(np.linspace(0, 2 * np.pi, 33)), np.sin(np.linspace(0, 2 * np.pi, 33))])


def frame_indices(steps: int, max_frames: int = 150) -> np.ndarray:
    """Up to ``max_frames`` cycle indices from 0 to ``steps`` (the final pose), evenly spread."""
    if max_frames < 2:
        raise ValueError(f"max_frames = {short_repr(max_frames)}: must be >= 2")
    count = min(int(max_frames), steps + 1)
    return np.unique(np.linspace(0, steps, count).round().astype(int))


def write_gif(result: EpisodeResult, scenario: Scenario, path, planner=None, seed: int = 0,
              max_frames: int = 150, dpi: int = 100, fps: int = 10, progress: bool = True) -> Path:
    """Animate ``result``, the run of ``planner`` on ``scenario`` with ``seed`` recorded
    with ``record_cycles=True``, into a GIF at ``path``: at most ``max_frames``
    frames, ``fps`` a second, ``progress`` showing a bar over them on stderr."""
    path = Path(path)
    trace = result.trace
    if len(trace.cycles) != result.summary.steps:
        raise FgdwaError("write_gif replays the recorded cycles: run the episode with record_cycles=True")
    _, params = scenario_params(scenario, planner)
    _, world, _ = trial_variation(scenario, seed)
    scene = AnimationScene(result, scenario, world, params.dt, dpi)
    frames = frame_indices(result.summary.steps, max_frames)
    path.parent.mkdir(parents=True, exist_ok=True)
    images = (scene.frame(int(k)) for k in tqdm(frames, desc=f"drawing {path.name}", unit="frame",
                                                 disable=not progress))
    try:
        _write_gif(images, path, fps)
    finally:
        plt.close(scene.fig)
    return path


class AnimationScene:
    """The figure of an episode's animation (``fig``): what stays drawn once, what moves
    updated per :meth:`frame`; ``world`` is the trial's, ``dt`` the control period (s)."""

    def __init__(self, result: EpisodeResult, scenario: Scenario, world, dt: float, dpi: int):
        self.result, self.dt = result, dt
        self.footprint, self.window = scenario.footprint, scenario.window
        self.world = world
        poses = result.motion.poses
        # A fixed layout (the map left, under two lines of status; the legend and the colour bar right):
        # a layout engine would cost more than the frames.
        self.fig = fig = plt.figure(figsize=FRAME_SIZE, dpi=dpi)
        self.ax = ax = fig.add_axes((0.055, 0.075, 0.62, 0.80), anchor="NW")
        entries = draw_world(ax, dataclasses.replace(world, discs=(), movers=()), None)
        moving = self._animated(ax.plot([], [], "--", color="tab:red", linewidth=1.0)[0])
        entries.append(Line2D([], [], linestyle="--", color="tab:red", linewidth=1.0,
                              label="global path (the one in force)"))
        self.global_line = moving
        self.driven = self._animated(ax.plot([], [], color="tab:blue", linewidth=1.5)[0])
        entries.append(Line2D([], [], color="tab:blue", linewidth=1.5, label="path driven so far"))
        self.fan = self._animated(LineCollection([], cmap=FAN_COLOURS, norm=Normalize(0.0, 1.0), linewidths=0.7))
        ax.add_collection(self.fan)
        entries.append(Line2D([], [], color=plt.get_cmap(FAN_COLOURS)(0.6), linewidth=1.2,
                              label="best rollouts of the cycle (colour: score)"))
        self.chosen = self._animated(ax.plot([], [], color="red", linewidth=1.8)[0])
        entries.append(Line2D([], [], color="red", linewidth=1.8, label="chosen rollout"))
        self.hits = self._animated(ax.scatter([], [], s=3, color="tab:red", zorder=4))
        entries.append(Line2D([], [], marker=".", linestyle="none", color="tab:red", label="lidar hits"))
        self.sector = self._animated(Wedge((0, 0), self.window.radius, 0, 0, facecolor="tab:cyan",
                                           edgecolor="tab:blue", alpha=0.18, linestyle="--"))
        ax.add_patch(self.sector)
        entries.append(Patch(facecolor="tab:cyan", edgecolor="tab:blue", alpha=0.3, linestyle="--",
                             label="detect window (obstacle density I)"))
        self.body = self._animated(footprint_patch(self.footprint, poses[0], facecolor="tab:blue", edgecolor="k",
                                                   alpha=0.6, zorder=5))
        ax.add_patch(self.body)
        self.heading = self._animated(ax.plot([], [], color="k", linewidth=1.2, zorder=6)[0])
        entries.append(Patch(facecolor="tab:blue", edgecolor="k", alpha=0.6, label="robot: footprint, heading"))
        self.discs = [self._animated(Circle((0, 0), max(d.radius, 0.05), color=MOVER_COLOUR, alpha=0.7, zorder=3))
                      for d in world.discs_at(0.0)]
        for patch in self.discs:
            ax.add_patch(patch)
        if self.discs:
            entries.append(Line2D([], [], marker="o", linestyle="none", markersize=10, color=MOVER_COLOUR, alpha=0.7,
                                  label="moving obstacles, numbered"))
        self.tracked = self._animated(LineCollection([], colors="k", linewidths=0.9, linestyles="dotted", zorder=4))
        ax.add_collection(self.tracked)
        if any(len(c.tracked) for c in result.trace.cycles):
            entries.append(Line2D([], [], marker="o", linestyle="none", markersize=10, markerfacecolor="none",
                                  markeredgecolor="k", label="moving obstacles as the robot tracks them"))
        entries += ax.plot(*poses[0, :2], "o", color="tab:green", markersize=8, label="start")
        entries += ax.plot(*np.asarray(scenario.goal)[:2], "*", color="tab:orange", markersize=14, label="goal")
        contact = result.collision
        self.contact = self._animated(ax.plot([], [], "X", color="red", markeredgecolor="k", markersize=13,
                                              zorder=7)[0])
        if contact is not None:
            entries.append(Line2D([], [], marker="X", linestyle="none", color="red", markeredgecolor="k",
                                  markersize=11, label=f"point of contact ({contact.what})"))
        ax.set_aspect("equal")
        ax.set_xlabel("x [m]")
        ax.set_ylabel("y [m]")
        if world.grid is not None:
            x0, x1, y0, y1 = world.grid.extent
        else:  # nothing but the run and its goal to frame
            seen = np.vstack([poses[:, :2], np.asarray(scenario.goal)[:2]])
            (x0, y0), (x1, y1) = seen.min(axis=0) - 1.0, seen.max(axis=0) + 1.0
        ax.set_xlim(x0, x1)
        ax.set_ylim(y0, y1)
        bar = fig.colorbar(ScalarMappable(Normalize(0.0, 1.0), FAN_COLOURS), cax=fig.add_axes((0.71, 0.10, 0.26, 0.03)),
                           orientation="horizontal", ticks=[0.0, 1.0])
        bar.ax.set_xticklabels(["lowest", "highest"], fontsize=8)
        bar.ax.xaxis.set_label_position("top")
        bar.set_label("rollouts' total score within the frame's cycle\n(higher is better; the highest is chosen)",
                      fontsize=8)
        fig.legend(handles=entries, loc="upper left", bbox_to_anchor=(0.695, 0.97), fontsize=8)
        # Two lines of status above the map, written by Pillow: a tenth of what matplotlib takes to
        # render text that changes every frame.
        status = self._animated(ax.set_title("t\nt", fontsize=STATUS_POINTS, loc="left"))
        fig.canvas.draw()
        self.background = fig.canvas.copy_from_bbox(fig.bbox)
        self.size = fig.canvas.get_width_height()
        box = status.get_window_extent()
        self.status_at = (box.x0, self.size[1] - box.y1)
        font = font_manager.findfont(FontProperties(family="DejaVu Sans"))
        self.font = ImageFont.truetype(font, round(STATUS_POINTS * dpi / 72))
        self.small = ImageFont.truetype(font, round(8 * dpi / 72))

    def _animated(self, artist):
        artist.set_animated(True)
        return artist

    def frame(self, k: int) -> Image.Image:
        """The picture of cycle ``k`` (``steps``: the end), RGB."""
        self._update(k)
        canvas, ax = self.fig.canvas, self.ax
        canvas.restore_region(self.background)
        for artist in (self.sector, self.global_line, self.fan, self.chosen, self.driven, self.hits, *self.discs,
                       self.tracked, self.body, self.heading, self.contact):
            ax.draw_artist(artist)
        image = Image.frombytes("RGB", self.size, canvas.buffer_rgba(), "raw", "RGBX")
        pen = ImageDraw.Draw(image)
        pen.multiline_text(self.status_at, frame_status(self.result, k, self.dt), fill="black", font=self.font,
                           spacing=4)
        if self.discs:
            box = ax.get_window_extent()
            for index, (x, y) in enumerate(ax.transData.transform([patch.center for patch in self.discs])):
                if box.x0 <= x <= box.x1 and box.y0 <= y <= box.y1:
                    pen.text((x, self.size[1] - y), str(index), fill="white", font=self.small, anchor="mm")
        return image

    def _update(self, k: int) -> None:
        result, trace = self.result, self.result.trace
        steps = result.summary.steps
        poses = result.motion.poses
        x, y, theta = poses[k]
        t = k * self.dt
        radius, window = self.footprint.radius, self.window
        self.driven.set_data(poses[: k + 1, 0], poses[: k + 1, 1])
        if self.footprint.is_circle:
            self.body.center = (x, y)
        else:
            self.body.set_xy(placed_outline(self.footprint.vertices, poses[k]))
        self.heading.set_data([x, x + 1.4 * radius * np.cos(theta)], [y, y + 1.4 * radius * np.sin(theta)])
        self.sector.set_center((x, y))
        self.sector.set_theta1(np.degrees(theta - window.half_angle))
        self.sector.set_theta2(np.degrees(theta + window.half_angle))
        for patch, disc in zip(self.discs, self.world.discs_at(t)):
            patch.center = tuple(disc.center)
        paths = result.context.paths
        held = np.searchsorted([cycle for cycle, _ in paths], k, side="right") - 1
        points = np.asarray(paths[held][1]) if held >= 0 else np.zeros((0, 2))
        self.global_line.set_data(points[:, 0], points[:, 1])
        if k < steps:
            cycle = trace.cycles[k]
            self.hits.set_offsets(cycle.hits if len(cycle.hits) else np.zeros((0, 2)))
            self.fan.set_segments([np.vstack([[x, y], r[:, :2]]) for r in cycle.rollouts])
            self.fan.set_array(_relative(cycle.totals))
            best = np.vstack([[x, y], cycle.chosen[:, :2]]) if len(cycle.chosen) else np.zeros((0, 2))
            self.chosen.set_data(best[:, 0], best[:, 1])
            self.tracked.set_segments([(cx, cy) + r * CIRCLE for cx, cy, r, _, _ in cycle.tracked])
        else:
            self.hits.set_offsets(np.zeros((0, 2)))
            self.fan.set_segments([])
            self.chosen.set_data([], [])
            self.tracked.set_segments([])
        contact = result.collision if k == steps else None
        self.contact.set_data(*([[contact.point[0]], [contact.point[1]]] if contact is not None else [[], []]))


def frame_status(result: EpisodeResult, k: int, dt: float) -> str:
    """The two status lines above frame ``k`` of ``result`` (``dt``: the control period,
    s): the time, the cycle, the navigator's mode (and the planner's status when it
    differs) and I, D, beta, delta; at the end the outcome and why."""
    trace, summary = result.trace, result.summary
    steps = summary.steps
    first = f"t = {k * dt:5.2f} s   cycle {k}/{steps}"
    if k < steps:
        first += f"   mode {trace.modes[k]}"
        if trace.statuses[k] != trace.modes[k]:
            first += f" ({trace.statuses[k]})"
        values = [f"{name} {values[k]:.2f}" for name, values in
                  (("I", trace.density), ("D", trace.deviation), ("beta", trace.beta), ("delta", trace.delta))
                  if k < len(values) and np.isfinite(values[k])]
        return first + "\n" + ("   ".join(values) if values else " ")
    return first + f"   {summary.outcome}\n" + (summary.reason or "reached the goal")


def _relative(totals: np.ndarray) -> np.ndarray:
    """Scores placed in [0, 1] from the cycle's lowest to its highest (all 1 when they tie)."""
    totals = np.asarray(totals, dtype=float)
    if not len(totals):
        return totals
    low, high = np.min(totals), np.max(totals)
    return np.ones_like(totals) if high <= low else (totals - low) / (high - low)


def _write_gif(images, path: Path, fps: int) -> None:
    """Frames to a GIF in one palette, made from the first frame and the fan's colours: mapping
    each frame to a fixed palette costs a millisecond where choosing a palette per frame costs ten."""
    frames, palette = [], None
    for rgb in images:
        if palette is None:
            swatch = (255 * plt.get_cmap(FAN_COLOURS)(np.linspace(0, 1, rgb.width))[:, :3]).astype(np.uint8)
            sample = np.vstack([np.asarray(rgb), np.repeat(swatch[None], 8, axis=0)])
            palette = Image.fromarray(sample).quantize(256, method=Image.Quantize.FASTOCTREE)
        frames.append(rgb.quantize(palette=palette, dither=Image.Dither.NONE))
    frames[0].save(path, save_all=True, append_images=frames[1:], duration=round(1000 / fps), loop=0)
