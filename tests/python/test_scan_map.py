"""The log-odds ScanMap against a plain Python reference on random scans.

The reference shares no code with the library: the cells a beam passes are
found by intersecting the beam with every cell square of its bounding box, not
by stepping from cell to cell."""

import numpy as np
import pytest

import fgdwa

RES = 0.1
ROWS, COLS = 30, 40
ORIGIN = (-1.0, -0.5)


def random_world(rng):
    cells = (rng.random((ROWS, COLS)) < 0.04).astype(np.uint8)
    cells[12:18, 15:21] = 0  # room for the robot
    return fgdwa.OccupancyGrid(cells, RES, ORIGIN)


def crossed_cells(a, b):
    """Cells (row, col) whose square the segment a-b passes through."""
    lo = np.floor((np.minimum(a, b) - ORIGIN) / RES).astype(int)
    hi = np.floor((np.maximum(a, b) - ORIGIN) / RES).astype(int)
    cols = np.arange(max(lo[0], 0), min(hi[0], COLS - 1) + 1)
    rows = np.arange(max(lo[1], 0), min(hi[1], ROWS - 1) + 1)
    if len(cols) == 0 or len(rows) == 0:
        return set()
    cc, rr = np.meshgrid(cols, rows)
    x0, y0 = ORIGIN[0] + cc * RES, ORIGIN[1] + rr * RES
    d = np.asarray(b, float) - np.asarray(a, float)
    t_low, t_high = np.zeros(cc.shape), np.ones(cc.shape)
    for axis, low_edge in ((0, x0), (1, y0)):
        if d[axis] == 0.0:
            inside = (a[axis] >= low_edge) & (a[axis] < low_edge + RES)
            t_high = np.where(inside, t_high, -1.0)
            continue
        t1 = (low_edge - a[axis]) / d[axis]
        t2 = (low_edge + RES - a[axis]) / d[axis]
        t_low = np.maximum(t_low, np.minimum(t1, t2))
        t_high = np.minimum(t_high, np.maximum(t1, t2))
    hit = t_low < t_high
    return set(zip(rr[hit].tolist(), cc[hit].tolist()))


def cell_of(p):
    col, row = np.floor((np.asarray(p) - ORIGIN) / RES).astype(int)
    return (row, col) if 0 <= row < ROWS and 0 <= col < COLS else None


class ReferenceMap:
    def __init__(self, params):
        self.p = params
        self.log_odds = np.zeros((ROWS, COLS))
        self.state = np.zeros((ROWS, COLS), dtype=np.uint8)  # 0 unknown, 1 free, 2 occupied

    def update(self, cell, delta):
        p = self.p
        value = min(max(self.log_odds[cell] + delta, p.clamp_min), p.clamp_max)
        self.log_odds[cell] = value
        if value >= p.occupied:
            self.state[cell] = 2
        elif value <= p.free or self.state[cell] == 0:
            self.state[cell] = 1

    def integrate(self, scan):
        p = self.p
        origin = np.array([scan.pose.x, scan.pose.y])
        angles = scan.pose.theta + scan.angles
        hits, passes = {}, {}
        for r, a in zip(scan.ranges, angles):
            direction = np.array([np.cos(a), np.sin(a)])
            hit = cell_of(origin + (r + 2 * p.range_std + 1e-6 * RES) * direction) if np.isfinite(r) else None
            if hit is not None:
                hits[hit] = hits.get(hit, 0) + 1
            reach = min(r - 3 * p.range_std if np.isfinite(r) else scan.max_range, p.clear_range)
            if reach > 0:
                for cell in crossed_cells(origin, origin + reach * direction) - {hit}:
                    passes[cell] = passes.get(cell, 0) + 1
        for cell in set(hits) | set(passes):
            h, n = hits.get(cell, 0), passes.get(cell, 0)
            self.update(cell, p.hit if h > 0 and h >= p.hit_share * (h + n) else p.miss)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_log_odds_update_matches_the_reference_on_random_scans(seed):
    rng = np.random.default_rng(seed)
    truth = random_world(rng)
    # Ranges of 2-5 m: beams leave the 4 m x 3 m layout, some with no return.
    lidar = fgdwa.LidarParams(beams=181, max_range=float(rng.uniform(2.0, 5.0)), noise_std=0.03)
    scanner = fgdwa.LaserScanner(lidar, fgdwa.DistanceField(truth))
    params = fgdwa.OccupancyParams(range_std=0.03, clear_range=float(rng.uniform(1.5, 6.0)),
                                   hit_share=float(rng.uniform(0.1, 0.6)))
    scan_map = fgdwa.ScanMap(truth, params)
    reference = ReferenceMap(params)
    for k in range(8):
        pose = (ORIGIN[0] + RES * rng.uniform(15.5, 20.5), ORIGIN[1] + RES * rng.uniform(12.5, 17.5),
                rng.uniform(-np.pi, np.pi))
        scan = scanner.scan(pose, seed=int(rng.integers(1 << 30)))
        scan_map.integrate(scan)
        reference.integrate(scan)
        np.testing.assert_allclose(scan_map.log_odds, reference.log_odds, atol=1e-5, err_msg=f"scan {k}")
        np.testing.assert_array_equal(scan_map.states, reference.state, err_msg=f"scan {k}")
        np.testing.assert_array_equal(scan_map.grid.cells, (reference.state == 2).astype(np.uint8))
    assert scan_map.known_count == int(np.count_nonzero(reference.state))
    assert scan_map.occupied_count == int(np.count_nonzero(reference.state == 2))


def test_a_spurious_hit_fades_and_the_field_follows():
    truth = fgdwa.OccupancyGrid(np.zeros((ROWS, COLS), dtype=np.uint8), RES, ORIGIN)
    scan_map = fgdwa.ScanMap(truth)
    assert scan_map.mark([[1.05, 1.05]]) == 1
    field = scan_map.field()
    assert field.distance([[1.5, 1.05]])[0] == pytest.approx(0.4, abs=1e-9)
    walls = np.zeros((ROWS, COLS), dtype=np.uint8)
    walls[:, -1] = 1
    scanner = fgdwa.LaserScanner(fgdwa.LidarParams(beams=361), fgdwa.DistanceField(
        fgdwa.OccupancyGrid(walls, RES, ORIGIN)))
    # One hit (0.85) takes four passes (-0.4 each) to reach the free threshold -0.5.
    for k in range(3):
        scan_map.integrate(scanner.scan((0.5, 1.05, 0.0), seed=k))
    assert scan_map.states[15, 20] == 2
    scan_map.integrate(scanner.scan((0.5, 1.05, 0.0), seed=3))
    assert scan_map.states[15, 20] == 1
    assert not scan_map.field().distance([[1.5, 1.05]])[0] < 1.0
    np.testing.assert_array_equal(scan_map.field().cells, fgdwa.DistanceField(scan_map.grid).cells)


def test_bad_occupancy_settings_name_the_field():
    with pytest.raises(fgdwa.FgdwaError, match="miss"):
        fgdwa.OccupancyParams(miss=0.2)
    with pytest.raises(fgdwa.FgdwaError, match="range_std"):
        fgdwa.OccupancyParams(range_std=float("nan"))
    scan_map = fgdwa.ScanMap(fgdwa.OccupancyGrid(np.zeros((4, 4), dtype=np.uint8), RES, ORIGIN))
    scanner = fgdwa.LaserScanner(fgdwa.LidarParams(beams=11), None)
    with pytest.raises(fgdwa.FgdwaError, match="keep_hit"):
        scan_map.integrate(scanner.scan((0.0, 0.0, 0.0)), keep_hit=np.ones(3, dtype=np.uint8))
