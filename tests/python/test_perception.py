import numpy as np
import pytest

import fgdwa

R = 2.0


def empty_field():
    return fgdwa.DistanceField(fgdwa.OccupancyGrid(np.zeros((4, 4), np.uint8), 0.1, (-100.0, -100.0)))


def wall_field(x_wall, gap=None):
    """A wall one cell thick whose near face is at x = x_wall, across y in [-5, 5], with an optional gap (y0, y1)."""
    res = 0.01
    cells = np.zeros((1000, 20), np.uint8)
    cells[:, 0] = 1
    if gap is not None:
        y = -5.0 + (np.arange(1000) + 0.5) * res
        cells[(y > gap[0]) & (y < gap[1]), 0] = 0
    return fgdwa.DistanceField(fgdwa.OccupancyGrid(cells, res, (x_wall, -5.0)))


def test_no_obstacle_gives_the_closed_form():
    scan = fgdwa.LaserScanner(fgdwa.LidarParams(), empty_field()).scan((0.0, 0.0, 0.3))
    assert np.all(np.isinf(scan.ranges))
    reading = fgdwa.obstacle_density(scan)
    assert reading.beams == 241  # +-60 deg at 0.5 deg per beam
    assert reading.area_ratio == 0.0
    assert reading.max_gap == pytest.approx(2 * R * np.sin(np.radians(60)))
    assert reading.density == pytest.approx(0.5 ** (2 * R * np.sin(np.radians(60))))


def test_wall_at_the_robot_gives_two():
    field = fgdwa.DistanceField(fgdwa.OccupancyGrid(np.ones((50, 50), np.uint8), 0.1, (-2.5, -2.5)))
    scan = fgdwa.LaserScanner(fgdwa.LidarParams(), field).scan((0.0, 0.0, 0.0))
    assert np.all(scan.ranges == 0.0)
    assert fgdwa.obstacle_density(scan).density == 2.0


@pytest.mark.parametrize("d", [0.5, 1.0, 1.5, 1.9])
def test_wall_across_the_window(d):
    scan = fgdwa.LaserScanner(fgdwa.LidarParams(), wall_field(d)).scan((0.0, 0.0, 0.0))
    angles = scan.angles
    window = np.abs(angles) <= np.radians(60) + 1e-9
    expected_ranges = d / np.cos(angles[window])
    hit = expected_ranges <= 10.0
    np.testing.assert_allclose(scan.ranges[window][hit], expected_ranges[hit], atol=1e-9)
    r = np.minimum(expected_ranges, R)
    area = np.mean(1 - (r / R) ** 2)
    # Free beams (beyond R) form two runs at the window's edges, |a| >= acos(d / R).
    free = expected_ranges >= R
    run = int(free[: len(free) // 2].sum())
    phi = (run - 1) * np.radians(0.5) if run > 1 else 0.0
    reading = fgdwa.obstacle_density(scan)
    assert reading.area_ratio == pytest.approx(area, abs=1e-9)
    assert reading.max_gap == pytest.approx(2 * R * np.sin(phi / 2), abs=1e-9)
    assert reading.density == pytest.approx(min(2.0, area + 0.5 ** reading.max_gap), abs=1e-9)


def test_single_gap_of_known_width():
    # A wall 1 m ahead, 0.01 m thick, with a gap of 0.8 m straight ahead: the free
    # beams are those through the gap's far end, |tan a| < 0.4 / 1.01; their run
    # spans 2 atan(0.4 / 1.01) less up to a beam at each side.
    scan = fgdwa.LaserScanner(fgdwa.LidarParams(beams=2701), wall_field(1.0, gap=(-0.4, 0.4))).scan((0.0, 0.0, 0.0))
    reading = fgdwa.obstacle_density(scan)
    phi = 2 * np.arctan(0.4 / 1.01)
    step = np.radians(0.1)
    assert 2 * R * np.sin((phi - 2 * step) / 2) <= reading.max_gap <= 2 * R * np.sin(phi / 2)


def test_discs_noise_and_determinism():
    lidar = fgdwa.LidarParams(beams=361, max_range=5.0, noise_std=0.02)
    scanner = fgdwa.LaserScanner(lidar, empty_field())
    disc = fgdwa.Disc((2.0, 0.0), 0.5, velocity=(1.0, 0.0))
    clean = fgdwa.LaserScanner(fgdwa.LidarParams(beams=361, max_range=5.0), empty_field())
    assert clean.scan((0, 0, 0), [disc]).ranges[180] == pytest.approx(1.5)
    assert clean.scan((0, 0, 0), [disc], t=1.0).ranges[180] == pytest.approx(2.5)
    a = scanner.scan((0, 0, 0), [disc], seed=7).ranges
    b = scanner.scan((0, 0, 0), [disc], seed=7).ranges
    c = scanner.scan((0, 0, 0), [disc], seed=8).ranges
    np.testing.assert_array_equal(a, b)
    assert not np.array_equal(a[np.isfinite(a)], c[np.isfinite(c)])
    assert abs(a[180] - 1.5) < 0.1


def test_dropped_beams_read_inf_at_the_rate_asked():
    # A wall 1 m ahead in every beam's way: without dropout each beam hits it.
    field = wall_field(1.0)
    lidar = fgdwa.LidarParams(fov=np.pi / 2, beams=2001, dropout=0.1)
    assert lidar.dropout == 0.1
    assert "dropout=0.1" in repr(lidar)
    scanner = fgdwa.LaserScanner(lidar, field)
    ranges = scanner.scan((0.0, 0.0, 0.0), seed=5).ranges
    dropped = np.isinf(ranges)
    # Binomial(2001, 0.1): mean 200, std 13.4; six standard deviations either side.
    assert 120 < dropped.sum() < 280
    clean = fgdwa.LaserScanner(fgdwa.LidarParams(fov=np.pi / 2, beams=2001), field).scan((0.0, 0.0, 0.0)).ranges
    np.testing.assert_array_equal(ranges[~dropped], clean[~dropped])
    np.testing.assert_array_equal(ranges, scanner.scan((0.0, 0.0, 0.0), seed=5).ranges)
    assert not np.array_equal(dropped, np.isinf(scanner.scan((0.0, 0.0, 0.0), seed=6).ranges))
    assert fgdwa.LidarParams().dropout == 0.0


def test_scan_hits_are_sensed_as_obstacles():
    scan = fgdwa.LaserScanner(fgdwa.LidarParams(), wall_field(1.0)).scan((0.0, 0.0, 0.0))
    hits = scan.hit_points
    assert np.allclose(hits[:, 0], 1.0, atol=1e-9)
    sensed = fgdwa.points_field(hits, 0.05)
    world = fgdwa.FieldClearance()
    world.sensed = sensed
    assert world.clearance(fgdwa.Footprint.circle(0.2), (0.0, 0.0, 0.0)) == pytest.approx(0.8, abs=0.06)
    assert fgdwa.points_field(np.zeros((0, 2)), 0.1) is None


def test_perception_bad_input():
    with pytest.raises(fgdwa.FgdwaError, match="beams"):
        fgdwa.LidarParams(beams=0)
    with pytest.raises(fgdwa.FgdwaError, match="max_range"):
        fgdwa.LidarParams(max_range=-1.0)
    with pytest.raises(fgdwa.FgdwaError, match="fov"):
        fgdwa.LidarParams(fov=7.0)
    with pytest.raises(fgdwa.FgdwaError, match="noise_std"):
        fgdwa.LidarParams(noise_std=float("nan"))
    for bad in (-0.1, 1.0, float("nan")):
        with pytest.raises(fgdwa.FgdwaError, match="dropout"):
            fgdwa.LidarParams(dropout=bad)
    with pytest.raises(fgdwa.FgdwaError, match="radius"):
        fgdwa.DetectWindowParams(radius=0.0)
    with pytest.raises(fgdwa.FgdwaError, match="pose"):
        fgdwa.LaserScanner(fgdwa.LidarParams(), empty_field()).scan((0.0, 0.0))
    narrow = fgdwa.LaserScanner(fgdwa.LidarParams(fov=np.pi / 2, beams=2), empty_field()).scan((0, 0, 0))
    with pytest.raises(fgdwa.FgdwaError, match="no lidar beam"):
        fgdwa.obstacle_density(narrow, fgdwa.DetectWindowParams(half_angle=np.radians(10)))


def test_a_scan_measured_elsewhere_matches_the_scanners_own():
    lidar = fgdwa.LidarParams(fov=np.pi, beams=91, max_range=5.0)
    pose = (0.3, -0.2, 0.4)
    own = fgdwa.LaserScanner(lidar, wall_field(1.5, gap=(0.2, 0.6))).scan(pose)
    given = fgdwa.Scan(own.ranges, own.angle_min, own.angle_increment, own.max_range, pose)
    np.testing.assert_array_equal(given.ranges, own.ranges)
    np.testing.assert_allclose(given.angles, lidar.angles)
    np.testing.assert_allclose(given.hit_points, own.hit_points)
    assert fgdwa.obstacle_density(given).density == fgdwa.obstacle_density(own).density
    assert fgdwa.Scan([1.0], 0.0, 0.0, 2.0).pose.x == 0.0


@pytest.mark.parametrize("kwargs, match", [
    (dict(ranges=[1.0, float("nan")]), r"ranges\[1\]"),
    (dict(ranges=[-0.5]), r"ranges\[0\]"),
    (dict(ranges=[[1.0]]), "ranges: expected shape"),
    (dict(ranges="far"), "ranges"),
    (dict(angle_min=float("inf")), "angle_min"),
    (dict(angle_increment=-0.1), "angle_increment"),
    (dict(max_range=0.0), "max_range"),
    (dict(pose=(0.0, 0.0)), "pose"),
])
def test_scan_bad_input(kwargs, match):
    args = dict(ranges=[1.0, float("inf")], angle_min=-0.5, angle_increment=0.1, max_range=5.0, pose=(0, 0, 0))
    args.update(kwargs)
    with pytest.raises(fgdwa.FgdwaError, match=match):
        fgdwa.Scan(**args)
