"""Keyframed movers against positions worked out by hand from Gazebo's rules
(fgdwa.sim.keyframes): Hermite segments with Catmull-Rom tangents per
keyframe index, the segment's time fraction as parameter, a wrapping clock."""

import numpy as np
import pytest

from fgdwa import FgdwaError
from fgdwa.sim.keyframes import KeyframedMover
from fgdwa.sim.world import World


def state(mover, t):
    position, velocity = mover.state_at(t)
    return np.round(position, 12), np.round(velocity, 12)


def test_a_straight_segment_is_walked_at_even_speed():
    # Two keyframes: both tangents are the chord, and the Hermite cubic is the line itself.
    mover = KeyframedMover(0.5, [[0, 0, 0], [2, 2, 0]])
    np.testing.assert_allclose(mover.state_at(0.5)[0], [0.5, 0.0])
    np.testing.assert_allclose(mover.state_at(0.5)[1], [1.0, 0.0])
    np.testing.assert_allclose(mover.state_at(1.5)[0], [1.5, 0.0])


def test_a_bend_swings_wide_as_the_spline_does():
    # Tangents (1, 0), (0.5, 0.5), (0, 1). At s = 0.5 the Hermite weights are
    # 0.5, 0.5, 0.125, -0.125 (points, tangents): (0.5 + 0.125 - 0.0625, -0.0625),
    # below the polyline's y = 0; the derivative's weights -1.5, 1.5, -0.25, -0.25.
    mover = KeyframedMover(0.5, [[0, 0, 0], [1, 1, 0], [2, 1, 1]], loop=False)
    position, velocity = mover.state_at(0.5)
    np.testing.assert_allclose(position, [0.5625, -0.0625])
    np.testing.assert_allclose(velocity, [1.125, -0.125])
    # A segment twice as long in time: the same curve, half the speed.
    slow = KeyframedMover(0.5, [[0, 0, 0], [1, 1, 0], [3, 1, 1]], loop=False)
    position, velocity = slow.state_at(2.0)
    np.testing.assert_allclose(position, [1.0625, 0.4375])
    np.testing.assert_allclose(velocity, [-0.0625, 0.5625])


def test_a_closed_route_shares_its_end_tangent():
    # First point = last: the end tangents are both 0.5 (p[1] - p[n-2]) = (0.5, -0.5).
    square = KeyframedMover(0.3, [[0, 0, 0], [1, 1, 0], [2, 1, 1], [3, 0, 1], [4, 0, 0]])
    np.testing.assert_allclose(square.state_at(0.5)[0], [0.5, -0.125])
    np.testing.assert_allclose(square.state_at(3.5)[0], [-0.125, 0.5])


def test_the_clock_wraps_and_the_mover_jumps_back():
    mover = KeyframedMover(0.5, [[0, 0, 0], [2, 2, 0]])
    np.testing.assert_allclose(mover.state_at(1.99)[0], [1.99, 0.0])
    np.testing.assert_allclose(mover.state_at(2.0)[0], [0.0, 0.0])  # the jump back to the start
    np.testing.assert_allclose(mover.state_at(2.5)[0], [0.5, 0.0])
    np.testing.assert_allclose(mover.state_at(-0.5)[0], [1.5, 0.0])
    shifted = KeyframedMover(0.5, [[0, 0, 0], [2, 2, 0]], phase=0.5)
    np.testing.assert_allclose(shifted.state_at(0.0)[0], [0.5, 0.0])
    assert mover.period == 2.0


def test_past_the_last_keyframe_it_waits_there():
    # Longer than its keyframes: between the last and the wrap it holds the last point.
    waits = KeyframedMover(0.5, [[0, 0, 0], [2, 2, 0]], length=3.0)
    assert state(waits, 2.5)[0].tolist() == [2.0, 0.0] and state(waits, 2.5)[1].tolist() == [0.0, 0.0]
    np.testing.assert_allclose(waits.state_at(3.5)[0], [0.5, 0.0])
    once = KeyframedMover(0.5, [[0, 0, 0], [2, 2, 0]], loop=False)
    assert state(once, 10.0)[0].tolist() == [2.0, 0.0] and once.period == 0.0
    late = KeyframedMover(0.5, [[1, 0, 0], [3, 2, 0]], loop=False)
    assert state(late, 0.5)[0].tolist() == [0.0, 0.0]  # before its first keyframe, at it


def test_a_keyframe_time_gives_the_keyframe():
    mover = KeyframedMover(0.5, [[0, 0, 0], [1, 1, 0], [2, 1, 1]], loop=False)
    assert state(mover, 1.0)[0].tolist() == [1.0, 0.0]
    np.testing.assert_allclose(mover.state_at(1.0)[1], [0.5, 0.5])  # leaving along its tangent


def test_a_world_places_keyframed_movers_with_the_others():
    mover = KeyframedMover(0.5, [[0, 0, 0], [2, 2, 0]])
    disc = World(movers=(mover,)).discs_at(0.5)[0]
    assert disc.radius == 0.5
    np.testing.assert_allclose(disc.center, [0.5, 0.0])
    np.testing.assert_allclose(disc.velocity, [1.0, 0.0])
    assert mover.route.shape[1] == 2 and len(mover.route) > 2


@pytest.mark.parametrize("kwargs, named", [
    (dict(radius=0.0, keyframes=[[0, 0, 0], [1, 1, 0]]), "radius"),
    (dict(radius=0.5, keyframes=[[0, 0, 0]]), "keyframes"),
    (dict(radius=0.5, keyframes=[[0, 0, 0], [0, 1, 0]]), "keyframes\\[1\\]"),
    (dict(radius=0.5, keyframes=[[-1, 0, 0], [1, 1, 0]]), "keyframes\\[0\\]"),
    (dict(radius=0.5, keyframes=[[0, 0, 0], [1, np.nan, 0]]), "keyframes"),
    (dict(radius=0.5, keyframes="abc"), "keyframes"),
    (dict(radius=0.5, keyframes=[[0, 0, 0], [2, 1, 0]], length=1.0), "length"),
    (dict(radius=0.5, keyframes=[[0, 0, 0], [2, 1, 0]], phase=np.inf), "phase"),
    (dict(radius=0.5, keyframes=[[0, 0, 0], [2, 1, 0]], loop="yes"), "loop"),
])
def test_bad_keyframes_are_refused_by_name(kwargs, named):
    with pytest.raises(FgdwaError, match=named):
        KeyframedMover(**kwargs)


def test_a_scenario_file_gives_keyframed_movers(tmp_path):
    from fgdwa.io.scenario_file import load_scenario

    text = """
map: {size: [6.0, 4.0], resolution: 0.1}
moving_obstacles:
  - radius: 0.4
    keyframes: [[0, 1.0, 1.0], [2, 3.0, 1.0], [4, 3.0, 3.0]]
    loop: true
    length: 5.0
    phase: 1.0
start: [0.5, 2.0, 0]
goal: [5.5, 2.0]
"""
    path = tmp_path / "keyframes.yaml"
    path.write_text(text)
    mover = load_scenario(path).world.movers[0]
    assert isinstance(mover, KeyframedMover) and mover.length == 5.0 and mover.phase == 1.0
    np.testing.assert_allclose(mover.state_at(0.0)[0], KeyframedMover(0.4, [[0, 1, 1], [2, 3, 1], [4, 3, 3]],
                                                                      length=5.0).state_at(1.0)[0])
    bad = text.replace("loop: true", "speed: 1.0")
    path.write_text(bad)
    with pytest.raises(FgdwaError, match=r"moving_obstacles\[0\]\.speed.*keyframes"):
        load_scenario(path)
    path.write_text(text.replace("[2, 3.0, 1.0]", "[2, 3.0]"))
    with pytest.raises(FgdwaError, match=r"moving_obstacles\[0\]\.keyframes\[1\]"):
        load_scenario(path)
    path.write_text(text.replace("[2, 3.0, 1.0]", "[0, 3.0, 1.0]"))
    with pytest.raises(FgdwaError, match=r"keyframes\[1\].*increase"):
        load_scenario(path)
