"""The robot's body between the navigator's command and the ground: command
latency, actuation noise and lag, and the odometry the navigator believes.

``run_episode`` keeps one :class:`Body` per episode. Each cycle the navigator's
command goes in (:meth:`Body.wheels`), the twist the robot really moves with
comes out (:meth:`Body.drive`), and the pose the robot believes it reached is
its odometry (:meth:`Body.odometry`). Every draw comes from generators seeded
from the episode's seed, one stream for the actuators and one for odometry, so
switching one on leaves the other's draws unchanged.
"""

from __future__ import annotations

import dataclasses
import math
from collections import deque
from dataclasses import dataclass

import numpy as np

from fgdwa._core import FgdwaError, Twist, unicycle_step, wrap_angle
from fgdwa.file_limits import MAX_STEPS, short_repr

ACTUATION_STREAM = 1  # the second word of the actuators' generator seed: (seed, ACTUATION_STREAM)
ODOMETRY_STREAM = 2


def _non_negative_pair(value, name: str, units: str) -> np.ndarray:
    try:
        pair = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        pair = None
    if pair is None or pair.shape != (2,) or not np.all(np.isfinite(pair)) or np.any(pair < 0):
        raise FgdwaError(f"{name} = {short_repr(value)}: expected two finite numbers >= 0 ({units})")
    return pair


SCAN_SEED_STRIDE = 1_000_003  # the lidar's seed in cycle k of a run with `seed`: seed * stride + k
# The largest episode seed: the lidar's seed in its last cycle must fit the scanner's 64 bits.
MAX_SEED = (2**64 - 1 - MAX_STEPS) // SCAN_SEED_STRIDE


def check_seed(seed) -> int:
    """The episode's seed as a Python int: an integer in [0, MAX_SEED]."""
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or not 0 <= seed <= MAX_SEED:
        raise FgdwaError(f"seed = {short_repr(seed)}: must be an integer in [0, {MAX_SEED}]")
    return int(seed)


@dataclass(frozen=True)
class BodySettings:
    """How honest the body is (see Body); BODY_PROFILES names the usual ones."""

    latency: int = 0  # cycles
    actuation_noise: tuple = (0.0, 0.0)  # (m/s, rad/s)
    actuation_lag: float = 0.0  # s
    odometry_drift: tuple = (0.0, 0.0)  # (m per sqrt(m) travelled, rad per sqrt(rad) turned)
    motor_rate: float = 0.0  # Hz: the wheels ramp toward the command at the acceleration limits this often; 0: at once

    def __post_init__(self):
        latency = self.latency
        if isinstance(latency, bool) or not isinstance(latency, (int, np.integer)) or latency < 0:
            raise FgdwaError(f"latency = {short_repr(latency)}: must be an integer >= 0 (control cycles)")
        object.__setattr__(self, "actuation_noise",
                           tuple(_non_negative_pair(self.actuation_noise, "actuation_noise", "std of v in m/s, "
                                                    "std of omega in rad/s")))
        object.__setattr__(self, "odometry_drift",
                           tuple(_non_negative_pair(self.odometry_drift, "odometry_drift", "m per metre travelled, "
                                                    "rad per rad turned")))
        for name, unit, top in (("actuation_lag", "s, time constant", 60.0), ("motor_rate", "Hz, 0 for none", 1e4)):
            value = getattr(self, name)
            # Compared before any conversion: a huge integer has no float.
            if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)) \
                    or not 0 <= value <= top:
                raise FgdwaError(f"{name} = {short_repr(value)}: must be a number in [0, {top:g}] ({unit})")


# The bodies the benchmarks run: "default", what a wheeled robot with wheel
# odometry and a gyro does (docs/simulation.md, "The body", says where the
# figures come from), and "ideal", the command applied at once and the pose
# known exactly; "harsh", a worn robot for stress tests: a 0.1 s lag on top of
# the ramp and twice the default's drift in position, 2.5 times in heading.
BODY_PROFILES = {
    "ideal": BodySettings(),
    "default": BodySettings(motor_rate=100.0, actuation_noise=(0.02, 0.05), odometry_drift=(0.01, 0.002)),
    "harsh": BodySettings(motor_rate=100.0, actuation_lag=0.1, actuation_noise=(0.02, 0.05),
                          odometry_drift=(0.02, 0.005)),
}
DEFAULT_BODY = "default"


def body_profile(body) -> BodySettings:
    """A BodySettings, or the one BODY_PROFILES names."""
    if isinstance(body, BodySettings):
        return body
    if isinstance(body, str) and body in BODY_PROFILES:
        return BODY_PROFILES[body]
    raise FgdwaError(f"body = {short_repr(body)}: expected a BodySettings or one of {', '.join(BODY_PROFILES)}")


class Body:
    """One episode's actuators and odometry (see the module's docstring).

    * latency: the command computed in cycle k reaches the wheels in cycle
      k + latency; until a computed command arrives the wheels keep the last
      one they had (at rest at the start).
    * actuation noise: Gaussian noise (std_v, std_omega) added to the command
      the wheels get, every cycle they are asked to move.
    * actuation lag: what the wheels aim at approaches that command as a
      first-order lag of time constant ``actuation_lag``.
    * motor rate: at ``motor_rate`` Hz the motor controller moves (v, omega)
      toward what it aims at by at most the robot's acceleration (its braking
      deceleration when slowing) times the period, as a velocity loop with
      acceleration limits does; 0 reaches it at once.
      Over a cycle the robot moves with the mean twist and ends it at the last one.
    * odometry drift: the believed pose follows the driven twist plus a random
      walk whose std grows as ``drift[0] * sqrt(metres travelled)`` in x and y
      and ``drift[1] * sqrt(radians turned)`` in heading; the heading's error
      turns later motion, so the position's error grows beyond it.
    """

    def __init__(self, settings: BodySettings, dt: float, seed: int, limits=None):
        self.settings = settings
        self.dt = float(dt)
        self._pending = deque()
        self._wheels = Twist(0.0, 0.0)  # the last command the wheels got
        self.twist = Twist(0.0, 0.0)  # the robot's velocity now
        self._aim = Twist(0.0, 0.0)  # what the lagged command has reached
        self._actuation_rng = np.random.default_rng([seed, ACTUATION_STREAM])
        self._odometry_rng = np.random.default_rng([seed, ODOMETRY_STREAM])
        noise = settings.actuation_noise
        self._noisy = noise[0] > 0 or noise[1] > 0
        drift = settings.odometry_drift
        self.drifts = drift[0] > 0 or drift[1] > 0
        self._substeps = 0
        if settings.motor_rate > 0:
            if limits is None:
                raise FgdwaError("Body: a motor_rate needs the robot's limits (its accelerations)")
            self._substeps = max(1, int(round(self.dt * settings.motor_rate)))
            self._accel = (limits.acc_v, limits.acc_omega)
            self._brake = (limits.braking_v(), limits.braking_omega())

    def wheels(self, computed: Twist) -> Twist:
        """The command the wheels get this cycle, given the one the navigator computed."""
        latency = self.settings.latency
        if latency == 0:
            command = computed
        else:
            self._pending.append(computed)
            command = self._pending.popleft() if len(self._pending) > latency else self._wheels
        self._wheels = command
        # A motor controller holds a standing command: the noise is on motion asked for.
        if self._noisy and (command.v != 0.0 or command.omega != 0.0):
            std_v, std_omega = self.settings.actuation_noise
            dv, domega = self._actuation_rng.normal(0.0, (std_v, std_omega))
            command = Twist(command.v + dv, command.omega + domega)
        return command

    def drive(self, target: Twist) -> Twist:
        """Move the velocity toward ``target`` for one cycle; the mean twist of the cycle."""
        if self._substeps:
            return self._ramp(target)
        tau = self.settings.actuation_lag
        if tau == 0:
            self.twist = target
            return target
        keep = math.exp(-self.dt / tau)  # what remains of the gap to the target at the cycle's end
        mean_keep = tau / self.dt * (1.0 - keep)  # its mean over the cycle
        v0, w0 = self.twist.v, self.twist.omega
        mean = Twist(target.v + (v0 - target.v) * mean_keep, target.omega + (w0 - target.omega) * mean_keep)
        self.twist = Twist(target.v + (v0 - target.v) * keep, target.omega + (w0 - target.omega) * keep)
        return mean

    def _ramp(self, target: Twist) -> Twist:
        """The motor controller's loop over one cycle: each period the aim follows
        the lag, the velocity steps toward it within the acceleration limits."""
        h = self.dt / self._substeps
        tau = self.settings.actuation_lag
        follow = 1.0 - math.exp(-h / tau) if tau > 0 else 1.0
        aim = np.array([self._aim.v, self._aim.omega])
        twist = np.array([self.twist.v, self.twist.omega])
        goal = np.array([target.v, target.omega])
        accel, brake = np.array(self._accel) * h, np.array(self._brake) * h
        total = np.zeros(2)
        for _ in range(self._substeps):
            aim += (goal - aim) * follow
            gap = aim - twist
            # Speeding up (away from zero) is limited by the acceleration, slowing down by the braking.
            limit = np.where(gap * twist > 0, accel, np.where(twist == 0, accel, brake))
            start = twist.copy()
            twist = twist + np.clip(gap, -limit, limit)
            total += 0.5 * (start + twist)
        self._aim = Twist(*aim)
        self.twist = Twist(*twist)
        mean = total / self._substeps
        return Twist(float(mean[0]), float(mean[1]))

    def odometry(self, believed, driven: Twist, true_pose) -> np.ndarray:
        """The pose the robot believes after moving with ``driven`` for one cycle
        from ``believed``; the true pose itself when odometry does not drift."""
        if not self.drifts:
            return np.array([true_pose.x, true_pose.y, true_pose.theta])
        pose = unicycle_step(believed, driven, self.dt)
        std_xy, std_theta = self.settings.odometry_drift
        travelled, turned = abs(driven.v) * self.dt, abs(driven.omega) * self.dt
        ex, ey, etheta = self._odometry_rng.normal(
            0.0, (std_xy * math.sqrt(travelled), std_xy * math.sqrt(travelled), std_theta * math.sqrt(turned)))
        return np.array([pose.x + ex, pose.y + ey, wrap_angle(pose.theta + etheta)])


def body_settings(options) -> BodySettings:
    """The BodySettings of an EpisodeOptions: its body profile, with the body
    fields it gives (not None) in place of the profile's."""
    base = body_profile(options.body)
    given = {f.name: getattr(options, f.name) for f in dataclasses.fields(BodySettings)
             if getattr(options, f.name) is not None}
    return dataclasses.replace(base, **given)
