"""Moving-obstacle fields in the style of DynaBARN (Nair et al. 2022): a
walled room, a start and a goal about 9 m apart, discs moving along random
smooth routes across the robot's way, and a few boxes the map does not show.

``generate_field(level, seed)`` makes one field as a scenario document (a dict
in the YAML scenario format of docs/scenarios.md), the same for the same
(level, seed) on any machine; ``write_field`` writes it to a file that
``fgdwa run FILE`` opens. The movers are unknown to the planner (``known:
false``): it sees them only through its lidar.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import yaml

from fgdwa._core import FgdwaError, robot_preset
from fgdwa.file_limits import short_repr

FIELD_SIZE = (12.0, 8.0)  # m, the room's outer size; its walls are one cell thick
RESOLUTION = 0.1  # m per cell
WALL = RESOLUTION  # m, wall thickness
START_X, GOAL_X = 1.5, 10.5  # m
END_Y_RANGE = (2.5, 5.5)  # m, where the start and the goal lie across the room
DISC_RADIUS_RANGE = (0.3, 0.5)  # m
CROSSING_RANGE = (0.2, 0.8)  # where a route crosses the start-goal line, as a share of its length
END_CLEARANCE = 0.5  # m kept between the robot at its start or goal and any disc anywhere on its route
BOXES = 3  # static boxes missing from the map
BOX_SIZE_RANGE = (0.3, 0.8)  # m, each side
BOX_END_CLEARANCE = 1.0  # m between a box and the start or the goal
BOX_ROUTE_CLEARANCE = 0.1  # m between a box and a disc on its route
BOX_GAP = 1.0  # m at least between two boxes, so that each stands alone
TIME_LIMIT = 60.0  # s of simulated time
PRESET_DT = 0.15  # s, the control period of every planner preset
# s, the rollout horizon of every planner on these fields. Among movers a 3 s
# rollout is mostly prediction: 1.5 s keeps what the planner scores close to
# what it can know (fgdwa, medium seeds 0-29: success 0.57 at 3 s, 0.70 at 1-2 s).
ROLLOUT_TIME = 1.5
LIDAR = {"fov_deg": 270.0, "beams": 541, "max_range": 10.0}
NOISE_STD = 0.03  # m, lidar range noise
DROPOUT = 0.01  # probability a lidar beam returns nothing
MAX_TRIES = 1000  # draws of one disc's route or one box before the field is given up as impossible


@dataclass(frozen=True)
class Level:
    discs: int
    speed: tuple  # (low, high) m/s


LEVELS = {
    "easy": Level(discs=2, speed=(0.2, 0.4)),
    "medium": Level(discs=4, speed=(0.3, 0.6)),
    "hard": Level(discs=6, speed=(0.4, 0.8)),
}


def check_level(level) -> str:
    if level not in LEVELS:
        raise FgdwaError(f"level = {short_repr(level)}: expected one of {', '.join(LEVELS)}")
    return level


def check_field_seed(seed) -> int:
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise FgdwaError(f"seed = {short_repr(seed)}: must be an integer >= 0")
    return int(seed)


def field_name(level: str, seed: int) -> str:
    return f"dynamic_{level}_{seed}"


def _round(values, digits: int = 3) -> list:
    return [round(float(v), digits) for v in values]


def _segment_distance(points: np.ndarray, p) -> float:
    """Distance from the point ``p`` to the polyline ``points`` ((k, 2))."""
    p = np.asarray(p, dtype=float)
    a, b = points[:-1], points[1:]
    ab = b - a
    length_sq = np.maximum(np.sum(ab * ab, axis=1), 1e-12)
    f = np.clip(np.sum((p - a) * ab, axis=1) / length_sq, 0.0, 1.0)
    closest = a + f[:, None] * ab
    return float(np.min(np.hypot(*(closest - p).T)))


def closed_route(waypoints, mode: str) -> np.ndarray:
    """The polyline a mover travels: a loop comes back to its first point."""
    points = np.asarray(waypoints, dtype=float)
    return np.vstack([points, points[:1]]) if mode == "loop" else points


def _draw_route(rng: np.random.Generator, start: np.ndarray, goal: np.ndarray, radius: float) -> tuple:
    """(waypoints, mode) of one route crossing the start-goal line."""
    way = goal - start
    along = way / np.hypot(*way)
    across = np.array([-along[1], along[0]])
    crossing = start + rng.uniform(*CROSSING_RANGE) * way
    if rng.random() < 0.5:
        # Back and forth across the way, bent once so that it crosses at a slant.
        tilt = math.radians(rng.uniform(-35.0, 35.0))
        direction = math.cos(tilt) * across + math.sin(tilt) * along
        half = rng.uniform(1.5, 3.0)
        bend = crossing + rng.uniform(-0.6, 0.6) * along
        points = np.array([crossing - half * direction, bend, crossing + half * direction])
        return points, "back_and_forth"
    # A loop round an ellipse stretched across the way: it crosses it twice a lap.
    a, b = rng.uniform(0.6, 1.5), rng.uniform(1.2, 2.8)
    tilt = math.radians(rng.uniform(-25.0, 25.0))
    u = math.cos(tilt) * along + math.sin(tilt) * across
    w = -math.sin(tilt) * along + math.cos(tilt) * across
    angles = np.linspace(0.0, 2.0 * math.pi, 12, endpoint=False) + rng.uniform(0.0, 2.0 * math.pi)
    if rng.random() < 0.5:
        angles = angles[::-1]
    points = crossing + np.outer(a * np.cos(angles), u) + np.outer(b * np.sin(angles), w)
    return points, "loop"


def _route_fits(points: np.ndarray, mode: str, radius: float, ends: list, robot_radius: float) -> bool:
    width, height = FIELD_SIZE
    margin = WALL + radius + 0.05
    if np.any(points[:, 0] < margin) or np.any(points[:, 0] > width - margin) or \
            np.any(points[:, 1] < margin) or np.any(points[:, 1] > height - margin):
        return False
    route = closed_route(points, mode)
    return all(_segment_distance(route, end) >= radius + robot_radius + END_CLEARANCE for end in ends)


def _box_distance(box, point) -> float:
    x0, y0, x1, y1 = box
    dx = max(x0 - point[0], 0.0, point[0] - x1)
    dy = max(y0 - point[1], 0.0, point[1] - y1)
    return math.hypot(dx, dy)


def _boxes_apart(a, b, gap: float) -> bool:
    """Whether two boxes are at least ``gap`` apart along x or along y."""
    return max(a[0] - b[2], b[0] - a[2], a[1] - b[3], b[1] - a[3]) >= gap


def _box_route_distance(box, route: np.ndarray) -> float:
    """A lower bound of the distance from a box to a polyline, sampled densely
    enough (every 2 cm) that it errs by at most a centimetre."""
    pieces = []
    for a, b in zip(route[:-1], route[1:]):
        n = max(2, int(math.ceil(np.hypot(*(b - a)) / 0.02)) + 1)
        pieces.append(a + np.linspace(0.0, 1.0, n)[:, None] * (b - a))
    samples = np.vstack(pieces)
    return min(_box_distance(box, p) for p in samples) - 0.01


def _draw_box(rng: np.random.Generator, start: np.ndarray, goal: np.ndarray, spread: float) -> list:
    """[x0, y0, x1, y1] on the cell grid, about ``spread`` metres from the start-goal line."""
    w, h = rng.uniform(*BOX_SIZE_RANGE, size=2)
    x = rng.uniform(START_X + 1.5, GOAL_X - 1.5)
    line_y = start[1] + (x - start[0]) / (goal[0] - start[0]) * (goal[1] - start[1])
    y = float(np.clip(line_y + rng.normal(0.0, spread), 1.0, FIELD_SIZE[1] - 1.0))
    snap = lambda v: round(round(v / RESOLUTION) * RESOLUTION, 3)  # noqa: E731
    x0, y0 = snap(x - w / 2), snap(y - h / 2)
    return [x0, y0, snap(max(x0 + RESOLUTION, x + w / 2)), snap(max(y0 + RESOLUTION, y + h / 2))]


def generate_field(level: str, seed: int, noise_std: float = NOISE_STD, dropout: float = DROPOUT) -> dict:
    """The scenario document of field ``seed`` of ``level`` (see the module's
    docstring). ``noise_std`` (m) and ``dropout`` go into its variability: the
    lidar every run of it senses with."""
    level = check_level(level)
    seed = check_field_seed(seed)
    if not (isinstance(noise_std, (int, float)) and math.isfinite(noise_std) and noise_std >= 0):
        raise FgdwaError(f"noise_std = {short_repr(noise_std)}: must be a finite number >= 0 (m)")
    if not (isinstance(dropout, (int, float)) and math.isfinite(dropout) and 0 <= dropout < 1):
        raise FgdwaError(f"dropout = {short_repr(dropout)}: must be in [0, 1) (a probability)")
    spec = LEVELS[level]
    rng = np.random.default_rng([seed, list(LEVELS).index(level)])
    robot = robot_preset("default")
    robot_radius = robot.footprint.radius
    start = np.array([START_X, rng.uniform(*END_Y_RANGE)])
    goal = np.array([GOAL_X, rng.uniform(*END_Y_RANGE)])
    start, goal = np.array(_round(start)), np.array(_round(goal))
    heading = math.degrees(math.atan2(*(goal - start)[::-1]))

    movers = []
    for _ in range(spec.discs):
        for _ in range(MAX_TRIES):
            radius = round(rng.uniform(*DISC_RADIUS_RANGE), 2)
            points, mode = _draw_route(rng, start, goal, radius)
            points = np.array([_round(p) for p in points])
            if _route_fits(points, mode, radius, [start, goal], robot_radius):
                break
        else:
            raise FgdwaError(f"dynamic field {level} seed {seed}: no route fits after {MAX_TRIES} draws")
        speed = round(rng.uniform(*spec.speed), 3)
        movers.append({"radius": radius, "waypoints": points.tolist(), "speed": speed, "mode": mode, "known": False})

    boxes = []
    routes = [(closed_route(m["waypoints"], m["mode"]), m["radius"]) for m in movers]
    for _ in range(BOXES):
        for tries in range(MAX_TRIES):
            # Near the robot's way first; farther out where the routes leave no room there.
            box = _draw_box(rng, start, goal, spread=1.0 + tries / 100)
            if all(_box_distance(box, end) >= BOX_END_CLEARANCE + robot_radius for end in (start, goal)) and \
                    all(_boxes_apart(box, other, BOX_GAP) for other in boxes) and \
                    all(_box_route_distance(box, route) >= radius + BOX_ROUTE_CLEARANCE for route, radius in routes) \
                    and _passable(boxes + [box], start, goal, robot_radius):
                break
        else:
            raise FgdwaError(f"dynamic field {level} seed {seed}: no box fits after {MAX_TRIES} draws")
        boxes.append(box)

    limits = robot.limits
    return {
        "name": field_name(level, seed),
        "description": f"DynaBARN-style field, level {level} ({spec.discs} discs at {spec.speed[0]:g}-"
                       f"{spec.speed[1]:g} m/s, unknown to the planner), seed {seed}; {len(boxes)} boxes "
                       f"missing from the map.",
        "map": {"size": list(FIELD_SIZE), "resolution": RESOLUTION, "border": True},
        "unknown_obstacles": boxes,
        "moving_obstacles": movers,
        "start": [float(start[0]), float(start[1]), round(heading, 2)],
        "goal": [float(goal[0]), float(goal[1])],
        "robot": {"limits": {name: getattr(limits, name) for name in ("v_max", "omega_max", "acc_v", "acc_omega")},
                  "footprint": {"radius": robot_radius}},
        "planner": {"preset": "fgdwa", "overrides": {"sim_time": ROLLOUT_TIME}},
        "lidar": dict(LIDAR),
        "variability": {"start_xy_std": 0.05, "start_theta_std_deg": 3.0, "mover_phase": True,
                        "lidar_noise_std": float(noise_std), "lidar_dropout": float(dropout)},
        "max_steps": int(round(TIME_LIMIT / PRESET_DT)),
    }


def _passable(boxes: list, start, goal, robot_radius: float) -> bool:
    """Whether A* finds a way from start to goal round the walls and the boxes,
    kept the robot's radius + 0.3 m away from them."""
    from fgdwa._core import GlobalStatus, OccupancyGrid
    from fgdwa.global_planning import plan_global

    cols, rows = (int(round(v / RESOLUTION)) for v in FIELD_SIZE)
    cells = np.zeros((rows, cols), dtype=np.uint8)
    cells[0, :] = cells[-1, :] = cells[:, 0] = cells[:, -1] = 1
    for x0, y0, x1, y1 in boxes:
        c0, c1 = int(round(x0 / RESOLUTION)), int(round(x1 / RESOLUTION))
        r0, r1 = int(round(y0 / RESOLUTION)), int(round(y1 / RESOLUTION))
        cells[r0:max(r1, r0 + 1), c0:max(c1, c0 + 1)] = 1
    plan = plan_global(OccupancyGrid(cells, RESOLUTION, (0.0, 0.0)), start, goal, inflation_radius=robot_radius + 0.3)
    return plan.status == GlobalStatus.Found


def field_yaml(document: dict, command: str = "") -> str:
    """The field as YAML text, headed by a comment saying how it was made."""
    head = f"# {document['name']}: made by `{command}`\n" if command else f"# {document['name']}\n"
    head += "# Units: metres, seconds, degrees for headings (the format: docs/scenarios.md).\n"
    return head + yaml.safe_dump(document, sort_keys=False, default_flow_style=None, width=110)


def write_field(document: dict, path, command: str = "") -> Path:
    path = Path(path)
    if path.parent != Path(""):
        path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(field_yaml(document, command))
    return path
