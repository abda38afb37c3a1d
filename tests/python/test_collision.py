import numpy as np
import pytest

import fgdwa
from conftest import random_block_grid


def random_free_poses(rng, truth, footprint, n, extent):
    poses = []
    while len(poses) < n:
        pose = (rng.uniform(0, extent[0]), rng.uniform(0, extent[1]), rng.uniform(-np.pi, np.pi))
        if not truth.in_collision(footprint, pose):
            poses.append(pose)
    return np.array(poses)


@pytest.mark.parametrize("footprint", [fgdwa.Footprint.circle(0.25),
                                       fgdwa.Footprint.polygon([[0.21, 0.165], [-0.21, 0.165],
                                                                [-0.21, -0.165], [0.21, -0.165]])])
def test_field_clearance_agrees_with_fcl_within_one_cell(footprint):
    rng = np.random.default_rng(7)
    cells = random_block_grid(rng, rows=100, cols=100, blocks=60, max_size=10)
    grid = fgdwa.OccupancyGrid(cells, 0.1)
    truth = fgdwa.CollisionWorld(grid)
    fast = fgdwa.FieldClearance(fgdwa.DistanceField(grid))
    poses = random_free_poses(rng, truth, footprint, 300, (10.0, 10.0))
    exact = truth.clearance(footprint, poses)
    approx = fast.clearance(footprint, poses)
    near = exact < 2.0
    assert near.sum() > 100
    assert np.max(np.abs(exact[near] - approx[near])) <= 0.1


def test_merged_boxes_cover_exactly_the_occupied_cells(rng):
    cells = random_block_grid(rng, rows=100, cols=100, blocks=40)
    world = fgdwa.CollisionWorld(fgdwa.OccupancyGrid(cells, 0.1))
    covered = np.zeros_like(cells, dtype=int)
    for row, col, rows, cols in world.boxes:
        covered[row:row + rows, col:col + cols] += 1
    np.testing.assert_array_equal(covered, cells.astype(int))
    assert len(world.boxes) < cells.sum() / 4


def test_moving_disc_distance():
    footprint = fgdwa.Footprint.circle(0.3)
    disc = fgdwa.Disc((2.0, 0.0), 0.2, velocity=(-0.5, 0.0))
    world = fgdwa.CollisionWorld(discs=[disc])
    assert world.clearance(footprint, (0.0, 0.0, 0.0), 0.0) == pytest.approx(1.5, abs=1e-6)
    assert world.clearance(footprint, (0.0, 0.0, 0.0), 2.0) == pytest.approx(0.5, abs=1e-6)
    assert world.in_collision(footprint, (0.0, 0.0, 0.0), 3.1)
    fast = fgdwa.FieldClearance(None, [disc])
    assert fast.clearance(footprint, (0.0, 0.0, 0.0), 2.0) == pytest.approx(0.5, abs=1e-12)


def test_discs_read_back_are_copies_that_outlive_a_replacement():
    # A disc read from a world must stay valid after the world's discs are replaced
    # (or a controller's next step replaces them): views into the vector would dangle.
    import fgdwa

    for world in (fgdwa.FieldClearance(None, [fgdwa.Disc((1.0, 1.0), 0.3)] * 2000),
                  fgdwa.CollisionWorld(None, [fgdwa.Disc((1.0, 1.0), 0.3)] * 2000)):
        kept = world.discs[1000]
        world.discs = []
        world.discs = [fgdwa.Disc((5.0, 5.0), 0.1)] * 3000
        assert tuple(kept.center) == (1.0, 1.0) and kept.radius == 0.3


def test_an_accelerating_disc_as_worked_out_by_hand():
    # From rest 5 m off, pulled at 2 m/s^2 for 1 s: at 4 m moving at 2 m/s, then 1 m off at 2.5 s.
    disc = fgdwa.Disc((5.0, 0.0), 0.0, acceleration=(-2.0, 0.0), accel_time=1.0)
    assert disc.center_at(0.5) == pytest.approx((4.75, 0.0))
    assert disc.center_at(2.0) == pytest.approx((2.0, 0.0))
    assert disc.acceleration == (-2.0, 0.0) and disc.accel_time == 1.0
    assert disc.time_to_reach((0.0, 0.0), 1.0) == pytest.approx(2.5)
    assert "accel_time=1" in repr(disc)
