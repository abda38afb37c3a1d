"""fgdwa.io.rosbag_reader against ROS 1 bags written by ROS's own rosbag (Debian's
python3-rosbag under /usr/bin/python3, which make test installs) and ROS 2 bags
written by rosbags."""

import json
import subprocess
import textwrap
from pathlib import Path

import numpy as np
import pytest

from fgdwa import FgdwaError
from fgdwa.cli import main
from fgdwa.adapters.replay import quaternion_yaw, scan_ranges
from fgdwa.io.rosbag_reader import (
    decode_diagnostics,
    decode_laser_scan,
    decode_odometry,
    decode_string,
    decode_twist,
    read_bag,
    topic_of_type,
    topics,
)

ROS_PYTHON = "/usr/bin/python3"

WRITER = textwrap.dedent("""
    import math, sys
    import rosbag, rospy
    from diagnostic_msgs.msg import DiagnosticArray, DiagnosticStatus, KeyValue
    from geometry_msgs.msg import Twist
    from nav_msgs.msg import Odometry
    from sensor_msgs.msg import LaserScan
    from std_msgs.msg import String

    path, compression = sys.argv[1], sys.argv[2]
    with rosbag.Bag(path, "w", compression=compression, chunk_threshold=2000) as bag:
        for k in range(5):
            t = rospy.Time(100 + k, 250000000)
            scan = LaserScan()
            scan.header.stamp, scan.header.frame_id = t, "front_laser"
            scan.angle_min, scan.angle_max, scan.angle_increment = -2.0, 2.0, 1.0
            scan.range_min, scan.range_max = 0.1, 30.0
            scan.ranges = [1.5 + k, float("inf"), float("nan"), float("-inf"), 0.05]
            scan.intensities = [1.0] * 5
            bag.write("/front/scan", scan, t)
            odom = Odometry()
            odom.header.stamp, odom.header.frame_id, odom.child_frame_id = t, "odom", "base_link"
            odom.pose.pose.position.x, odom.pose.pose.position.y = 0.5 * k, -0.25
            odom.pose.pose.orientation.z, odom.pose.pose.orientation.w = math.sin(0.15 * k), math.cos(0.15 * k)
            odom.twist.twist.linear.x, odom.twist.twist.angular.z = 0.75, -0.5
            bag.write("/odometry/filtered", odom, t)
            cmd = Twist()
            cmd.linear.x, cmd.angular.z = 0.1 * k, 0.2
            bag.write("/cmd_vel", cmd, t)
            diag = DiagnosticArray()
            diag.status = [DiagnosticStatus(level=0, name="fgdwa_node: cycle", message="Following (Ok)",
                                            values=[KeyValue("time", str(k)), KeyValue("v", "0.5")])]
            bag.write("/diagnostics", diag, t)
        bag.write("/fgdwa_node/events", String(data='{"event": "goal", "goal": [10, 0]}'), rospy.Time(106))
""")


def _write_bag(tmp_path: Path, compression: str) -> Path:
    probe = subprocess.run([ROS_PYTHON, "-c", "import rosbag"], capture_output=True, text=True) \
        if Path(ROS_PYTHON).exists() else None
    if probe is None or probe.returncode != 0:
        pytest.skip("ROS's rosbag module is not importable by /usr/bin/python3 (make test installs it)")
    path = tmp_path / f"test_{compression}.bag"
    done = subprocess.run([ROS_PYTHON, "-c", WRITER, str(path), compression], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return path


def _check_messages(messages, bag):
    assert [m.topic for m in messages[:4]] == ["/front/scan", "/odometry/filtered", "/cmd_vel", "/diagnostics"]
    assert len(messages) == 21
    found = topics(bag)
    assert found["/front/scan"] == ("sensor_msgs/LaserScan", 5)
    assert found["/fgdwa_node/events"] == ("std_msgs/String", 1)
    assert topic_of_type(found, "nav_msgs/Odometry", None, "bag") == "/odometry/filtered"

    scans = [decode_laser_scan(m.data) for m in messages if m.topic == "/front/scan"]
    odoms = [decode_odometry(m.data) for m in messages if m.topic == "/odometry/filtered"]
    cmds = [decode_twist(m.data) for m in messages if m.topic == "/cmd_vel"]
    for k, (scan, odom, cmd) in enumerate(zip(scans, odoms, cmds)):
        assert scan.stamp == pytest.approx(100.25 + k, abs=1e-9)
        assert scan.frame_id == "front_laser"
        assert (scan.angle_min, scan.angle_increment, scan.range_min) == pytest.approx((-2.0, 1.0, 0.1))
        assert scan.ranges[0] == pytest.approx(1.5 + k) and np.isposinf(scan.ranges[1])
        assert np.isnan(scan.ranges[2]) and np.isneginf(scan.ranges[3])
        assert (odom.frame_id, odom.child_frame_id) == ("odom", "base_link")
        assert odom.position[:2] == (0.5 * k, -0.25)
        assert quaternion_yaw(*odom.orientation) == pytest.approx(0.3 * k)
        assert (odom.linear[0], odom.angular[2]) == (0.75, -0.5)
        assert cmd == pytest.approx((0.1 * k, 0.2))
    assert messages[0].time == pytest.approx(100.25)
    diag = decode_diagnostics(next(m.data for m in messages if m.topic == "/diagnostics"))
    assert diag == [("fgdwa_node: cycle", "Following (Ok)", {"time": "0", "v": "0.5"})]
    event = json.loads(decode_string(messages[-1].data))
    assert event == {"event": "goal", "goal": [10, 0]}


@pytest.mark.parametrize("compression", ["none", "bz2", "lz4"])
def test_reads_what_rosbag_wrote(tmp_path, compression):
    bag = _write_bag(tmp_path, compression)
    _check_messages(list(read_bag(bag)), bag)


@pytest.mark.parametrize("storage", ["sqlite3", "mcap"])
def test_reads_a_ros2_bag(tmp_path, storage):
    """The same messages in a ROS 2 bag (rosbags' writer), read from its directory or its storage file."""
    ros1 = list(read_bag(_write_bag(tmp_path, "none")))
    from rosbags.rosbag2 import StoragePlugin, Writer
    from rosbags.typesys import Stores, get_typestore

    store = get_typestore(Stores.ROS2_HUMBLE)
    ros2 = tmp_path / f"ros2_{storage}"
    plugin = StoragePlugin.SQLITE3 if storage == "sqlite3" else StoragePlugin.MCAP
    with Writer(ros2, version=8, storage_plugin=plugin) as writer:
        connections = {}
        for m in ros1:
            kind = m.type.replace("/", "/msg/", 1)
            if m.topic not in connections:
                connections[m.topic] = writer.add_connection(m.topic, kind, typestore=store)
            writer.write(connections[m.topic], round(m.time * 1e9), store.serialize_cdr(_as_ros2(m.data, store, kind),
                                                                                      kind))
    _check_messages(list(read_bag(ros2)), ros2)
    storage_file = next(p for p in ros2.iterdir() if p.suffix in (".db3", ".mcap"))
    assert len(list(read_bag(storage_file))) == 21


def _as_ros2(message, store, kind):
    """A ROS 1 message read by rosbags as the ROS 2 message of the same fields."""
    import dataclasses

    cls = store.types[kind]
    values = {}
    for f in dataclasses.fields(cls):
        value = getattr(message, f.name)
        if dataclasses.is_dataclass(value) and not isinstance(value, type):
            sub = type(value).__msgtype__ if hasattr(type(value), "__msgtype__") else None
            value = _as_ros2(value, store, sub) if sub in store.types else value
        elif isinstance(value, list):
            value = [_as_ros2(v, store, type(v).__msgtype__) if dataclasses.is_dataclass(v) else v for v in value]
        values[f.name] = value
    return cls(**values)


def test_scan_ranges_follow_rep_117(tmp_path):
    scan = decode_laser_scan(next(m.data for m in read_bag(_write_bag(tmp_path, "none"))
                                  if m.topic == "/front/scan"))
    ranges = scan_ranges(scan)
    # a reading, no return (+inf), invalid (NaN), too near (-inf: a hit at range_min), below range_min (invalid)
    assert ranges[0] == pytest.approx(1.5)
    assert np.isposinf(ranges[1]) and np.isposinf(ranges[2]) and np.isposinf(ranges[4])
    assert ranges[3] == pytest.approx(0.1)


def test_bad_bags_are_refused_with_the_reason(tmp_path):
    not_bag = tmp_path / "x.bag"
    not_bag.write_bytes(b"#ROSRECORD V1.2\nxxxx")
    with pytest.raises(FgdwaError, match="not a readable ROS 1 or ROS 2 bag"):
        list(read_bag(not_bag))
    with pytest.raises(FgdwaError, match="no such file"):
        list(read_bag(tmp_path / "missing.bag"))
    whole = _write_bag(tmp_path, "none").read_bytes()
    for keep in (len(whole) // 2, len(whole) - 50, 20):
        cut = tmp_path / "cut.bag"
        cut.write_bytes(whole[:keep])
        with pytest.raises(FgdwaError, match="bag .*cut.bag"):
            list(read_bag(cut))


def test_replay_says_what_the_bag_lacks(tmp_path, capsys):
    bag = _write_bag(tmp_path, "none")
    assert main(["replay", str(bag), "--out", str(tmp_path / "replay")]) == 2
    err = capsys.readouterr().err
    assert "no fgdwa_node cycle diagnostics or navigator events" in err and "/fgdwa_node/events" in err


def test_a_compressed_chunk_expands_within_bounds(monkeypatch):
    import bz2

    import lz4.frame

    from fgdwa.io import rosbag_reader

    bomb = bz2.compress(b"x" * 300_000_000)  # about 200 bytes that expand to 300 MB
    run = rosbag_reader._bounded("bz2", "b.bag")
    with pytest.raises(FgdwaError, match=f"a bz2 chunk of {len(bomb)} bytes expands past {1000 * len(bomb) + 2**20}"):
        run(bomb)
    # lz4 expands 255 times at most; a tighter bound shows the same check.
    monkeypatch.setattr(rosbag_reader, "MAX_EXPANSION", 10)
    for kind, compress in (("bz2", bz2.compress), ("lz4", lz4.frame.compress)):
        run = rosbag_reader._bounded(kind, "b.bag")
        assert run(compress(b"y" * 1000)) == b"y" * 1000
        big = compress(b"x" * 20_000_000)
        with pytest.raises(FgdwaError, match=f"a {kind} chunk of {len(big)} bytes expands past"):
            run(big)
        with pytest.raises(FgdwaError, match=f"a {kind} chunk that (does not decompress|ends early)"):
            run(compress(bytes(range(256)) * 40)[:-8])


def test_replay_of_a_bag_with_a_malformed_event_says_which_message(tmp_path, capsys):
    probe = subprocess.run([ROS_PYTHON, "-c", "import rosbag"], capture_output=True, text=True) \
        if Path(ROS_PYTHON).exists() else None
    if probe is None or probe.returncode != 0:
        pytest.skip("ROS's rosbag module is not importable by /usr/bin/python3 (make test installs it)")
    path = tmp_path / "bad_event.bag"
    writer = WRITER.replace('{"event": "goal", "goal": [10, 0]}', '{not json')
    done = subprocess.run([ROS_PYTHON, "-c", writer, str(path), "none"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert main(["replay", str(path), "--out", str(tmp_path / "replay")]) == 2
    err = capsys.readouterr().err
    assert "a malformed std_msgs/String message on /fgdwa_node/events at 106.000 s (JSONDecodeError" in err, err
    assert "Traceback" not in err
