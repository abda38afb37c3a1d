"""Reading bags without ROS for ``fgdwa replay``, through the ``rosbags`` library:
ROS 1 bags (uncompressed, bz2 or lz4 chunks) and ROS 2 bags (a directory with
its metadata.yaml, sqlite3 or MCAP storage). :func:`read_bag` yields every
message in time order, deserialized; the ``decode_*`` functions turn the few
message types replay needs into plain values.

A bag is outside data: whatever ``rosbags`` cannot read, or a message it cannot
deserialize, becomes an FgdwaError naming the bag (and the message), and a
compressed ROS 1 chunk is expanded no further than ``MAX_EXPANSION`` times its
size (a few kilobytes of bz2 can expand to gigabytes).
"""

from __future__ import annotations

import bz2
import contextlib
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Dict, Iterator, List, Optional, Tuple

import numpy as np

from fgdwa._core import FgdwaError
from fgdwa.file_limits import MAX_ARRAY_BYTES, short_repr

# A compressed ROS 1 chunk expands to at most this many times its size (plus a
# mebibyte), and never past MAX_ARRAY_BYTES: bz2 and lz4 reach 10-50 on sensor data.
MAX_EXPANSION = 1000


@dataclass(frozen=True)
class BagMessage:
    topic: str
    type: str  # ROS 1 style, e.g. "sensor_msgs/LaserScan", whatever the bag's ROS
    time: float  # s, when the recorder received it
    data: Any  # the deserialized message


def _bag_path(path) -> Path:
    """The path rosbags opens: a ROS 1 bag file, or a ROS 2 bag's directory (also
    when given one of its storage files)."""
    p = Path(path)
    if not p.exists():
        raise FgdwaError(f"bag {str(path)!r}: no such file or directory")
    if p.is_file() and p.suffix in (".db3", ".mcap") and (p.parent / "metadata.yaml").is_file():
        return p.parent
    return p


def _bounded(kind: str, where: str):
    """A decompressor of ``kind`` (bz2 or lz4) that stops at MAX_EXPANSION times its input."""
    def run(data: bytes) -> bytes:
        limit = min(MAX_EXPANSION * len(data) + 2**20, MAX_ARRAY_BYTES)
        if kind == "bz2":
            decompressor = bz2.BZ2Decompressor()
        else:
            import lz4.frame

            decompressor = lz4.frame.LZ4FrameDecompressor()
        try:
            out = decompressor.decompress(data, max_length=limit)
        except (OSError, EOFError, RuntimeError) as error:
            raise FgdwaError(f"{where}: a {kind} chunk that does not decompress ({error})") from None
        if not decompressor.eof:
            if len(out) >= limit:
                raise FgdwaError(f"{where}: a {kind} chunk of {len(data)} bytes expands past {limit} bytes")
            raise FgdwaError(f"{where}: a {kind} chunk that ends early")
        return out
    return run


def _bound_chunks(reader, where: str) -> None:
    """Every compressed chunk of the ROS 1 bags in ``reader`` expands within bounds."""
    from rosbags.rosbag1 import reader as rosbag1

    kinds = {id(rosbag1.decompressors[name]): name for name in ("bz2", "lz4") if name in rosbag1.decompressors}
    for bag in getattr(reader, "readers", []):
        chunks = getattr(bag, "chunks", None)
        if not isinstance(chunks, dict):
            continue
        for pos, chunk in list(chunks.items()):
            kind = kinds.get(id(chunk.decompressor))
            if kind is not None:
                chunks[pos] = chunk._replace(decompressor=_bounded(kind, where))


def _ros1_type(msgtype: str) -> str:
    return msgtype.replace("/msg/", "/")


@contextlib.contextmanager
def _opened(path):
    """(reader, where): the bag at ``path`` open in rosbags' AnyReader, its
    compressed chunks bounded; FgdwaError naming the bag if it cannot be read."""
    from rosbags.highlevel import AnyReader

    where = f"bag {str(path)!r}"
    opened = _bag_path(path)
    try:
        reader = AnyReader([opened])
        reader.open()
    except Exception as error:  # noqa: BLE001 - rosbags raises its own errors, OSError, struct.error and more
        raise FgdwaError(f"{where}: not a readable ROS 1 or ROS 2 bag ({type(error).__name__}: "
                         f"{short_repr(str(error), 200)})") from None
    try:
        _bound_chunks(reader, where)
        yield reader, where
    finally:
        reader.close()


def read_bag(path) -> Iterator[BagMessage]:
    """Every message of the bag at ``path``, in time order."""
    with _opened(path) as (reader, where):
        messages = reader.messages()
        while True:
            try:
                connection, stamp, raw = next(messages)
            except StopIteration:
                return
            except FgdwaError:
                raise
            except Exception as error:  # noqa: BLE001 - a truncated or corrupt bag
                raise FgdwaError(f"{where}: truncated or corrupt ({type(error).__name__}: "
                                 f"{short_repr(str(error), 200)})") from None
            kind = _ros1_type(connection.msgtype)
            try:
                message = reader.deserialize(raw, connection.msgtype)
            except Exception as error:  # noqa: BLE001 - bytes that are not the message their type says
                raise FgdwaError(f"{where}: a malformed {kind} message on {connection.topic} at {stamp * 1e-9:.3f} s "
                                 f"({type(error).__name__}: {short_repr(str(error), 200)})") from None
            yield BagMessage(connection.topic, kind, stamp * 1e-9, message)


@dataclass(frozen=True)
class LaserScanMsg:
    stamp: float
    frame_id: str
    angle_min: float
    angle_max: float
    angle_increment: float
    range_min: float
    range_max: float
    ranges: np.ndarray  # float32 values as float64


@dataclass(frozen=True)
class OdometryMsg:
    stamp: float
    frame_id: str
    child_frame_id: str
    position: Tuple[float, float, float]
    orientation: Tuple[float, float, float, float]  # x, y, z, w
    linear: Tuple[float, float, float]
    angular: Tuple[float, float, float]


def _stamp(header) -> float:
    return float(header.stamp.sec) + 1e-9 * float(header.stamp.nanosec)


def _xyz(v) -> Tuple[float, float, float]:
    return float(v.x), float(v.y), float(v.z)


def decode_laser_scan(msg) -> LaserScanMsg:
    """sensor_msgs/LaserScan."""
    return LaserScanMsg(_stamp(msg.header), str(msg.header.frame_id), float(msg.angle_min), float(msg.angle_max),
                        float(msg.angle_increment), float(msg.range_min), float(msg.range_max),
                        np.asarray(msg.ranges, dtype=np.float32).astype(float))


def decode_odometry(msg) -> OdometryMsg:
    """nav_msgs/Odometry."""
    pose, twist = msg.pose.pose, msg.twist.twist
    q = pose.orientation
    return OdometryMsg(_stamp(msg.header), str(msg.header.frame_id), str(msg.child_frame_id), _xyz(pose.position),
                       (float(q.x), float(q.y), float(q.z), float(q.w)), _xyz(twist.linear), _xyz(twist.angular))


def decode_twist(msg) -> Tuple[float, float]:
    """geometry_msgs/Twist as (linear.x, angular.z)."""
    return float(msg.linear.x), float(msg.angular.z)


def decode_string(msg) -> str:
    """std_msgs/String."""
    return str(msg.data)


def decode_diagnostics(msg) -> List[Tuple[str, str, Dict[str, str]]]:
    """diagnostic_msgs/DiagnosticArray as (name, message, {key: value}) per status."""
    return [(str(s.name), str(s.message), {str(kv.key): str(kv.value) for kv in s.values}) for s in msg.status]


def topics(path) -> Dict[str, Tuple[str, int]]:
    """{topic: (type, messages)} of the bag, from its index: no message is read."""
    out: Dict[str, Tuple[str, int]] = {}
    with _opened(path) as (reader, _where):
        for connection in reader.connections:
            kind, n = out.get(connection.topic, (_ros1_type(connection.msgtype), 0))
            out[connection.topic] = (kind, n + int(connection.msgcount))
    return out


def topic_of_type(available: Dict[str, Tuple[str, int]], kind: str, given: Optional[str], where: str) -> str:
    """The bag's one topic of ``kind``, or ``given`` checked; FgdwaError saying which to choose otherwise."""
    if given is not None:
        if given not in available:
            raise FgdwaError(f"bag {where!r}: no topic {short_repr(given)} (it has {', '.join(sorted(available))})")
        if available[given][0] != kind:
            raise FgdwaError(f"bag {where!r}: topic {short_repr(given)} is {available[given][0]}, not {kind}")
        return given
    matching = sorted(t for t, (k, _) in available.items() if k == kind)
    if not matching:
        raise FgdwaError(f"bag {where!r}: no {kind} topic (it has {', '.join(sorted(available)) or 'nothing'})")
    if len(matching) > 1:
        raise FgdwaError(f"bag {where!r}: several {kind} topics ({', '.join(matching)}); name one")
    return matching[0]
