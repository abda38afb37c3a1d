"""
fgdwa's C++ core: robot model, grids, collision, dynamic window, critics and planner.
"""
from __future__ import annotations
import collections.abc
import numpy
import numpy.typing
import typing
__all__: list[str] = ['AStarPlanner', 'ClearanceSource', 'Cluster', 'CollisionWorld', 'Controller', 'CriticConfig', 'CriticSense', 'CycleRecord', 'CycleReport', 'DensityReading', 'DetectWindowParams', 'Disc', 'DistanceField', 'FailureReason', 'FgdwaError', 'FieldClearance', 'FixedWeights', 'Footprint', 'FuzzyRule', 'FuzzyVariable', 'FuzzyWeights', 'GlobalPath', 'GlobalPlan', 'GlobalStatus', 'LaserScanner', 'LidarParams', 'LocalPlanner', 'MamdaniEngine', 'MembershipFunction', 'NO_BAND', 'Navigator', 'NavigatorMode', 'NavigatorParams', 'OccupancyGrid', 'OccupancyParams', 'OmplPlanner', 'OrientedBox', 'PathProjection', 'PlanResult', 'PlannerParams', 'PlannerPreset', 'Pose2', 'RejectReason', 'RobotLimits', 'RobotPreset', 'RobotState', 'Scan', 'ScanMap', 'ScoredRollout', 'SegmentParams', 'Status', 'TerrainGrid', 'Track', 'TrackStatus', 'Tracker', 'TrackerParams', 'Twist', 'VelocityWindow', 'WeightPolicy', 'angle_difference', 'critic_names', 'dtw', 'dynamic_window', 'inflate', 'obstacle_density', 'paper_fuzzy_controller', 'path_blocked', 'planner_preset', 'points_field', 'preset_names', 'reference_samples', 'register_python_critic', 'robot_names', 'robot_preset', 'rollout', 'sample_window', 'segment_scan', 'step', 'wrap_angle']
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
    Velocity and acceleration limits of a differential-drive robot (SI units). brake_v / brake_omega of 0 mean: equal to the accelerations.
    """
    def __init__(self, v_min: typing.SupportsFloat | typing.SupportsIndex = 0.0, v_max: typing.SupportsFloat | typing.SupportsIndex = 1.2, omega_max: typing.SupportsFloat | typing.SupportsIndex = 1.0, acc_v: typing.SupportsFloat | typing.SupportsIndex = 1.0, acc_omega: typing.SupportsFloat | typing.SupportsIndex = 2.0, brake_v: typing.SupportsFloat | typing.SupportsIndex = 0.0, brake_omega: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> None:
        ...
    def __repr__(self) -> str:
        ...
    def braking_omega(self) -> float:
        ...
    def braking_v(self) -> float:
        ...
    def validate(self) -> None:
        """
        Raise FgdwaError naming the first bad field.
        """
    @property
    def acc_omega(self) -> float:
        ...
    @acc_omega.setter
    def acc_omega(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def acc_v(self) -> float:
        ...
    @acc_v.setter
    def acc_v(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def brake_omega(self) -> float:
        ...
    @brake_omega.setter
    def brake_omega(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def brake_v(self) -> float:
        ...
    @brake_v.setter
    def brake_v(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def omega_max(self) -> float:
        ...
    @omega_max.setter
    def omega_max(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def v_max(self) -> float:
        ...
    @v_max.setter
    def v_max(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def v_min(self) -> float:
        ...
    @v_min.setter
    def v_min(self, arg1: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
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
    A disc obstacle moving at constant velocity; radius 0 is a point.
    """
    def __init__(self, center: typing.Any, radius: typing.SupportsFloat | typing.SupportsIndex = 0.0, velocity: typing.Any = (0.0, 0.0), growth: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> None:
        """
        growth (m/s): radius added per second ahead, for a predicted obstacle.
        """
    def __repr__(self) -> str:
        ...
    def center_at(self, t: typing.SupportsFloat | typing.SupportsIndex) -> tuple[float, float]:
        ...
    def radius_at(self, t: typing.SupportsFloat | typing.SupportsIndex) -> float:
        """
        The radius t seconds ahead (for a t in the past, never below 0).
        """
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
    def key_nodes(self, min_turn_deg: typing.SupportsFloat | typing.SupportsIndex = 10.0) -> list[int]:
        """
        Indices of the vertices where the path turns by more than min_turn_deg degrees, then the last vertex.
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
    A planar lidar: field of view (deg), beams, max range (m), range noise (m), the probability a beam returns nothing (reads +inf).
    """
    def __init__(self, fov_deg: typing.SupportsFloat | typing.SupportsIndex = 270.0, beams: typing.SupportsInt | typing.SupportsIndex = 541, max_range: typing.SupportsFloat | typing.SupportsIndex = 10.0, noise_std: typing.SupportsFloat | typing.SupportsIndex = 0.0, dropout: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> None:
        ...
    def __repr__(self) -> str:
        ...
    @property
    def angles(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        Beam angles relative to the heading, rad.
        """
    @property
    def beams(self) -> int:
        ...
    @property
    def dropout(self) -> float:
        ...
    @property
    def fov_deg(self) -> float:
        ...
    @property
    def max_range(self) -> float:
        ...
    @property
    def noise_std(self) -> float:
        ...
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
    The detect window: +-half_angle_deg about the heading, radius R (m), base c of Eq. 13.
    """
    def __init__(self, half_angle_deg: typing.SupportsFloat | typing.SupportsIndex = 60.0, radius: typing.SupportsFloat | typing.SupportsIndex = 2.0, base: typing.SupportsFloat | typing.SupportsIndex = 0.5) -> None:
        ...
    @property
    def base(self) -> float:
        ...
    @property
    def half_angle_deg(self) -> float:
        ...
    @property
    def radius(self) -> float:
        ...
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
class AStarPlanner:
    """
    8-connected grid A* (octile heuristic, no corner cutting, inflated obstacles, optional terrain cost = step length x (1 + w_risk x risk[grade])).
    """
    def __init__(self, grid: OccupancyGrid, inflation_radius: typing.SupportsFloat | typing.SupportsIndex = 0.25, simplify: bool = True, terrain: TerrainGrid = None, w_risk: typing.SupportsFloat | typing.SupportsIndex = 1.0, risk: typing.Any = (0.0, 0.5, 1.0, 2.0), unknown_cost: typing.SupportsFloat | typing.SupportsIndex = 0.0) -> None:
        """
        unknown_cost: extra cost per metre through the cells set_unknown() marks (a step costs 1 + unknown_cost times more).
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
    def __init__(self, grid: OccupancyGrid, footprint: Footprint, planner: str = 'RRTstar', time_limit: typing.SupportsFloat | typing.SupportsIndex = 1.0, range: typing.SupportsFloat | typing.SupportsIndex = 1.0, max_iterations: typing.SupportsInt | typing.SupportsIndex = 0, seed: typing.SupportsInt | typing.SupportsIndex = 0, inflation_radius: typing.Any = None, w_length: typing.SupportsFloat | typing.SupportsIndex = 1.0, w_clearance: typing.SupportsFloat | typing.SupportsIndex = 0.5, clearance_reference: typing.SupportsFloat | typing.SupportsIndex = 1.0, terrain: TerrainGrid = None, w_risk: typing.SupportsFloat | typing.SupportsIndex = 1.0, risk: typing.Any = (0.0, 0.5, 1.0, 2.0), simplify: bool = True, interpolation: typing.SupportsFloat | typing.SupportsIndex = 0.1, verbose: bool = False) -> None:
        ...
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
class PlannerParams:
    """
    Parameters of the local planner (SI units).
    """
    def __init__(self, dt: typing.SupportsFloat | typing.SupportsIndex = 0.15, sim_time: typing.SupportsFloat | typing.SupportsIndex = 3.0, n_v: typing.SupportsInt | typing.SupportsIndex = 21, n_omega: typing.SupportsInt | typing.SupportsIndex = 21, normalization: str = 'sum', braking: str = 'discrete', goal_tolerance: typing.SupportsFloat | typing.SupportsIndex = 0.3, critics: typing.Any = None, heading_target: str = 'goal', key_node_angle_deg: typing.SupportsFloat | typing.SupportsIndex = 10.0, key_node_radius: typing.SupportsFloat | typing.SupportsIndex = 1.0, safety_margin: typing.SupportsFloat | typing.SupportsIndex = 0.02, key_node_sight: bool = False, moving_horizon: typing.SupportsFloat | typing.SupportsIndex = 1.0, mover_caution_radius: typing.SupportsFloat | typing.SupportsIndex = 2.0, mover_speed_weight: typing.SupportsFloat | typing.SupportsIndex = 0.5) -> None:
        """
        dt: control period and rollout step (s); sim_time: rollout horizon (s); n_v, n_omega: sample counts; normalization: 'sum', 'minmax' or 'none' (raw terms, as Nav2's DWB adds them); braking: 'discrete' (stop within the free distance with one control period of latency and stepped deceleration) or 'continuous' (Eq. 3 as written); goal_tolerance (m); critics: list of CriticConfig, dicts or (name, weight[, params]) tuples (default: heading 0.5, clearance 0.15, velocity 1.0); heading_target: 'goal' (DWA) or 'key_nodes' (GDWA: the first key node of the global path not yet reached); key_node_angle_deg: turn that makes a vertex a key node; key_node_radius (m): a key node this near is reached; safety_margin (m): a rollout closer than this to an obstacle counts as in contact (never more than the robot's own clearance); key_node_sight: a key node within key_node_radius counts as reached only once the next one is in sight (default False: SPEC 5 as written); moving_horizon (s): a rollout predicted to meet a moving obstacle this soon is rejected, standing still included (0: moving obstacles count only as the braking rule counts them); while a moving obstacle is within mover_caution_radius (m) the velocity critic's weight is multiplied by mover_speed_weight (in [0, 1]; 1: no change).
        """
    def __repr__(self) -> str:
        ...
    @property
    def braking(self) -> str:
        ...
    @property
    def critics(self) -> list[CriticConfig]:
        ...
    @property
    def dt(self) -> float:
        ...
    @property
    def goal_tolerance(self) -> float:
        ...
    @property
    def heading_target(self) -> str:
        ...
    @property
    def key_node_angle_deg(self) -> float:
        ...
    @property
    def key_node_radius(self) -> float:
        ...
    @property
    def key_node_sight(self) -> bool:
        ...
    @property
    def mover_caution_radius(self) -> float:
        ...
    @property
    def mover_speed_weight(self) -> float:
        ...
    @property
    def moving_horizon(self) -> float:
        ...
    @property
    def n_omega(self) -> int:
        ...
    @property
    def n_steps(self) -> int:
        ...
    @property
    def n_v(self) -> int:
        ...
    @property
    def normalization(self) -> str:
        ...
    @property
    def safety_margin(self) -> float:
        ...
    @property
    def sim_time(self) -> float:
        ...
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
    def weights(self, density: typing.SupportsFloat | typing.SupportsIndex, deviation: typing.SupportsFloat | typing.SupportsIndex) -> dict[str, float]:
        """
        {critic name: weight} for obstacle density I and path deviation D (m).
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
    Critics' weights from a Mamdani engine with inputs I and D, each output mapped to a critic.
    """
    def __init__(self, engine: MamdaniEngine = None, output_critics: collections.abc.Mapping[str, str] | None = None) -> None:
        """
        engine: a MamdaniEngine with inputs I and D (default: the paper's); output_critics: {output: critic} (default: beta -> clearance, delta -> similarity).
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
    A robot by name: limits and footprint.
    """
    def __repr__(self) -> str:
        ...
    @property
    def description(self) -> str:
        ...
    @property
    def footprint(self) -> Footprint:
        ...
    @property
    def limits(self) -> RobotLimits:
        ...
    @property
    def name(self) -> str:
        ...
class CycleReport:
    """
    What a control cycle sensed and how it weighed it.
    """
    def __repr__(self) -> str:
        ...
    @property
    def beta(self) -> float:
        """
        Clearance weight used; NaN without that critic.
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
    def sensed_points(self) -> int:
        """
        Lidar hits that neither the map nor the known discs explain.
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
    """
    def __init__(self, hit: typing.SupportsFloat | typing.SupportsIndex = 0.85, miss: typing.SupportsFloat | typing.SupportsIndex = -0.4, clamp_min: typing.SupportsFloat | typing.SupportsIndex = -2.0, clamp_max: typing.SupportsFloat | typing.SupportsIndex = 3.5, occupied: typing.SupportsFloat | typing.SupportsIndex = 0.5, free: typing.SupportsFloat | typing.SupportsIndex = -0.5, range_std: typing.SupportsFloat | typing.SupportsIndex = 0.0, clear_range: typing.SupportsFloat | typing.SupportsIndex = ..., hit_share: typing.SupportsFloat | typing.SupportsIndex = 0.2, clear: bool = True, edge_margin: typing.SupportsFloat | typing.SupportsIndex = 3.0) -> None:
        """
        hit / miss: log-odds added to a hit's cell / to each cell a beam passes; clamp_min, clamp_max: the range a cell's log-odds stays in; a cell turns occupied at `occupied` and free again at `free`; range_std (m): the lidar's range noise (hits placed 2 std beyond the reading, clearing stops 3 std short); clear_range (m): the farthest a beam clears; hit_share: a cell some beams of a scan end in and others pass is hit when at least this share end in it; clear=False: hits only, nothing clears; edge_margin (m): the free margin the map's field keeps past the grid's edge (DistanceField).
        """
    def __repr__(self) -> str:
        ...
    @property
    def clamp_max(self) -> float:
        ...
    @property
    def clamp_min(self) -> float:
        ...
    @property
    def clear(self) -> bool:
        ...
    @property
    def clear_range(self) -> float:
        ...
    @property
    def edge_margin(self) -> float:
        ...
    @property
    def free(self) -> float:
        ...
    @property
    def hit(self) -> float:
        ...
    @property
    def hit_share(self) -> float:
        ...
    @property
    def miss(self) -> float:
        ...
    @property
    def occupied(self) -> float:
        ...
    @property
    def range_std(self) -> float:
        ...
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
    def integrate(self, scan: Scan, keep_hit: typing.Any = None) -> int:
        """
        One scan's evidence (each cell updated once, by the vote of the beams ending and passing in it); keep_hit (one flag per beam) says which hits to mark. Returns how many cells turned occupied or stopped being occupied.
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
    How segment_scan cuts a scan into clusters: breakpoint gap (m, growing by range_gap_factor m per m of range), min_points, max_size (m), min_radius (m) of a fitted disc, range_noise (m) the disc fit assumes.
    """
    def __init__(self, base_gap: typing.SupportsFloat | typing.SupportsIndex = 0.15, range_gap_factor: typing.SupportsFloat | typing.SupportsIndex = 0.03, min_points: typing.SupportsInt | typing.SupportsIndex = 3, max_size: typing.SupportsFloat | typing.SupportsIndex = 1.6, min_radius: typing.SupportsFloat | typing.SupportsIndex = 0.05, range_noise: typing.SupportsFloat | typing.SupportsIndex = 0.03) -> None:
        ...
    def __repr__(self) -> str:
        ...
    @property
    def base_gap(self) -> float:
        ...
    @property
    def max_size(self) -> float:
        ...
    @property
    def min_points(self) -> int:
        ...
    @property
    def min_radius(self) -> float:
        ...
    @property
    def range_gap_factor(self) -> float:
        ...
    @property
    def range_noise(self) -> float:
        ...
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
    Tracker settings: gates (m and std devs), accel_std (m/s^2), measurement_std (m), confirm_hits, lost_time (s), moving test (moving_speed m/s, moving_sigmas, moving_window s, free_margin m), prediction_window (s, velocity fit for prediction), max_speed (m/s), uncertainty_sigmas, max_uncertainty (m).
    """
    def __init__(self, gate: typing.SupportsFloat | typing.SupportsIndex = 1.0, gate_sigmas: typing.SupportsFloat | typing.SupportsIndex = 4.0, accel_std: typing.SupportsFloat | typing.SupportsIndex = 1.5, measurement_std: typing.SupportsFloat | typing.SupportsIndex = 0.03, confirm_hits: typing.SupportsInt | typing.SupportsIndex = 3, lost_time: typing.SupportsFloat | typing.SupportsIndex = 0.5, moving_speed: typing.SupportsFloat | typing.SupportsIndex = 0.1, moving_sigmas: typing.SupportsFloat | typing.SupportsIndex = 2.0, moving_window: typing.SupportsFloat | typing.SupportsIndex = 1.0, free_margin: typing.SupportsFloat | typing.SupportsIndex = 0.1, max_speed: typing.SupportsFloat | typing.SupportsIndex = 3.0, uncertainty_sigmas: typing.SupportsFloat | typing.SupportsIndex = 2.0, max_uncertainty: typing.SupportsFloat | typing.SupportsIndex = 0.3, prediction_window: typing.SupportsFloat | typing.SupportsIndex = 0.6) -> None:
        ...
    def __repr__(self) -> str:
        ...
    @property
    def accel_std(self) -> float:
        ...
    @property
    def confirm_hits(self) -> int:
        ...
    @property
    def free_margin(self) -> float:
        ...
    @property
    def gate(self) -> float:
        ...
    @property
    def gate_sigmas(self) -> float:
        ...
    @property
    def lost_time(self) -> float:
        ...
    @property
    def max_speed(self) -> float:
        ...
    @property
    def max_uncertainty(self) -> float:
        ...
    @property
    def measurement_std(self) -> float:
        ...
    @property
    def moving_sigmas(self) -> float:
        ...
    @property
    def moving_speed(self) -> float:
        ...
    @property
    def moving_window(self) -> float:
        ...
    @property
    def prediction_window(self) -> float:
        ...
    @property
    def uncertainty_sigmas(self) -> float:
        ...
class Track:
    """
    One followed object: constant-velocity Kalman state and its moving label.
    """
    def __repr__(self) -> str:
        ...
    @property
    def age(self) -> float:
        ...
    @property
    def covariance(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (4, 4) covariance of (x, y, vx, vy).
        """
    @property
    def hits(self) -> int:
        ...
    @property
    def id(self) -> int:
        ...
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
class NavigatorParams:
    """
    Replanning and recovery settings of a Navigator (SPEC 13).
    """
    def __init__(self, path_margin: typing.SupportsFloat | typing.SupportsIndex = 0.3, replan_period: typing.SupportsFloat | typing.SupportsIndex = 0.5, stall_time: typing.SupportsFloat | typing.SupportsIndex = 3.0, stall_distance: typing.SupportsFloat | typing.SupportsIndex = 0.1, give_up_length: typing.SupportsFloat | typing.SupportsIndex = 0.6, keep_clear: typing.SupportsFloat | typing.SupportsIndex = 0.3, sensed_close_radius: typing.SupportsFloat | typing.SupportsIndex = 2.0, backup_distance: typing.SupportsFloat | typing.SupportsIndex = 0.3, backup_speed: typing.SupportsFloat | typing.SupportsIndex = 0.2, rotate_limit_deg: typing.SupportsFloat | typing.SupportsIndex = 360.0, wait_time: typing.SupportsFloat | typing.SupportsIndex = 2.0, wait_radius: typing.SupportsFloat | typing.SupportsIndex = 1.5, max_recoveries: typing.SupportsInt | typing.SupportsIndex = 6, progress_reset: typing.SupportsFloat | typing.SupportsIndex = 1.0, record_top_k: typing.SupportsInt | typing.SupportsIndex = 5, occupancy: OccupancyParams = ..., unknown_cost: typing.SupportsFloat | typing.SupportsIndex = 0.0, track_moving: bool = True, segment: SegmentParams = ..., tracker: TrackerParams = ..., learn_obstacles: bool = True, mover_margin: typing.SupportsFloat | typing.SupportsIndex = 0.0, route_around_movers: bool = True, mover_route_horizon: typing.SupportsFloat | typing.SupportsIndex = 1.0, mover_route_lookahead: typing.SupportsFloat | typing.SupportsIndex = 3.0) -> None:
        """
        path_margin: m kept beyond the footprint's radius by the global path where the map allows; replan_period: s between replans for a blocked path; stall_time: s over which less than stall_distance (m) of progress is a stall (0: never); give_up_length: m of path ahead closed to the global planner after a stall, except within keep_clear (m) of the robot and the goal; sensed_close_radius (m): at a stall, the scan's hits the map lacks this near are closed to the global planner too; backup_distance (m) at backup_speed (m/s); rotate_limit_deg: the most a rotation recovery turns; wait_time (s) for a known moving obstacle within wait_radius (m); max_recoveries in a row without progress_reset (m) of progress before Failed; record_top_k: best rollouts kept in each CycleRecord; occupancy: the map built from scans (its range_std is at least the lidar's noise_std); unknown_cost: extra cost per metre of the global path through cells the scans have not observed (0: unknown is free); track_moving: segment and track moving obstacles in the scans, predict them in the planner and keep their hits out of the map (False: every hit is static where it is, the ablation); segment, tracker: their settings; learn_obstacles: with a known map, obstacles the scans find that it lacks join it (False: they reach only the local planner, and the global one at a stall); mover_margin (m): added to a tracked mover's radius; route_around_movers: the global path keeps off the floor each moving obstacle sweeps over the next mover_route_horizon (s) at its predicted velocity, and a sweep within the footprint's inscribed radius of the path's next mover_route_lookahead (m) asks for a new path (False: movers reach only the local planner).
        """
    def __repr__(self) -> str:
        ...
    @property
    def backup_distance(self) -> float:
        ...
    @property
    def backup_speed(self) -> float:
        ...
    @property
    def give_up_length(self) -> float:
        ...
    @property
    def keep_clear(self) -> float:
        ...
    @property
    def learn_obstacles(self) -> bool:
        ...
    @property
    def max_recoveries(self) -> int:
        ...
    @property
    def mover_margin(self) -> float:
        ...
    @property
    def mover_route_horizon(self) -> float:
        ...
    @property
    def mover_route_lookahead(self) -> float:
        ...
    @property
    def occupancy(self) -> OccupancyParams:
        ...
    @property
    def path_margin(self) -> float:
        ...
    @property
    def progress_reset(self) -> float:
        ...
    @property
    def record_top_k(self) -> int:
        ...
    @property
    def replan_period(self) -> float:
        ...
    @property
    def rotate_limit_deg(self) -> float:
        ...
    @property
    def route_around_movers(self) -> bool:
        ...
    @property
    def segment(self) -> SegmentParams:
        ...
    @property
    def sensed_close_radius(self) -> float:
        ...
    @property
    def stall_distance(self) -> float:
        ...
    @property
    def stall_time(self) -> float:
        ...
    @property
    def track_moving(self) -> bool:
        ...
    @property
    def tracker(self) -> TrackerParams:
        ...
    @property
    def unknown_cost(self) -> float:
        ...
    @property
    def wait_radius(self) -> float:
        ...
    @property
    def wait_time(self) -> float:
        ...
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
    def sample(self) -> int:
        ...
    @property
    def total(self) -> float:
        ...
class CycleRecord:
    """
    Everything one Navigator cycle decided.
    """
    def __repr__(self) -> str:
        ...
    @property
    def best(self) -> list[ScoredRollout]:
        ...
    @property
    def beta(self) -> float:
        ...
    @property
    def chosen(self) -> int:
        ...
    @property
    def chosen_rollout(self) -> numpy.typing.NDArray[numpy.float64]:
        ...
    @property
    def command(self) -> Twist:
        ...
    @property
    def critic_vetoes(self) -> list[int]:
        """
        Per critic of the planner (in PlannerParams.critics order): samples it vetoed this cycle.
        """
    @property
    def delta(self) -> float:
        ...
    @property
    def density(self) -> float:
        ...
    @property
    def deviation(self) -> float:
        ...
    @property
    def failure(self) -> FailureReason:
        ...
    @property
    def key_node(self) -> int:
        ...
    @property
    def mode(self) -> NavigatorMode:
        ...
    @property
    def new_cells(self) -> int:
        ...
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
    def state(self) -> RobotState:
        ...
    @property
    def status(self) -> Status:
        ...
    @property
    def target(self) -> tuple[float, float]:
        ...
    @property
    def time(self) -> float:
        ...
    @property
    def times(self) -> dict:
        """
        Wall-clock seconds per stage: map, global, perception, plan.
        """
    @property
    def tracked(self) -> list[Disc]:
        """
        The moving tracks the planner predicted (Discs now, with velocity).
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
    (n, 2) reference samples E of the similarity cost (SPEC 4, Eq. 9): from the robot's projection onto the path, i * v_ref * dt further along the current segment ('segment') or along the path ('polyline').
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
def step(pose: typing.Any, twist: typing.Any, dt: typing.SupportsFloat | typing.SupportsIndex) -> Pose2:
    """
    One unicycle step: theta += omega dt, then x += v cos(theta) dt, y += v sin(theta) dt.
    """
def wrap_angle(angle: typing.SupportsFloat | typing.SupportsIndex) -> float:
    """
    The angle in (-pi, pi].
    """
NO_BAND: int = -1
