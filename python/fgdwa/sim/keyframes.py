"""Movers that follow timed keyframes the way Gazebo animates a model.

Gazebo-classic's ``PoseAnimation`` (the DynaBARN worlds' cylinders) moves a
model through keyframes ``(t, x, y)`` as follows:

* the positions are the points of a cubic Hermite spline whose tangents are
  Catmull-Rom's, taken per keyframe *index*, not per unit time: ``0.5 (p[i+1] -
  p[i-1])`` inside, ``p[1] - p[0]`` and ``p[n-1] - p[n-2]`` at the ends of an
  open route; a closed one (first point equal to the last within 1 mm) uses
  ``0.5 (p[1] - p[n-2])`` at both ends (ignition-math's ``Spline``, tension 0);
* between keyframes k and k + 1 the spline's parameter is the fraction
  ``(t - t_k) / (t_k+1 - t_k)`` of the segment's time, so the speed along the
  curve varies within a segment;
* a looping animation's clock wraps as ``fmod(t, length)``: after the last
  keyframe the model jumps back to the first; one that does not loop holds its
  last pose; past the last keyframe but before ``length`` the model waits at the
  last keyframe (a spline cannot blend from its last point to nothing).

The velocity is the spline's derivative over the segment's duration.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from typing import Optional

import numpy as np

from fgdwa._core import Disc, FgdwaError
from fgdwa.file_limits import short_repr

# ignition-math compares points within this (Vector3::operator==) and times
# within this (math::equal's default).
_SAME_POINT = 1e-3
_SAME_TIME = 1e-6


def catmull_rom_tangents(points: np.ndarray) -> np.ndarray:
    """Each keyframe's tangent, per keyframe index, as ignition-math's Spline
    computes it (tension 0)."""
    n = len(points)
    tangents = np.empty_like(points)
    closed = bool(np.all(np.abs(points[0] - points[-1]) <= _SAME_POINT))
    tangents[1:-1] = 0.5 * (points[2:] - points[:-2])
    if closed:
        tangents[0] = 0.5 * (points[1] - points[n - 2])
        tangents[-1] = tangents[0]
    else:
        tangents[0] = points[1] - points[0]
        tangents[-1] = points[-1] - points[-2]
    return tangents


def hermite(p0, p1, m0, m1, s: float) -> tuple:
    """(point, d point / d s) of the cubic Hermite segment at parameter s in [0, 1]."""
    s2, s3 = s * s, s * s * s
    point = (2 * s3 - 3 * s2 + 1) * p0 + (-2 * s3 + 3 * s2) * p1 + (s3 - 2 * s2 + s) * m0 + (s3 - s2) * m1
    slope = (6 * s2 - 6 * s) * p0 + (-6 * s2 + 6 * s) * p1 + (3 * s2 - 4 * s + 1) * m0 + (3 * s2 - 2 * s) * m1
    return point, slope


@dataclass(frozen=True)
class KeyframedMover:
    """A disc of ``radius`` (m) moved through ``keyframes`` ((k, 3): t s, x m,
    y m; k >= 2, times increasing from >= 0) as Gazebo's PoseAnimation does (see
    the module). ``length`` (s) is the animation's period (default: the last
    keyframe's time); ``loop`` wraps the clock, otherwise the last pose holds.
    ``phase`` (s) is where the animation's clock stands at the episode's t = 0.
    """

    radius: float
    keyframes: np.ndarray
    loop: bool = True
    length: Optional[float] = None
    phase: float = 0.0

    def __post_init__(self):
        if not (isinstance(self.radius, (int, float)) and math.isfinite(self.radius) and self.radius > 0):
            raise FgdwaError(f"keyframed mover radius = {short_repr(self.radius)}: must be a finite number > 0 (m)")
        try:
            frames = np.asarray(self.keyframes, dtype=float)
        except (TypeError, ValueError):
            raise FgdwaError(f"keyframed mover keyframes = {short_repr(self.keyframes)}: expected (k, 3) numbers [t, x, y]") \
                from None
        if frames.ndim != 2 or frames.shape[1] != 3 or len(frames) < 2 or not np.all(np.isfinite(frames)):
            raise FgdwaError(f"keyframed mover keyframes: expected (k >= 2, 3) finite [t s, x m, y m], "
                             f"got shape {frames.shape}")
        times = frames[:, 0]
        if times[0] < 0 or np.any(np.diff(times) <= 0):
            bad = int(np.argmax(np.diff(times) <= 0)) + 1 if times[0] >= 0 else 0
            raise FgdwaError(f"keyframed mover keyframes[{bad}]: time {short_repr(times[bad])} s: times must start >= 0 "
                             "and increase")
        object.__setattr__(self, "keyframes", frames)
        length = float(times[-1]) if self.length is None else self.length
        if not (isinstance(length, (int, float)) and math.isfinite(length) and length >= times[-1] and length > 0):
            raise FgdwaError(f"keyframed mover length = {short_repr(self.length)}: must be a finite number of seconds "
                             f">= the last keyframe's time ({times[-1]:g} s)")
        object.__setattr__(self, "length", float(length))
        if not isinstance(self.loop, (bool, np.bool_)):
            raise FgdwaError(f"keyframed mover loop = {short_repr(self.loop)}: must be true or false")
        if not (isinstance(self.phase, (int, float)) and math.isfinite(self.phase)):
            raise FgdwaError(f"keyframed mover phase = {short_repr(self.phase)}: must be a finite number of seconds")

    @cached_property
    def _tangents(self) -> np.ndarray:
        return catmull_rom_tangents(self.keyframes[:, 1:])

    @property
    def period(self) -> float:
        """Time (s) to come back to where it was: the animation's length when it loops, else 0."""
        return self.length if self.loop else 0.0

    def clock(self, t: float) -> float:
        """The animation's time at the episode's time ``t`` (s)."""
        time = t + self.phase
        if self.loop:
            time = math.fmod(time, self.length)
            if time < 0:
                time += self.length
            return time
        return min(max(time, 0.0), self.length)

    def state_at(self, t: float) -> tuple:
        """(position, velocity) at the episode's time ``t`` (s)."""
        time = self.clock(t)
        times = self.keyframes[:, 0]
        points = self.keyframes[:, 1:]
        # The first keyframe at or after the time; at or before it, the segment's start.
        after = int(np.searchsorted(times, time - _SAME_TIME, side="left"))
        if after >= len(times):
            return points[-1].copy(), np.zeros(2)  # after the last keyframe: held there
        if abs(times[after] - time) <= _SAME_TIME:
            k = after
            if k == len(times) - 1:
                return points[-1].copy(), np.zeros(2)  # it holds the last keyframe from here
            return self._segment(k, 0.0)  # the keyframe itself, leaving along its tangent
        if after == 0:
            return points[0].copy(), np.zeros(2)  # before the first keyframe: waits at it
        k = after - 1
        return self._segment(k, (time - times[k]) / (times[k + 1] - times[k]))

    def _segment(self, k: int, s: float) -> tuple:
        """(position, velocity in m/s) in segment k at parameter s."""
        points = self.keyframes[:, 1:]
        point, slope = hermite(points[k], points[k + 1], self._tangents[k], self._tangents[k + 1], s)
        return point, slope / (self.keyframes[k + 1, 0] - self.keyframes[k, 0])

    def disc_at(self, t: float) -> Disc:
        position, velocity = self.state_at(t)
        return Disc(position, self.radius, velocity)

    @cached_property
    def route(self) -> np.ndarray:
        """The path it draws over one period, sampled every 0.05 s of animation (for figures)."""
        steps = max(2, int(math.ceil(self.length / 0.05)) + 1)
        return np.array([self.state_at(t - self.phase)[0] for t in np.linspace(0.0, self.length, steps)])
