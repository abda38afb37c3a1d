import numpy as np
import pytest
from scipy import ndimage

import fgdwa
from conftest import brute_force_square_distance, random_block_grid


@pytest.mark.parametrize("seed", range(10))
def test_cell_distances_equal_scipy_edt(seed):
    rng = np.random.default_rng(seed)
    cells = (rng.random((37, 53)) < rng.uniform(0.01, 0.4)).astype(np.uint8)
    field = fgdwa.DistanceField(fgdwa.OccupancyGrid(cells, 0.15, (1.0, -2.0)))
    expected = ndimage.distance_transform_edt(cells == 0) * 0.15
    np.testing.assert_allclose(field.cells, expected, rtol=0, atol=1e-12)


@pytest.mark.parametrize("seed", range(10))
def test_point_distance_is_exact_inside_the_grid(seed):
    rng = np.random.default_rng(100 + seed)
    cells = random_block_grid(rng)
    origin = (-1.0, 0.5)
    field = fgdwa.DistanceField(fgdwa.OccupancyGrid(cells, 0.1, origin))
    points = np.column_stack([rng.uniform(-1.0, 7.0, 4000), rng.uniform(0.5, 6.5, 4000)])
    exact = brute_force_square_distance(points, cells, 0.1, origin)
    np.testing.assert_allclose(field.distance(points), exact, rtol=0, atol=1e-9)


def test_point_distance_outside_the_grid_is_a_lower_bound(rng):
    cells = random_block_grid(rng)
    field = fgdwa.DistanceField(fgdwa.OccupancyGrid(cells, 0.1))
    points = np.column_stack([rng.uniform(-3.0, 11.0, 4000), rng.uniform(-3.0, 9.0, 4000)])
    outside = (points[:, 0] < 0) | (points[:, 0] > 8) | (points[:, 1] < 0) | (points[:, 1] > 6)
    exact = brute_force_square_distance(points[outside], cells, 0.1, (0.0, 0.0))
    got = field.distance(points[outside])
    assert np.all(got <= exact + 1e-9)
    assert np.all(got >= 0.0)


@pytest.mark.parametrize("margin", [0.0, 0.45, None])
def test_point_distance_past_the_edge_is_exact_with_or_without_a_margin(rng, margin):
    cells = random_block_grid(rng)
    grid = fgdwa.OccupancyGrid(cells, 0.1)
    field = fgdwa.DistanceField(grid) if margin is None else fgdwa.DistanceField(grid, edge_margin=margin)
    # Whole cells, rounded up: 0.45 m is 5 cells of 0.1 m.
    assert field.edge_margin == pytest.approx({None: 3.0, 0.0: 0.0, 0.45: 0.5}[margin], abs=1e-12)
    assert field.grid.shape == grid.shape
    points = np.column_stack([rng.uniform(-4.0, 12.0, 2000), rng.uniform(-4.0, 10.0, 2000)])
    exact = brute_force_square_distance(points, cells, 0.1, (0.0, 0.0))
    np.testing.assert_allclose(field.distance(points), exact, rtol=0, atol=1e-9)


def test_edge_margin_comes_from_previous_when_it_is_given(rng):
    grid = fgdwa.OccupancyGrid(random_block_grid(rng), 0.1)
    previous = fgdwa.DistanceField(grid, edge_margin=0.5)
    assert fgdwa.DistanceField(grid, previous).edge_margin == pytest.approx(0.5)
    with pytest.raises(fgdwa.FgdwaError, match="edge_margin"):
        fgdwa.DistanceField(grid, previous, edge_margin=1.0)
    with pytest.raises(fgdwa.FgdwaError, match="edge_margin"):
        fgdwa.OccupancyParams(edge_margin=-0.5)


def test_no_obstacle_gives_infinity(open_world):
    field = fgdwa.DistanceField(open_world)
    assert np.all(np.isinf(field.cells))
    assert np.isinf(field.distance(np.array([[1.0, 1.0]]))[0])


def test_inside_an_obstacle_is_zero():
    cells = np.zeros((10, 10), dtype=np.uint8)
    cells[4, 6] = 1
    field = fgdwa.DistanceField(fgdwa.OccupancyGrid(cells, 0.5))
    assert field.distance(np.array([[3.25, 2.25]]))[0] == 0.0
    assert field.distance(np.array([[4.0, 2.25]]))[0] == pytest.approx(0.5)


def test_update_from_a_previous_field_matches_a_fresh_build(rng):
    cells = random_block_grid(rng)
    before = fgdwa.DistanceField(fgdwa.OccupancyGrid(cells, 0.1))
    added = cells.copy()
    added[rng.integers(0, cells.shape[0], 12), rng.integers(0, cells.shape[1], 12)] = 1
    grid = fgdwa.OccupancyGrid(added, 0.1)
    updated = fgdwa.DistanceField(grid, previous=before)
    fresh = fgdwa.DistanceField(grid)
    points = np.column_stack([rng.uniform(-1.0, 9.0, 4000), rng.uniform(-1.0, 7.0, 4000)])
    np.testing.assert_array_equal(updated.distance(points), fresh.distance(points))
    np.testing.assert_array_equal(updated.cells, fresh.cells)
    other = fgdwa.OccupancyGrid(np.zeros((5, 5), np.uint8), 0.1)
    with pytest.raises(fgdwa.FgdwaError, match="layout"):
        fgdwa.DistanceField(other, previous=before)
