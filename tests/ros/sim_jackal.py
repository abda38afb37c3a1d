"""A simulated BARN Jackal for fgdwa_node's test, as a ROS 1 node.

Run by Debian's /usr/bin/python3 (rospy) with fgdwa's package on the path.
The world is a BARN map (fgdwa.io.load_barn); the robot is the
``jackal`` robot preset driven by ``cmd_vel`` in real time: each tick
(``--tick`` s) its velocity moves toward the last command within the Jackal's
accelerations (a command older than ``--cmd-timeout`` s counts as a stop, as
the Jackal's controller does), then fgdwa's unicycle step moves it.
It publishes what a Jackal publishes: ``front/scan`` (fgdwa's LaserScanner,
720 beams over 270 degrees, range noise and dropped beams), ``odometry/filtered``
and the ``odom -> base_link`` transform, which drift as the ``default`` body's
odometry does (fgdwa.sim.body: a random walk per sqrt(m) travelled and per
sqrt(rad) turned, ``--drift``), the static ``base_link -> front_laser``
mounting, and ``/clock``: the simulated time, which the node runs on
(``use_sim_time``) and every stamp carries.

The referee is fgdwa's own (fgdwa.sim.collides_during_step on the exact FCL
world) and judges the Jackal's true outline, 0.508 m x 0.430 m, not the
smaller box the planner is configured with: a collision is the body touching
the map's obstacles anywhere along a tick, at the true pose. ``sim/referee`` carries
its verdict and the robot's true state as JSON; ``sim/scan_enabled``
(std_msgs/Bool) silences the lidar and brings it back; ``sim/reset``
(std_msgs/Empty) puts the robot back at the start, at rest. ``map`` (latched)
is the world's grid in the odom frame, for fgdwa_node's known-map mode.
``sim/door`` (std_msgs/Bool) closes a wall across the whole world ``--door``
m past the start (true) or takes it away (false): the lidar, the referee and
``map`` see it at once.
"""

from __future__ import annotations

import argparse
import json
import math
import time

import numpy as np
import rospy
import tf2_ros
from geometry_msgs.msg import TransformStamped, Twist as TwistMsg
from nav_msgs.msg import OccupancyGrid as GridMsg, Odometry
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import LaserScan
from std_msgs.msg import Bool, Empty, String

import fgdwa
from fgdwa.io import load_barn
from fgdwa.sim import collides_during_step
from fgdwa.sim.body import BODY_PROFILES, Body, BodySettings

# m, m, rad: the challenge's UST-10 sits 0.065 m behind the Jackal's front mount (0.12 m ahead of base_link).
LASER_MOUNT = (0.055, 0.0, 0.0)
LASER_FRAME = "front_laser"
# The challenge's odometry fuses an IMU that reads Gazebo's heading: its odom
# frame has Gazebo's axes, the start at its origin, and the robot at 1.57 rad
# (the goal, 10 m ahead, is (0, 10) in odom). BARN's map frame has x along the
# direction of travel, so the odom frame is the map's turned by this much about the start.
ODOM_YAW = 1.57


def quaternion(yaw: float):
    return 0.0, 0.0, math.sin(0.5 * yaw), math.cos(0.5 * yaw)


def toward(value: float, target: float, step: float) -> float:
    return value + max(-step, min(step, target - value))


class SimJackal:
    def __init__(self, args):
        world = load_barn(args.barn).world(args.world)
        self.world = world
        self.grid = world.grid
        self.door_closed = False
        jackal = fgdwa.robot_preset("jackal")
        self.outline = jackal.outline  # the body the referee judges
        self.limits = jackal.limits
        self.odometry = Body(BodySettings(odometry_drift=tuple(args.drift)), args.tick, args.seed)
        self.lidar = fgdwa.LidarParams(fov=270.0 * math.pi / 180.0, beams=720, max_range=args.range_max,
                                       noise_std=args.noise, dropout=args.dropout)
        self.use_grid(world.grid)
        self.args = args
        self.origin = np.array(world.start, dtype=float)
        self.odom_turn = args.odom_yaw - world.start[2]
        self.pose = np.array(world.start, dtype=float)  # map frame
        self.believed = self.pose.copy()  # where the odometry says the robot is, map frame
        self.sim_time = 0.0  # s since the start, published on /clock
        self.v = self.omega = 0.0
        self.cmd = (0.0, 0.0)
        self.cmd_time = -math.inf
        self.scan_enabled = True
        self.collided = False
        self.collision_pose = None
        self.min_clearance = math.inf
        self.travelled = 0.0
        self.scans = 0
        self.last_scan_time = 0.0
        self.scan_seed = args.seed * 1_000_003

        self.clock_pub = rospy.Publisher("/clock", Clock, queue_size=10)
        self.scan_pub = rospy.Publisher("front/scan", LaserScan, queue_size=5)
        self.odom_pub = rospy.Publisher("odometry/filtered", Odometry, queue_size=5)
        self.referee_pub = rospy.Publisher("sim/referee", String, queue_size=5, latch=True)
        self.tf = tf2_ros.TransformBroadcaster()
        self.static_tf = tf2_ros.StaticTransformBroadcaster()
        rospy.Subscriber("cmd_vel", TwistMsg, self.on_cmd, queue_size=5)
        rospy.Subscriber("sim/scan_enabled", Bool, self.on_scan_enabled, queue_size=5)
        rospy.Subscriber("sim/reset", Empty, self.on_reset, queue_size=1)
        rospy.Subscriber("sim/door", Bool, self.on_door, queue_size=1)
        self.map_pub = rospy.Publisher("map", GridMsg, queue_size=1, latch=True)
        self.publish_mount()
        self.publish_map()

    def on_cmd(self, msg: TwistMsg) -> None:
        self.cmd = (msg.linear.x, msg.angular.z)
        self.cmd_time = time.monotonic()

    def on_scan_enabled(self, msg: Bool) -> None:
        self.scan_enabled = bool(msg.data)

    def use_grid(self, grid) -> None:
        """The world the lidar sees and the referee judges (each swapped whole: the tick reads them)."""
        self.grid = grid
        self.truth = fgdwa.CollisionWorld(grid)
        self.scanner = fgdwa.LaserScanner(self.lidar, fgdwa.DistanceField(grid))

    def on_door(self, msg: Bool) -> None:
        if bool(msg.data) == self.door_closed:
            return
        self.door_closed = bool(msg.data)
        grid = self.world.grid
        if self.door_closed:
            cells = np.array(grid.cells, dtype=np.uint8)
            col = int((self.world.start[0] + self.args.door - grid.origin[0]) / grid.resolution)
            cells[:, col] = 1
            grid = fgdwa.OccupancyGrid(cells, grid.resolution, grid.origin)
        self.use_grid(grid)
        self.publish_map()
        rospy.loginfo(f"sim_jackal: door {'closed' if self.door_closed else 'open'}")

    def on_reset(self, _msg: Empty) -> None:
        self.pose = np.array(self.world.start, dtype=float)
        self.believed = self.pose.copy()
        self.v = self.omega = 0.0
        self.cmd = (0.0, 0.0)
        self.travelled = 0.0
        self.min_clearance = math.inf  # a collision, once seen, stays reported

    def publish_map(self) -> None:
        """The world's grid in the odom frame: turned by odom_turn (a multiple of a right
        angle, as in BARN) about the start, cell for cell."""
        quarter = self.odom_turn / (0.5 * math.pi)
        turns = int(round(quarter)) % 4
        if abs(quarter - round(quarter)) > 1e-3:
            rospy.logwarn("sim_jackal: odom frame not a right angle off the map's; no map published")
            return
        cells = np.asarray(self.grid.cells, dtype=np.int8)
        res = self.grid.resolution
        ox, oy = self.grid.origin
        rows, cols = cells.shape
        x0, y0, _ = self.origin
        # Corners of the map in odom; the turned grid's origin is their lowest x and y.
        c, s = math.cos(self.odom_turn), math.sin(self.odom_turn)
        corners = [(c * (x - x0) - s * (y - y0), s * (x - x0) + c * (y - y0))
                   for x in (ox, ox + cols * res) for y in (oy, oy + rows * res)]
        # np.rot90 turns counter-clockwise as printed, row 0 at the top; with row 0 at the
        # bottom (y up) that is clockwise, so a counter-clockwise turn is k = -turns.
        turned = np.rot90(cells, k=-turns)
        msg = GridMsg()
        msg.header.stamp = rospy.Time.now()
        msg.header.frame_id = "odom"
        msg.info.resolution = res
        msg.info.height, msg.info.width = turned.shape
        msg.info.origin.position.x = min(p[0] for p in corners)
        msg.info.origin.position.y = min(p[1] for p in corners)
        msg.info.origin.orientation.w = 1.0
        msg.data = (100 * turned).astype(np.int8).ravel().tolist()
        self.map_pub.publish(msg)

    def publish_mount(self) -> None:
        t = TransformStamped()
        t.header.stamp = rospy.Time.now()
        t.header.frame_id = "base_link"
        t.child_frame_id = LASER_FRAME
        t.transform.translation.x, t.transform.translation.y = LASER_MOUNT[0], LASER_MOUNT[1]
        (t.transform.rotation.x, t.transform.rotation.y, t.transform.rotation.z,
         t.transform.rotation.w) = quaternion(LASER_MOUNT[2])
        self.static_tf.sendTransform(t)

    def odom_pose(self, pose=None):
        """A pose (default: where the odometry believes the robot is) in the odometry
        frame: the map's, turned by odom_turn about the start."""
        pose = self.believed if pose is None else pose
        x0, y0, _ = self.origin
        dx, dy = pose[0] - x0, pose[1] - y0
        c, s = math.cos(self.odom_turn), math.sin(self.odom_turn)
        return c * dx - s * dy, s * dx + c * dy, fgdwa.wrap_angle(pose[2] + self.odom_turn)

    def advance(self, dt: float, now: float) -> None:
        cmd_v, cmd_omega = self.cmd if now - self.cmd_time <= self.args.cmd_timeout else (0.0, 0.0)
        self.v = toward(self.v, cmd_v, self.limits.acc_v * dt)
        self.omega = toward(self.omega, cmd_omega, self.limits.acc_omega * dt)
        before = self.pose.copy()
        after = fgdwa.unicycle_step(tuple(before), (self.v, self.omega), dt)
        self.pose = np.array([after.x, after.y, after.theta])
        self.odometry.dt = dt
        self.believed = self.odometry.odometry(self.believed, fgdwa.Twist(self.v, self.omega), after)
        self.sim_time += dt
        self.travelled += math.hypot(*(self.pose[:2] - before[:2]))
        self.min_clearance = min(self.min_clearance, float(self.truth.clearance(self.outline, tuple(self.pose), 0.0)))
        if not self.collided and collides_during_step(self.truth, self.outline, before, self.pose, 0.0, dt):
            self.collided = True
            self.collision_pose = self.pose.tolist()
            rospy.logwarn(f"sim_jackal: COLLISION at {self.collision_pose}")

    def publish_state(self, stamp) -> None:
        x, y, th = self.odom_pose()
        qx, qy, qz, qw = quaternion(th)
        odom = Odometry()
        odom.header.stamp = stamp
        odom.header.frame_id = "odom"
        odom.child_frame_id = "base_link"
        odom.pose.pose.position.x, odom.pose.pose.position.y = x, y
        (odom.pose.pose.orientation.x, odom.pose.pose.orientation.y, odom.pose.pose.orientation.z,
         odom.pose.pose.orientation.w) = qx, qy, qz, qw
        odom.twist.twist.linear.x = self.v
        odom.twist.twist.angular.z = self.omega
        t = TransformStamped()
        t.header = odom.header
        t.child_frame_id = "base_link"
        t.transform.translation.x, t.transform.translation.y = x, y
        (t.transform.rotation.x, t.transform.rotation.y, t.transform.rotation.z,
         t.transform.rotation.w) = qx, qy, qz, qw
        self.tf.sendTransform(t)
        self.odom_pub.publish(odom)

    def publish_scan(self, stamp) -> None:
        c, s = math.cos(self.pose[2]), math.sin(self.pose[2])
        mx, my, mth = LASER_MOUNT
        laser = (self.pose[0] + c * mx - s * my, self.pose[1] + s * mx + c * my, self.pose[2] + mth)
        scan = self.scanner.scan(laser, seed=self.scan_seed + self.scans)
        self.scans += 1
        msg = LaserScan()
        msg.header.stamp = stamp
        msg.header.frame_id = LASER_FRAME
        msg.angle_min = -0.5 * self.lidar.fov
        msg.angle_max = 0.5 * self.lidar.fov
        msg.angle_increment = self.lidar.fov / (self.lidar.beams - 1)
        msg.scan_time = 1.0 / self.args.scan_rate
        msg.range_min = 0.1
        msg.range_max = self.lidar.max_range
        msg.ranges = np.asarray(scan.ranges, dtype=np.float32).tolist()
        self.scan_pub.publish(msg)
        self.last_scan_time = stamp.to_sec()

    def publish_referee(self) -> None:
        x, y, th = self.odom_pose()
        tx, ty, tth = self.odom_pose(self.pose)
        report = {"collided": self.collided, "collision_pose": self.collision_pose,
                  "min_clearance": self.min_clearance, "map_pose": self.pose.tolist(), "odom_pose": [x, y, th],
                  "true_odom_pose": [tx, ty, tth], "odometry_error": float(np.hypot(*(self.believed - self.pose)[:2])),
                  "sim_time": self.sim_time,
                  "v": self.v, "omega": self.omega, "travelled": self.travelled, "scans": self.scans,
                  "scan_enabled": self.scan_enabled, "last_scan_time": self.last_scan_time,
                  "world": self.world.world_id, "optimal_time": self.world.optimal_time,
                  "goal_map": list(self.world.goal), "start_map": list(self.world.start),
                  "goal_radius": self.world.goal_radius}
        self.referee_pub.publish(String(data=json.dumps(report)))

    def run(self) -> None:
        tick = self.args.tick
        odom_every = max(1, round(1.0 / (self.args.odom_rate * tick)))
        scan_every = max(1, round(1.0 / (self.args.scan_rate * tick)))
        referee_every = max(1, round(0.1 / tick))
        count = 0
        next_time = time.monotonic()
        last = next_time
        while not rospy.is_shutdown():
            now = time.monotonic()
            # Real time: integrate what passed, however late this tick is.
            self.advance(now - last, now)
            last = now
            stamp = rospy.Time.from_sec(self.sim_time)
            self.clock_pub.publish(Clock(clock=stamp))
            if count % odom_every == 0:
                self.publish_state(stamp)
            if count % scan_every == 0 and self.scan_enabled:
                self.publish_scan(stamp)
            if count % referee_every == 0:
                self.publish_referee()
            count += 1
            next_time += tick
            delay = next_time - time.monotonic()
            if delay > 0:
                time.sleep(delay)
            else:
                next_time = time.monotonic()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--barn", required=True, help="barn.npz")
    parser.add_argument("--world", type=int, default=0, help="BARN world id")
    parser.add_argument("--seed", type=int, default=0, help="seed of the lidar's noise and dropped beams")
    parser.add_argument("--tick", type=float, default=0.01, help="s per physics tick")
    parser.add_argument("--odom-rate", type=float, default=50.0, help="Hz of odometry and TF")
    parser.add_argument("--scan-rate", type=float, default=25.0, help="Hz of the lidar (10-50)")
    parser.add_argument("--noise", type=float, default=0.03, help="m, range noise std")
    parser.add_argument("--dropout", type=float, default=0.01, help="probability a beam returns nothing")
    parser.add_argument("--range-max", type=float, default=30.0, help="m, the lidar's range")
    parser.add_argument("--odom-yaw", type=float, default=ODOM_YAW, help="rad, the robot's heading at the start, in odom")
    parser.add_argument("--door", type=float, default=7.5, help="m past the start (along the map's x) of sim/door's wall")
    parser.add_argument("--cmd-timeout", type=float, default=0.25, help="s after which a command counts as a stop")
    parser.add_argument("--drift", type=float, nargs=2, default=BODY_PROFILES["default"].odometry_drift,
                        metavar=("M", "RAD"), help="odometry drift: m per sqrt(m) travelled, rad per sqrt(rad) turned "
                                                   "(default: fgdwa's default body)")
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node("sim_jackal")
    SimJackal(args).run()


if __name__ == "__main__":
    main()
