"""Reading ROS 1 bags (format 2.0) without ROS: enough for ``fgdwa replay``.

ROS's own ``rosbag`` module imports only under Debian's Python, so fgdwa reads
the format itself (http://wiki.ros.org/Bags/Format/2.0): a bag is a magic line
and then records, each a header of ``name=value`` fields and a data block; the
messages sit in chunks (uncompressed or bz2; lz4 chunks are refused with what
to do), each message naming its connection, whose record says its topic and
type. :func:`read_bag` yields every message in file order; the ``decode_*``
functions deserialize the few message types replay needs from ROS's wire
format (little-endian, strings and arrays prefixed by a uint32 length).
"""

from __future__ import annotations

import bz2
import struct
from dataclasses import dataclass
from pathlib import Path
from typing import Dict, Iterator, List, Optional, Tuple

import numpy as np

from fgdwa._core import FgdwaError
from fgdwa.file_limits import short_repr

MAGIC = b"#ROSBAG V2.0\n"
OP_MESSAGE, OP_BAG_HEADER, OP_INDEX, OP_CHUNK, OP_CHUNK_INFO, OP_CONNECTION = 0x02, 0x03, 0x04, 0x05, 0x06, 0x07


@dataclass(frozen=True)
class Connection:
    id: int
    topic: str
    type: str  # e.g. "sensor_msgs/LaserScan"
    md5sum: str


@dataclass(frozen=True)
class BagMessage:
    topic: str
    type: str
    time: float  # s, when the recorder received it
    data: bytes  # the serialized message


def _fields(block: bytes, where: str) -> Dict[str, bytes]:
    fields, pos = {}, 0
    while pos < len(block):
        if pos + 4 > len(block):
            raise FgdwaError(f"{where}: a header field's length runs past its header")
        (length,) = struct.unpack_from("<I", block, pos)
        pos += 4
        field = block[pos:pos + length]
        if len(field) != length or b"=" not in field:
            raise FgdwaError(f"{where}: a malformed header field")
        name, value = field.split(b"=", 1)
        fields[name.decode("ascii", "replace")] = value
        pos += length
    return fields


def _records(buffer: bytes, start: int, where: str) -> Iterator[Tuple[Dict[str, bytes], bytes]]:
    pos = start
    while pos < len(buffer):
        if pos + 4 > len(buffer):
            raise FgdwaError(f"{where}: truncated at byte {pos}")
        (header_len,) = struct.unpack_from("<I", buffer, pos)
        header = buffer[pos + 4:pos + 4 + header_len]
        pos += 4 + header_len
        if len(header) != header_len or pos + 4 > len(buffer):
            raise FgdwaError(f"{where}: truncated record at byte {pos} (was the recording stopped cleanly?)")
        (data_len,) = struct.unpack_from("<I", buffer, pos)
        data = buffer[pos + 4:pos + 4 + data_len]
        pos += 4 + data_len
        if len(data) != data_len:
            raise FgdwaError(f"{where}: truncated record data at byte {pos} (was the recording stopped cleanly?)")
        fields = _fields(header, where)
        if "op" not in fields or len(fields["op"]) != 1:
            raise FgdwaError(f"{where}: a record without its op field")
        yield fields, data


def _uint32(fields: Dict[str, bytes], name: str, where: str) -> int:
    if name not in fields or len(fields[name]) != 4:
        raise FgdwaError(f"{where}: record without a 4-byte {short_repr(name)} field")
    return struct.unpack("<I", fields[name])[0]


def _text(value: bytes, what: str, where: str) -> str:
    try:
        return value.decode("utf-8")
    except UnicodeDecodeError:
        raise FgdwaError(f"{where}: the {what} {short_repr(value[:40])} is not UTF-8 text") from None


def _chunk_data(fields: Dict[str, bytes], data: bytes, where: str) -> bytes:
    compression = fields.get("compression", b"none").decode("ascii", "replace")
    if compression == "none":
        return data
    if compression == "bz2":
        # No further than the chunk says it holds: a small chunk may expand to gigabytes.
        size = _uint32(fields, "size", where)
        decompressor = bz2.BZ2Decompressor()
        try:
            out = decompressor.decompress(data, max_length=size)
        except (OSError, EOFError) as error:
            raise FgdwaError(f"{where}: a bz2 chunk that does not decompress ({error})") from None
        if len(out) != size or not (decompressor.eof or decompressor.needs_input):
            raise FgdwaError(f"{where}: a bz2 chunk that expands past its declared {size} bytes")
        return out
    raise FgdwaError(f"{where}: chunks compressed with {short_repr(compression)}; fgdwa reads uncompressed and bz2 bags. "
                     f"Write an uncompressed copy with: rosbag decompress {where}")


def read_bag(path) -> Iterator[BagMessage]:
    """Every message of the bag at ``path``, in file order (the recorder's order within a chunk)."""
    where = str(path)
    file = Path(path)
    if not file.is_file():
        raise FgdwaError(f"bag {short_repr(where)}: no such file")
    buffer = file.read_bytes()
    if not buffer.startswith(MAGIC):
        version = buffer[:13].split(b"\n")[0].decode("ascii", "replace")
        raise FgdwaError(f"bag {short_repr(where)}: not a ROS bag of format 2.0 (starts with {short_repr(version)})")
    connections: Dict[int, Connection] = {}

    def connection(fields, data):
        conn = _uint32(fields, "conn", where)
        info = _fields(data, where)
        connections[conn] = Connection(conn, _text(fields.get("topic", info.get("topic", b"")), "topic", where),
                                       _text(info.get("type", b""), "type", where),
                                       _text(info.get("md5sum", b""), "md5sum", where))

    for fields, data in _records(buffer, len(MAGIC), where):
        op = fields["op"][0]
        if op == OP_CONNECTION:
            connection(fields, data)
        elif op == OP_CHUNK:
            for inner, payload in _records(_chunk_data(fields, data, where), 0, where + " (chunk)"):
                inner_op = inner["op"][0]
                if inner_op == OP_CONNECTION:
                    connection(inner, payload)
                elif inner_op == OP_MESSAGE:
                    conn = _uint32(inner, "conn", where)
                    if conn not in connections:
                        raise FgdwaError(f"bag {short_repr(where)}: a message on connection {conn} before its connection record")
                    stamp = inner.get("time", b"")
                    if len(stamp) != 8:
                        raise FgdwaError(f"bag {short_repr(where)}: a message without its 8-byte time")
                    sec, nsec = struct.unpack("<II", stamp)
                    c = connections[conn]
                    yield BagMessage(c.topic, c.type, sec + 1e-9 * nsec, payload)
        # Bag header, index and chunk info records only locate what is read here in order.


class _Reader:
    """ROS's wire format, read front to back."""

    def __init__(self, data: bytes, what: str):
        self.data, self.pos, self.what = data, 0, what

    def take(self, fmt: str):
        try:
            values = struct.unpack_from("<" + fmt, self.data, self.pos)
        except struct.error:
            raise FgdwaError(f"{self.what}: message shorter than its type") from None
        self.pos += struct.calcsize("<" + fmt)
        return values

    def string(self) -> str:
        (n,) = self.take("I")
        raw = self.data[self.pos:self.pos + n]
        if len(raw) != n:
            raise FgdwaError(f"{self.what}: message shorter than its type")
        self.pos += n
        return raw.decode("utf-8", "replace")

    def floats32(self) -> np.ndarray:
        (n,) = self.take("I")
        raw = self.data[self.pos:self.pos + 4 * n]
        if len(raw) != 4 * n:
            raise FgdwaError(f"{self.what}: message shorter than its type")
        self.pos += 4 * n
        return np.frombuffer(raw, dtype="<f4").astype(float)

    def header(self) -> Tuple[float, str]:
        _seq, sec, nsec = self.take("III")
        return float(sec) + 1e-9 * float(nsec), self.string()


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


def decode_laser_scan(data: bytes) -> LaserScanMsg:
    r = _Reader(data, "sensor_msgs/LaserScan")
    stamp, frame = r.header()
    angle_min, angle_max, increment, _time_inc, _scan_time, range_min, range_max = r.take("7f")
    ranges = r.floats32()
    r.floats32()  # intensities
    return LaserScanMsg(stamp, frame, angle_min, angle_max, increment, range_min, range_max, ranges)


def decode_odometry(data: bytes) -> OdometryMsg:
    r = _Reader(data, "nav_msgs/Odometry")
    stamp, frame = r.header()
    child = r.string()
    pose = r.take("7d")
    r.take("36d")
    twist = r.take("6d")
    r.take("36d")
    return OdometryMsg(stamp, frame, child, pose[:3], pose[3:], twist[:3], twist[3:])


def decode_twist(data: bytes) -> Tuple[float, float]:
    """geometry_msgs/Twist as (linear.x, angular.z)."""
    values = _Reader(data, "geometry_msgs/Twist").take("6d")
    return values[0], values[5]


def decode_string(data: bytes) -> str:
    return _Reader(data, "std_msgs/String").string()


def decode_diagnostics(data: bytes) -> List[Tuple[str, str, Dict[str, str]]]:
    """diagnostic_msgs/DiagnosticArray as (name, message, {key: value}) per status."""
    r = _Reader(data, "diagnostic_msgs/DiagnosticArray")
    r.header()
    (count,) = r.take("I")
    statuses = []
    for _ in range(count):
        r.take("b")  # level
        name, message, _hardware = r.string(), r.string(), r.string()
        (n,) = r.take("I")
        values = {}
        for _ in range(n):
            key = r.string()
            values[key] = r.string()
        statuses.append((name, message, values))
    return statuses


def topics(path) -> Dict[str, Tuple[str, int]]:
    """{topic: (type, messages)} of the bag."""
    out: Dict[str, Tuple[str, int]] = {}
    for msg in read_bag(path):
        kind, n = out.get(msg.topic, (msg.type, 0))
        out[msg.topic] = (kind, n + 1)
    return out


def topic_of_type(available: Dict[str, Tuple[str, int]], kind: str, given: Optional[str], where: str) -> str:
    """The bag's one topic of ``kind``, or ``given`` checked; FgdwaError saying which to choose otherwise."""
    if given is not None:
        if given not in available:
            raise FgdwaError(f"bag {short_repr(where)}: no topic {short_repr(given)} (it has {', '.join(sorted(available))})")
        if available[given][0] != kind:
            raise FgdwaError(f"bag {short_repr(where)}: topic {short_repr(given)} is {available[given][0]}, not {kind}")
        return given
    matching = sorted(t for t, (k, _) in available.items() if k == kind)
    if not matching:
        raise FgdwaError(f"bag {short_repr(where)}: no {kind} topic (it has {', '.join(sorted(available)) or 'nothing'})")
    if len(matching) > 1:
        raise FgdwaError(f"bag {short_repr(where)}: several {kind} topics ({', '.join(matching)}); name one")
    return matching[0]
