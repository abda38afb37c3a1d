"""``fgdwa replay BAG``: fgdwa_node's planner rerun on a bag's scans and odometry.

A bag recorded from fgdwa_node (docs/ros.md) holds, besides the scans,
odometry and cmd_vel, the node's ``events`` (its settings, each navigator it
built with the map's layout and the laser's mounting, each goal) and its
per-cycle ``diagnostics`` (which scan and which odometry message the cycle
stepped on, where the laser was, the time, the command). Replay rebuilds the
same :class:`fgdwa.Navigator` from the events and steps it, cycle by cycle, on
the recorded scan and odometry messages the node named, then compares its
command with the one the node recorded for that cycle. On the same build and
settings they agree; where they do not (another fgdwa version, changed
settings given with ``--set``, a dropped message), the table and the figure
show when, by how much, and in which navigator mode.
"""

from __future__ import annotations

import csv
import json
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Dict, List, Optional, Sequence

import numpy as np

from fgdwa._core import (
    DetectWindowParams,
    FgdwaError,
    Footprint,
    FuzzyWeights,
    LidarParams,
    Navigator,
    NavigatorParams,
    OccupancyGrid,
    PlannerParams,
    RobotLimits,
    RobotState,
    Scan,
    nearest_names,
)
from fgdwa.io.rosbag_reader import (
    decode_diagnostics,
    decode_laser_scan,
    decode_odometry,
    decode_string,
    read_bag,
)
from fgdwa.io.table import Table
from fgdwa.file_limits import short_repr
from fgdwa.settings import parse_overrides

CYCLE_STATUS = "fgdwa_node: cycle"
TOLERANCE = 1e-9  # m/s and rad/s: commands this close count as the same


def quaternion_yaw(x: float, y: float, z: float, w: float) -> float:
    """The heading of a quaternion, written as fgdwa_node writes it (ros_convert.cpp: yaw_of)."""
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def scan_ranges(msg) -> np.ndarray:
    """A LaserScan's ranges as fgdwa_node hands them to the navigator (REP 117,
    ros_convert.cpp: to_scan): no return is +inf, -inf a hit at range_min."""
    r = np.asarray(msg.ranges, dtype=float)
    out = np.full(r.shape, np.inf)
    valid = np.isfinite(r) & (r >= msg.range_min) & (r < msg.range_max)
    out[valid] = r[valid]
    out[r == -np.inf] = msg.range_min
    return out


# ---------------------------------------------------------------- settings

def _param_set(cls, config: dict):
    """The parameter set ``cls`` from the node's settings: its fields are named
    ``<cls.name>/<field>`` there, nested sets '/'-joined, as in the schema."""
    params = cls()
    prefix = cls.name + "/"
    for name, value in config.items():
        if name.startswith(prefix):
            params.set(name[len(prefix):].replace("/", "."), value)
    params.validate()
    return params


def navigator_from_event(event: dict, overrides: Optional[Dict[str, object]] = None) -> Navigator:
    """The Navigator fgdwa_node built, from its ``navigator`` event (the parameter
    names and units of the schema, docs/parameters.md), with ``overrides``
    ({"planner/dt": 0.2, ...}) on top."""
    config = dict(event["config"])
    for name, value in (overrides or {}).items():
        if name not in config:
            close = nearest_names(name, sorted(config))
            hint = f"; did you mean {' or '.join(repr(c) for c in close)}?" if close else ""
            raise FgdwaError(f"--set {name}: not a setting of fgdwa_node{hint} (docs/parameters.md lists them)")
        config[name] = value
    if event.get("mapping") != "scan":
        raise FgdwaError(f"navigator {event.get('id')}: mapping {short_repr(event.get('mapping'))}; replay rebuilds maps "
                         f"from scans only (mapping scan): the known map is not in the bag")
    try:
        limits = _param_set(RobotLimits, config)
        planner = _param_set(PlannerParams, config)
        navigator = _param_set(NavigatorParams, config)
        window = _param_set(DetectWindowParams, config)
    except FgdwaError as error:
        # A value given with --set is the user's to fix, not the bag's.
        named = [n for n in (overrides or {}) if n.replace("/", ".") in str(error)]
        if named:
            raise FgdwaError(f"--set {named[0]}={short_repr(overrides[named[0]])}: {error}") from None
        raise
    if config.get("footprint") is not None:
        footprint = Footprint.polygon(np.asarray(config["footprint"], dtype=float))
    else:
        footprint = Footprint.circle(float(config["footprint_radius"]))
    lidar = event["lidar"]
    lidar_params = LidarParams(beams=int(lidar["beams"]), max_range=float(lidar["max_range"]),
                               noise_std=float(lidar["noise_std"]))
    layout = event["layout"]
    grid = OccupancyGrid(np.zeros((int(layout["rows"]), int(layout["cols"])), dtype=np.uint8),
                         float(layout["resolution"]), tuple(layout["origin"]))
    policy = FuzzyWeights() if config.get("fuzzy") else None
    return Navigator(limits, footprint, planner, grid, mapping="scan", lidar=lidar_params, policy=policy,
                     navigator=navigator, window=window)


# ---------------------------------------------------------------- the recording

@dataclass
class Recording:
    """What replay needs from a bag, decoded."""

    scans: Dict[float, object] = field(default_factory=dict)  # stamp -> LaserScanMsg
    odometry: Dict[float, object] = field(default_factory=dict)  # stamp -> OdometryMsg
    navigators: Dict[int, dict] = field(default_factory=dict)  # id -> the node's navigator event
    cycles: List[dict] = field(default_factory=list)  # the node's cycle diagnostics, in order
    commands: int = 0  # cmd_vel messages
    topics: Dict[str, str] = field(default_factory=dict)  # topic -> type


def _take(rec: Recording, msg, scan_topic: Optional[str], odom_topic: Optional[str]) -> None:
    """One bag message into the recording."""
    rec.topics.setdefault(msg.topic, msg.type)
    if msg.type == "sensor_msgs/LaserScan" and scan_topic in (None, msg.topic):
        scan = decode_laser_scan(msg.data)
        rec.scans[scan.stamp] = scan
    elif msg.type == "nav_msgs/Odometry" and odom_topic in (None, msg.topic):
        odom = decode_odometry(msg.data)
        rec.odometry[odom.stamp] = odom
    elif msg.type == "geometry_msgs/Twist" and msg.topic.endswith("cmd_vel"):
        rec.commands += 1
    elif msg.type == "std_msgs/String" and msg.topic.endswith("/events"):
        event = json.loads(decode_string(msg.data))
        if not isinstance(event, dict):
            raise TypeError(f"an event is a JSON object, not {type(event).__name__}")
        if event.get("event") == "navigator":
            rec.navigators[int(event["id"])] = event
    elif msg.type == "diagnostic_msgs/DiagnosticArray":
        for name, _message, values in decode_diagnostics(msg.data):
            if name == CYCLE_STATUS:
                rec.cycles.append(values)


def read_recording(path, scan_topic: Optional[str] = None, odom_topic: Optional[str] = None) -> Recording:
    rec = Recording()
    where = str(path)
    for msg in read_bag(path):
        try:
            _take(rec, msg, scan_topic, odom_topic)
        except (KeyError, TypeError, ValueError, OverflowError, UnicodeDecodeError) as error:
            # A bag is outside data: what it holds wrong is said, not raised as a traceback.
            raise FgdwaError(f"bag {where!r}: a malformed {msg.type} message on {msg.topic} at {msg.time:.3f} s "
                             f"({type(error).__name__}: {error})") from None
    if not rec.cycles or not rec.navigators:
        raise FgdwaError(f"bag {where!r}: no fgdwa_node cycle diagnostics or navigator events (it has "
                         f"{', '.join(sorted(rec.topics)) or 'nothing'}); record /diagnostics and "
                         f"/fgdwa_node/events with the scan and odometry (docs/ros.md)")
    for kind, found in (("sensor_msgs/LaserScan", rec.scans), ("nav_msgs/Odometry", rec.odometry)):
        if not found:
            raise FgdwaError(f"bag {where!r}: no {kind} messages to replay on")
    return rec


def _nearest(messages: Dict[float, object], stamp: float):
    """The message of exactly this stamp (as the node printed it, to 17 digits), None if absent."""
    hit = messages.get(stamp)
    if hit is not None:
        return hit
    keys = np.fromiter(messages.keys(), dtype=float)
    k = int(np.argmin(np.abs(keys - stamp)))
    return messages[float(keys[k])] if abs(keys[k] - stamp) < 1e-6 else None


# ---------------------------------------------------------------- replaying

@dataclass
class ReplayCycle:
    time: float  # s, node time
    mode_recorded: str
    mode_replayed: str
    v_recorded: float
    omega_recorded: float
    v_replayed: float
    omega_replayed: float
    note: str = ""  # why the cycle could not be stepped as recorded
    gap: str = ""  # cycles of the node missing from the bag before this one

    @property
    def dv(self) -> float:
        return self.v_replayed - self.v_recorded

    @property
    def domega(self) -> float:
        return self.omega_replayed - self.omega_recorded

    @property
    def matches(self) -> bool:
        return not self.note and abs(self.dv) <= TOLERANCE and abs(self.domega) <= TOLERANCE


def replay(rec: Recording, overrides: Optional[Dict[str, object]] = None) -> List[ReplayCycle]:
    """Steps a navigator through every recorded cycle; one ReplayCycle each."""
    navigator, navigator_id, goal_id = None, None, None
    out = []
    expected = 1
    for values in rec.cycles:
        time = float(values["time"])
        recorded = (float(values["v"]), float(values["omega"]))
        mode = values.get("mode", "")
        number = int(values["cycle"])
        # A cycle missing from the bag changed the node's map and state, not the replay's.
        gap = f"after {number - expected} cycle(s) missing from the bag" if number != expected else ""
        expected = number + 1

        def skipped(note: str) -> None:
            out.append(ReplayCycle(time, mode, "-", *recorded, math.nan, math.nan, note, gap))

        # As the node does: a new navigator is given the goal once; a new goal (even to
        # the same point), or the same one again after the navigator failed, is set on the
        # navigator there is (goal_set counts both; bags of older nodes lack it).
        nid, gid = int(values["navigator"]), (int(values["goal_id"]), int(values.get("goal_set", 0)))
        cycle_goal = tuple(float(v) for v in values["goal"].split())
        if nid != navigator_id:
            if nid not in rec.navigators:
                skipped(f"navigator {nid}'s event is not in the bag")
                continue
            navigator, navigator_id = navigator_from_event(rec.navigators[nid], overrides), nid
            navigator.set_goal(cycle_goal)
            goal_id = gid
        elif gid != goal_id:
            navigator.set_goal(cycle_goal)
            goal_id = gid
        odom = _nearest(rec.odometry, float(values["odom_stamp"]))
        if odom is None:
            skipped(f"odometry of stamp {values['odom_stamp']} not in the bag")
            continue
        state = RobotState((odom.position[0], odom.position[1], quaternion_yaw(*odom.orientation)),
                           (odom.linear[0], odom.angular[2]))
        msg = _nearest(rec.scans, float(values["scan_stamp"]))
        if msg is None:
            skipped(f"scan of stamp {values['scan_stamp']} not in the bag")
            continue
        pose = tuple(float(v) for v in values["scan_pose"].split())
        scan = Scan(scan_ranges(msg), float(msg.angle_min), float(msg.angle_increment), float(msg.range_max), pose)
        record = navigator.step(state, scan, time)
        out.append(ReplayCycle(time, mode, record.mode.name, *recorded, record.command.v, record.command.omega,
                               gap=gap))
    return out


def summarize(cycles: Sequence[ReplayCycle]) -> dict:
    stepped = [c for c in cycles if not c.note]
    dv = np.array([abs(c.dv) for c in stepped]) if stepped else np.zeros(0)
    domega = np.array([abs(c.domega) for c in stepped]) if stepped else np.zeros(0)
    first = next((c for c in cycles if not c.matches), None)
    return {"cycles": len(cycles), "stepped": len(stepped), "matching": sum(c.matches for c in cycles),
            "skipped": len(cycles) - len(stepped), "gaps": sum(bool(c.gap) for c in cycles), "tolerance": TOLERANCE,
            "max_dv": float(dv.max()) if len(dv) else 0.0, "max_domega": float(domega.max()) if len(domega) else 0.0,
            "first_difference": None if first is None else first.time}


def format_table(cycles: Sequence[ReplayCycle], limit: int = 20) -> str:
    """The cycles whose commands differ (at most ``limit``), then the totals."""
    s = summarize(cycles)
    lines = [f"{s['cycles']} cycles replayed: {s['matching']} commands the same (within {TOLERANCE:g}), "
             f"{s['stepped'] - s['matching']} different, {s['skipped']} not steppable, {s['gaps']} gap(s) in the "
             f"recording; "
             f"max |dv| {s['max_dv']:.4g} m/s, max |domega| {s['max_domega']:.4g} rad/s"]
    differing = [c for c in cycles if not c.matches]
    if differing:
        rows = [[f"{c.time:.3f}", c.mode_recorded, c.mode_replayed, f"{c.v_recorded:.3f}", f"{c.v_replayed:.3f}",
                 f"{c.omega_recorded:.3f}", f"{c.omega_replayed:.3f}", "; ".join(filter(None, [c.note, c.gap]))]
                for c in differing[:limit]]
        lines.append(Table(["time s", "mode (bag)", "mode (replay)", "v bag", "v replay", "w bag", "w replay", "note"],
                           rows).text())
        if len(differing) > limit:
            lines.append(f"... and {len(differing) - limit} more (replay.csv has every cycle)")
    return "\n".join(lines)


def write_outputs(cycles: Sequence[ReplayCycle], out_dir, bag: str) -> dict:
    """replay.csv (every cycle), replay.json (the totals), replay.png (commands over time)."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "replay.csv", "w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(["time", "mode_bag", "mode_replay", "v_bag", "v_replay", "omega_bag", "omega_replay",
                         "dv", "domega", "note", "gap"])
        for c in cycles:
            writer.writerow([f"{c.time:.6f}", c.mode_recorded, c.mode_replayed, f"{c.v_recorded:.9g}",
                             f"{c.v_replayed:.9g}", f"{c.omega_recorded:.9g}", f"{c.omega_replayed:.9g}",
                             f"{c.dv:.3g}", f"{c.domega:.3g}", c.note, c.gap])
    summary = {"bag": bag, **summarize(cycles)}
    (out / "replay.json").write_text(json.dumps(summary, indent=2) + "\n")
    from fgdwa.plot.replay import plot_replay

    plot_replay(cycles, out / "replay.png", title=Path(bag).name)
    return summary


def replay_command(args) -> int:
    """``fgdwa replay``: replay, print the table, write the outputs."""
    rec = read_recording(args.bag, scan_topic=args.scan_topic, odom_topic=args.odom_topic)
    try:
        cycles = replay(rec, parse_overrides(args.set or []))
    except FgdwaError as error:
        if str(error).startswith("--set "):
            raise
        raise FgdwaError(f"bag {str(args.bag)!r}: malformed fgdwa_node events or cycle diagnostics "
                         f"({error})") from None
    except (KeyError, TypeError, ValueError, OverflowError) as error:
        # The node's events and cycle diagnostics came from the bag: a field missing or of the wrong kind is the bag's.
        raise FgdwaError(f"bag {str(args.bag)!r}: malformed fgdwa_node events or cycle diagnostics "
                         f"({type(error).__name__}: {error})") from None
    print(f"bag {args.bag}: {len(rec.scans)} scans, {len(rec.odometry)} odometry messages, {rec.commands} cmd_vel, "
          f"{len(rec.cycles)} fgdwa_node cycles, {len(rec.navigators)} navigator(s)")
    print(format_table(cycles))
    write_outputs(cycles, args.out, str(args.bag))
    out = Path(args.out)
    print(f"wrote {out / 'replay.csv'}, {out / 'replay.json'}, {out / 'replay.png'}")
    return 0
