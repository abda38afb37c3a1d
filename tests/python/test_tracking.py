"""segment_scan and Tracker through the bindings: a walking disc is found, followed and called moving; a
pillar beside it is not; misuse raises FgdwaError naming what was wrong."""
import math

import numpy as np
import pytest

import fgdwa


def empty_field():
    return fgdwa.DistanceField(fgdwa.OccupancyGrid(np.zeros((4, 4), np.uint8), 0.1, (-100.0, -100.0)))


def test_a_walker_is_tracked_and_a_pillar_is_not_moving():
    scanner = fgdwa.LaserScanner(fgdwa.LidarParams(noise_std=0.03), empty_field())
    walker = fgdwa.Disc((3.0, -1.0), 0.3, (0.0, 0.5))
    pillar = fgdwa.Disc((2.0, 1.5), 0.2)
    tracker = fgdwa.Tracker()
    for k in range(16):
        t = 0.1 * k
        scan = scanner.scan((0.0, 0.0, 0.0), [walker, pillar], t, seed=k)
        clusters = fgdwa.segment_scan(scan)
        assert len(clusters) == 2
        tracker.update(clusters, t, scan)
    assert tracker.time == pytest.approx(1.5)
    assert sorted(tracker.cluster_tracks) == sorted(track.id for track in tracker.tracks)
    discs = tracker.moving_discs()
    assert len(discs) == 1
    assert np.hypot(*np.subtract(discs[0].center, walker.center_at(1.5))) < 0.05
    assert np.hypot(*np.subtract(discs[0].velocity, walker.velocity)) < 0.05
    still = min(tracker.tracks, key=lambda track: np.hypot(*np.subtract(track.position, pillar.center)))
    assert still.status == fgdwa.TrackStatus.Confirmed and not still.moving
    assert still.covariance.shape == (4, 4)
    assert tracker.explains(walker.center_at(1.5))
    assert not tracker.explains(pillar.center)
    assert "2 tracks, 1 moving" in repr(tracker)


def test_the_mask_and_the_fitted_disc():
    scan = fgdwa.LaserScanner(fgdwa.LidarParams(), empty_field()).scan((0.0, 0.0, 0.0), [fgdwa.Disc((3.0, 0.0), 0.3)])
    (cluster,) = fgdwa.segment_scan(scan)
    assert cluster.center == pytest.approx((3.0, 0.0), abs=0.02)
    assert cluster.radius == pytest.approx(0.3, abs=0.03)
    assert cluster.points.shape[1] == 2
    assert fgdwa.segment_scan(scan, mask=np.zeros(len(scan.ranges), bool)) == []


def test_bad_input_raises_naming_the_problem():
    scan = fgdwa.LaserScanner(fgdwa.LidarParams(), empty_field()).scan((0.0, 0.0, 0.0))
    with pytest.raises(fgdwa.FgdwaError, match="mask size"):
        fgdwa.segment_scan(scan, mask=np.ones(3, bool))
    with pytest.raises(fgdwa.FgdwaError, match="gate"):
        fgdwa.TrackerParams(gate=-1.0)
    with pytest.raises(fgdwa.FgdwaError, match="min_points"):
        fgdwa.SegmentParams(min_points=0)
    tracker = fgdwa.Tracker()
    tracker.update([], 1.0)
    with pytest.raises(fgdwa.FgdwaError, match="time"):
        tracker.update([], 0.5)
    with pytest.raises(fgdwa.FgdwaError, match="time"):
        tracker.update([], math.nan)
    with pytest.raises(fgdwa.FgdwaError, match="center"):
        fgdwa.Cluster((math.nan, 0.0))


def test_a_scan_of_many_clusters_tracks_the_nearest_and_bounds_the_work():
    # 1000 clusters: the association would cost the cube of the count; the
    # nearest max_clusters are tracked, the rest left untracked this update.
    params = fgdwa.TrackerParams(max_clusters=50)
    tracker = fgdwa.Tracker(params)
    angles = np.linspace(0, 2 * np.pi, 1000, endpoint=False)
    radii = 1.0 + np.arange(1000) * 0.01
    clusters = [fgdwa.Cluster((r * np.cos(a), r * np.sin(a)), 0.05) for r, a in zip(radii, angles)]
    for k in range(5):
        tracker.update(clusters, 0.1 * k)
    ids = np.asarray(tracker.cluster_tracks)
    assert (ids[:50] >= 0).all() and (ids[50:] < 0).all()
    assert len(tracker.tracks) <= 100
    with pytest.raises(fgdwa.FgdwaError, match="max_clusters"):
        fgdwa.TrackerParams(max_clusters=0)
