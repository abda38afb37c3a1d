"""Scenarios from YAML: the shipped ones load, bad files are named with the key and value at fault."""

import importlib.resources
import math
import textwrap

import numpy as np
import pytest

import fgdwa
from fgdwa.sim.scenario import Scenario, run_scenario
from fgdwa.io.scenario_file import load_scenario, shipped_scenarios

# A 3 m x 1.5 m map of 0.5 m cells: one obstacle cell at x 1.0-1.5, y 0-0.5.
TINY = """\
name: tiny
map:
  resolution: 0.5
  ascii: |
    ......
    ......
    ..#...
start: [0.75, 0.75, 0]
goal: [2.75, 1.25]
"""


def fails(text_or_path, *fragments):
    """Loading raises FgdwaError whose message holds every fragment (the file, the key, the value)."""
    with pytest.raises(fgdwa.FgdwaError) as info:
        load_scenario(text_or_path)
    message = str(info.value)
    for fragment in fragments:
        assert fragment in message, f"{fragment!r} not in {message!r}"
    return message


def write(tmp_path, text, name="bad.yaml"):
    path = tmp_path / name
    path.write_text(textwrap.dedent(text))
    return path


# --- shipped scenarios ----------------------------------------------------------------------------------------------


def test_shipped_names():
    assert {"e1", "e2", "e3", "demo"} <= set(shipped_scenarios())


def test_shipped_files_are_package_data():
    names = {p.name for p in (importlib.resources.files("fgdwa") / "scenarios").iterdir()}
    assert {"e1.yaml", "e2.yaml", "e3.yaml", "demo.yaml"} <= names


@pytest.mark.parametrize("name", ["e1", "e2", "e3", "demo"])
def test_shipped_scenario_loads(name):
    scenario = load_scenario(name)
    assert isinstance(scenario, Scenario)
    assert scenario.name == name
    assert scenario.description
    assert scenario.world.grid is not None
    assert fgdwa.CollisionWorld(scenario.world.true_grid()).in_collision(scenario.footprint, scenario.start) is False


def test_shipped_scenarios_hold_what_their_experiments_need():
    e2 = load_scenario("e2")
    assert e2.world.hidden is not None and e2.world.hidden.cells.any()
    e3 = load_scenario("e3")
    grades = set(np.unique(e3.world.terrain.grades))
    assert {1, 2, 3, 4} <= grades
    assert 2 <= len(e3.world.movers) <= 3 and not e3.world.discs_known
    demo = load_scenario("demo")
    assert demo.world.hidden.cells.any() and len(demo.world.movers) == 1


def test_e2_has_danger_points():
    """Global-path points closer to an obstacle (unknown ones included) than the footprint radius + 0.3 m."""
    from fgdwa.global_planning import plan_global
    from fgdwa.sim.referee import danger_points

    e2 = load_scenario("e2")
    plan = plan_global(e2.world.grid, e2.start[:2], e2.goal, inflation_radius=e2.footprint.radius + 0.3)
    assert plan.status == fgdwa.GlobalStatus.Found
    static = fgdwa.DistanceField(e2.world.true_grid())
    assert len(danger_points(plan.path, static, e2.footprint.radius + 0.3)) >= 2


def test_a_loaded_scenario_runs():
    result = run_scenario(load_scenario("demo"), "fgdwa", seed=0, max_steps=5)
    assert result.summary.steps == 5 and result.summary.outcome == "timeout"


def test_a_path_a_path_string_and_text_agree(tmp_path):
    path = write(tmp_path, TINY, "tiny.yaml")
    first = load_scenario(path)
    for other in (load_scenario(str(path)), load_scenario(TINY)):
        assert np.array_equal(other.world.grid.cells, first.world.grid.cells)
        assert other.start == first.start and other.goal == first.goal


# --- layout ---------------------------------------------------------------------------------------------------------


def test_ascii_top_row_is_the_highest_y():
    scenario = load_scenario("""
        map:
          resolution: 0.5
          origin: [10.0, 20.0]
          ascii: |
            #...
            ....
            ...#
        start: [11.25, 20.75]
        goal: [11.75, 21.25]
    """)
    grid = scenario.world.grid
    assert grid.shape == (3, 4)
    cells = grid.cells
    assert cells[2, 0] == 1 and cells[0, 3] == 1 and cells.sum() == 2
    # top-left character: x 10.0-10.5, y 21.0-21.5; bottom-right: x 11.5-12.0, y 20.0-20.5
    assert list(grid.occupied_at([[10.25, 21.25], [11.75, 20.25], [10.25, 20.25], [11.75, 21.25]])) == \
        [True, True, False, False]


def test_cells_per_char_and_terrain_layers():
    scenario = load_scenario("""
        map:
          resolution: 0.1
          cells_per_char: 5
          ascii: |
            ....
            #...
        terrain:
          ascii: |
            4...
            .123
        start: [1.25, 0.75, 90]
        goal: [1.75, 0.25]
    """)
    assert scenario.world.grid.shape == (10, 20)
    assert scenario.world.grid.cells[:5, :5].all() and scenario.world.grid.cells[5:].sum() == 0
    terrain = scenario.world.terrain
    assert terrain.grade_at((0.25, 0.75)) == 4 and terrain.grade_at((1.25, 0.25)) == 2
    assert terrain.grade_at((1.75, 0.25)) == 3 and terrain.grade_at((0.25, 0.25)) == 0
    assert math.isclose(scenario.start[2], math.pi / 2)


def test_rectangles_movers_and_sections():
    scenario = load_scenario("""
        map: {size: [4.0, 3.0], resolution: 0.1, border: true, rectangles: [[2.0, 0.0, 2.2, 1.0]]}
        unknown_obstacles:
          rectangles: [[1.0, 2.0, 1.4, 2.4]]
        moving_obstacles:
          - {radius: 0.2, waypoints: [[3.0, 0.5], [3.0, 2.5]], speed: 0.4, mode: loop, start_delay: 1.0}
          - {radius: 0.3, start: [3.5, 1.0], velocity: [0.0, 0.1]}
        start: {x: 0.6, y: 0.6, theta: 0.5}
        goal: [3.3, 2.3]
        robot:
          limits: {v_max: 0.8, omega_max: 1.5}
          footprint: {polygon: [[0.3, 0.2], [-0.2, 0.2], [-0.2, -0.2], [0.3, -0.2]]}
        planner: {preset: gdwa, overrides: {window: {n_v: 11}, critics: [{name: heading, weight: 0.5}, {name: velocity}]}}
        global_planner: {method: astar, options: {terrain_cost: {w_risk: 2.0}}}
        lidar: {beams: 91, fov_deg: 180, max_range: 5.0}
        detect_window: {half_angle_deg: 45, radius: 1.5}
        variability: {start_xy_std: 0.0, start_theta_std_deg: 0.0, mover_phase: false, lidar_noise_std: 0.0}
        max_steps: 50
        goal_tolerance: 0.2
    """)
    world = scenario.world
    assert world.grid.shape == (30, 40)
    assert world.grid.cells[0].all() and world.grid.cells[:, -1].all()
    assert world.grid.occupied_at([[2.1, 0.5]])[0]
    assert world.hidden.occupied_at([[1.2, 2.2]])[0] and not world.grid.occupied_at([[1.2, 2.2]])[0]
    assert len(world.movers) == 2 and world.movers[0].mode == "loop" and world.movers[0].start_delay == 1.0
    assert tuple(world.movers[1].velocity) == (0.0, 0.1)
    assert scenario.start == (0.6, 0.6, 0.5)
    assert scenario.limits.v_max == 0.8 and not scenario.footprint.is_circle
    assert scenario.planner == "gdwa" and scenario.overrides["window.n_v"] == 11
    assert scenario.global_options == {"terrain_cost": {"w_risk": 2.0}}
    assert scenario.lidar.beams == 91 and scenario.window.half_angle == pytest.approx(math.radians(45))
    assert scenario.variability.mover_phase is False
    assert scenario.max_steps == 50 and scenario.goal_tolerance == 0.2
    result = run_scenario(scenario, seed=1, max_steps=3)
    assert result.summary.steps == 3


def test_png_map(tmp_path):
    matplotlib_image = pytest.importorskip("matplotlib.image")
    image = np.ones((4, 6, 3))
    image[0, 0] = 0.0          # top-left pixel dark: the top-left cell of the map
    image[3, 5] = 0.2          # bottom-right dark grey: an obstacle too
    image[1, 2] = 0.7          # light grey: free
    matplotlib_image.imsave(tmp_path / "room.png", image)
    path = write(tmp_path, """
        map: {png: room.png, resolution: 0.5}
        start: [1.25, 0.75]
        goal: [1.75, 1.25]
    """, "room.yaml")
    grid = load_scenario(path).world.grid
    assert grid.shape == (4, 6)
    assert grid.cells[3, 0] == 1 and grid.cells[0, 5] == 1 and grid.cells.sum() == 2
    assert grid.occupied_at([[0.25, 1.75]])[0]


def test_npy_map_and_terrain(tmp_path):
    cells = np.zeros((4, 6), dtype=np.uint8)
    cells[0, 0] = 1            # row 0 is the bottom, as in OccupancyGrid
    grades = np.zeros((4, 6), dtype=np.int64)
    grades[3, 5] = 4
    np.save(tmp_path / "cells.npy", cells)
    np.save(tmp_path / "grades.npy", grades)
    path = write(tmp_path, """
        map: {npy: cells.npy, resolution: 0.5}
        terrain: {npy: grades.npy, passing_factors: [1.0, 0.9, 0.7, 0.5, 0.0]}
        start: [1.25, 0.75]
        goal: [1.75, 1.25]
    """, "arrays.yaml")
    scenario = load_scenario(path)
    assert np.array_equal(scenario.world.grid.cells, cells)
    assert scenario.world.grade_at((2.75, 1.75)) == 4
    assert scenario.world.passing_factors == (1.0, 0.9, 0.7, 0.5, 0.0)


def test_text_resolves_files_against_base_dir(tmp_path):
    np.save(tmp_path / "cells.npy", np.zeros((4, 6), dtype=np.uint8))
    text = "map: {npy: cells.npy, resolution: 0.5}\nstart: [1.25, 0.75]\ngoal: [1.75, 1.25]\n"
    assert load_scenario(text, base_dir=tmp_path).world.grid.shape == (4, 6)


# --- errors: each names the file, the key path and the value --------------------------------------------------------


def test_unknown_key(tmp_path):
    path = write(tmp_path, TINY + "max_step: 300\n")
    message = fails(path, str(path), "max_step", "300", "unknown key")
    assert "did you mean 'max_steps'" in message


def test_unknown_nested_key(tmp_path):
    path = write(tmp_path, TINY + "lidar: {beams: 91, range: 5}\n")
    fails(path, str(path), "lidar.range", "5", "unknown key")


def test_wrong_type(tmp_path):
    path = write(tmp_path, TINY + "moving_obstacles:\n"
                                  "  - {radius: 0.2, waypoints: [[0.5, 0.5], [2.5, 0.5]], speed: 0.5}\n"
                                  "  - {radius: 0.2, waypoints: [[0.5, 0.5], [2.5, 0.5]], speed: fast}\n")
    fails(path, str(path), "moving_obstacles[1].speed", "'fast'", "expected a number")


def test_bad_value(tmp_path):
    path = write(tmp_path, TINY + "moving_obstacles:\n"
                                  "  - {radius: 0.2, waypoints: [[0.5, 0.5], [2.5, 0.5]], speed: -0.5}\n")
    fails(path, str(path), "moving_obstacles[0].speed", "-0.5", "must be > 0")


@pytest.mark.parametrize("extra,key,value", [
    ("max_steps: 0\n", "max_steps", "0"),
    ("goal_tolerance: -1\n", "goal_tolerance", "-1"),
    ("lidar: {beams: 0}\n", "lidar.beams", "0"),
    ("robot: {limits: {v_max: -1}}\n", "robot.limits.v_max", "-1"),
    ("robot: {footprint: {radius: 0}}\n", "robot.footprint.radius", "0"),
    ("planner: {preset: fastest}\n", "planner.preset", "'fastest'"),
    ("planner: {overrides: {dt: -0.1}}\n", "planner.overrides.dt", "-0.1"),
    ("planner: {overrides: {normalization: median}}\n", "planner.overrides.normalization", "'median'"),
    ("planner: {overrides: {safety_margin: -0.01}}\n", "planner.overrides.safety_margin", "-0.01"),
    ("planner: {overrides: {key_node_sight: sometimes}}\n", "planner.overrides.key_node_sight", "'sometimes'"),
    ("planner: {overrides: {critics: [{name: speed, weight: 1}]}}\n", "planner.overrides.critics[0].name", "'speed'"),
    ("global_planner: {method: dijkstra}\n", "global_planner.method", "'dijkstra'"),
    ("global_planner: {options: {inflation_radius: -1}}\n", "global_planner.options.inflation_radius", "-1"),
    ("moving_obstacles: [{radius: 0.2, waypoints: [[0, 0], [1, 1]], speed: 1, mode: zigzag}]\n",
     "moving_obstacles[0].mode", "'zigzag'"),
    ("unknown_obstacles: [[1.0, 1.0, 0.5, 1.2]]\n", "unknown_obstacles[0]", "[1.0, 1.0, 0.5, 1.2]"),
    ("unknown_obstacles: [[1.0, 1.0, 9.0, 1.2]]\n", "unknown_obstacles[0]", "[1.0, 1.0, 9.0, 1.2]"),
    ("variability: {lidar_noise_std: -0.01}\n", "variability.lidar_noise_std", "-0.01"),
    ("variability: {lidar_dropout: 1.0}\n", "variability.lidar_dropout", "1.0"),
])
def test_bad_values_name_key_and_value(tmp_path, extra, key, value):
    path = write(tmp_path, TINY + extra)
    fails(path, str(path), key, value)


def test_movers_share_known(tmp_path):
    path = write(tmp_path, TINY + "moving_obstacles:\n"
                                  "  - {radius: 0.2, start: [0.5, 1.2], known: true}\n"
                                  "  - {radius: 0.2, start: [2.5, 1.2], known: false}\n")
    fails(path, str(path), "moving_obstacles[1].known", "False", "moving_obstacles[0].known")


def test_start_inside_obstacle(tmp_path):
    path = write(tmp_path, TINY.replace("start: [0.75, 0.75, 0]", "start: [1.25, 0.25, 90]"))
    fails(path, str(path), "start", "[1.25, 0.25, 90]", "overlaps an obstacle")


def test_start_inside_unknown_obstacle(tmp_path):
    path = write(tmp_path, TINY + "unknown_obstacles: [[0.5, 0.5, 1.0, 1.0]]\n")
    fails(path, str(path), "start", "[0.75, 0.75, 0]", "unknown obstacle")


def test_goal_off_map(tmp_path):
    path = write(tmp_path, TINY.replace("goal: [2.75, 1.25]", "goal: [3.5, 1.25]"))
    fails(path, str(path), "goal", "[3.5, 1.25]", "off the map")


def test_goal_inside_obstacle(tmp_path):
    path = write(tmp_path, TINY.replace("goal: [2.75, 1.25]", "goal: [1.25, 0.25]"))
    fails(path, str(path), "goal", "[1.25, 0.25]", "inside an obstacle")


def test_goal_unreachable(tmp_path):
    walled = TINY.replace("    ......\n    ......\n    ..#...\n", "    ...#..\n    ...#..\n    ..##..\n")
    path = write(tmp_path, walled)
    fails(path, str(path), "goal", "[2.75, 1.25]", "no global path")


def test_goal_on_impassable_terrain(tmp_path):
    path = write(tmp_path, TINY + "terrain:\n  ascii: |\n    .....4\n    ......\n    ......\n")
    fails(path, str(path), "goal", "[2.75, 1.25]", "grade 4")


def test_terrain_shape_mismatch(tmp_path):
    path = write(tmp_path, TINY + "terrain:\n  ascii: |\n    0000\n    0000\n")
    fails(path, str(path), "terrain.ascii", "0000", "2 rows x 4 characters", "3 x 6 cells")


def test_terrain_npy_shape_mismatch(tmp_path):
    np.save(tmp_path / "grades.npy", np.zeros((5, 5), dtype=np.uint8))
    path = write(tmp_path, TINY + "terrain: {npy: grades.npy}\n")
    fails(path, str(path), "terrain.npy", "'grades.npy'", "shape 5 x 5", "3 x 6 cells")


def test_terrain_bad_grade(tmp_path):
    path = write(tmp_path, TINY + "terrain:\n  ascii: |\n    000000\n    000500\n    000000\n")
    fails(path, str(path), "terrain.ascii", "'5'", "row 2", "column 4")


def test_ragged_ascii(tmp_path):
    path = write(tmp_path, "map:\n  ascii: |\n    ....\n    ...\nstart: [0.05, 0.05]\ngoal: [0.15, 0.05]\n")
    fails(path, str(path), "map.ascii", "'...'", "row 2")


def test_malformed_yaml(tmp_path):
    path = write(tmp_path, TINY + "lidar: {beams: [1, 2\n")
    fails(path, str(path), "malformed YAML", "line 11")


def test_duplicate_key(tmp_path):
    path = write(tmp_path, TINY + "max_steps: 3\nmax_steps: 4\n")
    fails(path, str(path), "duplicate key 'max_steps'", "line 11")


def test_missing_referenced_file(tmp_path):
    path = write(tmp_path, "map: {png: rooms/missing.png, resolution: 0.1}\nstart: [0.5, 0.5]\ngoal: [1, 1]\n")
    fails(path, str(path), "map.png", "'rooms/missing.png'", "no such file", str(tmp_path / "rooms" / "missing.png"))


def test_missing_scenario_file(tmp_path):
    fails(str(tmp_path / "nowhere.yaml"), "nowhere.yaml", "no such scenario file")


def test_text_is_named_text():
    fails(TINY + "max_steps: many\n", "<text>", "max_steps", "'many'")


def test_top_level_must_be_a_mapping():
    fails("- map\n- start\n", "<text>", "mapping")


def test_required_keys():
    fails("map: {size: [1, 1]}\ngoal: [0.5, 0.5]\n", "<text>", "start", "required")


def test_neither_name_file_nor_text():
    message = fails("e9", "'e9'", "shipped")
    assert all(name in message for name in ("e1", "e2", "e3", "demo"))


def test_scientific_notation_is_a_number():
    assert load_scenario(TINY + "goal_tolerance: 1e-1\n").goal_tolerance == pytest.approx(0.1)


def test_no_python_errors_leak():
    """Odd but parseable documents still end in FgdwaError, never KeyError or TypeError."""
    for text in ["map: 3\nstart: [0, 0]\ngoal: [1, 1]\n",
                 "map: {ascii: 3}\nstart: [0, 0]\ngoal: [1, 1]\n",
                 TINY + "moving_obstacles: {radius: 1}\n",
                 TINY + "moving_obstacles: [3]\n",
                 TINY + "unknown_obstacles: 5\n",
                 TINY + "robot: {footprint: {polygon: [[0, 0], [1]]}}\n",
                 TINY + "planner: {overrides: {critics: heading}}\n",
                 "map: {size: [1, 1]}\nstart: {x: 0.75}\ngoal: [0.5, 0.5]\n",
                 TINY + "global_planner: {options: [1, 2]}\n",
                 "? [1, 2]\n: 3\n"]:
        with pytest.raises(fgdwa.FgdwaError):
            load_scenario(text)


def test_planner_overrides_are_the_bound_params_fields(tmp_path):
    from fgdwa.sim.scenario import PARAM_FIELDS

    assert {"safety_margin", "key_nodes", "critics", "dt"} <= set(PARAM_FIELDS)
    defaults = fgdwa.PlannerParams()
    assert all(hasattr(defaults, name) for name in PARAM_FIELDS)
    path = write(tmp_path, TINY + "planner: {preset: gdwa, overrides: {safety_margin: 0.05, "
                 "key_nodes: {require_sight: true, min_turn_deg: 20}}}\n")
    scenario = load_scenario(path)
    assert scenario.overrides == {"safety_margin": 0.05, "key_nodes.require_sight": True,
                                  "key_nodes.min_turn": 20 * math.pi / 180.0}


def test_constructor_keywords_are_the_schemas_fields():
    from fgdwa.sim.scenario import init_keywords

    names = init_keywords(fgdwa.NavigatorParams)
    assert names[:3] == ("footprint_padding", "path_margin", "replan_period")
    assert {"occupancy", "segment", "tracker", "learn_obstacles", "mover_margin"} <= set(names)
    assert all(hasattr(fgdwa.NavigatorParams(), name) for name in names)
    assert init_keywords(fgdwa.RobotLimits) == ("v_min", "v_max", "omega_max", "acc_v", "acc_omega", "brake_v",
                                                "brake_omega")


# --- limits: numbers a file may give (fgdwa.file_limits) -------------------------------------------------------------


@pytest.mark.parametrize("text,key,message", [
    (TINY.replace("resolution: 0.5", "resolution: 1e308"), "map.resolution", "must be <= 1000"),
    (TINY.replace("resolution: 0.5", "resolution: 1e-9"), "map.resolution", "must be >= 0.0001"),
    ("map: {size: [1e5, 1e5], resolution: 0.001}\nstart: [1, 1]\ngoal: [2, 2]\n", "map.size", "MAX_MAP_CELLS"),
    (TINY.replace("resolution: 0.5", "resolution: 0.5\n  cells_per_char: 100000"), "map.ascii", "MAX_MAP_CELLS"),
    (TINY.replace("resolution: 0.5", "resolution: 0.5\n  origin: [1e7, 0]"), "map.origin[0]", "MAX_COORDINATE"),
    (TINY.replace("resolution: 0.5", "resolution: 1000\n  origin: [999999, 0]"), "map", "corners must lie"),
    (TINY + "lidar: {beams: 1000000000}\n", "lidar.beams", "must be <= 1e+05"),
    (TINY + "lidar: {max_range: 1e300}\n", "lidar.max_range", "must be <= 1e+06 (m)"),
    (TINY.replace("start: [0.75, 0.75, 0]", "start: [1e300, 0.75, 0]"), "start[0]", "MAX_COORDINATE"),
    (TINY.replace("start: [0.75, 0.75, 0]", "start: {x: 0.75, y: -1e7}"), "start.y", "MAX_COORDINATE"),
    (TINY.replace("goal: [2.75, 1.25]", "goal: [2.75, 1e7]"), "goal[1]", "MAX_COORDINATE"),
    (TINY + "max_steps: 1000000000\n", "max_steps", "MAX_STEPS"),
    (TINY + "goal_tolerance: 1e300\n", "goal_tolerance", "MAX_LENGTH"),
    (TINY + "moving_obstacles: [{radius: 0.1, start: [2, 1], start_delay: 1e9}]\n",
     "moving_obstacles[0].start_delay", "MAX_DURATION"),
    (TINY + "moving_obstacles: [{radius: 0.1, start: [2, 1], velocity: [1e6, 0]}]\n",
     "moving_obstacles[0].velocity[0]", "MAX_SPEED"),
    (TINY + "moving_obstacles: [{radius: 0.1, waypoints: [[2, 1], [2, 1e300]], speed: 1}]\n",
     "moving_obstacles[0].waypoints[1][1]", "MAX_COORDINATE"),
    (TINY + "robot: {limits: {v_max: 1e9}}\n", "robot.limits.v_max", "MAX_SPEED"),
    (TINY + "robot: {footprint: {radius: 1e300}}\n", "robot.footprint.radius", "MAX_LENGTH"),
    (TINY + "planner: {overrides: {sim_time: 1e300}}\n", "planner.overrides.sim_time", "must be <= 3600 (s)"),
    (TINY + "planner: {overrides: {dt: 1e-9}}\n", "planner.overrides.dt", "must be >= 1e-04 (s)"),
    (TINY + "planner: {overrides: {dt: 1e-4}}\n", "planner.overrides", "poses, more than 10000000"),
    (TINY + "planner: {overrides: {window: {n_v: 1000, n_omega: 1000}}}\n", "planner.overrides",
     "poses, more than 10000000"),
    (TINY + "planner: {overrides: {window: {n_v: 1000000}}}\n", "planner.overrides.window.n_v", "must be <= 10000"),
    (TINY + "planner: {overrides: {critics: [{name: heading, weight: 1e300}]}}\n",
     "planner.overrides.critics[0].weight", "MAX_MAGNITUDE"),
    (TINY + "global_planner: {options: {inflation_radius: 1e300}}\n", "global_planner.options.inflation_radius",
     "must be <= 1e+06 (m)"),
    (TINY + "variability: {start_xy_std: 1e300}\n", "variability.start_xy_std", "MAX_LENGTH"),
])
def test_numbers_over_their_limits_name_file_and_key(tmp_path, text, key, message):
    path = write(tmp_path, text)
    fails(path, str(path), f"{key} = ", message)


def test_a_start_within_the_goal_tolerance_would_succeed_at_once(tmp_path):
    path = write(tmp_path, TINY + "goal_tolerance: 2.5\n")
    fails(path, str(path), "goal_tolerance = 2.5", "every run would succeed")
    path = write(tmp_path, TINY + "planner: {overrides: {goal_tolerance: 2.5}}\n")
    fails(path, str(path), "planner.overrides.goal_tolerance = 2.5", "every run would succeed")
    near = TINY.replace("goal: [2.75, 1.25]", "goal: [0.75, 0.95]")
    fails(write(tmp_path, near), "goal = [0.75, 0.95]", "within the goal tolerance 0.3 m")


def test_lists_are_bounded(tmp_path, monkeypatch):
    from fgdwa import file_limits

    monkeypatch.setattr(file_limits, "MAX_COUNT", 3)
    movers = "".join(f"  - {{radius: 0.1, start: [2.{i}, 1]}}\n" for i in range(4))
    fails(write(tmp_path, TINY + "moving_obstacles:\n" + movers), "moving_obstacles = ", "more than 3 items")
    route = TINY + "moving_obstacles: [{radius: 0.1, waypoints: [[2, 1], [2.1, 1], [2.2, 1], [2.3, 1]], speed: 1}]\n"
    fails(write(tmp_path, route), "moving_obstacles[0].waypoints = ", "more than 3 items")


def _npy_header_only(path, shape, dtype=np.uint8):
    """A .npy file whose header announces ``shape`` but holds 16 bytes of data."""
    with open(path, "wb") as handle:
        np.lib.format.write_array_header_1_0(handle, {"descr": np.lib.format.dtype_to_descr(np.dtype(dtype)),
                                                      "fortran_order": False, "shape": shape})
        handle.write(bytes(16))


def test_npy_map_over_the_cell_limit_is_refused_from_its_header(tmp_path):
    _npy_header_only(tmp_path / "huge.npy", (20_000, 20_000))
    path = write(tmp_path, "map: {npy: huge.npy, resolution: 0.1}\nstart: [0.5, 0.5]\ngoal: [1, 1]\n")
    fails(path, str(path), "map.npy = 'huge.npy'", "20000 x 20000 = 400000000 cells", "MAX_MAP_CELLS")
    _npy_header_only(tmp_path / "grades.npy", (20_000, 20_000))
    fails(write(tmp_path, TINY + "terrain: {npy: grades.npy}\n"), "terrain.npy", "MAX_MAP_CELLS")


def test_npy_map_over_the_byte_limit_is_refused_unread(tmp_path, monkeypatch):
    from fgdwa import file_limits

    np.save(tmp_path / "cells.npy", np.zeros((40, 40)))  # float64: 12 800 bytes
    monkeypatch.setattr(file_limits, "MAX_ARRAY_BYTES", 10_000)
    monkeypatch.setattr(np.lib.format, "read_array", lambda *a, **k: pytest.fail("the data was read"))
    path = write(tmp_path, "map: {npy: cells.npy, resolution: 0.1}\nstart: [0.5, 0.5]\ngoal: [1, 1]\n")
    fails(path, str(path), "map.npy", "12800 bytes", "refused unread")


def test_png_map_over_the_cell_limit_is_refused_before_decoding(tmp_path, monkeypatch):
    matplotlib_image = pytest.importorskip("matplotlib.image")
    from fgdwa import file_limits

    matplotlib_image.imsave(tmp_path / "room.png", np.ones((4, 6, 3)))
    monkeypatch.setattr(file_limits, "MAX_MAP_CELLS", 20)
    monkeypatch.setattr(matplotlib_image, "imread", lambda *a, **k: pytest.fail("the pixels were decoded"))
    path = write(tmp_path, "map: {png: room.png, resolution: 0.5}\nstart: [0.5, 0.5]\ngoal: [1, 1]\n")
    fails(path, str(path), "map.png = 'room.png'", "4 x 6 = 24 cells")


def test_a_robot_may_give_its_true_outline_which_the_referee_judges():
    robot = "robot:\n  footprint: {radius: 0.2}\n  outline: {radius: 0.3}\n"
    scenario = load_scenario(TINY + robot)
    assert scenario.footprint.radius == 0.2 and scenario.outline.radius == 0.3
    fails(TINY + "robot:\n  outline: {radius: -1}\n", "robot.outline.radius", "-1")
    assert load_scenario(TINY).outline is None
