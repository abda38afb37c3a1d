"""fgdwa_node end to end: a private rosmaster, the node started by its shipped
launch file, and a simulated Jackal (sim_jackal.py) on a BARN world: its
odometry drifts as fgdwa's default body's does, its referee judges the Jackal's
true outline, and it drives the node's clock (``use_sim_time``, ``/clock``).

Run by Debian's /usr/bin/python3 (ROS's Python modules import only there);
ctest runs it (tests/ros/CMakeLists.txt). In turn:

1. bad parameters: the node refuses to start and names the parameter;
2. the BARN world through ROS: the move_base action ends SUCCEEDED at the goal,
   the referee saw no collision, every cmd_vel was inside the robot's limits;
   what the node shows of it (check_views): the per-critic evaluation of each
   cycle, the rollout fan coloured by the clearance critic, the map it builds
   from the scans, the footprint, and the rviz config's topics;
3. bad goals (a frame with no transform, NaN) are aborted with the reason;
4. a preempt: the action ends PREEMPTED and the robot stops;
5. the scan goes silent for 2 s while driving: the robot stops, the node says why
   (a ``wait`` event, WARN diagnostics) and keeps the goal, and it reaches the goal
   when the scan comes back;
6. the run's bag (scan, odometry, cmd_vel, the node's diagnostics and events)
   is replayed by ``fgdwa replay``, which must step the same commands;
7. the known-map mode: the node launched again with ``mapping:=known`` and a short
   ``~patience``; a wall across the world (``sim/door``) leaves no path, the robot
   stands and the node waits; when the wall opens it reaches the goal on the world's
   grid, no collision; a goal behind the closed wall is aborted once the patience
   has run out, naming why;
8. the node stopped (SIGINT) while it drives: the goal ends ABORTED saying so, and
   the robot is sent a stop.

Every process it starts it stops again, by its own id. Exit 77 (skipped) when
the BARN data is missing.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
SKIP = 77
DEFAULT_BARN = Path("/work/shared/benchmarks/barn/barn.npz")


class Failure(Exception):
    pass


def check(condition: bool, message: str) -> None:
    if not condition:
        raise Failure(message)


def free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def fgdwa_site(python: str) -> str:
    """The directory fgdwa's package (and its numpy) import from in `python`."""
    code = "import fgdwa, numpy, os; print(os.path.dirname(os.path.dirname(fgdwa.__file__)))"
    try:
        out = subprocess.run([python, "-c", code], capture_output=True, text=True, timeout=60)
    except OSError as error:
        raise Failure(f"cannot run {python} ({error}): the simulated Jackal needs fgdwa installed there "
                      f"(make setup)") from None
    if out.returncode != 0:
        raise Failure(f"{python} cannot import fgdwa: {out.stderr.strip()[-400:]} (make setup installs it)")
    return out.stdout.strip()


def barn_file(given) -> Path:
    if given:
        return Path(given)
    env = os.environ.get("FGDWA_BARN_DATA")
    base = Path(env) if env else DEFAULT_BARN
    return base if base.suffix == ".npz" else base / "barn.npz"


class Processes:
    """The processes this test started, each in its own session, stopped by id."""

    def __init__(self, log_dir: Path, env: dict):
        self.log_dir, self.env = log_dir, env
        self.running = []  # (name, Popen)

    def start(self, name: str, argv, env=None):
        log = open(self.log_dir / f"{name}.log", "w")
        proc = subprocess.Popen(argv, stdout=log, stderr=subprocess.STDOUT, env=env or self.env,
                                start_new_session=True)
        self.running.append((name, proc))
        return proc

    def stop(self, proc, sig=signal.SIGINT, wait: float = 10.0) -> None:
        if proc.poll() is None:
            try:
                os.killpg(proc.pid, sig)  # its session: the process and what it started
            except ProcessLookupError:
                pass
            try:
                proc.wait(wait)
            except subprocess.TimeoutExpired:
                os.killpg(proc.pid, signal.SIGKILL)
                proc.wait(5)

    def stop_all(self) -> None:
        # Last started first; the master (first) is stopped with SIGTERM: it ignores SIGINT.
        for name, proc in reversed(self.running):
            self.stop(proc, signal.SIGTERM if name == "rosmaster" else signal.SIGINT)

    def log(self, name: str) -> str:
        path = self.log_dir / f"{name}.log"
        return path.read_text(errors="replace") if path.exists() else ""


def wait_for(predicate, timeout: float, what: str, poll: float = 0.05):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        value = predicate()
        if value:
            return value
        time.sleep(poll)
    raise Failure(f"timed out after {timeout:.0f} s waiting for {what}")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--prefix", required=True, help="the build tree's ROS prefix (share/fgdwa_ros)")
    parser.add_argument("--fgdwa-python", required=True, help="a Python with fgdwa installed (the venv's)")
    parser.add_argument("--out", required=True, help="directory for logs, the bag and the replay")
    parser.add_argument("--barn", default=None, help="barn.npz (default: $FGDWA_BARN_DATA or the shared copy)")
    parser.add_argument("--world", type=int, default=0, help="BARN world id")
    parser.add_argument("--scan-rate", type=float, default=25.0, help="Hz of the simulated lidar")
    parser.add_argument("--time-limit", type=float, default=100.0, help="s, BARN's time limit")
    args = parser.parse_args()

    tic = time.monotonic()
    barn = barn_file(args.barn)
    if not barn.is_file():
        print(f"SKIPPED: no BARN data at {barn}; set FGDWA_BARN_DATA to barn.npz or its directory")
        return SKIP
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    site = fgdwa_site(args.fgdwa_python)
    sys.path.append(site)  # after Debian's packages, which ROS's modules need
    port = free_port()
    prefix = Path(args.prefix)
    env = dict(os.environ)
    env.update(ROS_MASTER_URI=f"http://127.0.0.1:{port}", ROS_IP="127.0.0.1", ROS_HOME=str(out / "ros_home"),
               ROS_LOG_DIR=str(out / "ros_log"),
               ROS_PACKAGE_PATH=os.pathsep.join(filter(None, [str(prefix / "share"), env.get("ROS_PACKAGE_PATH")])),
               ROSCONSOLE_STDOUT_LINE_BUFFERED="1", PYTHONUNBUFFERED="1")
    env.pop("ROS_HOSTNAME", None)
    os.environ.update({k: env[k] for k in ("ROS_MASTER_URI", "ROS_IP", "ROS_HOME", "ROS_LOG_DIR")})
    os.environ.pop("ROS_HOSTNAME", None)
    procs = Processes(out, env)
    print(f"rosmaster on 127.0.0.1:{port}; logs in {out}", flush=True)
    try:
        result = run(args, procs, barn, out, prefix, env, site)
    except Failure as failure:
        print(f"FAILED: {failure}", flush=True)
        for name, _ in procs.running:
            print(f"---- {name}.log (tail)\n{procs.log(name)[-2500:]}")
        return 1
    finally:
        procs.stop_all()
    print(f"ros test wall time {time.monotonic() - tic:.1f} s (timings on a shared 2-core machine are noisy)")
    return result


def run(args, procs: Processes, barn: Path, out: Path, prefix: Path, env: dict, site: str) -> int:
    import numpy as np
    import yaml

    procs.start("rosmaster", ["rosmaster", "--core", "-p", os.environ["ROS_MASTER_URI"].rsplit(":", 1)[1]])
    import rosgraph

    wait_for(lambda: rosgraph.Master("/fgdwa_test").is_online(), 15, "the rosmaster")

    import actionlib
    import rospy
    from actionlib_msgs.msg import GoalStatus
    from diagnostic_msgs.msg import DiagnosticArray
    from geometry_msgs.msg import Twist
    from move_base_msgs.msg import MoveBaseAction, MoveBaseGoal
    from std_msgs.msg import Bool, Empty, String

    from fgdwa.io import load_barn

    rospy.init_node("fgdwa_test", disable_signals=True)
    node_exe = prefix / "share" / "fgdwa_ros" / "bin" / "fgdwa_node"
    config = yaml.safe_load((prefix / "share" / "fgdwa_ros" / "config" / "barn_jackal.yaml").read_text())

    # 1. Bad parameters: refused at start-up, by name.
    def start_up(params: dict) -> tuple:
        for name, value in params.items():
            rospy.set_param(f"/fgdwa_bad/{name}", value)
        run = subprocess.run([str(node_exe), "__name:=fgdwa_bad"], env=env, capture_output=True, text=True,
                             timeout=30)
        rospy.delete_param("/fgdwa_bad")
        return run.returncode, run.stdout + run.stderr

    code, message = start_up({"planner/dt": -1.0})
    check(code == 2 and "planner.dt = -1: must be >= 1e-04 (s)" in message,
          f"bad parameter: exit {code}, output {message.strip()!r}")
    print(f"bad parameter refused: {message.strip().splitlines()[-1]}", flush=True)

    # A typo is refused with the nearest names; move_base's names are read as fgdwa's, and say so.
    code, message = start_up({"planner/sim_tim": 1.0})
    check(code == 2 and "~planner/sim_tim: unknown to fgdwa_node; did you mean ~planner/sim_time" in message,
          f"unknown parameter: exit {code}, output {message.strip()!r}")
    code, message = start_up({"DWAPlannerROS/max_vel_x": 0.5, "planner/dt": -1.0})
    check(code == 2 and "~DWAPlannerROS/max_vel_x (move_base's name) sets ~limits/v_max = 0.5" in message,
          f"move_base names: exit {code}, output {message.strip()!r}")
    code, message = start_up({"controller_frequency": 0.0})
    check(code == 2 and "~controller_frequency = " in message and "must be a finite number > 0 (Hz)" in message,
          f"move_base's controller_frequency: exit {code}, output {message.strip()!r}")
    code, message = start_up({"patience": 0.0})
    check(code == 2 and "parameter ~patience = 0: must be a finite number > 0" in message,
          f"patience 0: exit {code}, output {message.strip()!r}")
    print("move_base names read, a typo refused with the nearest names, a patience of 0 refused", flush=True)
    code, message = start_up({"rollout_colour_by": "nope"})
    check(code == 2 and "~rollout_colour_by = \"nope\": expected one of total, heading, clearance, velocity, "
          "similarity" in message, f"bad rollout_colour_by: exit {code}, output {message.strip()!r}")

    world = load_barn(barn).world(args.world)
    commands, cycle_ms, step_ms, stages_ms, referee, events = [], [], [], [], {}, []

    def on_cmd(msg):
        commands.append((time.monotonic(), msg.linear.x, msg.angular.z))

    cycles = {}  # the header stamp (ns) of each cycle's diagnostics -> their values

    def on_diagnostics(msg):
        for status in msg.status:
            values = {kv.key: kv.value for kv in status.values}
            if "cycle_ms" in values:
                cycles[msg.header.stamp.to_nsec()] = values
                cycle_ms.append(float(values["cycle_ms"]))
                step_ms.append(float(values["step_ms"]))
                stages_ms.append([float(v) for v in values["stages_ms"].split()])

    track = []  # (time, map pose) of every referee report

    def on_referee(msg):
        referee.clear()
        referee.update(json.loads(msg.data))
        referee["received"] = time.monotonic()
        track.append((referee["received"], referee["map_pose"]))

    rospy.Subscriber("cmd_vel", Twist, on_cmd, queue_size=100)
    rospy.Subscriber("diagnostics", DiagnosticArray, on_diagnostics, queue_size=100)
    rospy.Subscriber("sim/referee", String, on_referee, queue_size=10)
    rospy.Subscriber("fgdwa_node/events", String, lambda m: events.append(json.loads(m.data)), queue_size=100)
    scan_switch = rospy.Publisher("sim/scan_enabled", Bool, queue_size=1, latch=True)

    bag = out / "run.bag"
    recorder = procs.start("rosbag", ["rosbag", "record", "--output-name", str(bag), "/front/scan",
                                      "/odometry/filtered", "/cmd_vel", "/diagnostics", "/fgdwa_node/events",
                                      "__name:=fgdwa_test_bag"])
    master = rosgraph.Master("/fgdwa_test")
    wait_for(lambda: any("/fgdwa_test_bag" in nodes for topic, nodes in master.getSystemState()[1]
                         if topic == "/front/scan"), 15, "rosbag record to subscribe")
    # fgdwa and its numpy from the venv, for the simulated Jackal alone: with the
    # venv's packages first on its path roslaunch hangs (its YAML is another).
    sim_env = dict(env, PYTHONPATH=os.pathsep.join(filter(None, [site, env.get("PYTHONPATH")])))
    # The node and the simulated Jackal run on the simulated time it publishes on /clock (the test's own
    # node, started before, keeps the wall clock for its timeouts).
    rospy.set_param("/use_sim_time", True)
    procs.start("sim_jackal", [sys.executable, str(HERE / "sim_jackal.py"), "--barn", str(barn), "--world",
                               str(args.world), "--scan-rate", str(args.scan_rate)], env=sim_env)
    launch = procs.start("fgdwa_node", ["roslaunch", "fgdwa_ros", "barn_jackal.launch",
                                        f"rollout_colour_by:={COLOUR_BY}"])
    views = Views(prefix)
    client = actionlib.SimpleActionClient("move_base", MoveBaseAction)
    check(client.wait_for_server(rospy.Duration(30)), "the move_base action server of fgdwa_node did not come up")
    # ~events is latched, but it keeps only the last event: the config must be in before a goal's events follow it.
    wait_for(lambda: any(e.get("event") == "config" for e in events), 15, "the node's config event")
    wait_for(lambda: referee.get("scans", 0) > 0, 30, "the simulated Jackal's first scan")

    def recorder_connected():
        """Whether fgdwa_node has connections to the recorder for all it publishes that the bag keeps:
        a cycle published before that would be missing from the bag, and its replay."""
        import xmlrpc.client

        try:
            uri = master.lookupNode("/fgdwa_node")
            _code, _msg, bus = xmlrpc.client.ServerProxy(uri).getBusInfo("/fgdwa_test")
        except Exception:  # noqa: BLE001 - not registered yet
            return False
        linked = {c[4] for c in bus if c[1] == "/fgdwa_test_bag" and c[2] == "o"}
        return {"/cmd_vel", "/diagnostics", "/fgdwa_node/events"} <= linked

    wait_for(recorder_connected, 30, "rosbag record to connect to fgdwa_node")

    limits = config["limits"]
    jackal_omega = 4.0  # rad/s, the jackal robot preset's
    v_low = -0.2  # m/s, the navigator's backup_speed: the only reverse it commands

    def goal(x, y, frame="odom"):
        g = MoveBaseGoal()
        g.target_pose.header.frame_id = frame
        g.target_pose.header.stamp = rospy.Time(0)
        g.target_pose.pose.position.x, g.target_pose.pose.position.y = x, y
        g.target_pose.pose.orientation.w = 1.0
        return g

    def state_name(state):
        return GoalStatus.to_string(state) if hasattr(GoalStatus, "to_string") else str(state)

    def wait_result(timeout):
        check(client.wait_for_result(rospy.Duration(timeout)), f"no action result within {timeout:.0f} s")
        return client.get_state(), client.get_goal_status_text()

    def stopped():
        fresh = time.monotonic() - referee.get("received", 0) < 0.5
        return fresh and abs(referee["v"]) < 1e-3 and abs(referee["omega"]) < 1e-3

    # 2. The BARN world, as the challenge's run.py sends it: (0, 10) in odom. Its
    # clock runs from the robot's first 0.1 m until it is within the goal radius.
    sx, sy, _ = world.start
    gx, gy = world.goal
    odom_goal = (0.0, 10.0)
    first_cmd = len(commands)
    track.clear()
    sent = time.monotonic()
    client.send_goal(goal(*odom_goal))
    # The first cycles' evaluations and fans; then no more, so that decoding them here
    # does not take the CPU the node and the simulator run on for the rest of the run.
    wait_for(views.enough, 30, f"{Views.CYCLES} evaluations and rollout fans from fgdwa_node")
    views.stop_cycles()
    state, text = wait_result(args.time_limit + 10)
    wall = time.monotonic() - sent
    time.sleep(0.3)  # the referee's last report
    x, y = referee["map_pose"][:2]
    distance = math.hypot(x - gx, y - gy)
    moved = next((t for t, p in track if math.hypot(p[0] - sx, p[1] - sy) >= 0.1), None)
    arrived = next((t for t, p in track if math.hypot(p[0] - gx, p[1] - gy) < world.goal_radius), None)
    print(f"BARN world {world.world_id}: {state_name(state)} ({text}) {wall:.1f} s after the goal was sent, "
          f"{distance:.2f} m from the goal, travelled {referee['travelled']:.2f} m, min clearance "
          f"{referee['min_clearance']:.3f} m", flush=True)
    check(state == GoalStatus.SUCCEEDED, f"BARN goal ended {state_name(state)}: {text}")
    check(not referee["collided"], f"collision at {referee['collision_pose']}")
    check(distance <= world.goal_radius, f"ended {distance:.2f} m from the goal (radius {world.goal_radius})")
    check(moved is not None and arrived is not None, "the referee's reports missed the start or the arrival")
    elapsed = arrived - moved
    score = world.score(elapsed < args.time_limit, elapsed)
    print(f"BARN score {score:.3f} (time {elapsed:.1f} s as run.py counts it, optimal {world.optimal_time:.2f} s)",
          flush=True)
    barn_commands = commands[first_cmd:]
    check(len(barn_commands) > 10, f"only {len(barn_commands)} commands on cmd_vel")
    check_views(views, cycles, events, config, world, referee, prefix, master)

    # 3. Bad goals: aborted with the reason.
    client.send_goal(goal(1.0, 0.0, frame="nowhere"))
    state, text = wait_result(10)
    check(state == GoalStatus.ABORTED and "nowhere" in text, f"goal in frame 'nowhere': {state_name(state)}, {text!r}")
    print(f"goal in an unknown frame aborted: {text}", flush=True)
    client.send_goal(goal(float("nan"), 0.0))
    state, text = wait_result(10)
    check(state == GoalStatus.ABORTED and "not finite" in text, f"NaN goal: {state_name(state)}, {text!r}")
    print(f"NaN goal aborted: {text}", flush=True)

    # 4. Preempt: on past the goal into open ground, cancelled once the robot is under way.
    further = (0.0, 12.5)
    client.send_goal(goal(*further))
    wait_for(lambda: abs(referee.get("v", 0.0)) > 0.2, 15, "the robot to start toward the preempted goal")
    client.cancel_goal()
    state, text = wait_result(10)
    check(state == GoalStatus.PREEMPTED, f"cancelled goal ended {state_name(state)}: {text}")
    wait_for(stopped, 5, "the robot to stop after the preempt")
    check(commands and commands[-1][1:] == (0.0, 0.0), f"last command after the preempt: {commands[-1]}")
    print(f"preempted: {text}; robot stopped", flush=True)

    # 5. The scan goes silent for 2 s while driving: the robot stops, the node says why and keeps
    # the goal, and it drives on to the goal when the scan comes back.
    client.send_goal(goal(*further))
    wait_for(lambda: abs(referee.get("v", 0.0)) > 0.2, 15, "the robot to start for the silent-scan goal")
    waits_before = sum(e.get("event") == "wait" for e in events)
    scan_switch.publish(Bool(data=False))
    waiting = wait_for(lambda: next((e for e in events[::-1] if e.get("event") == "wait"), None)
                       if sum(e.get("event") == "wait" for e in events) > waits_before else None,
                       5, "the node's wait event for the silent scan")
    silenced_at = referee["last_scan_time"]
    check("no scan" in waiting["reason"], f"the node waits for {waiting['reason']!r}, not the scan")
    wait_for(stopped, 5, "the robot to stop after the scan went silent")
    check(commands[-1][1:] == (0.0, 0.0), f"last command after the silent scan: {commands[-1]}")
    check(client.get_state() == GoalStatus.ACTIVE, f"the goal ended {state_name(client.get_state())} while the "
          f"scan was silent: {client.get_goal_status_text()}")
    stop_delay = waiting["stamp"] - silenced_at
    time.sleep(max(0.0, 2.0 - (referee["sim_time"] - silenced_at)))
    scan_switch.publish(Bool(data=True))
    state, text = wait_result(60)
    check(state == GoalStatus.SUCCEEDED, f"after the silent scan the goal ended {state_name(state)}: {text}")
    resumed = next((e for e in events[::-1] if e.get("event") == "resume"), None)
    check(resumed is not None and resumed["waited"] >= 1.0, f"no resume event after the silent scan: {resumed}")
    period = config["planner"]["dt"]
    print(f"silent scan for 2 s: the node stopped the robot {stop_delay:.2f} s after the last scan (scan_timeout "
          f"0.5 s + one period {period} s = {0.5 + period:.2f} s): {waiting['reason']}; it went on after "
          f"{resumed['waited']:.2f} s of waiting and reached the goal: {text}", flush=True)
    # Every command of the run inside the robot's limits.
    def check_limits(sent):
        bad_cmds = [c for c in sent if not (v_low - 1e-9 <= c[1] <= limits["v_max"] + 1e-9
                                            and abs(c[2]) <= jackal_omega + 1e-9)]
        check(not bad_cmds, f"{len(bad_cmds)} commands outside the limits, e.g. {bad_cmds[:3]}")

    check_limits(commands)
    check(not referee["collided"], f"collision at {referee['collision_pose']}")
    print(f"{len(commands)} cmd_vel messages, all inside v in [{v_low}, {limits['v_max']}] m/s, "
          f"|omega| <= {jackal_omega} rad/s", flush=True)
    ms = np.asarray(cycle_ms)
    check(len(ms) > 0, "no cycle diagnostics from fgdwa_node")
    print(f"fgdwa_node cycle time (inside the node, whole cycle): median {np.median(ms):.2f} ms, p95 "
          f"{np.percentile(ms, 95):.2f} ms over {len(ms)} cycles; Navigator::step alone median "
          f"{np.median(step_ms):.2f} ms, p95 {np.percentile(step_ms, 95):.2f} ms", flush=True)
    stages = np.median(np.asarray(stages_ms), axis=0)
    print("  its stages, median ms: " + ", ".join(f"{name} {value:.2f}" for name, value in
                                                zip(("tracking", "map", "global", "perception", "plan"), stages)))

    # 6. The bag: closed cleanly, then replayed.
    procs.stop(recorder, signal.SIGINT)
    # rosbag's recorder, a child of the command, renames run.bag.active once it has closed the file.
    active = bag.with_name(bag.name + ".active")
    wait_for(lambda: bag.is_file() and not active.exists(), 20, f"rosbag to close {bag}")
    summary = {"world": world.world_id, "barn_time": elapsed, "score": score, "cycles": len(ms),
               "cycle_ms_median": float(np.median(ms)), "cycle_ms_p95": float(np.percentile(ms, 95)),
               "stop_delay": stop_delay}
    replay(args, bag, out)

    # 7. The known-map mode: the node started again with mapping known, the world's
    # grid on `map`, the robot back at the start, a short patience. A wall closes the
    # whole world first (sim/door): no path, so the robot stands and the node waits;
    # when the wall opens the goal is reached. Then a goal behind the closed wall is
    # aborted once the patience has run out.
    procs.stop(launch, signal.SIGINT)
    rospy.Publisher("sim/reset", Empty, queue_size=1, latch=True).publish(Empty())
    wait_for(lambda: stopped() and math.hypot(referee["map_pose"][0] - sx, referee["map_pose"][1] - sy) < 1e-6,
             10, "the simulated Jackal to go back to the start")
    door = rospy.Publisher("sim/door", Bool, queue_size=1, latch=True)
    door.publish(Bool(data=True))
    patience = 4.0
    rospy.set_param("/fgdwa_node/patience", patience)
    launch = procs.start("fgdwa_node_known", ["roslaunch", "fgdwa_ros", "barn_jackal.launch", "mapping:=known"])
    check(client.wait_for_server(rospy.Duration(30)), "the known-map fgdwa_node's action server did not come up")
    before = len(commands)
    waits_before = sum(e.get("event") == "wait" for e in events)
    client.send_goal(goal(*odom_goal))
    waiting = wait_for(lambda: next((e for e in events[::-1] if e.get("event") == "wait"), None)
                       if sum(e.get("event") == "wait" for e in events) > waits_before else None,
                       15, "the node's wait event for the closed wall")
    check("NoGlobalPath" in waiting["reason"], f"with the wall closed the node waits for {waiting['reason']!r}")
    time.sleep(0.5 * patience)
    check(client.get_state() == GoalStatus.ACTIVE, f"the goal behind the wall ended {state_name(client.get_state())}"
          f" before the wall opened: {client.get_goal_status_text()}")
    check(stopped() and math.hypot(referee["map_pose"][0] - sx, referee["map_pose"][1] - sy) < 0.05,
          f"the robot did not stand at the start while no path existed: {referee['map_pose']}")
    door.publish(Bool(data=False))
    state, text = wait_result(args.time_limit + 10)
    time.sleep(0.3)
    distance = math.hypot(referee["map_pose"][0] - gx, referee["map_pose"][1] - gy)
    print(f"known map, BARN world {world.world_id}: waited ({waiting['reason']}) until the wall opened, then "
          f"{state_name(state)} ({text}), {distance:.2f} m from the goal, min clearance "
          f"{referee['min_clearance']:.3f} m", flush=True)
    check(state == GoalStatus.SUCCEEDED, f"known-map goal ended {state_name(state)}: {text}")
    check(not referee["collided"], f"collision at {referee['collision_pose']} (known map)")
    check("map of 0.150 m cells (known)" in procs.log("fgdwa_node_known"),
          "the known-map node did not build its navigator on the world's grid")
    door.publish(Bool(data=True))
    sent = time.monotonic()
    client.send_goal(goal(0.0, 0.5))  # back at the start, behind the wall
    state, text = wait_result(patience + 20)
    waited = time.monotonic() - sent
    print(f"a goal behind the closed wall: {state_name(state)} after {waited:.1f} s: {text}", flush=True)
    check(state == GoalStatus.ABORTED and "NoGlobalPath" in text and f"patience {patience:.1f} s" in text,
          f"the goal behind the wall ended {state_name(state)}: {text!r}")
    check(waited >= patience, f"aborted after {waited:.1f} s, before the patience of {patience} s")
    check_limits(commands[before:])
    rospy.delete_param("/fgdwa_node/patience")

    # 8. The node stopped while it drives: the goal ends ABORTED saying so and the robot is sent a stop.
    door.publish(Bool(data=False))
    client.send_goal(goal(0.0, 0.5))
    wait_for(lambda: abs(referee.get("v", 0.0)) > 0.2, 20, "the robot to start back to the start")
    procs.stop(launch, signal.SIGINT)
    state, text = wait_result(10)
    check(state == GoalStatus.ABORTED and "shutting down" in text, f"node stopped mid-goal: {state_name(state)}, "
                                                                     f"{text!r}")
    wait_for(stopped, 5, "the robot to stop after the node did")
    check(commands[-1][1:] == (0.0, 0.0), f"last command after the node stopped: {commands[-1]}")
    print(f"node stopped mid-goal: {state_name(state)} ({text}); the robot stopped", flush=True)
    summary["known_map"] = text
    (out / "summary.json").write_text(json.dumps(summary, indent=2) + "\n")
    return 0


COLOUR_BY = "clearance"  # the critic the test has the rollout fan coloured by


class Views:
    """What fgdwa_node publishes to be looked at: the first cycles' evaluations and
    rollout fans, every map, the footprint."""

    CYCLES = 20

    def __init__(self, prefix: Path):
        import rospy
        from geometry_msgs.msg import PolygonStamped
        from nav_msgs.msg import OccupancyGrid
        from visualization_msgs.msg import MarkerArray

        # The node's messages, generated at build time into its prefix.
        sys.path.insert(0, str(prefix / "lib" / "python3" / "dist-packages"))
        from fgdwa_ros.msg import LocalPlanEvaluation

        self.evaluations, self.fans, self.maps, self.footprints = {}, {}, [], []
        big = 1 << 24  # rospy's buffer must hold a whole evaluation (a few hundred kB) or it lags behind
        self.subscribers = [
            rospy.Subscriber("fgdwa_node/evaluation", LocalPlanEvaluation,
                             lambda m: self.evaluations.setdefault(m.header.stamp.to_nsec(), m),
                             queue_size=50, buff_size=big),
            rospy.Subscriber("fgdwa_node/rollouts", MarkerArray, self.on_fan, queue_size=50, buff_size=big)]
        rospy.Subscriber("fgdwa_node/map", OccupancyGrid, lambda m: self.maps.append((time.monotonic(), m)),
                         queue_size=10, buff_size=big)
        rospy.Subscriber("fgdwa_node/footprint", PolygonStamped, self.footprints.append, queue_size=1)

    def on_fan(self, msg) -> None:
        stamps = {m.header.stamp.to_nsec() for m in msg.markers if m.action == m.ADD}
        if len(stamps) == 1:
            self.fans.setdefault(stamps.pop(), msg)

    def enough(self) -> bool:
        planned = [e for e in self.evaluations.values() if e.planned]
        return len(planned) >= self.CYCLES and len(self.fans) >= self.CYCLES

    def stop_cycles(self) -> None:
        for subscriber in self.subscribers:
            subscriber.unregister()


def colour_scale(t: float):
    """The fan's colour scale, as docs/ros.md states it: blue, magenta, yellow."""
    stops = ((0.15, 0.25, 1.0), (0.9, 0.2, 0.65), (1.0, 0.9, 0.1))
    t = min(max(t, 0.0), 1.0) if math.isfinite(t) else 0.5
    k = 0 if t < 0.5 else 1
    u = 2.0 * t - k
    return tuple(a + u * (b - a) for a, b in zip(stops[k], stops[k + 1]))


def fan_colours(evaluation, critic):
    """Per admissible rollout of `evaluation`, in order: its colour with the fan coloured
    by `critic`'s term (None: by the total)."""
    def value(twist):
        return twist.total if critic is None else twist.scores[evaluation.critic_names.index(critic)].term

    admissible = [t for t in evaluation.twists if not t.rejected]
    values = [value(t) for t in admissible]
    low, high = min(values), max(values)
    return [colour_scale((v - low) / (high - low) if high - low > 1e-12 else 0.5) for v in values], admissible


def check_views(views: Views, cycles: dict, events: list, config: dict, world, referee: dict, prefix: Path,
                master) -> None:
    """The content of what fgdwa_node publishes to be looked at, against the node's
    settings, its diagnostics of the same cycle and the world the simulated Jackal drives in."""
    import numpy as np
    import yaml

    import fgdwa

    settings = next(e for e in events if e.get("event") == "config")["config"]
    built = next(e for e in events if e.get("event") == "navigator")
    critics = [c["name"] for c in fgdwa.planner_preset(config["preset"]).params.critics]
    check([c["name"] for c in settings["planner/critics"]] == critics,
          f"the node's critics {settings['planner/critics']} are not the {config['preset']} preset's {critics}")
    samples = settings["planner/window/n_v"] * settings["planner/window/n_omega"]

    # The evaluation: every sample with each critic's part, the best one what was commanded.
    planned = [e for e in views.evaluations.values() if e.planned]
    checked_command = 0
    for ev in planned:
        check(list(ev.critic_names) == critics, f"evaluation's critics {ev.critic_names}, configured {critics}")
        check(ev.header.frame_id == "odom", f"evaluation in frame {ev.header.frame_id!r}")
        check(len(ev.twists) == samples, f"evaluation of {len(ev.twists)} rollouts, the window has {samples}")
        check(len(ev.weights) == len(critics) and len(ev.critic_vetoes) == len(critics),
              f"evaluation's weights {ev.weights}, vetoes {ev.critic_vetoes}")
        admissible = 0
        for twist in ev.twists:
            check([s.name for s in twist.scores] == critics, f"rollout's critics {[s.name for s in twist.scores]}")
            check(len(twist.poses) >= 2, f"a rollout of {len(twist.poses)} poses")
            for score in twist.scores:
                check(abs(score.term - score.scale * score.normalized_score) <= 1e-12 * max(1.0, abs(score.term)),
                      f"{score.name}: term {score.term} is not scale {score.scale} x {score.normalized_score}")
            terms = sum(s.term for s in twist.scores)
            if twist.rejected:
                check(twist.total == -math.inf and terms == 0.0,
                      f"rejected ({twist.rejected}) rollout: total {twist.total}, terms {terms}")
                check(bool(twist.vetoed_by) == (twist.rejected == "Critic"),
                      f"rejected {twist.rejected}, vetoed by {twist.vetoed_by!r}")
            else:
                admissible += 1
                check(abs(terms - twist.total) <= 1e-9 * max(1.0, abs(twist.total)),
                      f"terms sum to {terms!r}, total {twist.total!r}")
        check(sum(ev.critic_vetoes) == sum(t.rejected == "Critic" for t in ev.twists),
              f"vetoes {list(ev.critic_vetoes)} against the rollouts' vetoes")
        cycle = cycles.get(ev.header.stamp.to_nsec())
        if cycle is not None:
            check(int(cycle["admissible"]) == admissible,
                  f"{admissible} admissible rollouts, the cycle's diagnostics say {cycle['admissible']}")
            check((float(cycle["v"]), float(cycle["omega"])) == (ev.command.linear.x, ev.command.angular.z),
                  f"evaluation's command {ev.command}, the cycle's ({cycle['v']}, {cycle['omega']})")
        check(0 <= ev.best_index < len(ev.twists), f"best index {ev.best_index} of {len(ev.twists)}")
        best = ev.twists[ev.best_index]
        if ev.mode == "Following":
            check((best.twist.linear.x, best.twist.angular.z) == (ev.command.linear.x, ev.command.angular.z),
                  f"best rollout's twist {best.twist}, commanded {ev.command}")
            checked_command += cycle is not None
    check(checked_command >= 5, f"only {checked_command} evaluations matched a cycle's diagnostics")
    print(f"evaluation: {len(planned)} cycles of {samples} rollouts x {len(critics)} critics ({', '.join(critics)}); "
          f"terms sum to each total, best index commanded ({checked_command} cycles against the diagnostics)",
          flush=True)

    # The fan: the admissible rollouts coloured by the clearance critic's term, as the evaluation gives them.
    matched = differs_from_total = varied = 0
    for stamp, fan in views.fans.items():
        ev = views.evaluations.get(stamp)
        if ev is None or not ev.planned:
            continue
        matched += 1
        markers = {m.ns: m for m in fan.markers if m.action == m.ADD}
        expected, admissible = fan_colours(ev, COLOUR_BY)
        by_total, _ = fan_colours(ev, None)
        rollouts = markers["rollouts"]
        points = [(p.x, p.y) for t in admissible for a, b in zip(t.poses[:-1], t.poses[1:]) for p in (a, b)]
        colours = [c for t, c in zip(admissible, expected) for _ in range(2 * (len(t.poses) - 1))]
        check([(p.x, p.y) for p in rollouts.points] == points, "the fan's lines are not the admissible rollouts")
        got = [(c.r, c.g, c.b) for c in rollouts.colors]
        check(len(got) == len(colours) and all(max(abs(a - b) for a, b in zip(g, e)) < 1e-6
                                               for g, e in zip(got, colours)),
              f"the fan's colours are not the {COLOUR_BY} terms' on the scale")
        varied += len({tuple(round(x, 4) for x in c) for c in expected}) > 1
        differs_from_total += any(max(abs(a - b) for a, b in zip(x, y)) > 1e-3 for x, y in zip(expected, by_total))
        chosen = markers.get("chosen")
        best = ev.twists[ev.best_index]
        check(chosen is not None and [(p.x, p.y) for p in chosen.points] == [(p.x, p.y) for p in best.poses],
              "the chosen marker is not the best index's rollout")
    check(matched >= 5, f"only {matched} rollout fans matched an evaluation")
    check(varied >= matched // 2 and differs_from_total > 0,
          f"the fan's colours vary in {varied} of {matched} cycles, differ from the total's in {differs_from_total}")
    print(f"rollout fan: {matched} cycles coloured by the {COLOUR_BY} term, as the evaluation's terms put it on "
          f"the scale (varying in {varied}, unlike the total's in {differs_from_total})", flush=True)

    # The map from the scans: the navigator's layout, occupied cells on the world's obstacles.
    check(views.maps, "no map on fgdwa_node/map")
    times = [m.header.stamp.to_sec() for _, m in views.maps]
    check(all(b - a >= 0.5 - 1e-6 for a, b in zip(times, times[1:])),
          f"maps {min(np.diff(times)) if len(times) > 1 else 0:.2f} s apart: more often than 2 Hz")
    grid = views.maps[-1][1]
    layout = built["layout"]
    info = grid.info
    check(grid.header.frame_id == "odom" and abs(info.resolution - config["map_resolution"]) < 1e-6
          and (info.height, info.width) == (layout["rows"], layout["cols"])
          and abs(info.origin.position.x - layout["origin"][0]) < 1e-9
          and abs(info.origin.position.y - layout["origin"][1]) < 1e-9,
          f"map {info.width} x {info.height} of {info.resolution} m at ({info.origin.position.x}, "
          f"{info.origin.position.y}) in {grid.header.frame_id!r}; the navigator's layout is {layout}")
    cells = np.asarray(grid.data, dtype=np.int8).reshape(info.height, info.width)
    values, counts = np.unique(cells, return_counts=True)
    check(set(values.tolist()) == {-1, 0, 100}, f"map values {dict(zip(values.tolist(), counts.tolist()))}")
    rows, cols = np.nonzero(cells == 100)
    odom = np.column_stack([info.origin.position.x + (cols + 0.5) * info.resolution,
                            info.origin.position.y + (rows + 0.5) * info.resolution])
    # odom is the world's frame turned about the start (sim_jackal.py), by the referee's two headings' difference.
    sx, sy, _ = world.start
    turn = referee["true_odom_pose"][2] - referee["map_pose"][2]
    c, s = math.cos(-turn), math.sin(-turn)
    in_world = np.column_stack([sx + c * odom[:, 0] - s * odom[:, 1], sy + s * odom[:, 0] + c * odom[:, 1]])
    distance = fgdwa.DistanceField(world.grid).distance(in_world)
    near = float(np.mean(distance <= 0.15))
    check(len(rows) > 100 and near >= 0.95,
          f"{len(rows)} occupied cells, {100 * near:.1f} % of them within 0.15 m of the world's obstacles")
    print(f"map: {info.width} x {info.height} cells of {info.resolution:.3f} m ({len(views.maps)} published, "
          f"{counts[values == -1][0]} unknown, {len(rows)} occupied, {100 * near:.1f} % of those within 0.15 m "
          f"of the world's obstacles, median {np.median(distance):.3f} m)", flush=True)

    # The footprint: the jackal preset's rectangle in the base frame.
    check(views.footprints, "no footprint on fgdwa_node/footprint")
    footprint = views.footprints[-1]
    vertices = np.asarray(fgdwa.robot_preset(config["robot"]).footprint.vertices)
    got = np.asarray([(p.x, p.y) for p in footprint.polygon.points])
    check(footprint.header.frame_id == "base_link" and got.shape == vertices.shape
          and np.allclose(got, vertices, atol=1e-6),
          f"footprint {got.tolist()} in {footprint.header.frame_id!r}, configured {vertices.tolist()}")

    # The rviz config names topics the node publishes, with the types its displays take.
    rviz = yaml.safe_load((prefix / "share" / "fgdwa_ros" / "config" / "fgdwa.rviz").read_text())
    kinds = {"rviz/Map": "nav_msgs/OccupancyGrid", "rviz/Path": "nav_msgs/Path",
             "rviz/MarkerArray": "visualization_msgs/MarkerArray", "rviz/Polygon": "geometry_msgs/PolygonStamped",
             "rviz/LaserScan": "sensor_msgs/LaserScan"}
    published = dict(master.getTopicTypes())
    shown = 0
    for display in rviz["Visualization Manager"]["Displays"]:
        if display["Class"] in kinds:
            topic = display.get("Topic") or display.get("Marker Topic")
            check(published.get(topic) == kinds[display["Class"]],
                  f"rviz display {display['Name']!r}: {topic} is {published.get(topic)}, not {kinds[display['Class']]}")
            shown += 1
    check(rviz["Visualization Manager"]["Global Options"]["Fixed Frame"] == "odom", "rviz's fixed frame is not odom")
    print(f"footprint: {len(got)} vertices as configured; rviz config: {shown} displays on the node's topics",
          flush=True)


def replay(args, bag: Path, out: Path) -> None:
    """``fgdwa replay`` on the run's bag: the planner rerun on the recorded scans
    and odometry must command what the node commanded."""
    venv_fgdwa = Path(args.fgdwa_python).parent / "fgdwa"
    argv = [str(venv_fgdwa), "replay", str(bag), "--out", str(out / "replay")]
    done = subprocess.run(argv, capture_output=True, text=True, timeout=600)
    print(done.stdout[-3000:], flush=True)
    check(done.returncode == 0, f"fgdwa replay exited {done.returncode}: {done.stderr[-2000:]}")
    report = json.loads((out / "replay" / "replay.json").read_text())
    check(report["cycles"] > 10, f"replay stepped only {report['cycles']} cycles")
    check(report["gaps"] == 0, f"the bag misses cycles of the node ({report['gaps']} gaps)")
    check(report["matching"] == report["cycles"],
          f"replay matched only {report['matching']} of {report['cycles']} recorded commands (same build, same inputs)")
    # A setting given wrong is the user's to fix, and named so, not blamed on the bag.
    bad = subprocess.run(argv + ["--set", "navigator/max_recoveries=1.5"], capture_output=True, text=True, timeout=600)
    check(bad.returncode == 2 and "--set navigator/max_recoveries=1.5: " in bad.stderr and "Traceback" not in bad.stderr,
          f"replay with a bad --set: exit {bad.returncode}, {bad.stderr[-500:]!r}")


if __name__ == "__main__":
    sys.exit(main())
