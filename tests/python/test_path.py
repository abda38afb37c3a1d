import numpy as np
import pytest

import fgdwa


def key_nodes(points, angle=np.radians(10.0)):
    return fgdwa.GlobalPath(np.array(points, dtype=float)).key_nodes(angle)


def test_key_nodes_of_hand_made_polylines():
    assert key_nodes([[0, 0], [5, 0]]) == [1]
    assert key_nodes([[0, 0], [2, 0], [2, 3]]) == [1, 2]  # L
    assert key_nodes([[0, 0], [1, 1], [2, 0], [3, 1], [4, 0]]) == [1, 2, 3, 4]  # zig-zag
    # Collinear and repeated points make no key node; repeats are dropped first.
    assert key_nodes([[0, 0], [1, 0], [1, 0], [2, 0], [3, 0], [3, 2]]) == [3, 4]
    # A turn of 5 degrees is below the default 10.
    assert key_nodes([[0, 0], [1, 0], [2, np.tan(np.radians(5))]]) == [2]
    assert key_nodes([[0, 0], [1, 0], [2, np.tan(np.radians(5))]], angle=np.radians(4.0)) == [1, 2]


def test_projection_deviation_and_walking_on_a_vertical_segment():
    path = fgdwa.GlobalPath([[0.0, 0.0], [0.0, 4.0], [3.0, 4.0]])
    proj = path.project((1.0, 2.5))
    assert proj.point == pytest.approx((0.0, 2.5))
    assert proj.segment == 0 and proj.arc_length == pytest.approx(2.5) and proj.distance == pytest.approx(1.0)
    assert path.deviation((2.0, 5.0)) == pytest.approx(1.0)
    assert path.length == pytest.approx(7.0)
    assert path.point_at(5.5) == pytest.approx((1.5, 4.0))
    assert path.point_at(-1.0) == pytest.approx((0.0, 0.0)) and path.point_at(99.0) == pytest.approx((3.0, 4.0))
    assert path.segment_direction(0) == pytest.approx(np.pi / 2)
    assert path.segment_direction(1) == pytest.approx(0.0)


def test_bad_paths():
    with pytest.raises(fgdwa.FgdwaError, match="at least 2"):
        fgdwa.GlobalPath(np.zeros((1, 2)))
    with pytest.raises(fgdwa.FgdwaError, match="coincide"):
        fgdwa.GlobalPath(np.ones((3, 2)))
    with pytest.raises(fgdwa.FgdwaError, match="not finite"):
        fgdwa.GlobalPath([[0, 0], [np.nan, 1]])
    with pytest.raises(fgdwa.FgdwaError, match="shape"):
        fgdwa.GlobalPath(np.zeros((3, 3)))
    with pytest.raises(fgdwa.FgdwaError, match=r"planner.key_nodes.min_turn = -1: must be >= 0 \(rad\)"):
        fgdwa.PlannerParams(key_nodes={"min_turn": -1.0})
    with pytest.raises(fgdwa.FgdwaError, match="planner.key_nodes.reach_radius = nan: must be finite"):
        fgdwa.PlannerParams(key_nodes={"reach_radius": float("nan")})
    with pytest.raises(fgdwa.FgdwaError, match="heading_target"):
        fgdwa.PlannerParams(heading_target="path")


def test_key_node_target_switching():
    """The target is the first key node not reached: within the radius, or passed along the path."""
    planner = fgdwa.LocalPlanner(fgdwa.RobotLimits(), fgdwa.Footprint.circle(0.2),
                                 fgdwa.PlannerParams(heading_target="key_nodes", key_nodes={"reach_radius": 1.0}))
    world = fgdwa.FieldClearance()
    with pytest.raises(fgdwa.FgdwaError, match="global path"):
        planner.plan(fgdwa.RobotState((0, 0, 0)), (10, 10), world)
    planner.set_global_path([[0, 0], [5, 0], [5, 5], [10, 5]])
    assert planner.key_nodes == [1, 2, 3]
    plan = lambda x, y: planner.plan(fgdwa.RobotState((x, y, 0.0)), (10, 5), world)
    assert plan(0.0, 0.0).target == (5.0, 0.0) and planner.last_key_node == 0 if hasattr(planner, "last_key_node") else True
    r = plan(3.5, 0.3)
    assert r.target == (5.0, 0.0) and r.key_node == 0
    r = plan(4.2, 0.3)  # within 1 m of (5, 0)
    assert r.target == (5.0, 5.0) and r.key_node == 1
    r = plan(4.0, 0.0)  # going back does not bring a reached node back
    assert r.target == (5.0, 5.0)
    r = plan(5.5, 3.0)  # still short of (5, 5) along the path
    assert r.target == (5.0, 5.0)
    r = plan(7.0, 5.5)  # projection passed (5, 5)
    assert r.target == (10.0, 5.0) and r.key_node == 2
    goal_mode = fgdwa.LocalPlanner(fgdwa.RobotLimits(), fgdwa.Footprint.circle(0.2))
    r = goal_mode.plan(fgdwa.RobotState((0, 0, 0)), (10, 5), world)
    assert r.target == (10.0, 5.0) and r.key_node == -1


@pytest.mark.parametrize("sight", [True, False])
def test_a_near_key_node_is_kept_while_the_next_is_out_of_sight(sight):
    cells = np.zeros((80, 120), np.uint8)
    cells[20:22, 30:49] = 1  # a wall at y = 2.0 from x = 3.0 to 4.9: it hides (5, 5) from (4.2, 0.3)
    world = fgdwa.FieldClearance(fgdwa.DistanceField(fgdwa.OccupancyGrid(cells, 0.1)))
    params = fgdwa.PlannerParams(heading_target="key_nodes", key_nodes={"reach_radius": 1.0, "require_sight": sight})
    planner = fgdwa.LocalPlanner(fgdwa.RobotLimits(), fgdwa.Footprint.circle(0.2), params)
    planner.set_global_path([[0, 0], [5, 0], [5, 5], [10, 5]])
    r = planner.plan(fgdwa.RobotState((4.2, 0.3, 0.0)), (10, 5), world)
    assert r.target == ((5.0, 0.0) if sight else (5.0, 5.0))
    r = planner.plan(fgdwa.RobotState((5.6, 0.5, 1.5)), (10, 5), world)  # past the wall's end: in sight
    assert r.target == (5.0, 5.0)
