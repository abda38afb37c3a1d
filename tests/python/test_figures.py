"""Pictures a person reads: every element of a figure has a legend entry, the colour
bar says what it scores and which way is better, failures.png has axes, start,
goal and the point of contact, and the animation shows the time and the mode."""

import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import fgdwa  # noqa: E402
from fgdwa.bench.runs import Run, episode_columns  # noqa: E402
from fgdwa.bench.experiments import resolve_scenario  # noqa: E402
from fgdwa.plot.animation import AnimationScene, frame_status, write_gif  # noqa: E402
from fgdwa.plot.episode import plot_episode  # noqa: E402
from fgdwa.plot.failures import failures_figure  # noqa: E402
from fgdwa.sim import World, run_episode, run_scenario, trial_variation  # noqa: E402


def legend_labels(fig) -> list:
    return [text.get_text() for legend in [*fig.legends, *(ax.get_legend() for ax in fig.axes)] if legend
            for text in legend.get_texts()]


def colour_bar_labels(fig) -> list:
    return [label for ax in fig.axes for label in (ax.get_xlabel(), ax.get_ylabel()) if "score" in label]


def marker_points(ax, marker: str) -> list:
    return [tuple(np.ravel(line.get_xydata())) for line in ax.get_lines()
            if line.get_marker() == marker and len(line.get_xydata())]


@pytest.fixture(scope="module")
def demo_run():
    """The first 30 cycles of the shipped demo (a map, a box missing from it, a mover) driven by fgdwa."""
    scenario = resolve_scenario("demo")
    result = run_scenario(scenario, "fgdwa", 0, max_steps=30, record_cycles=True,
                          navigator=fgdwa.NavigatorParams(record_top_k=10))
    return scenario, result


@pytest.fixture(scope="module")
def mover_collision():
    """A disc driving into a robot that cannot get away: a collision with mover 0."""
    disc = fgdwa.Disc((3.0, 0.0), 0.3, velocity=(-2.0, 0.0))
    params = fgdwa.PlannerParams(critics=[("heading", 1.0), ("velocity", 1.0)])
    world = World(discs=[disc])
    result = run_episode(world, (0.0, 0.0, np.pi), (-20.0, 0.0), limits=fgdwa.RobotLimits(v_max=0.2), params=params,
                         max_steps=50, record_cycles=True)
    assert result.summary.outcome == "collision"
    return world, result


def test_the_episode_figure_names_every_element_and_its_colour_bar(demo_run):
    scenario, result = demo_run
    fig = plot_episode(result, trial_variation(scenario, 0)[1], scenario.goal)
    labels = legend_labels(fig)
    for expected in ("map (known to the robot)", "obstacles missing from the map", "executed path", "key nodes",
                     "footprint at the end", "rollout chosen in the last cycle", "start", "goal"):
        assert expected in labels
    assert any(label.startswith("global path") for label in labels)
    assert any(re.fullmatch(r"moving obstacles at t = 4\.5 s, numbered", label) for label in labels)
    assert any(re.fullmatch(r"rollouts scored in the last cycle \(\d+; colour: score\)", label) for label in labels)
    (bar,) = colour_bar_labels(fig)
    assert "total score" in bar and "higher is better" in bar and "cycle 29 at t = 4.35 s" in bar
    plt.close(fig)


def test_terrain_grades_have_legend_entries():
    grades = np.zeros((40, 60), np.uint8)
    grades[5:10, 5:10] = 2
    grades[20:25, 20:25] = 4
    cells = np.zeros_like(grades)
    cells[0, :] = 1
    world = World(grid=fgdwa.OccupancyGrid(cells, 0.1), terrain=fgdwa.TerrainGrid(grades, 0.1))
    result = run_episode(world, (1.0, 3.0, 0.0), (5.0, 3.0), max_steps=5)
    fig = plot_episode(result, world, (5.0, 3.0))
    labels = legend_labels(fig)
    assert "terrain grade 2 (speed x0.6)" in labels and "terrain grade 4 (entering it is a fall)" in labels
    assert not any(label.startswith(("terrain grade 1", "terrain grade 3")) for label in labels)
    assert "obstacles missing from the map" not in labels and not any("moving" in label for label in labels)
    plt.close(fig)


def test_the_episode_figure_marks_the_point_of_contact(mover_collision):
    world, result = mover_collision
    fig = plot_episode(result, world, (-20.0, 0.0))
    (ax,) = [ax for ax in fig.axes if ax.get_xlabel() == "x [m]"]
    assert "point of contact (mover 0)" in legend_labels(fig)
    (point,) = marker_points(ax, "X")
    np.testing.assert_allclose(point, result.collision.point)
    assert "mover 0 drove into the robot" in ax.get_title()
    # The disc that hit is numbered as the reason names it.
    assert "0" in [text.get_text() for text in ax.texts]
    plt.close(fig)


def test_benchmark_rows_carry_the_goal_and_the_contact(mover_collision, demo_run):
    _, result = mover_collision
    row = episode_columns(result, 1.0)
    assert (row["goal_x"], row["goal_y"]) == (-20.0, 0.0)
    assert (row["contact_x"], row["contact_y"]) == result.collision.point and row["hit"] == "mover 0"
    row = episode_columns(demo_run[1], 1.0)
    assert np.isnan(row["contact_x"]) and np.isnan(row["contact_y"]) and row["hit"] == ""


def _run(outcome: str, reason: str, contact=None, hit: str = "", discs=()) -> Run:
    cells = np.zeros((40, 80), np.uint8)
    cells[20:24, 40:44] = 1  # a block at x 4.0 .. 4.4, y 2.0 .. 2.4
    cells[10:12, 60:62] = 2  # one the map misses
    poses = np.column_stack([np.linspace(0.5, 3.8, 20), np.full(20, 2.2), np.zeros(20)])
    x, y = contact if contact is not None else (np.nan, np.nan)
    row = {"world": 3, "planner": "fgdwa", "outcome": outcome, "time": 12.0, "reason": reason, "goal_x": 7.5,
           "goal_y": 2.2, "contact_x": x, "contact_y": y, "hit": hit}
    return Run(row=row, cells=cells, extent=(0.0, 8.0, 0.0, 4.0), poses=poses, paths=[(0, poses[:, :2])],
               routes=[np.array([[5.0, 1.0], [6.0, 1.0], [5.0, 1.0]])] if discs else [], discs=list(discs))


def test_failure_panels_have_axes_start_goal_reason_and_the_point_of_contact():
    runs = [_run("success", ""),
            _run("collision", "collision: the robot drove into a wall at (4.00, 2.20)", (4.0, 2.2), "a wall"),
            _run("timeout", "timeout: 3.70 m from the goal after 60 s, last mode Following"),
            _run("collision", "collision: mover 1 drove into the robot at (3.95, 2.20) (closing at 0.50 m/s, "
                 "the robot at 0.10 m/s)", (3.95, 2.2), "mover 1", discs=[(5.0, 1.0, 0.3), (4.1, 2.2, 0.2)])]
    fig = failures_figure(runs)
    panels = [ax for ax in fig.axes if ax.axison]
    assert len(panels) == 3
    for ax, run in zip(panels, runs[1:]):
        assert (ax.get_xlabel(), ax.get_ylabel()) == ("x [m]", "y [m]")
        assert run.row["reason"][:40] in ax.get_title().replace("\n", " ")
        assert len(ax.get_xticks()) > 1 and len(ax.get_yticks()) > 1
        assert marker_points(ax, "o") == [(0.5, 2.2)]  # start
        assert marker_points(ax, "*") == [(7.5, 2.2)]  # goal
        hit = run.row["hit"]
        if hit:
            assert marker_points(ax, "X") == [(run.row["contact_x"], run.row["contact_y"])]
            assert hit in [text.get_text() for text in ax.texts]
        else:
            assert marker_points(ax, "X") == []
    assert "1" in [text.get_text() for text in panels[2].texts]  # the mover hit, numbered
    labels = legend_labels(fig)
    for expected in ("map", "obstacles missing from the map", "last global path", "moving obstacles' routes",
                     "moving obstacles at the end, numbered", "start", "goal", "point of contact (what was hit)",
                     "path driven, x where it ended (collision)", "path driven, x where it ended (timeout)"):
        assert expected in labels
    assert "what the robot mapped" not in labels
    plt.close(fig)


def test_the_animation_shows_time_mode_legend_and_a_progress_bar(demo_run, tmp_path, capsys):
    from PIL import Image

    scenario, result = demo_run
    dt = fgdwa.PlannerParams().dt
    gif = write_gif(result, scenario, tmp_path / "demo.gif", max_frames=12)
    with Image.open(gif) as image:
        assert image.n_frames == 12 and image.size == (1120, 640)
    bar = capsys.readouterr().err
    assert "drawing demo.gif" in bar and "12/12" in bar
    write_gif(result, scenario, tmp_path / "quiet.gif", max_frames=3, progress=False)
    assert capsys.readouterr().err == ""

    assert frame_status(result, 3, dt).startswith(f"t =  0.45 s   cycle 3/30   mode {result.trace.modes[3]}")
    assert re.search(r"\nI \d\.\d\d   D \d\.\d\d   beta \d\.\d\d   delta \d\.\d\d$", frame_status(result, 3, dt))
    assert frame_status(result, 30, dt).startswith("t =  4.50 s   cycle 30/30   timeout\ntimeout: ")

    _, world, _ = trial_variation(scenario, 0)
    scene = AnimationScene(result, scenario, world, dt, 100)
    labels = legend_labels(scene.fig)
    for expected in ("map (known to the robot)", "obstacles missing from the map", "moving obstacles, numbered",
                     "global path (the one in force)", "path driven so far", "chosen rollout", "lidar hits",
                     "detect window (obstacle density I)", "robot: footprint, heading", "start", "goal",
                     "best rollouts of the cycle (colour: score)"):
        assert expected in labels
    (bar,) = colour_bar_labels(scene.fig)
    assert "higher is better" in bar and "frame's cycle" in bar
    first = np.asarray(scene.frame(0))
    last = np.asarray(scene.frame(30))
    assert first.shape == (640, 1120, 3) and not np.array_equal(first, last)
    plt.close(scene.fig)


def test_the_animation_marks_a_collision(mover_collision):
    from fgdwa.sim.scenario import Scenario

    world, result = mover_collision
    scenario = Scenario(name="disc", world=world, start=(0.0, 0.0, np.pi), goal=(-20.0, 0.0))
    scene = AnimationScene(result, scenario, world, fgdwa.PlannerParams().dt, 100)
    assert "point of contact (mover 0)" in legend_labels(scene.fig)
    steps = result.summary.steps
    scene.frame(steps - 1)
    assert len(scene.contact.get_xdata()) == 0  # shown at the end only
    scene.frame(steps)
    np.testing.assert_allclose(np.ravel(scene.contact.get_xydata()), result.collision.point)
    assert "mover 0 drove into the robot" in frame_status(result, steps, fgdwa.PlannerParams().dt)
    plt.close(scene.fig)
