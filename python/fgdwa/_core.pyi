"""
fgdwa's C++ core: robot model, grids, collision, dynamic window, critics and planner.
"""
from __future__ import annotations
import collections.abc
import numpy
import numpy.typing
import typing
__all__: list[str] = ['AStarParams', 'AStarPlanner', 'CONTACT_TIME_RANGE', 'ClearanceParams', 'ClearanceSource', 'Cluster', 'CollisionWorld', 'Controller', 'CriticConfig', 'CriticSense', 'CriticStats', 'CycleRecord', 'CycleReport', 'DensityReading', 'DetectWindowParams', 'Disc', 'DistanceField', 'DwbGridParams', 'DwbObstacleParams', 'FailureReason', 'FgdwaError', 'FieldClearance', 'FixedWeights', 'Footprint', 'FuzzyRule', 'FuzzyVariable', 'FuzzyWeights', 'GlobalPath', 'GlobalPlan', 'GlobalStatus', 'KeyNodeParams', 'LaserScanner', 'LidarParams', 'LocalPlanner', 'MamdaniEngine', 'MatchStatus', 'MembershipFunction', 'NO_BAND', 'Navigator', 'NavigatorMode', 'NavigatorParams', 'OccupancyGrid', 'OccupancyParams', 'OmplParams', 'OmplPlanner', 'OrientedBox', 'PathProjection', 'PlanResult', 'PlannerParams', 'PlannerPreset', 'Pose2', 'RecoveryTrigger', 'RejectReason', 'RobotLimits', 'RobotPreset', 'RobotState', 'Scan', 'ScanMap', 'ScanMatch', 'ScanMatchParams', 'ScanMatcher', 'ScoredRollout', 'SegmentParams', 'SimilarityParams', 'Status', 'TerrainCost', 'TerrainGrid', 'Track', 'TrackStatus', 'Tracker', 'TrackerParams', 'Twist', 'VelocityWindow', 'WeightPolicy', 'WindowParams', 'angle_difference', 'critic_names', 'dtw', 'dynamic_window', 'inflate', 'mover_fuzzy_controller', 'nearest_names', 'obstacle_density', 'paper_fuzzy_controller', 'path_blocked', 'planner_preset', 'points_field', 'preset_names', 'reference_samples', 'register_python_critic', 'robot_names', 'robot_preset', 'rollout', 'sample_window', 'segment_scan', 'unicycle_step', 'wrap_angle']
class FgdwaError(ValueError):
    pass
class Pose2:
    """
    A planar pose: x, y in metres and theta in radians.
    """
    def __init__(self, x: typing.SupportsFloat | typing.SupportsIndex = 0.0, y: typing.SupportsFloat | typing.SupportsIndex = 0.0, theta: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> None:
        ...
    def __iter__(self) -> collections.abc.Iterator:
        ...
    def __repr__(self) -> str:
        ...
    @property
    def theta(self) -> float:
        ...
    @theta.setter
    def theta(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def x(self) -> float:
        ...
    @x.setter
    def x(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def y(self) -> float:
        ...
    @y.setter
    def y(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class Twist:
    """
    A velocity command: v in m/s forward, omega in rad/s counter-clockwise.
    """
    def __init__(self, v: typing.SupportsFloat | typing.SupportsIndex = 0.0, omega: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> None:
        ...
    def __iter__(self) -> collections.abc.Iterator:
        ...
    def __repr__(self) -> str:
        ...
    @property
    def omega(self) -> float:
        ...
    @omega.setter
    def omega(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def v(self) -> float:
        ...
    @v.setter
    def v(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class RobotLimits:
    """
    Velocity and acceleration limits of a differential-drive robot.
    
    Keyword arguments, attributes (SI units, radians):
      v_min (m/s): slowest forward speed (0: forward only, down to standing)
      v_max (m/s): fastest forward speed
      omega_max (rad/s): symmetric turn-rate limit
      acc_v (m/s^2): linear acceleration
      acc_omega (rad/s^2): angular acceleration
      brake_v (m/s^2): linear braking deceleration; 0: the same as acc_v
      brake_omega (rad/s^2): angular braking deceleration; 0: the same as acc_omega
    """
    __hash__: typing.ClassVar[None] = None
    name: typing.ClassVar[str] = 'limits'
    acc_omega: typing.Any
    acc_v: typing.Any
    brake_omega: typing.Any
    brake_v: typing.Any
    omega_max: typing.Any
    v_max: typing.Any
    v_min: typing.Any
    @staticmethod
    def schema() -> list:
        """
        Every field, nested ones by their dotted names: name, type, unit, bounds, doc, choices, default.
        """
    def __copy__(self) -> RobotLimits:
        ...
    def __deepcopy__(self, arg0: typing.Any) -> RobotLimits:
        ...
    def __eq__(self, arg0: typing.Any) -> bool:
        ...
    def __getstate__(self) -> dict:
        ...
    def __init__(self, **kwargs) -> None:
        """
        Every field a keyword (defaults: the C++ struct's); a nested set takes its own class or a dict.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: dict) -> None:
        ...
    def braking_omega(self) -> float:
        ...
    def braking_v(self) -> float:
        ...
    def get(self, name: str) -> typing.Any:
        """
        One field's value, nested ones by dotted name.
        """
    def set(self, name: str, value: typing.Any) -> None:
        """
        Sets one field, nested ones by dotted name ("window.n_v").
        """
    def to_dict(self) -> dict:
        """
        The fields as a dict, nested sets as dicts.
        """
    def validate(self) -> None:
        """
        Checks every field and the rules between them; raises FgdwaError naming the first bad one.
        """
class RobotState:
    """
    Pose and velocity of the robot.
    """
    pose: Pose2
    twist: Twist
    def __init__(self, pose: typing.Any = ..., twist: typing.Any = ...) -> None:
        ...
    def __repr__(self) -> str:
        ...
class Footprint:
    """
    The robot's outline: a circle, or a convex polygon in the robot frame.
    """
    @staticmethod
    def circle(radius: typing.SupportsFloat | typing.SupportsIndex) -> Footprint:
        """
        A circle of `radius` metres about the robot origin.
        """
    @staticmethod
    def polygon(vertices: typing.Any) -> Footprint:
        """
        A convex polygon, (n, 2) vertices in metres, robot frame (x forward, y left).
        """
    def __repr__(self) -> str:
        ...
    def padded(self, margin: typing.SupportsFloat | typing.SupportsIndex) -> Footprint:
        """
        The footprint grown by `margin` metres on every side (a polygon's corners kept sharp).
        """
    def signed_distance(self, pose: typing.Any, point: typing.Any) -> float:
        ...
    @property
    def half_width(self) -> float:
        """
        Half the footprint's least width (the radius for a circle): no point inside lies farther than this from the outline, m.
        """
    @property
    def inscribed_radius(self) -> float:
        """
        Largest circle about the robot origin inside the footprint, m.
        """
    @property
    def is_circle(self) -> bool:
        ...
    @property
    def radius(self) -> float:
        """
        Circle radius or circumscribed radius, m.
        """
    @property
    def vertices(self) -> numpy.typing.NDArray[numpy.float64]:
        ...
class OccupancyGrid:
    """
    An occupancy grid: cells[row, col], row 0 at the bottom (lowest y), 1 = obstacle. Cell (row, col) covers x in origin.x + [col, col + 1) * resolution and y in origin.y + [row, row + 1) * resolution. Outside the grid is free.
    """
    def __init__(self, cells: typing.Any, resolution: typing.SupportsFloat | typing.SupportsIndex, origin: typing.Any = (0.0, 0.0)) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def cell_center(self, row: typing.SupportsInt | typing.SupportsIndex, col: typing.SupportsInt | typing.SupportsIndex) -> tuple[float, float]:
        ...
    def occupied_at(self, points: typing.Any) -> numpy.typing.NDArray[numpy.bool]:
        """
        Whether each of (n, 2) points lies in an occupied cell.
        """
    @property
    def cells(self) -> numpy.typing.NDArray[numpy.uint8]:
        """
        A copy of the cells, (rows, cols) uint8.
        """
    @property
    def cols(self) -> int:
        ...
    @property
    def extent(self) -> tuple[float, float, float, float]:
        """
        (x_min, x_max, y_min, y_max) in metres, as matplotlib's imshow takes it.
        """
    @property
    def origin(self) -> tuple[float, float]:
        ...
    @property
    def resolution(self) -> float:
        ...
    @property
    def rows(self) -> int:
        ...
    @property
    def shape(self) -> tuple[int, int]:
        ...
class TerrainGrid:
    """
    Slope grades 0-4 per cell, laid out like an OccupancyGrid (grades[row, col]); grade 4 cannot be entered.
    """
    def __init__(self, grades: typing.Any, resolution: typing.SupportsFloat | typing.SupportsIndex, origin: typing.Any = (0.0, 0.0)) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def grade_at(self, point: typing.Any) -> int:
        ...
    @property
    def extent(self) -> tuple[float, float, float, float]:
        ...
    @property
    def grades(self) -> numpy.typing.NDArray[numpy.uint8]:
        ...
    @property
    def origin(self) -> tuple[float, float]:
        ...
    @property
    def resolution(self) -> float:
        ...
    @property
    def shape(self) -> tuple[int, int]:
        ...
class DistanceField:
    """
    Exact Euclidean distance transform of a grid. `cells` holds centre-to-centre distances in metres (scipy's distance_transform_edt(cells == 0) * resolution); `distance(points)` is the exact distance to the nearest obstacle cell's edge. Given `previous`, the field of an earlier grid with the same layout, only the cells near changed obstacles are recomputed (same result, faster).
    """
    def __init__(self, grid: OccupancyGrid, previous: DistanceField = None, *, edge_margin: typing.Any = None) -> None:
        """
        edge_margin: free space in metres the field adds around the grid (default 3), so that points past the edge cost no more than inside; held to 64 cells and, on large grids, a sixteenth more cells.
        """
    def __repr__(self) -> str:
        ...
    def distance(self, points: typing.Any) -> numpy.typing.NDArray[numpy.float64]:
        """
        Distance in metres from each of (n, 2) points to the nearest obstacle edge.
        """
    @property
    def cells(self) -> numpy.typing.NDArray[numpy.float64]:
        ...
    @property
    def edge_margin(self) -> float:
        """
        the free margin kept around the grid, in metres: edge_margin rounded up to whole cells, less where the budget holds it
        """
    @property
    def grid(self) -> OccupancyGrid:
        ...
class Disc:
    """
    A disc obstacle moving at constant velocity (after an optional constant acceleration); radius 0 is a point.
    """
    def __init__(self, center: typing.Any, radius: typing.SupportsFloat | typing.SupportsIndex = 0.0, velocity: typing.Any = (0.0, 0.0), growth: typing.SupportsFloat | typing.SupportsIndex = 0.0, acceleration: typing.Any = (0.0, 0.0), accel_time: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> None:
        """
        growth (m/s): radius added per second ahead, for a predicted obstacle; acceleration (m/s^2) lasts the first accel_time (s), then the velocity reached holds (a mover predicted to turn, slow or reverse).
        """
    def __repr__(self) -> str:
        ...
    def center_at(self, t: typing.SupportsFloat | typing.SupportsIndex) -> tuple[float, float]:
        ...
    def radius_at(self, t: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        The radius t seconds ahead (for a t in the past, never below 0).
        """
    def time_to_reach(self, point: typing.Any, reach: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> float:
        """
        s, the first time ahead at which the disc grown by reach (m) covers point; inf if never.
        """
    @property
    def accel_time(self) -> float:
        ...
    @property
    def acceleration(self) -> tuple[float, float]:
        ...
    @property
    def center(self) -> tuple[float, float]:
        ...
    @property
    def growth(self) -> float:
        ...
    @property
    def radius(self) -> float:
        ...
    @property
    def velocity(self) -> tuple[float, float]:
        ...
class ClearanceSource:
    """
    Where a rollout's clearance comes from (FieldClearance or CollisionWorld).
    """
    def clearance(self, footprint: Footprint, poses: typing.Any, t: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> typing.Any:
        """
        Clearance in metres of the footprint at each of (n, 3) poses (or one pose), moving obstacles predicted t seconds ahead; <= 0 means contact.
        """
class FieldClearance(ClearanceSource):
    """
    The fast clearance: a distance field of the static map plus analytic discs.
    """
    def __init__(self, field: DistanceField = None, discs: collections.abc.Sequence[Disc] = []) -> None:
        ...
    def __repr__(self) -> str:
        ...
    @property
    def discs(self) -> list[Disc]:
        ...
    @discs.setter
    def discs(self, arg1: collections.abc.Sequence[Disc]) -> None:
        ...
    @property
    def field(self) -> DistanceField:
        ...
    @property
    def sensed(self) -> DistanceField:
        """
        Obstacles seen by the lidar but missing from the map, as a DistanceField (see points_field), or None.
        """
    @sensed.setter
    def sensed(self, arg1: DistanceField) -> None:
        ...
class CollisionWorld(ClearanceSource):
    """
    The exact world on FCL: the grid's occupied cells merged into boxes, plus moving discs. The simulator's ground truth.
    """
    def __init__(self, grid: OccupancyGrid = None, discs: collections.abc.Sequence[Disc] = []) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def in_collision(self, footprint: Footprint, pose: typing.Any, t: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> bool:
        ...
    @property
    def boxes(self) -> numpy.typing.NDArray[numpy.int32]:
        """
        (k, 4) merged boxes as (row, col, rows, cols) of cells.
        """
    @property
    def discs(self) -> list[Disc]:
        ...
    @discs.setter
    def discs(self, arg1: collections.abc.Sequence[Disc]) -> None:
        ...
class VelocityWindow:
    """
    Vm ∩ Vd: the commands reachable in one control period.
    """
    def __repr__(self) -> str:
        ...
    def contains(self, twist: typing.Any) -> bool:
        ...
    @property
    def omega_hi(self) -> float:
        ...
    @property
    def omega_lo(self) -> float:
        ...
    @property
    def v_hi(self) -> float:
        ...
    @property
    def v_lo(self) -> float:
        ...
class CriticSense:
    """
    Whether a critic's larger raw scores are better (reward) or worse (cost).
    
    Members:
    
      Reward
    
      Cost
    """
    Cost: typing.ClassVar[CriticSense]
    Reward: typing.ClassVar[CriticSense]
    __members__: typing.ClassVar[dict[str, CriticSense]]
    @typing.overload
    def __eq__(self, other: CriticSense) -> bool:
        ...
    @typing.overload
    def __eq__(self, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self) -> int:
        ...
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __int__(self) -> int:
        ...
    @typing.overload
    def __ne__(self, other: CriticSense) -> bool:
        ...
    @typing.overload
    def __ne__(self, other: typing.Any) -> bool:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, state: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __str__(self) -> str:
        ...
    @property
    def name(self) -> str:
        ...
    @property
    def value(self) -> int:
        ...
class ClearanceParams:
    """
    The parameters of critic 'clearance'.
    
    Keyword arguments, attributes (SI units, radians):
      cap (m): clearance beyond which a rollout scores no higher (the detect window's radius)
    """
    __hash__: typing.ClassVar[None] = None
    name: typing.ClassVar[str] = 'clearance'
    cap: typing.Any
    @staticmethod
    def schema() -> list:
        """
        Every field, nested ones by their dotted names: name, type, unit, bounds, doc, choices, default.
        """
    def __copy__(self) -> ClearanceParams:
        ...
    def __deepcopy__(self, arg0: typing.Any) -> ClearanceParams:
        ...
    def __eq__(self, arg0: typing.Any) -> bool:
        ...
    def __getstate__(self) -> dict:
        ...
    def __init__(self, **kwargs) -> None:
        """
        Every field a keyword (defaults: the C++ struct's); a nested set takes its own class or a dict.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: dict) -> None:
        ...
    def get(self, name: str) -> typing.Any:
        """
        One field's value, nested ones by dotted name.
        """
    def set(self, name: str, value: typing.Any) -> None:
        """
        Sets one field, nested ones by dotted name ("window.n_v").
        """
    def to_dict(self) -> dict:
        """
        The fields as a dict, nested sets as dicts.
        """
    def validate(self) -> None:
        """
        Checks every field and the rules between them; raises FgdwaError naming the first bad one.
        """
class SimilarityParams:
    """
    The parameters of critic 'similarity'.
    
    Keyword arguments, attributes (SI units, radians):
      sampling: reference samples along the path's arc (polyline) or straight along its current segment (segment, Eq. 9 as written)
      reference_speed: the samples' spacing is v_ref dt with v_ref the speed limit (limit) or the current speed (current, Eq. 9 as written)
      v_ref_min (m/s): least v_ref: keeps the samples from collapsing at standstill
      band: Sakoe-Chiba band of the DTW in samples (-1: the full DTW)
      precision: arithmetic of the full DTW: single (vectorised float) or double (a banded one is double)
    """
    __hash__: typing.ClassVar[None] = None
    name: typing.ClassVar[str] = 'similarity'
    band: typing.Any
    precision: typing.Any
    reference_speed: typing.Any
    sampling: typing.Any
    v_ref_min: typing.Any
    @staticmethod
    def schema() -> list:
        """
        Every field, nested ones by their dotted names: name, type, unit, bounds, doc, choices, default.
        """
    def __copy__(self) -> SimilarityParams:
        ...
    def __deepcopy__(self, arg0: typing.Any) -> SimilarityParams:
        ...
    def __eq__(self, arg0: typing.Any) -> bool:
        ...
    def __getstate__(self) -> dict:
        ...
    def __init__(self, **kwargs) -> None:
        """
        Every field a keyword (defaults: the C++ struct's); a nested set takes its own class or a dict.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: dict) -> None:
        ...
    def get(self, name: str) -> typing.Any:
        """
        One field's value, nested ones by dotted name.
        """
    def set(self, name: str, value: typing.Any) -> None:
        """
        Sets one field, nested ones by dotted name ("window.n_v").
        """
    def to_dict(self) -> dict:
        """
        The fields as a dict, nested sets as dicts.
        """
    def validate(self) -> None:
        """
        Checks every field and the rules between them; raises FgdwaError naming the first bad one.
        """
class DwbObstacleParams:
    """
    The parameters of critic 'dwb_obstacle'.
    
    Keyword arguments, attributes (SI units, radians):
      cost_scaling_factor (1/m): decay of the cost with clearance (Nav2 local costmap's inflation layer)
      inflation_margin (m): footprint clearance from which the cost is 0
      aggregation: the last pose's cost (last, DWB's default) or every pose's summed (sum)
    """
    __hash__: typing.ClassVar[None] = None
    name: typing.ClassVar[str] = 'dwb_obstacle'
    aggregation: typing.Any
    cost_scaling_factor: typing.Any
    inflation_margin: typing.Any
    @staticmethod
    def schema() -> list:
        """
        Every field, nested ones by their dotted names: name, type, unit, bounds, doc, choices, default.
        """
    def __copy__(self) -> DwbObstacleParams:
        ...
    def __deepcopy__(self, arg0: typing.Any) -> DwbObstacleParams:
        ...
    def __eq__(self, arg0: typing.Any) -> bool:
        ...
    def __getstate__(self) -> dict:
        ...
    def __init__(self, **kwargs) -> None:
        """
        Every field a keyword (defaults: the C++ struct's); a nested set takes its own class or a dict.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: dict) -> None:
        ...
    def get(self, name: str) -> typing.Any:
        """
        One field's value, nested ones by dotted name.
        """
    def set(self, name: str, value: typing.Any) -> None:
        """
        Sets one field, nested ones by dotted name ("window.n_v").
        """
    def to_dict(self) -> dict:
        """
        The fields as a dict, nested sets as dicts.
        """
    def validate(self) -> None:
        """
        Checks every field and the rules between them; raises FgdwaError naming the first bad one.
        """
class DwbGridParams:
    """
    The parameters of the map-grid critics dwb_path_dist, dwb_goal_dist, dwb_path_align and dwb_goal_align (forward_point_distance: the align ones only).
    
    Keyword arguments, attributes (SI units, radians):
      resolution (m): cell size, the unit of the scores (Nav2's local costmap)
      local_extent (m): half the side of the square window the local path lives in (Nav2's 3 m x 3 m rolling costmap)
      forward_point_distance (m): ahead of the last pose, for the align critics (DWB's default)
    """
    __hash__: typing.ClassVar[None] = None
    name: typing.ClassVar[str] = 'dwb_grid'
    forward_point_distance: typing.Any
    local_extent: typing.Any
    resolution: typing.Any
    @staticmethod
    def schema() -> list:
        """
        Every field, nested ones by their dotted names: name, type, unit, bounds, doc, choices, default.
        """
    def __copy__(self) -> DwbGridParams:
        ...
    def __deepcopy__(self, arg0: typing.Any) -> DwbGridParams:
        ...
    def __eq__(self, arg0: typing.Any) -> bool:
        ...
    def __getstate__(self) -> dict:
        ...
    def __init__(self, **kwargs) -> None:
        """
        Every field a keyword (defaults: the C++ struct's); a nested set takes its own class or a dict.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: dict) -> None:
        ...
    def get(self, name: str) -> typing.Any:
        """
        One field's value, nested ones by dotted name.
        """
    def set(self, name: str, value: typing.Any) -> None:
        """
        Sets one field, nested ones by dotted name ("window.n_v").
        """
    def to_dict(self) -> dict:
        """
        The fields as a dict, nested sets as dicts.
        """
    def validate(self) -> None:
        """
        Checks every field and the rules between them; raises FgdwaError naming the first bad one.
        """
class CriticConfig:
    """
    A critic by registered name, its weight, and its own parameters (e.g. CriticConfig('clearance', 0.15, {'cap': 2.0})).
    """
    name: str
    def __init__(self, name: str, weight: typing.SupportsFloat | typing.SupportsIndex = 1.0, params: dict = {}) -> None:
        """
        params: numbers (e.g. {'cap': 2.0}) and words (e.g. {'sampling': 'segment'}).
        """
    def __repr__(self) -> str:
        ...
    @property
    def params(self) -> dict:
        ...
    @property
    def weight(self) -> float:
        ...
    @weight.setter
    def weight(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
class PathProjection:
    """
    The nearest point of a path to a query point.
    """
    def __repr__(self) -> str:
        ...
    @property
    def arc_length(self) -> float:
        ...
    @property
    def distance(self) -> float:
        ...
    @property
    def point(self) -> tuple[float, float]:
        ...
    @property
    def segment(self) -> int:
        ...
class GlobalPath:
    """
    A global path: a polyline of (n, 2) points in metres, with projection, deviation, arc-length walking and key nodes.
    """
    def __init__(self, points: typing.Any) -> None:
        ...
    def __len__(self) -> int:
        ...
    def __repr__(self) -> str:
        ...
    def deviation(self, point: typing.Any) -> float:
        """
        Distance in metres from the point to the path (D).
        """
    def key_nodes(self, min_turn: typing.SupportsFloat | typing.SupportsIndex = 0.17453292519943295) -> list[int]:
        """
        Indices of the vertices where the path turns by more than min_turn (rad), then the last vertex.
        """
    def point_at(self, s: typing.SupportsFloat | typing.SupportsIndex) -> tuple[float, float]:
        """
        The point at arc length s metres (clamped to the path).
        """
    def project(self, point: typing.Any) -> PathProjection:
        ...
    def segment_direction(self, segment: typing.SupportsInt | typing.SupportsIndex) -> float:
        ...
    @property
    def length(self) -> float:
        ...
    @property
    def points(self) -> numpy.typing.NDArray[numpy.float64]:
        ...
    @property
    def segment_count(self) -> int:
        ...
class LidarParams:
    """
    A planar lidar.
    
    Keyword arguments, attributes (SI units, radians):
      fov (rad): field of view centred on the heading
      beams: beams, both ends of the field of view included
      max_range (m): a beam with no hit within it reads +inf
      noise_std (m): Gaussian noise added to each hit's range
      dropout: probability that a beam returns nothing and reads +inf
    """
    __hash__: typing.ClassVar[None] = None
    name: typing.ClassVar[str] = 'lidar'
    beams: typing.Any
    dropout: typing.Any
    fov: typing.Any
    max_range: typing.Any
    noise_std: typing.Any
    @staticmethod
    def schema() -> list:
        """
        Every field, nested ones by their dotted names: name, type, unit, bounds, doc, choices, default.
        """
    def __copy__(self) -> LidarParams:
        ...
    def __deepcopy__(self, arg0: typing.Any) -> LidarParams:
        ...
    def __eq__(self, arg0: typing.Any) -> bool:
        ...
    def __getstate__(self) -> dict:
        ...
    def __init__(self, **kwargs) -> None:
        """
        Every field a keyword (defaults: the C++ struct's); a nested set takes its own class or a dict.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: dict) -> None:
        ...
    def get(self, name: str) -> typing.Any:
        """
        One field's value, nested ones by dotted name.
        """
    def set(self, name: str, value: typing.Any) -> None:
        """
        Sets one field, nested ones by dotted name ("window.n_v").
        """
    def to_dict(self) -> dict:
        """
        The fields as a dict, nested sets as dicts.
        """
    def validate(self) -> None:
        """
        Checks every field and the rules between them; raises FgdwaError naming the first bad one.
        """
    @property
    def angles(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Beam angles relative to the heading, rad.
        """
class Scan:
    """
    One lidar scan: ranges (m, +inf for no hit) of beams from angle_min by angle_increment.
    """
    def __init__(self, ranges: typing.Any, angle_min: typing.SupportsFloat | typing.SupportsIndex, angle_increment: typing.SupportsFloat | typing.SupportsIndex, max_range: typing.SupportsFloat | typing.SupportsIndex, pose: typing.Any = (0.0, 0.0, 0.0)) -> None:
        """
        A scan measured elsewhere: ranges (m, +inf for no hit) of beams from angle_min (rad, relative to the sensor's heading) by angle_increment (rad), max_range (m), taken at pose (x, y, theta) of the sensor.
        """
    def __repr__(self) -> str:
        ...
    @property
    def angle_increment(self) -> float:
        ...
    @property
    def angle_min(self) -> float:
        ...
    @property
    def angles(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Beam angles relative to the heading, rad.
        """
    @property
    def hit_points(self) -> numpy.typing.NDArray[numpy.float64]:
        ...
    @property
    def max_range(self) -> float:
        ...
    @property
    def pose(self) -> Pose2:
        """
        Where the scan was taken, as the robot believes: hit_points and the map place the ranges from it.
        """
    @pose.setter
    def pose(self, arg1: typing.Any) -> None:
        ...
    @property
    def ranges(self) -> numpy.typing.NDArray[numpy.float64]:
        ...
class LaserScanner:
    """
    Ray casting against the true world's distance field and moving discs, with seeded noise.
    """
    def __init__(self, params: LidarParams, world: DistanceField) -> None:
        ...
    def scan(self, pose: typing.Any, discs: collections.abc.Sequence[Disc] = [], t: typing.SupportsFloat | typing.SupportsIndex = 0.0, seed: typing.SupportsInt | typing.SupportsIndex = 0) -> Scan:
        """
        One scan at pose; discs placed t seconds ahead; noise and dropped beams drawn from a generator seeded with seed.
        """
    @property
    def params(self) -> LidarParams:
        ...
class DetectWindowParams:
    """
    The detect window ahead of the robot, over which the density I is measured.
    
    Keyword arguments, attributes (SI units, radians):
      half_angle (rad): the window spans +-half_angle about the heading
      radius (m): the window's radius R
      base: the base c of the density's exponential weight (Eq. 13)
    """
    __hash__: typing.ClassVar[None] = None
    name: typing.ClassVar[str] = 'detect_window'
    base: typing.Any
    half_angle: typing.Any
    radius: typing.Any
    @staticmethod
    def schema() -> list:
        """
        Every field, nested ones by their dotted names: name, type, unit, bounds, doc, choices, default.
        """
    def __copy__(self) -> DetectWindowParams:
        ...
    def __deepcopy__(self, arg0: typing.Any) -> DetectWindowParams:
        ...
    def __eq__(self, arg0: typing.Any) -> bool:
        ...
    def __getstate__(self) -> dict:
        ...
    def __init__(self, **kwargs) -> None:
        """
        Every field a keyword (defaults: the C++ struct's); a nested set takes its own class or a dict.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: dict) -> None:
        ...
    def get(self, name: str) -> typing.Any:
        """
        One field's value, nested ones by dotted name.
        """
    def set(self, name: str, value: typing.Any) -> None:
        """
        Sets one field, nested ones by dotted name ("window.n_v").
        """
    def to_dict(self) -> dict:
        """
        The fields as a dict, nested sets as dicts.
        """
    def validate(self) -> None:
        """
        Checks every field and the rules between them; raises FgdwaError naming the first bad one.
        """
class DensityReading:
    """
    Obstacle density I of the detect window and its parts.
    """
    def __repr__(self) -> str:
        ...
    @property
    def area_ratio(self) -> float:
        ...
    @property
    def beams(self) -> int:
        ...
    @property
    def density(self) -> float:
        ...
    @property
    def max_gap(self) -> float:
        ...
class GlobalStatus:
    """
    Outcome of a global planning query.
    
    Members:
    
      Found
    
      NoPath
    
      Timeout
    """
    Found: typing.ClassVar[GlobalStatus]
    NoPath: typing.ClassVar[GlobalStatus]
    Timeout: typing.ClassVar[GlobalStatus]
    __members__: typing.ClassVar[dict[str, GlobalStatus]]
    @typing.overload
    def __eq__(self, other: GlobalStatus) -> bool:
        ...
    @typing.overload
    def __eq__(self, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self) -> int:
        ...
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __int__(self) -> int:
        ...
    @typing.overload
    def __ne__(self, other: GlobalStatus) -> bool:
        ...
    @typing.overload
    def __ne__(self, other: typing.Any) -> bool:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, state: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __str__(self) -> str:
        ...
    @property
    def name(self) -> str:
        ...
    @property
    def value(self) -> int:
        ...
class GlobalPlan:
    """
    A global planner's result: status, (n, 2) path, cost, planning time (s).
    """
    def __repr__(self) -> str:
        ...
    @property
    def cost(self) -> float:
        ...
    @property
    def found(self) -> bool:
        ...
    @property
    def path(self) -> numpy.typing.NDArray[numpy.float64]:
        ...
    @property
    def planning_time(self) -> float:
        ...
    @property
    def status(self) -> GlobalStatus:
        ...
class TerrainCost:
    """
    Terrain risk in a global planner's cost: step length x (1 + w_risk x risk[grade]).
    
    Keyword arguments, attributes (SI units, radians):
      w_risk: weight of the terrain risk in the cost
      risk: risk of grades 0-3 (grade 4 is impassable)
    """
    __hash__: typing.ClassVar[None] = None
    name: typing.ClassVar[str] = 'terrain_cost'
    risk: typing.Any
    w_risk: typing.Any
    @staticmethod
    def schema() -> list:
        """
        Every field, nested ones by their dotted names: name, type, unit, bounds, doc, choices, default.
        """
    def __copy__(self) -> TerrainCost:
        ...
    def __deepcopy__(self, arg0: typing.Any) -> TerrainCost:
        ...
    def __eq__(self, arg0: typing.Any) -> bool:
        ...
    def __getstate__(self) -> dict:
        ...
    def __init__(self, **kwargs) -> None:
        """
        Every field a keyword (defaults: the C++ struct's); a nested set takes its own class or a dict.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: dict) -> None:
        ...
    def get(self, name: str) -> typing.Any:
        """
        One field's value, nested ones by dotted name.
        """
    def set(self, name: str, value: typing.Any) -> None:
        """
        Sets one field, nested ones by dotted name ("window.n_v").
        """
    def to_dict(self) -> dict:
        """
        The fields as a dict, nested sets as dicts.
        """
    def validate(self) -> None:
        """
        Checks every field and the rules between them; raises FgdwaError naming the first bad one.
        """
class AStarParams:
    """
    Grid A*: inflation, simplification, terrain and unknown-cell costs.
    
    Keyword arguments, attributes (SI units, radians):
      inflation_radius (m): cells nearer an obstacle than this are closed (usually the footprint's radius)
      simplify: shortcut the cell path by line of sight
      terrain_cost: step cost through terrain: length x (1 + w_risk x risk[grade])
      unknown_cost: extra cost per metre through cells the map has not observed (set_unknown; 0: unknown is free)
    """
    __hash__: typing.ClassVar[None] = None
    name: typing.ClassVar[str] = 'astar'
    inflation_radius: typing.Any
    simplify: typing.Any
    terrain_cost: typing.Any
    unknown_cost: typing.Any
    @staticmethod
    def schema() -> list:
        """
        Every field, nested ones by their dotted names: name, type, unit, bounds, doc, choices, default.
        """
    def __copy__(self) -> AStarParams:
        ...
    def __deepcopy__(self, arg0: typing.Any) -> AStarParams:
        ...
    def __eq__(self, arg0: typing.Any) -> bool:
        ...
    def __getstate__(self) -> dict:
        ...
    def __init__(self, **kwargs) -> None:
        """
        Every field a keyword (defaults: the C++ struct's); a nested set takes its own class or a dict.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: dict) -> None:
        ...
    def get(self, name: str) -> typing.Any:
        """
        One field's value, nested ones by dotted name.
        """
    def set(self, name: str, value: typing.Any) -> None:
        """
        Sets one field, nested ones by dotted name ("window.n_v").
        """
    def to_dict(self) -> dict:
        """
        The fields as a dict, nested sets as dicts.
        """
    def validate(self) -> None:
        """
        Checks every field and the rules between them; raises FgdwaError naming the first bad one.
        """
class OmplParams:
    """
    OMPL's planners: which, budget, seed, cost weights, output spacing.
    
    Keyword arguments, attributes (SI units, radians):
      planner: RRTstar, InformedRRTstar, PRMstar, BITstar or RRTConnect
      time_limit (s): planning time budget
      range (m): longest tree edge of the planners that have one (0: OMPL's default)
      max_iterations: stop after this many planner iterations too (0: time only)
      seed: with max_iterations binding, the same seed gives the same path (a time budget alone lets the machine's speed decide)
      inflation_radius (m): for a circle footprint: cells nearer an obstacle than this are closed
      w_length: weight of path length in the cost
      w_clearance: weight of the clearance cost
      clearance_reference (m): clearance beyond which a state costs nothing
      terrain_cost: terrain risk in the cost (its weight: terrain_cost.w_risk)
      simplify: OMPL's path simplifier
      interpolation (m): spacing of the interpolated output path
      verbose: OMPL's console output
    """
    __hash__: typing.ClassVar[None] = None
    name: typing.ClassVar[str] = 'ompl'
    clearance_reference: typing.Any
    inflation_radius: typing.Any
    interpolation: typing.Any
    max_iterations: typing.Any
    planner: typing.Any
    range: typing.Any
    seed: typing.Any
    simplify: typing.Any
    terrain_cost: typing.Any
    time_limit: typing.Any
    verbose: typing.Any
    w_clearance: typing.Any
    w_length: typing.Any
    @staticmethod
    def schema() -> list:
        """
        Every field, nested ones by their dotted names: name, type, unit, bounds, doc, choices, default.
        """
    def __copy__(self) -> OmplParams:
        ...
    def __deepcopy__(self, arg0: typing.Any) -> OmplParams:
        ...
    def __eq__(self, arg0: typing.Any) -> bool:
        ...
    def __getstate__(self) -> dict:
        ...
    def __init__(self, **kwargs) -> None:
        """
        Every field a keyword (defaults: the C++ struct's); a nested set takes its own class or a dict.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: dict) -> None:
        ...
    def get(self, name: str) -> typing.Any:
        """
        One field's value, nested ones by dotted name.
        """
    def set(self, name: str, value: typing.Any) -> None:
        """
        Sets one field, nested ones by dotted name ("window.n_v").
        """
    def to_dict(self) -> dict:
        """
        The fields as a dict, nested sets as dicts.
        """
    def validate(self) -> None:
        """
        Checks every field and the rules between them; raises FgdwaError naming the first bad one.
        """
class AStarPlanner:
    """
    8-connected grid A* (octile heuristic, no corner cutting, inflated obstacles, optional terrain cost = step length x (1 + w_risk x risk[grade])).
    """
    def __init__(self, grid: OccupancyGrid, params: AStarParams | None = None, terrain: TerrainGrid = None, **kwargs) -> None:
        """
        params: AStarParams, or its fields as keywords (AStarPlanner(grid, inflation_radius=0.3, terrain_cost={'w_risk': 2.0})); terrain: a TerrainGrid on the grid's layout.
        """
    def __repr__(self) -> str:
        ...
    def plan(self, start: typing.Any, goal: typing.Any) -> GlobalPlan:
        ...
    def set_unknown(self, unknown: typing.Any) -> None:
        """
        Which cells are unknown ((rows, cols), nonzero = unknown; None for none).
        """
    @property
    def blocked(self) -> numpy.typing.NDArray[numpy.uint8]:
        ...
class OmplPlanner:
    """
    OMPL's sampling-based planners over the same map, with a weighted cost of path length, clearance and terrain risk; seeded and time-bounded.
    """
    @staticmethod
    def planner_names() -> list[str]:
        ...
    def __init__(self, grid: OccupancyGrid, footprint: Footprint, params: OmplParams | None = None, terrain: TerrainGrid = None, **kwargs) -> None:
        """
        params: OmplParams, or its fields as keywords (OmplPlanner(grid, footprint, planner='PRMstar', time_limit=0.5)); without an inflation_radius, the footprint's radius; terrain: a TerrainGrid on the grid's layout.
        """
    def plan(self, start: typing.Any, goal: typing.Any) -> GlobalPlan:
        ...
class Status:
    """
    Outcome of one control cycle.
    
    Members:
    
      Ok
    
      NoAdmissibleVelocity
    
      GoalReached
    
      Evading
    """
    Evading: typing.ClassVar[Status]
    GoalReached: typing.ClassVar[Status]
    NoAdmissibleVelocity: typing.ClassVar[Status]
    Ok: typing.ClassVar[Status]
    __members__: typing.ClassVar[dict[str, Status]]
    @typing.overload
    def __eq__(self, other: Status) -> bool:
        ...
    @typing.overload
    def __eq__(self, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self) -> int:
        ...
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __int__(self) -> int:
        ...
    @typing.overload
    def __ne__(self, other: Status) -> bool:
        ...
    @typing.overload
    def __ne__(self, other: typing.Any) -> bool:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, state: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __str__(self) -> str:
        ...
    @property
    def name(self) -> str:
        ...
    @property
    def value(self) -> int:
        ...
class RejectReason:
    """
    Why a sampled command was rejected.
    
    Members:
    
      None_
    
      Collision
    
      Terrain
    
      Critic
    
      Moving
    """
    Collision: typing.ClassVar[RejectReason]
    Critic: typing.ClassVar[RejectReason]
    Moving: typing.ClassVar[RejectReason]
    None_: typing.ClassVar[RejectReason]
    Terrain: typing.ClassVar[RejectReason]
    __members__: typing.ClassVar[dict[str, RejectReason]]
    @typing.overload
    def __eq__(self, other: RejectReason) -> bool:
        ...
    @typing.overload
    def __eq__(self, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self) -> int:
        ...
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __int__(self) -> int:
        ...
    @typing.overload
    def __ne__(self, other: RejectReason) -> bool:
        ...
    @typing.overload
    def __ne__(self, other: typing.Any) -> bool:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, state: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __str__(self) -> str:
        ...
    @property
    def name(self) -> str:
        ...
    @property
    def value(self) -> int:
        ...
class WindowParams:
    """
    Samples of the dynamic window.
    
    Keyword arguments, attributes (SI units, radians):
      n_v: samples of the linear velocity, both window ends included
      n_omega: samples of the angular velocity, both window ends included
    """
    __hash__: typing.ClassVar[None] = None
    name: typing.ClassVar[str] = 'window'
    n_omega: typing.Any
    n_v: typing.Any
    @staticmethod
    def schema() -> list:
        """
        Every field, nested ones by their dotted names: name, type, unit, bounds, doc, choices, default.
        """
    def __copy__(self) -> WindowParams:
        ...
    def __deepcopy__(self, arg0: typing.Any) -> WindowParams:
        ...
    def __eq__(self, arg0: typing.Any) -> bool:
        ...
    def __getstate__(self) -> dict:
        ...
    def __init__(self, **kwargs) -> None:
        """
        Every field a keyword (defaults: the C++ struct's); a nested set takes its own class or a dict.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: dict) -> None:
        ...
    def get(self, name: str) -> typing.Any:
        """
        One field's value, nested ones by dotted name.
        """
    def set(self, name: str, value: typing.Any) -> None:
        """
        Sets one field, nested ones by dotted name ("window.n_v").
        """
    def to_dict(self) -> dict:
        """
        The fields as a dict, nested sets as dicts.
        """
    def validate(self) -> None:
        """
        Checks every field and the rules between them; raises FgdwaError naming the first bad one.
        """
class KeyNodeParams:
    """
    Key nodes of the global path: the temporary targets of GDWA.
    
    Keyword arguments, attributes (SI units, radians):
      min_turn (rad): turn that makes a path vertex a key node
      reach_radius (m): a key node closer than this is reached
      require_sight: a key node within reach_radius counts as reached only once the next one is in sight
    """
    __hash__: typing.ClassVar[None] = None
    name: typing.ClassVar[str] = 'key_nodes'
    min_turn: typing.Any
    reach_radius: typing.Any
    require_sight: typing.Any
    @staticmethod
    def schema() -> list:
        """
        Every field, nested ones by their dotted names: name, type, unit, bounds, doc, choices, default.
        """
    def __copy__(self) -> KeyNodeParams:
        ...
    def __deepcopy__(self, arg0: typing.Any) -> KeyNodeParams:
        ...
    def __eq__(self, arg0: typing.Any) -> bool:
        ...
    def __getstate__(self) -> dict:
        ...
    def __init__(self, **kwargs) -> None:
        """
        Every field a keyword (defaults: the C++ struct's); a nested set takes its own class or a dict.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: dict) -> None:
        ...
    def get(self, name: str) -> typing.Any:
        """
        One field's value, nested ones by dotted name.
        """
    def set(self, name: str, value: typing.Any) -> None:
        """
        Sets one field, nested ones by dotted name ("window.n_v").
        """
    def to_dict(self) -> dict:
        """
        The fields as a dict, nested sets as dicts.
        """
    def validate(self) -> None:
        """
        Checks every field and the rules between them; raises FgdwaError naming the first bad one.
        """
class PlannerParams:
    """
    Parameters of the local planner.
    
    Keyword arguments, attributes (SI units, radians):
      dt (s): control period and rollout step
      sim_time (s): rollout horizon (the paper's perDT)
      window: samples of the dynamic window
      normalization: how each critic's terms are scaled before weighting: sum (classic DWA), minmax, or none (raw, as Nav2's DWB adds them)
      braking: admissibility's braking rule (Eq. 3): discrete (one period of latency, stepped deceleration) or continuous (the paper's literal form)
      wheels: how a rollout's first steps reach the sampled velocity: ramp (from the measured twist at the acceleration limits, as a robot's wheels do) or instant (at once, as an ideal simulated body does)
      response_time (s): with wheels ramp: time constant of the first-order lag with which the wheels follow a command on top of the ramp, as the robot's identified response (0: the ramp alone)
      goal_tolerance (m): GoalReached within this distance of the goal
      safety_margin (m): clearance below which a rollout counts as in contact (never more than the robot's own)
      moving_horizon (s): a rollout predicted to meet a moving obstacle this soon is rejected, standing still included (0: only the braking rule counts movers)
      moving_reach (m): the rejection's horizon is at most the time the fastest mover (speed plus growth) takes to travel this far (0: moving_horizon alone)
      mover_caution_radius (m): while a moving obstacle is this near the footprint, the velocity critic's weight is scaled by mover_speed_weight
      mover_speed_weight: the velocity critic's weight factor beside a mover (1: no change)
      prefer_clear: choose among the admissible samples whose rollouts stay off the fixed world (to where they first come within the contact margin) when there are any, the others (admitted by the braking rule) only when there are none; an evasion among the samples whose rollouts keep the margin to their end when there are any (false: among all, as the paper)
      heading_target: what the heading critic aims at: goal (DWA) or key_nodes (GDWA: the first key node of the global path not yet reached)
      key_nodes: key nodes of the global path, for heading_target key_nodes
      critics: the critics scored, each {name, weight, params} (default heading 0.5, clearance 0.15, velocity 1.0)
    """
    __hash__: typing.ClassVar[None] = None
    name: typing.ClassVar[str] = 'planner'
    braking: typing.Any
    critics: typing.Any
    dt: typing.Any
    goal_tolerance: typing.Any
    heading_target: typing.Any
    key_nodes: typing.Any
    mover_caution_radius: typing.Any
    mover_speed_weight: typing.Any
    moving_horizon: typing.Any
    moving_reach: typing.Any
    normalization: typing.Any
    prefer_clear: typing.Any
    response_time: typing.Any
    safety_margin: typing.Any
    sim_time: typing.Any
    wheels: typing.Any
    window: typing.Any
    @staticmethod
    def schema() -> list:
        """
        Every field, nested ones by their dotted names: name, type, unit, bounds, doc, choices, default.
        """
    def __copy__(self) -> PlannerParams:
        ...
    def __deepcopy__(self, arg0: typing.Any) -> PlannerParams:
        ...
    def __eq__(self, arg0: typing.Any) -> bool:
        ...
    def __getstate__(self) -> dict:
        ...
    def __init__(self, **kwargs) -> None:
        """
        Every field a keyword (defaults: the C++ struct's); a nested set takes its own class or a dict.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: dict) -> None:
        ...
    def get(self, name: str) -> typing.Any:
        """
        One field's value, nested ones by dotted name.
        """
    def set(self, name: str, value: typing.Any) -> None:
        """
        Sets one field, nested ones by dotted name ("window.n_v").
        """
    def to_dict(self) -> dict:
        """
        The fields as a dict, nested sets as dicts.
        """
    def validate(self) -> None:
        """
        Checks every field and the rules between them; raises FgdwaError naming the first bad one.
        """
    @property
    def n_steps(self) -> int:
        """
        Poses per rollout: sim_time / dt, rounded.
        """
class PlanResult:
    """
    One control cycle's command, status and per-sample diagnostics.
    """
    def __repr__(self) -> str:
        ...
    @property
    def admissible(self) -> numpy.typing.NDArray[numpy.bool]:
        ...
    @property
    def best_index(self) -> int:
        ...
    @property
    def command(self) -> Twist:
        ...
    @property
    def critic_names(self) -> list[str]:
        ...
    @property
    def free_distance(self) -> numpy.typing.NDArray[numpy.float64]:
        ...
    @property
    def key_node(self) -> int:
        """
        Index of the target among the key nodes; -1 when aiming at the goal.
        """
    @property
    def min_clearance(self) -> numpy.typing.NDArray[numpy.float64]:
        ...
    @property
    def moving_contact(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        s, per sample: first predicted contact with a moving obstacle within moving_horizon (inf: none).
        """
    @property
    def normalized(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        (n, critics) normalised terms; 0 for rejected samples.
        """
    @property
    def raw(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, n]"]:
        """
        (n, critics) raw terms; 0 for rejected samples.
        """
    @property
    def reasons(self) -> list:
        """
        Per sample: 'None' (admissible) or the reject reason.
        """
    @property
    def reject_counts(self) -> dict:
        ...
    @property
    def samples(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, 2) sampled commands (v, omega).
        """
    @property
    def status(self) -> Status:
        ...
    @property
    def target(self) -> tuple[float, float]:
        ...
    @property
    def total(self) -> typing.Annotated[numpy.typing.NDArray[numpy.float64], "[m, 1]"]:
        """
        (n,) weighted totals; -inf for rejected samples.
        """
    @property
    def weights(self) -> list[float]:
        ...
class LocalPlanner:
    """
    The dynamic window planner: one control cycle in, one command and its diagnostics out.
    """
    def __init__(self, limits: RobotLimits, footprint: Footprint, params: PlannerParams = ...) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def clear_global_path(self) -> None:
        ...
    def plan(self, state: RobotState, goal: typing.Any, world: ClearanceSource, target: typing.Any = None) -> PlanResult:
        """
        One control cycle toward `goal`. The heading aims at `target` when given, else at the goal or the current key node per the params' heading_target.
        """
    def rollouts(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (samples, n_steps, 3) rollouts of the last cycle.
        """
    def set_global_path(self, path: typing.Any) -> None:
        """
        The global path to follow (a GlobalPath or (n, 2) points); resets key-node tracking.
        """
    def set_weight(self, critic: str, weight: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    def weight(self, critic: str) -> float:
        ...
    @property
    def footprint(self) -> Footprint:
        ...
    @property
    def global_path(self) -> typing.Any:
        ...
    @property
    def key_nodes(self) -> list[int]:
        """
        Indices of the key nodes in the global path's points.
        """
    @property
    def limits(self) -> RobotLimits:
        ...
    @property
    def needs_path(self) -> bool:
        """
        Whether a cycle needs a global path: the key-node heading or a critic reads it.
        """
    @property
    def params(self) -> PlannerParams:
        ...
class MembershipFunction:
    """
    A fuzzy membership function: degrees in [0, 1]. Build one with triangle(a, b, c), trapezoid(a, b, c, d) or gaussian(mean, sigma); a == b or b == c makes a shoulder. Calling it gives the degree of a number, or of every element of an array.
    """
    __hash__: typing.ClassVar[None] = None
    @staticmethod
    def gaussian(mean: typing.SupportsFloat | typing.SupportsIndex, sigma: typing.SupportsFloat | typing.SupportsIndex) -> MembershipFunction:
        """
        exp(-((x - mean) / sigma)^2 / 2), sigma > 0.
        """
    @staticmethod
    def trapezoid(a: typing.SupportsFloat | typing.SupportsIndex, b: typing.SupportsFloat | typing.SupportsIndex, c: typing.SupportsFloat | typing.SupportsIndex, d: typing.SupportsFloat | typing.SupportsIndex) -> MembershipFunction:
        """
        Zero outside [a, d], 1 on [b, c], linear in between (a <= b <= c <= d, a < d).
        """
    @staticmethod
    def triangle(a: typing.SupportsFloat | typing.SupportsIndex, b: typing.SupportsFloat | typing.SupportsIndex, c: typing.SupportsFloat | typing.SupportsIndex) -> MembershipFunction:
        """
        Zero outside [a, c], 1 at b, linear in between (a <= b <= c, a < c).
        """
    def __call__(self, x: typing.Any) -> typing.Any:
        """
        Degree of x (a number or an array) in this set.
        """
    def __eq__(self, arg0: MembershipFunction) -> bool:
        ...
    def __repr__(self) -> str:
        ...
    @property
    def params(self) -> tuple:
        """
        The shape's parameters: (a, b, c), (a, b, c, d) or (mean, sigma).
        """
    @property
    def shape(self) -> str:
        """
        'triangle', 'trapezoid' or 'gaussian'.
        """
class FuzzyVariable:
    """
    A linguistic variable: a name, a domain (lo, hi) and named terms (a dict {name: MembershipFunction}, in order). Names are letters, digits and '_'. Every term must reach a positive degree inside the domain.
    """
    @staticmethod
    def uniform(name: str, domain: typing.Any, terms: collections.abc.Sequence[str] = ['S', 'M', 'L']) -> FuzzyVariable:
        """
        The uniform triangular partition of the domain: evenly spaced peaks, shoulders at both ends (for S, M, L: S = tri(lo, lo, mid), M = tri(lo, mid, hi), L = tri(mid, hi, hi)).
        """
    def __init__(self, name: typing.Any, domain: typing.Any, terms: typing.Any) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def membership(self, term: str, x: typing.Any) -> typing.Any:
        """
        Degree of x (a number or an array, not clamped) in the named term.
        """
    @property
    def domain(self) -> tuple[float, float]:
        ...
    @property
    def hi(self) -> float:
        ...
    @property
    def lo(self) -> float:
        ...
    @property
    def name(self) -> str:
        ...
    @property
    def term_names(self) -> list[str]:
        ...
    @property
    def terms(self) -> dict:
        """
        {name: MembershipFunction}, in order.
        """
class FuzzyRule:
    """
    IF every antecedent holds (AND = min) THEN every consequent. Build one from text, FuzzyRule('IF I is S AND D is M THEN beta is S AND delta is M'), or from {variable: term} dicts: FuzzyRule({'I': 'S', 'D': 'M'}, {'beta': 'S'}).
    """
    @staticmethod
    def parse(text: str) -> FuzzyRule:
        """
        Read 'IF v is t AND ... THEN v is t AND ...' (keywords in any case).
        """
    def __init__(self, antecedents: typing.Any, consequents: typing.Any = None) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def __str__(self) -> str:
        ...
    @property
    def antecedents(self) -> list:
        """
        [(variable, term)] of the IF part.
        """
    @property
    def consequents(self) -> list:
        """
        [(variable, term)] of the THEN part.
        """
class MamdaniEngine:
    """
    Mamdani inference: AND = min, implication = min (clip), aggregation = max, centroid defuzzification on a uniform grid of `resolution` points per output domain (the centroid of the piecewise-linear aggregate through those points). Inputs outside their domains are clamped. When no rule fires for an output, it is the midpoint of its domain.
    """
    def __init__(self, inputs: typing.Any, outputs: typing.Any, rules: typing.Any, resolution: typing.SupportsInt | typing.SupportsIndex = 1001) -> None:
        """
        inputs and outputs: lists of FuzzyVariable; rules: FuzzyRule objects or rule strings.
        """
    def __repr__(self) -> str:
        ...
    def evaluate(self, *args, **kwargs) -> dict:
        """
        evaluate(*values, **inputs) -> {output: value}: one inference, inputs by position (in the order of `inputs`) or by name, e.g. engine.evaluate(I=0.4, D=1.2).
        """
    def evaluate_grid(self, *args, **kwargs) -> dict:
        """
        evaluate_grid(*arrays, **inputs) -> {output: array}: one inference per element of input arrays that broadcast together (numpy rules), e.g. engine.evaluate_grid(*np.meshgrid(I_axis, D_axis)). Each output has the broadcast shape.
        """
    def firing_strengths(self, *args, **kwargs) -> list[float]:
        """
        Firing strength of each rule (in the order of `rules`) for these inputs.
        """
    @property
    def input_names(self) -> list[str]:
        ...
    @property
    def inputs(self) -> list[FuzzyVariable]:
        ...
    @property
    def output_names(self) -> list[str]:
        ...
    @property
    def outputs(self) -> list[FuzzyVariable]:
        ...
    @property
    def resolution(self) -> int:
        ...
    @property
    def rules(self) -> list[FuzzyRule]:
        ...
class WeightPolicy:
    """
    Sets critics' weights from the obstacle density I and the path deviation D each cycle. Derive from it in Python (call super().__init__()) and define weights(density, deviation) -> {critic name: weight}; the controller applies the weights of the critics its planner has.
    """
    def __init__(self) -> None:
        ...
    def weights(self, density: typing.SupportsFloat | typing.SupportsIndex, deviation: typing.SupportsFloat | typing.SupportsIndex, contact_time: typing.SupportsFloat | typing.SupportsIndex = ...) -> dict[str, float]:
        """
        {critic name: weight} for obstacle density I, path deviation D (m) and the time T (s) to the nearest predicted contact with a mover (inf, the default: none); a policy that does not read T gives its weights(I, D).
        """
    @property
    def name(self) -> str:
        ...
class FixedWeights(WeightPolicy):
    """
    Critics' weights held fixed: FixedWeights(beta, delta) for clearance and similarity, or FixedWeights(weights={critic name: weight}).
    """
    @typing.overload
    def __init__(self, beta: typing.SupportsFloat | typing.SupportsIndex, delta: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @typing.overload
    def __init__(self, weights: collections.abc.Mapping[str, typing.SupportsFloat | typing.SupportsIndex]) -> None:
        ...
    def __repr__(self) -> str:
        ...
class FuzzyWeights(WeightPolicy):
    """
    Critics' weights from a Mamdani engine with inputs I and D, and optionally T (the time to the nearest predicted contact with a mover), each output mapped to a critic.
    """
    def __init__(self, engine: MamdaniEngine = None, output_critics: collections.abc.Mapping[str, str] | None = None) -> None:
        """
        engine: a MamdaniEngine with inputs I and D, and optionally T (default: the paper's; mover_fuzzy_controller() reads T too); output_critics: {output: critic} (default: beta -> clearance, delta -> similarity).
        """
    def __repr__(self) -> str:
        ...
    @property
    def engine(self) -> MamdaniEngine:
        ...
    @property
    def output_critics(self) -> dict[str, str]:
        ...
class PlannerPreset:
    """
    A named planner of the paper's experiments: its parameters and weights.
    """
    def __repr__(self) -> str:
        ...
    def weight_policy(self) -> WeightPolicy:
        """
        The policy to run it with; None for fixed weights.
        """
    @property
    def description(self) -> str:
        ...
    @property
    def fuzzy(self) -> bool:
        ...
    @property
    def name(self) -> str:
        ...
    @property
    def params(self) -> PlannerParams:
        ...
class RobotPreset:
    """
    A robot by name: limits, the footprint it is planned with and its true outline.
    """
    def __repr__(self) -> str:
        ...
    @property
    def description(self) -> str:
        ...
    @property
    def footprint(self) -> Footprint:
        """
        What the planner is configured with.
        """
    @property
    def limits(self) -> RobotLimits:
        ...
    @property
    def name(self) -> str:
        ...
    @property
    def outline(self) -> Footprint:
        """
        The body itself: what a referee judges contact with.
        """
class ScoredRollout:
    """
    A rollout the planner scored: its sample, command, total, poses.
    """
    @property
    def command(self) -> Twist:
        ...
    @property
    def poses(self) -> numpy.typing.NDArray[numpy.float64]:
        ...
    @property
    def raw(self) -> list[float]:
        """
        Per critic (the report's critic_names): its raw score.
        """
    @property
    def sample(self) -> int:
        ...
    @property
    def terms(self) -> list[float]:
        """
        Per critic: signed weight x normalised score, its part of the total (costs negative); they sum to total.
        """
    @property
    def total(self) -> float:
        ...
class CriticStats:
    """
    One critic's weighted term over a cycle's admissible samples (zeros when none).
    """
    def __repr__(self) -> str:
        ...
    @property
    def max(self) -> float:
        ...
    @property
    def mean(self) -> float:
        ...
    @property
    def min(self) -> float:
        ...
class CycleReport:
    """
    What a control cycle sensed, how it weighed it and what it chose.
    """
    def __repr__(self) -> str:
        ...
    @property
    def best(self) -> list[ScoredRollout]:
        """
        The best admissible rollouts (ScoredRollout), best first.
        """
    @property
    def beta(self) -> float:
        """
        Clearance weight used; NaN without that critic.
        """
    @property
    def choice(self) -> ScoredRollout:
        """
        The chosen sample as a ScoredRollout (sample -1 when none), its per-critic scores included.
        """
    @property
    def chosen(self) -> int:
        """
        The chosen sample, -1 when none.
        """
    @property
    def chosen_rollout(self) -> numpy.typing.NDArray[numpy.float64]:
        ...
    @property
    def command(self) -> Twist:
        ...
    @property
    def contact_time(self) -> float:
        """
        T (s): when the nearest moving disc would first touch the robot's circle, both keeping their velocities; inf without one on its way.
        """
    @property
    def critic_names(self) -> list[str]:
        """
        The planner's critics: the order of raw, terms and critic_vetoes.
        """
    @property
    def critic_stats(self) -> list[CriticStats]:
        """
        Per critic (CriticStats): min, mean and max of its term over the admissible samples.
        """
    @property
    def critic_vetoes(self) -> list[int]:
        """
        Per critic of the planner (in PlannerParams.critics order): samples it vetoed this cycle.
        """
    @property
    def delta(self) -> float:
        """
        Similarity weight used; NaN without that critic.
        """
    @property
    def density(self) -> float:
        """
        I; NaN without a scan.
        """
    @property
    def deviation(self) -> float:
        """
        D (m); NaN without a global path.
        """
    @property
    def key_node(self) -> int:
        ...
    @property
    def live_points(self) -> int:
        """
        Lidar hits near the map's obstacles but off them along their beam by more than the range noise explains: points the planner keeps clear of this cycle.
        """
    @property
    def reject_counts(self) -> dict:
        ...
    @property
    def sensed_points(self) -> int:
        """
        Lidar hits that neither the map nor the known discs explain.
        """
    @property
    def status(self) -> Status:
        ...
    @property
    def target(self) -> tuple[float, float]:
        """
        What the heading critic aimed at.
        """
class Controller:
    """
    One control cycle as a robot runs it: scan -> obstacles the map lacks and density I; global path -> deviation D; weight policy -> beta, delta; planner -> command.
    """
    def __init__(self, limits: RobotLimits, footprint: Footprint, params: PlannerParams = ..., map: DistanceField = None, policy: WeightPolicy = None, window: DetectWindowParams = ...) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def set_global_path(self, path: typing.Any) -> None:
        ...
    def set_map(self, map: DistanceField) -> None:
        """
        Replaces the map's distance field (None for none), e.g. with ScanMap.field() after new cells.
        """
    def step(self, state: RobotState, goal: typing.Any, scan: Scan = None, discs: collections.abc.Sequence[Disc] = []) -> PlanResult:
        """
        One cycle toward goal with this cycle's scan (or None) and the known moving discs placed now.
        """
    @property
    def map(self) -> DistanceField:
        ...
    @property
    def planner(self) -> LocalPlanner:
        ...
    @property
    def report(self) -> CycleReport:
        ...
    @property
    def world(self) -> FieldClearance:
        """
        What the planner saw last cycle: the map's field, the sensed points and the discs.
        """
class OccupancyParams:
    """
    The log-odds update of a ScanMap's cells (defaults: OctoMap's probabilities).
    
    Keyword arguments, attributes (SI units, radians):
      hit: log-odds added to the cell of a hit
      miss: log-odds added to each cell a beam passes (< 0: a pass is evidence of free space)
      clamp_min: lowest log-odds a cell holds
      clamp_max: highest log-odds a cell holds
      occupied: a cell at or above this log-odds turns occupied
      free: at or below this an occupied cell turns free (between free and occupied it keeps its state)
      range_std (m): the lidar's range noise: hits placed 2 std beyond, clearing stops 3 std short
      clear_range (m): the farthest a beam clears (inf: no limit)
      hit_share: a cell some beams of a scan end in and others pass is hit when at least this share end in it
      clear: beams clear the cells they pass (false: hits only, for static worlds)
      edge_margin (m): the free margin the map's distance field keeps past the grid's edge
      fade_time (s): time constant with which an occupied cell no beam reaches fades toward unknown; it is unknown again once below occupied (inf: never fades; 20 s lets what drift smeared go)
    """
    __hash__: typing.ClassVar[None] = None
    name: typing.ClassVar[str] = 'occupancy'
    clamp_max: typing.Any
    clamp_min: typing.Any
    clear: typing.Any
    clear_range: typing.Any
    edge_margin: typing.Any
    fade_time: typing.Any
    free: typing.Any
    hit: typing.Any
    hit_share: typing.Any
    miss: typing.Any
    occupied: typing.Any
    range_std: typing.Any
    @staticmethod
    def schema() -> list:
        """
        Every field, nested ones by their dotted names: name, type, unit, bounds, doc, choices, default.
        """
    def __copy__(self) -> OccupancyParams:
        ...
    def __deepcopy__(self, arg0: typing.Any) -> OccupancyParams:
        ...
    def __eq__(self, arg0: typing.Any) -> bool:
        ...
    def __getstate__(self) -> dict:
        ...
    def __init__(self, **kwargs) -> None:
        """
        Every field a keyword (defaults: the C++ struct's); a nested set takes its own class or a dict.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: dict) -> None:
        ...
    def get(self, name: str) -> typing.Any:
        """
        One field's value, nested ones by dotted name.
        """
    def set(self, name: str, value: typing.Any) -> None:
        """
        Sets one field, nested ones by dotted name ("window.n_v").
        """
    def to_dict(self) -> dict:
        """
        The fields as a dict, nested sets as dicts.
        """
    def validate(self) -> None:
        """
        Checks every field and the rules between them; raises FgdwaError naming the first bad one.
        """
class ScanMap:
    """
    A map built from lidar scans: log-odds per cell, beams ray-traced (the cells they pass are evidence of free space, the hit's cell of an obstacle), so spurious hits and moved objects fade.
    """
    @typing.overload
    def __init__(self, like: OccupancyGrid, params: OccupancyParams = ...) -> None:
        """
        An empty map with the layout of `like`.
        """
    @typing.overload
    def __init__(self, rows: typing.SupportsInt | typing.SupportsIndex, cols: typing.SupportsInt | typing.SupportsIndex, resolution: typing.SupportsFloat | typing.SupportsIndex, origin: typing.Any, params: OccupancyParams = ...) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def field(self) -> DistanceField:
        """
        Its distance field, brought up to date (incrementally) on the first call after changes.
        """
    def integrate(self, scan: Scan, keep_hit: typing.Any = None, time: typing.SupportsFloat | typing.SupportsIndex | None = None) -> int:
        """
        One scan's evidence (each cell updated once, by the vote of the beams ending and passing in it); keep_hit (one flag per beam) says which hits to mark; time (s, or None) lets the occupied cells no beam reached fade (fade_time). Returns how many cells turned occupied or stopped being occupied.
        """
    def mark(self, points: typing.Any) -> int:
        """
        One hit on each cell holding (n, 2) points; returns how many turned occupied.
        """
    @property
    def grid(self) -> OccupancyGrid:
        """
        The map so far (a copy): occupied cells are obstacles.
        """
    @property
    def known_count(self) -> int:
        """
        Cells observed at least once.
        """
    @property
    def log_odds(self) -> numpy.typing.NDArray[numpy.float32]:
        """
        (rows, cols) float32 log-odds of each cell.
        """
    @property
    def occupied_count(self) -> int:
        ...
    @property
    def params(self) -> OccupancyParams:
        ...
    @property
    def states(self) -> numpy.typing.NDArray[numpy.uint8]:
        """
        (rows, cols) uint8: 0 unknown, 1 free, 2 occupied.
        """
class SegmentParams:
    """
    How a scan's hits are split into clusters (objects to track).
    
    Keyword arguments, attributes (SI units, radians):
      base_gap (m): consecutive hits farther apart than base_gap + range_gap_factor * range start a new cluster
      range_gap_factor (m/m): the gap's growth per metre of range (beams spread with range)
      min_points: hits of the smallest cluster kept (smaller ones are noise)
      max_size (m): clusters whose oriented box is longer (walls) are not tracked
      min_radius (m): smallest fitted disc radius (the largest is max_size / 2)
      range_noise (m): range noise std the disc fit assumes when weighing hits against the apparent width
      notch_depth (m): a cluster is cut where two neighbouring hits lie this far behind the line over them from hits on either side (objects side by side, each convex toward the sensor)
      max_clusters: clusters kept per scan, the nearest to the scanner; farther ones are dropped (the tracker's work grows with their cube)
    """
    __hash__: typing.ClassVar[None] = None
    name: typing.ClassVar[str] = 'segment'
    base_gap: typing.Any
    max_clusters: typing.Any
    max_size: typing.Any
    min_points: typing.Any
    min_radius: typing.Any
    notch_depth: typing.Any
    range_gap_factor: typing.Any
    range_noise: typing.Any
    @staticmethod
    def schema() -> list:
        """
        Every field, nested ones by their dotted names: name, type, unit, bounds, doc, choices, default.
        """
    def __copy__(self) -> SegmentParams:
        ...
    def __deepcopy__(self, arg0: typing.Any) -> SegmentParams:
        ...
    def __eq__(self, arg0: typing.Any) -> bool:
        ...
    def __getstate__(self) -> dict:
        ...
    def __init__(self, **kwargs) -> None:
        """
        Every field a keyword (defaults: the C++ struct's); a nested set takes its own class or a dict.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: dict) -> None:
        ...
    def get(self, name: str) -> typing.Any:
        """
        One field's value, nested ones by dotted name.
        """
    def set(self, name: str, value: typing.Any) -> None:
        """
        Sets one field, nested ones by dotted name ("window.n_v").
        """
    def to_dict(self) -> dict:
        """
        The fields as a dict, nested sets as dicts.
        """
    def validate(self) -> None:
        """
        Checks every field and the rules between them; raises FgdwaError naming the first bad one.
        """
class OrientedBox:
    """
    A box along the principal axes of a cluster's hits.
    """
    def __repr__(self) -> str:
        ...
    @property
    def angle(self) -> float:
        """
        rad, of the major axis.
        """
    @property
    def center(self) -> tuple:
        ...
    @property
    def half_extents(self) -> tuple:
        """
        m, along the major then the minor axis.
        """
class Cluster:
    """
    Neighbouring hits of one scan and the disc fitted to them (its centre behind the near side the lidar sees).
    """
    def __init__(self, center: typing.Any, radius: typing.SupportsFloat | typing.SupportsIndex = 0.3, occluded: bool = False) -> None:
        """
        A cluster of one point at its centre, e.g. to feed a Tracker detections made elsewhere.
        """
    def __repr__(self) -> str:
        ...
    @property
    def box(self) -> OrientedBox:
        ...
    @property
    def center(self) -> tuple:
        ...
    @property
    def first_beam(self) -> int:
        ...
    @property
    def last_beam(self) -> int:
        ...
    @property
    def occluded(self) -> bool:
        """
        A beam beside an end hit something nearer, or an end is the field of view's.
        """
    @property
    def points(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, 2) hits, m.
        """
    @property
    def radius(self) -> float:
        ...
class TrackStatus:
    """
    Where a track is in its life.
    
    Members:
    
      Tentative
    
      Confirmed
    
      Lost
    """
    Confirmed: typing.ClassVar[TrackStatus]
    Lost: typing.ClassVar[TrackStatus]
    Tentative: typing.ClassVar[TrackStatus]
    __members__: typing.ClassVar[dict[str, TrackStatus]]
    @typing.overload
    def __eq__(self, other: TrackStatus) -> bool:
        ...
    @typing.overload
    def __eq__(self, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self) -> int:
        ...
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __int__(self) -> int:
        ...
    @typing.overload
    def __ne__(self, other: TrackStatus) -> bool:
        ...
    @typing.overload
    def __ne__(self, other: typing.Any) -> bool:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, state: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __str__(self) -> str:
        ...
    @property
    def name(self) -> str:
        ...
    @property
    def value(self) -> int:
        ...
class TrackerParams:
    """
    Tracks of moving obstacles: association, Kalman filter, moving label.
    
    Keyword arguments, attributes (SI units, radians):
      gate (m): largest distance between a track's prediction and a cluster it may take
      gate_sigmas: the same gate in standard deviations of the prediction (Mahalanobis)
      accel_std (m/s^2): white-noise acceleration of the constant-velocity model
      measurement_std (m): std of an unoccluded cluster centre (and the least scatter the moving test assumes)
      confirm_hits: associations before a tentative track is confirmed
      lost_time (s): time without association before a track is lost; removed after another lost_time
      moving_speed (m/s): a confirmed track whose window speed, less moving_sigmas std, exceeds this is moving
      moving_sigmas: std devs taken off the window speed before comparing it with moving_speed
      moving_window (s): the window speed is the slope of a line fitted to the centres this far back
      moving_hold (s): a track labelled moving for a whole moving_window keeps its label this long after its window speed fell below half moving_speed: what paused (a robot waiting, a disc turning back) may go on
      prediction_window (s): the predicted velocity is the slope of the centres this far back (no farther than moving_window) where it departs from moving_window's by more than 1 std, else moving_window's
      free_margin (m): a hit counts as in space an earlier scan saw free when that scan's beams reached this far past it
      max_speed (m/s): an association implying more speed is rejected
      uncertainty_sigmas: std devs of position added to a moving disc's radius, and of the filter's speed to its growth per second ahead
      max_uncertainty (m): the most the position's uncertainty adds to a disc (a coasting track's grows)
      hypothesis_time (s): how long a second prediction keeps a moving track's significant acceleration (turning, slowing, reversing) before its velocity holds; 0: constant velocity alone
      acceleration_sigmas: std devs the fitted acceleration must exceed before the second prediction is made
      max_acceleration (m/s^2): the most acceleration the second prediction keeps
      max_clusters: clusters an update tracks, the nearest to the scanner first (association costs the cube of the count); the rest stay the scan's points, and new tracks stop at twice this
    """
    __hash__: typing.ClassVar[None] = None
    name: typing.ClassVar[str] = 'tracker'
    accel_std: typing.Any
    acceleration_sigmas: typing.Any
    confirm_hits: typing.Any
    free_margin: typing.Any
    gate: typing.Any
    gate_sigmas: typing.Any
    hypothesis_time: typing.Any
    lost_time: typing.Any
    max_acceleration: typing.Any
    max_clusters: typing.Any
    max_speed: typing.Any
    max_uncertainty: typing.Any
    measurement_std: typing.Any
    moving_hold: typing.Any
    moving_sigmas: typing.Any
    moving_speed: typing.Any
    moving_window: typing.Any
    prediction_window: typing.Any
    uncertainty_sigmas: typing.Any
    @staticmethod
    def schema() -> list:
        """
        Every field, nested ones by their dotted names: name, type, unit, bounds, doc, choices, default.
        """
    def __copy__(self) -> TrackerParams:
        ...
    def __deepcopy__(self, arg0: typing.Any) -> TrackerParams:
        ...
    def __eq__(self, arg0: typing.Any) -> bool:
        ...
    def __getstate__(self) -> dict:
        ...
    def __init__(self, **kwargs) -> None:
        """
        Every field a keyword (defaults: the C++ struct's); a nested set takes its own class or a dict.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: dict) -> None:
        ...
    def get(self, name: str) -> typing.Any:
        """
        One field's value, nested ones by dotted name.
        """
    def set(self, name: str, value: typing.Any) -> None:
        """
        Sets one field, nested ones by dotted name ("window.n_v").
        """
    def to_dict(self) -> dict:
        """
        The fields as a dict, nested sets as dicts.
        """
    def validate(self) -> None:
        """
        Checks every field and the rules between them; raises FgdwaError naming the first bad one.
        """
class Track:
    """
    One followed object: constant-velocity Kalman state and its moving label.
    """
    def __repr__(self) -> str:
        ...
    @property
    def acceleration(self) -> tuple:
        """
        m/s^2, the same parabola's; the second prediction keeps it where significant.
        """
    @property
    def acceleration_std(self) -> float:
        """
        m/s^2, its std per coordinate (inf until four centres).
        """
    @property
    def age(self) -> float:
        ...
    @property
    def covariance(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (4, 4) covariance of (x, y, vx, vy).
        """
    @property
    def current_velocity(self) -> tuple:
        """
        m/s, a parabola's through the window's centres, at the last one (fitted while hypothesis_time > 0).
        """
    @property
    def hits(self) -> int:
        ...
    @property
    def id(self) -> int:
        ...
    @property
    def last_fast(self) -> float:
        """
        s, the last association at which a moving track's window speed held its label (moving_hold counts from it)
        """
    @property
    def last_seen(self) -> float:
        ...
    @property
    def moving(self) -> bool:
        ...
    @property
    def position(self) -> tuple:
        """
        m, at the last update.
        """
    @property
    def position_std(self) -> float:
        ...
    @property
    def predicted_velocity(self) -> tuple:
        """
        m/s, slope of the centres over the last prediction_window; moving_discs use it.
        """
    @property
    def radius(self) -> float:
        ...
    @property
    def speed_std(self) -> float:
        ...
    @property
    def status(self) -> TrackStatus:
        ...
    @property
    def velocity(self) -> tuple:
        """
        m/s, the filter's.
        """
    @property
    def window_speed_std(self) -> float:
        ...
    @property
    def window_velocity(self) -> tuple:
        """
        m/s, slope of the centres over the last moving_window; the moving label uses it.
        """
class Tracker:
    """
    Follows segment_scan's clusters from scan to scan and says which move. update() with each scan's clusters and time; read tracks, moving_discs(), explains().
    """
    def __init__(self, params: TrackerParams = ...) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def explains(self, point: typing.Any, margin: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> bool:
        """
        Whether the point lies within margin (m) of a confirmed moving track's grown disc.
        """
    def moving_discs(self) -> list[Disc]:
        """
        Moving tracks (confirmed or coasting) as Discs with their window velocity, radius grown by uncertainty_sigmas position std devs and growing by uncertainty_sigmas std devs of the filter's speed per second ahead.
        """
    def reset(self) -> None:
        """
        Forgets every track; ids keep counting.
        """
    def update(self, clusters: collections.abc.Sequence[Cluster], time: typing.SupportsFloat | typing.SupportsIndex, scan: Scan = None) -> None:
        """
        Predicts the tracks to time (s, never going back), assigns the clusters, corrects, starts, loses and removes tracks. Pass the scan the clusters came from: without it only the window speed decides what moves, and static clutter seen from a moving robot can be called moving.
        """
    @property
    def cluster_tracks(self) -> list[int]:
        """
        For each cluster of the last update, the id of the track that took it.
        """
    @property
    def params(self) -> TrackerParams:
        ...
    @property
    def time(self) -> float:
        """
        s, of the last update (NaN before the first).
        """
    @property
    def tracks(self) -> list[Track]:
        """
        The tracks after the last update (a copy).
        """
class ScanMatchParams:
    """
    The scan-to-map matcher: search window and steps, scoring, when a match is refused.
    
    Keyword arguments, attributes (SI units, radians):
      enabled: align each scan to the map before it goes in, and plan at the corrected pose (false: odometry is the pose)
      window_xy (m): farthest the search moves the scan from where odometry places it, in x and in y
      window_theta (rad): farthest the search turns the scan, either way
      step_xy (m): the coarse search's translation step over the whole window
      step_theta (rad): the coarse search's rotation step; refined by halves with the translation
      final_step_xy (m): the refinement halves the steps until the translation step is this fine
      sigma (m): a hit this far from the map's nearest obstacle scores exp(-1/2)
      point_spacing (m): hits nearer than this to the last one kept (in beam order) are skipped
      max_points: hits scored at most (evenly picked from those kept)
      min_points: fewer hits kept than this: no match
      min_score: the best pose's mean score below this: the map does not know the place yet, no match
      margin: the best pose must score this much above the pose odometry gives, and this much above every pose farther than ambiguity_radius from it
      ambiguity_radius (m): a pose this far from the best that scores within margin of it makes the match ambiguous
    """
    __hash__: typing.ClassVar[None] = None
    name: typing.ClassVar[str] = 'scan_match'
    ambiguity_radius: typing.Any
    enabled: typing.Any
    final_step_xy: typing.Any
    margin: typing.Any
    max_points: typing.Any
    min_points: typing.Any
    min_score: typing.Any
    point_spacing: typing.Any
    sigma: typing.Any
    step_theta: typing.Any
    step_xy: typing.Any
    window_theta: typing.Any
    window_xy: typing.Any
    @staticmethod
    def schema() -> list:
        """
        Every field, nested ones by their dotted names: name, type, unit, bounds, doc, choices, default.
        """
    def __copy__(self) -> ScanMatchParams:
        ...
    def __deepcopy__(self, arg0: typing.Any) -> ScanMatchParams:
        ...
    def __eq__(self, arg0: typing.Any) -> bool:
        ...
    def __getstate__(self) -> dict:
        ...
    def __init__(self, **kwargs) -> None:
        """
        Every field a keyword (defaults: the C++ struct's); a nested set takes its own class or a dict.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: dict) -> None:
        ...
    def get(self, name: str) -> typing.Any:
        """
        One field's value, nested ones by dotted name.
        """
    def set(self, name: str, value: typing.Any) -> None:
        """
        Sets one field, nested ones by dotted name ("window.n_v").
        """
    def to_dict(self) -> dict:
        """
        The fields as a dict, nested sets as dicts.
        """
    def validate(self) -> None:
        """
        Checks every field and the rules between them; raises FgdwaError naming the first bad one.
        """
class MatchStatus:
    """
    Why a scan's match was or was not used.
    
    Members:
    
      Accepted
    
      Off
    
      NoMap
    
      TooFewPoints
    
      PoorFit
    
      NotBetter
    
      Ambiguous
    """
    Accepted: typing.ClassVar[MatchStatus]
    Ambiguous: typing.ClassVar[MatchStatus]
    NoMap: typing.ClassVar[MatchStatus]
    NotBetter: typing.ClassVar[MatchStatus]
    Off: typing.ClassVar[MatchStatus]
    PoorFit: typing.ClassVar[MatchStatus]
    TooFewPoints: typing.ClassVar[MatchStatus]
    __members__: typing.ClassVar[dict[str, MatchStatus]]
    @typing.overload
    def __eq__(self, other: MatchStatus) -> bool:
        ...
    @typing.overload
    def __eq__(self, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self) -> int:
        ...
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __int__(self) -> int:
        ...
    @typing.overload
    def __ne__(self, other: MatchStatus) -> bool:
        ...
    @typing.overload
    def __ne__(self, other: typing.Any) -> bool:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, state: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __str__(self) -> str:
        ...
    @property
    def name(self) -> str:
        ...
    @property
    def value(self) -> int:
        ...
class ScanMatch:
    """
    One scan matched to a map.
    """
    def __repr__(self) -> str:
        ...
    @property
    def accepted(self) -> bool:
        ...
    @property
    def given_score(self) -> float:
        """
        The mean score at the pose given.
        """
    @property
    def points(self) -> int:
        """
        Hits scored.
        """
    @property
    def pose(self) -> Pose2:
        """
        The scan's best pose found (the one given when none was searched).
        """
    @property
    def runner_up(self) -> float:
        """
        The best score farther than ambiguity_radius from the best.
        """
    @property
    def score(self) -> float:
        """
        Its mean score, in [0, 1].
        """
    @property
    def status(self) -> MatchStatus:
        ...
class ScanMatcher:
    """
    Correlative scan-to-map matching in a bounded window around the scan's pose.
    """
    def __init__(self, params: ScanMatchParams = ...) -> None:
        ...
    def match(self, scan: Scan, field: DistanceField, depth: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> ScanMatch:
        """
        The pose near scan.pose at which the scan's hits (each pushed `depth` m along its beam) fit the field's obstacles best, and whether it is clearly better than scan.pose (ScanMatch).
        """
    @property
    def params(self) -> ScanMatchParams:
        ...
class NavigatorMode:
    """
    What the navigator is doing this cycle.
    
    Members:
    
      Following
    
      Replanning
    
      BackingUp
    
      Rotating
    
      Waiting
    
      GoalReached
    
      Failed
    """
    BackingUp: typing.ClassVar[NavigatorMode]
    Failed: typing.ClassVar[NavigatorMode]
    Following: typing.ClassVar[NavigatorMode]
    GoalReached: typing.ClassVar[NavigatorMode]
    Replanning: typing.ClassVar[NavigatorMode]
    Rotating: typing.ClassVar[NavigatorMode]
    Waiting: typing.ClassVar[NavigatorMode]
    __members__: typing.ClassVar[dict[str, NavigatorMode]]
    @typing.overload
    def __eq__(self, other: NavigatorMode) -> bool:
        ...
    @typing.overload
    def __eq__(self, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self) -> int:
        ...
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __int__(self) -> int:
        ...
    @typing.overload
    def __ne__(self, other: NavigatorMode) -> bool:
        ...
    @typing.overload
    def __ne__(self, other: typing.Any) -> bool:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, state: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __str__(self) -> str:
        ...
    @property
    def name(self) -> str:
        ...
    @property
    def value(self) -> int:
        ...
class FailureReason:
    """
    Why the navigator gave up.
    
    Members:
    
      None_
    
      NoGlobalPath
    
      RecoveriesExhausted
    """
    NoGlobalPath: typing.ClassVar[FailureReason]
    None_: typing.ClassVar[FailureReason]
    RecoveriesExhausted: typing.ClassVar[FailureReason]
    __members__: typing.ClassVar[dict[str, FailureReason]]
    @typing.overload
    def __eq__(self, other: FailureReason) -> bool:
        ...
    @typing.overload
    def __eq__(self, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self) -> int:
        ...
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __int__(self) -> int:
        ...
    @typing.overload
    def __ne__(self, other: FailureReason) -> bool:
        ...
    @typing.overload
    def __ne__(self, other: typing.Any) -> bool:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, state: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __str__(self) -> str:
        ...
    @property
    def name(self) -> str:
        ...
    @property
    def value(self) -> int:
        ...
class RecoveryTrigger:
    """
    What started a recovery.
    
    Members:
    
      None_
    
      NoProgress
    
      AllRejected
    
      Start
    
      Wandering
    """
    AllRejected: typing.ClassVar[RecoveryTrigger]
    NoProgress: typing.ClassVar[RecoveryTrigger]
    None_: typing.ClassVar[RecoveryTrigger]
    Start: typing.ClassVar[RecoveryTrigger]
    Wandering: typing.ClassVar[RecoveryTrigger]
    __members__: typing.ClassVar[dict[str, RecoveryTrigger]]
    @typing.overload
    def __eq__(self, other: RecoveryTrigger) -> bool:
        ...
    @typing.overload
    def __eq__(self, other: typing.Any) -> bool:
        ...
    def __getstate__(self) -> int:
        ...
    def __hash__(self) -> int:
        ...
    def __index__(self) -> int:
        ...
    def __init__(self, value: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __int__(self) -> int:
        ...
    @typing.overload
    def __ne__(self, other: RecoveryTrigger) -> bool:
        ...
    @typing.overload
    def __ne__(self, other: typing.Any) -> bool:
        ...
    def __repr__(self) -> str:
        ...
    def __setstate__(self, state: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    def __str__(self) -> str:
        ...
    @property
    def name(self) -> str:
        ...
    @property
    def value(self) -> int:
        ...
class NavigatorParams:
    """
    Replanning, recovery, the map from scans and moving obstacles of a Navigator.
    
    Keyword arguments, attributes (SI units, radians):
      footprint_padding (m): the footprint grows by this on every side for everything the navigator plans and checks (room for a body larger than its configured footprint)
      path_margin (m): kept beyond the footprint's circumscribed radius by the global path where the map allows
      replan_period (s): shortest time between two replans for a blocked path
      retry_period (s): shortest time between two global plans for a goal that had no path (set_goal() with the same goal again does not plan sooner)
      stall_time (s): time over which too little progress is a stall (0: never stalls)
      stall_distance (m): progress in stall_time below which the robot has stalled
      give_up_length (m): path ahead closed to the global planner after a stall
      keep_clear (m): around the robot and the goal, never closed by a stall
      sensed_close_radius (m): at a stall, the scan's hits the map lacks this near are closed to the global planner
      backup_distance (m): driven straight back after a stall
      backup_speed (m/s): reverse speed while backing up
      rotate_limit (rad): the most a rotation recovery turns
      wait_time (s): standing still for a moving obstacle to pass
      wait_radius (m): a known moving obstacle this near at a stall makes the robot wait
      max_recoveries: recoveries in a row without progress before Failed
      progress_reset (m): distance from where the last recovery began that counts as progress
      wander_time (s): a robot following the path that stays within wander_radius of one point this long has stalled too (0: never)
      wander_radius (m): how far from where it was the robot must get within wander_time
      record_top_k: best-scored rollouts kept in each CycleRecord
      occupancy: the map built from scans (its range_std is at least the lidar's noise_std)
      scan_match: each scan aligned to the map: the correction from the odometry's frame to the map's
      track_moving: segment and track moving obstacles in the scans (false: every hit is static where it is, the ablation)
      start_watch_time (s): with track_moving, the robot stands this long from its first scan, while the tracker labels what moves, unless a labelled mover comes at it
      mover_margin (m): added to a tracked mover's radius: room for a mover to change its mind
      route_around_movers: the global path keeps off the floor each mover sweeps over mover_route_horizon (false: movers reach only the local planner)
      mover_route_horizon (s): how far ahead a mover's sweep is closed to the global planner
      mover_route_lookahead (m): a sweep within the inscribed radius of this much path ahead asks for a new path
      segment: scan segmentation into clusters
      tracker: tracks of moving obstacles
      learn_obstacles: with a known map, obstacles the scans find that it lacks join it (false: they reach only the local planner)
      unknown_cost: extra cost per metre of global path through cells the scans have not observed (0: unknown is free)
    """
    __hash__: typing.ClassVar[None] = None
    name: typing.ClassVar[str] = 'navigator'
    backup_distance: typing.Any
    backup_speed: typing.Any
    footprint_padding: typing.Any
    give_up_length: typing.Any
    keep_clear: typing.Any
    learn_obstacles: typing.Any
    max_recoveries: typing.Any
    mover_margin: typing.Any
    mover_route_horizon: typing.Any
    mover_route_lookahead: typing.Any
    occupancy: typing.Any
    path_margin: typing.Any
    progress_reset: typing.Any
    record_top_k: typing.Any
    replan_period: typing.Any
    retry_period: typing.Any
    rotate_limit: typing.Any
    route_around_movers: typing.Any
    scan_match: typing.Any
    segment: typing.Any
    sensed_close_radius: typing.Any
    stall_distance: typing.Any
    stall_time: typing.Any
    start_watch_time: typing.Any
    track_moving: typing.Any
    tracker: typing.Any
    unknown_cost: typing.Any
    wait_radius: typing.Any
    wait_time: typing.Any
    wander_radius: typing.Any
    wander_time: typing.Any
    @staticmethod
    def schema() -> list:
        """
        Every field, nested ones by their dotted names: name, type, unit, bounds, doc, choices, default.
        """
    def __copy__(self) -> NavigatorParams:
        ...
    def __deepcopy__(self, arg0: typing.Any) -> NavigatorParams:
        ...
    def __eq__(self, arg0: typing.Any) -> bool:
        ...
    def __getstate__(self) -> dict:
        ...
    def __init__(self, **kwargs) -> None:
        """
        Every field a keyword (defaults: the C++ struct's); a nested set takes its own class or a dict.
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: dict) -> None:
        ...
    def get(self, name: str) -> typing.Any:
        """
        One field's value, nested ones by dotted name.
        """
    def set(self, name: str, value: typing.Any) -> None:
        """
        Sets one field, nested ones by dotted name ("window.n_v").
        """
    def to_dict(self) -> dict:
        """
        The fields as a dict, nested sets as dicts.
        """
    def validate(self) -> None:
        """
        Checks every field and the rules between them; raises FgdwaError naming the first bad one.
        """
class CycleRecord:
    """
    Everything one Navigator cycle decided.
    """
    def __repr__(self) -> str:
        ...
    @property
    def best(self) -> list[ScoredRollout]:
        """
        The best admissible rollouts (ScoredRollout), best first.
        """
    @property
    def beta(self) -> float:
        """
        Clearance weight used; NaN without that critic.
        """
    @property
    def choice(self) -> ScoredRollout:
        """
        The chosen sample as a ScoredRollout (sample -1 when none), its per-critic scores included.
        """
    @property
    def chosen(self) -> int:
        """
        The chosen sample, -1 when none.
        """
    @property
    def chosen_rollout(self) -> numpy.typing.NDArray[numpy.float64]:
        ...
    @property
    def command(self) -> Twist:
        ...
    @property
    def contact_time(self) -> float:
        """
        T (s): when the nearest moving disc would first touch the robot's circle, both keeping their velocities; inf without one on its way.
        """
    @property
    def control(self) -> CycleReport:
        """
        The controller's report (CycleReport).
        """
    @property
    def critic_names(self) -> list[str]:
        """
        The planner's critics: the order of raw, terms and critic_vetoes.
        """
    @property
    def critic_stats(self) -> list[CriticStats]:
        """
        Per critic (CriticStats): min, mean and max of its term over the admissible samples.
        """
    @property
    def critic_vetoes(self) -> list[int]:
        """
        Per critic of the planner (in PlannerParams.critics order): samples it vetoed this cycle.
        """
    @property
    def delta(self) -> float:
        """
        Similarity weight used; NaN without that critic.
        """
    @property
    def density(self) -> float:
        """
        I; NaN without a scan.
        """
    @property
    def deviation(self) -> float:
        """
        D (m); NaN without a global path.
        """
    @property
    def failure(self) -> FailureReason:
        ...
    @property
    def key_node(self) -> int:
        ...
    @property
    def live_points(self) -> int:
        """
        Lidar hits near the map's obstacles but off them along their beam by more than the range noise explains: points the planner keeps clear of this cycle.
        """
    @property
    def map_to_odom(self) -> Pose2:
        """
        The odometry's frame on the map after this cycle's scan (Pose2; the identity until a match moves it).
        """
    @property
    def match(self) -> ScanMatch:
        """
        This cycle's scan matched to the map (ScanMatch).
        """
    @property
    def mode(self) -> NavigatorMode:
        ...
    @property
    def new_cells(self) -> int:
        ...
    @property
    def odometry(self) -> Pose2:
        """
        The pose given to step(), as the odometry has it.
        """
    @property
    def path_points(self) -> typing.Any:
        """
        (n, 2) points of the global path followed, None without one.
        """
    @property
    def path_version(self) -> int:
        ...
    @property
    def planned(self) -> bool:
        """
        Whether the local planner ran this cycle.
        """
    @property
    def recoveries(self) -> int:
        ...
    @property
    def reject_counts(self) -> dict:
        ...
    @property
    def sensed_points(self) -> int:
        """
        Lidar hits that neither the map nor the known discs explain.
        """
    @property
    def state(self) -> RobotState:
        """
        The state planned from: its pose on the map (map_to_odom composed with the odometry's).
        """
    @property
    def status(self) -> Status:
        ...
    @property
    def target(self) -> tuple[float, float]:
        """
        What the heading critic aimed at.
        """
    @property
    def time(self) -> float:
        ...
    @property
    def times(self) -> dict:
        """
        Wall-clock seconds per stage: localise, tracking, map, global, perception, plan.
        """
    @property
    def tracked(self) -> list[Disc]:
        """
        The moving tracks the planner predicted (Discs now, with velocity).
        """
    @property
    def trigger(self) -> RecoveryTrigger:
        """
        What started the recovery under way (or the one that failed).
        """
class Navigator:
    """
    The robot side of the control cycle: map, global path, controller and recovery in one object.
    """
    def __init__(self, limits: RobotLimits, footprint: Footprint, params: PlannerParams, map: OccupancyGrid, mapping: str = 'known', lidar: LidarParams = ..., policy: WeightPolicy = None, navigator: NavigatorParams = ..., terrain: TerrainGrid | None = None, passing_factors: typing.Any = [1.0, 0.8, 0.6, 0.4, 0.0], window: DetectWindowParams = ...) -> None:
        """
        map: the known map (mapping='known') or the layout of the map to build from scans (mapping='scan'); lidar: the robot's scanner (scans are checked against it); policy: a WeightPolicy or None; terrain: a TerrainGrid on the map's layout; passing_factors: v_max scale of grades 0-4.
        """
    def __repr__(self) -> str:
        ...
    def set_global_path(self, path: typing.Any) -> None:
        """
        Follow this path (GlobalPath or (n, 2) points) instead of planning one; after set_goal().
        """
    def set_goal(self, goal: typing.Any) -> None:
        ...
    def step(self, state: RobotState, scan: Scan, time: typing.SupportsFloat | typing.SupportsIndex, discs: collections.abc.Sequence[Disc] = []) -> CycleRecord:
        """
        One cycle from `state` with this cycle's scan (or None) at `time` (s); `discs`: known moving obstacles placed now. The record stays valid until the next step().
        """
    @property
    def controller(self) -> Controller:
        ...
    @property
    def map(self) -> OccupancyGrid:
        """
        The navigator's map now (a copy).
        """
    @property
    def mapping(self) -> str:
        ...
    @property
    def mode_counts(self) -> dict:
        """
        Cycles spent in each mode so far.
        """
    @property
    def params(self) -> NavigatorParams:
        ...
    @property
    def path(self) -> typing.Any:
        ...
    @property
    def path_version(self) -> int:
        ...
    @property
    def plan_result(self) -> PlanResult:
        """
        The local planner's last result, every sample included.
        """
    @property
    def planner(self) -> LocalPlanner:
        ...
    @property
    def record(self) -> CycleRecord:
        ...
    @property
    def tracker(self) -> Tracker:
        ...
def angle_difference(a: typing.SupportsFloat | typing.SupportsIndex, b: typing.SupportsFloat | typing.SupportsIndex) -> float:
    """
    The signed difference a - b in (-pi, pi].
    """
def critic_names() -> list[str]:
    """
    Names of the critics that can be configured.
    """
def dtw(a: typing.Any, b: typing.Any, band: typing.SupportsInt | typing.SupportsIndex = -1) -> float:
    """
    Dynamic time warping between (n, 2) and (m, 2) point sequences: the sum of Euclidean point distances along the optimal warping path (steps (i-1, j), (i, j-1), (i-1, j-1)). band >= 0: Sakoe-Chiba band around the diagonal, in samples (widened where too narrow to connect the ends); -1: none.
    """
def dynamic_window(limits: RobotLimits, current: typing.Any, dt: typing.SupportsFloat | typing.SupportsIndex) -> VelocityWindow:
    """
    Vm ∩ Vd for the current (v, omega).
    """
def inflate(grid: OccupancyGrid, inflation_radius: typing.SupportsFloat | typing.SupportsIndex, terrain: TerrainGrid = None) -> numpy.typing.NDArray[numpy.uint8]:
    """
    (rows, cols) uint8, 1 where a robot of that radius cannot centre: obstacles, cells nearer than the radius to one, and grade-4 terrain.
    """
def mover_fuzzy_controller(resolution: typing.SupportsInt | typing.SupportsIndex = 1001) -> MamdaniEngine:
    """
    The paper's controller with a third input, T ([0, 3] s): the time to the nearest predicted contact with a mover. The paper's rules stand; as a contact nears (T 'near' below 3 s, 'imminent' below 1.5 s) rules adding the delta term one and two lower fire; beta is the paper's. FuzzyWeights(mover_fuzzy_controller()) runs it.
    """
def nearest_names(name: str, known: collections.abc.Sequence[str], count: typing.SupportsInt | typing.SupportsIndex = 3) -> list[str]:
    """
    The names among `known` closest to `name` (edit distance, a dotted or '/'-joined name matched on its last part too), best first: the 'did you mean' of every lookup by name.
    """
def obstacle_density(scan: Scan, window: DetectWindowParams = ...) -> DensityReading:
    """
    Eq. 13: I = S_d / S_w + c^max_gap over the detect window, clamped to [0, 2].
    """
def paper_fuzzy_controller(resolution: typing.SupportsInt | typing.SupportsIndex = 1001) -> MamdaniEngine:
    """
    The paper's weight controller (Section 2.2.2, Tables 3 and 4): inputs I (obstacle density, [0, 2]) and D (path deviation, [0, 5] m), outputs beta ([0, 1]) and delta ([0, 5]), S/M/L uniform triangular partitions, 9 rules.
    """
def path_blocked(path: GlobalPath, position: typing.Any, field: DistanceField, clearance: typing.SupportsFloat | typing.SupportsIndex) -> bool:
    """
    Whether the path ahead of `position` (from its nearest point on) passes closer than `clearance` (m) to an obstacle of `field`.
    """
def planner_preset(name: str) -> PlannerPreset:
    """
    A planner by name: dwa, gdwa, sgdwa, fgdwa, gdwa_high_safety, gdwa_high_similarity; dwb (Nav2's DWB critics).
    """
def points_field(points: typing.Any, resolution: typing.SupportsFloat | typing.SupportsIndex) -> DistanceField:
    """
    A DistanceField of scattered obstacle points on a grid just covering them (None for no point).
    """
def preset_names() -> list[str]:
    ...
def reference_samples(path: ..., robot: typing.Any, v_ref: typing.SupportsFloat | typing.SupportsIndex, dt: typing.SupportsFloat | typing.SupportsIndex, n: typing.SupportsInt | typing.SupportsIndex, sampling: str = 'polyline') -> numpy.typing.NDArray[numpy.float64]:
    """
    (n, 2) reference samples E of the similarity cost (Eq. 9): from the robot's projection onto the path, i * v_ref * dt further along the current segment ('segment') or along the path ('polyline').
    """
def register_python_critic(name: str, cls: typing.Any) -> None:
    """
    Registers a Python critic class under `name` (see fgdwa.register_critic).
    """
def robot_names() -> list[str]:
    ...
def robot_preset(name: str) -> RobotPreset:
    """
    A robot by name: default, jackal.
    """
def rollout(pose: typing.Any, twist: typing.Any, dt: typing.SupportsFloat | typing.SupportsIndex, n_steps: typing.SupportsInt | typing.SupportsIndex) -> numpy.typing.NDArray[numpy.float64]:
    """
    (n_steps, 3) poses of a constant command, each after one more step (the start is not included).
    """
def sample_window(window: VelocityWindow, current: typing.Any, n_v: typing.SupportsInt | typing.SupportsIndex = 21, n_omega: typing.SupportsInt | typing.SupportsIndex = 21) -> numpy.typing.NDArray[numpy.float64]:
    """
    (n_v * n_omega, 2) sampled commands (v, omega), v-major.
    """
def segment_scan(scan: Scan, params: SegmentParams = ..., mask: typing.Any = None) -> list[Cluster]:
    """
    Clusters of the scan's neighbouring hits, each with a fitted disc and box; beams whose mask entry is false are skipped (mask: one flag per beam, or None).
    """
def unicycle_step(pose: typing.Any, twist: typing.Any, dt: typing.SupportsFloat | typing.SupportsIndex) -> Pose2:
    """
    One unicycle step: theta += omega dt, then x += v cos(theta) dt, y += v sin(theta) dt.
    """
def wrap_angle(angle: typing.SupportsFloat | typing.SupportsIndex) -> float:
    """
    The angle in (-pi, pi].
    """
CONTACT_TIME_RANGE: float = 3.0
NO_BAND: int = -1
