#include "fgdwa/route_keeper.hpp"

#include <algorithm>
#include <cmath>

#include "fgdwa/error.hpp"
#include "mover_sweeps.hpp"

namespace fgdwa {

namespace {

// The sweeps of this cycle's moving obstacles that the global path keeps off.
std::vector<detail::SweptDisc> mover_sweeps(const std::vector<Disc>& discs, const NavigatorParams& params) {
  std::vector<detail::SweptDisc> sweeps;
  if (!params.route_around_movers) return sweeps;
  for (const Disc& d : discs)
    if (d.moves()) sweeps.push_back(detail::sweep_of(d, params.mover_route_horizon));
  return sweeps;
}

}  // namespace

RouteKeeper::RouteKeeper(const OccupancyGrid& map, const Footprint& footprint, const NavigatorParams& params,
                         double dt, std::optional<TerrainGrid> terrain)
    : footprint_(footprint),
      params_(params),
      terrain_(std::move(terrain)),
      // A path that keeps a margin beyond the footprint gives the local planner
      // room at the corners; where it closes every way, the footprint's radius;
      // a robot in a tight spot sits inside that band, so last the inscribed radius.
      radii_{footprint.radius() + params.path_margin, footprint.radius(), footprint.inscribed_radius()},
      closed_(static_cast<std::size_t>(map.rows()) * map.cols(), 0),
      replan_cycles_(std::max(1, static_cast<int>(std::lround(params.replan_period / dt)))),
      retry_cycles_(std::max(1, static_cast<int>(std::lround(params.retry_period / dt)))) {}

void RouteKeeper::set_goal(const Vec2& goal) {
  if (unreachable_ && *unreachable_ != goal) unreachable_.reset();
  goal_ = goal;
  path_.reset();
  std::fill(closed_.begin(), closed_.end(), 0);
  cycles_since_replan_ = replan_cycles_;
}

void RouteKeeper::adopt(GlobalPath path) {
  path_ = std::make_shared<const GlobalPath>(std::move(path));
  ++version_;
}

bool RouteKeeper::update(const Vec2& position, bool follow, WorldModel& world, const std::vector<Disc>& movers) {
  ++cycles_since_replan_;
  if (cycles_since_no_path_ < retry_cycles_) ++cycles_since_no_path_;
  if (!follow) return true;
  if (!path_ && unreachable_ && cycles_since_no_path_ < retry_cycles_) return false;
  const bool due = cycles_since_replan_ >= replan_cycles_;
  if (!path_ || replan_now_ || (due && ahead_blocked(position, world, movers))) {
    if (!plan(position, world, movers) && !path_) {
      unreachable_ = goal_;
      cycles_since_no_path_ = 0;
      return false;
    }
  }
  return true;
}

namespace {

// `from` if it lies on the grid; otherwise the grid's nearest point `inset` in
// from its edge (its centre on a grid narrower than twice that).
Vec2 onto_grid(const OccupancyGrid& grid, const Vec2& from, double inset) {
  int row, col;
  if (grid.cell_of(from, row, col)) return from;
  const Vec2 size(grid.cols() * grid.resolution(), grid.rows() * grid.resolution());
  Vec2 entry;
  for (int i = 0; i < 2; ++i) {
    const double lo = grid.origin()[i] + inset, hi = grid.origin()[i] + size[i] - inset;
    entry[i] = lo <= hi ? std::clamp(from[i], lo, hi) : grid.origin()[i] + 0.5 * size[i];
  }
  return entry;
}

}  // namespace

bool RouteKeeper::plan(const Vec2& position, WorldModel& world, const std::vector<Disc>& movers) {
  cycles_since_replan_ = 0;
  replan_now_ = false;
  const OccupancyGrid& base = world.map();
  // Kept open near the robot and the goal, beyond the widest inflation: the
  // path must leave the one and reach the other whatever stands beside them.
  const double keep = radii_.front() + base.resolution();
  // A robot off the map (out of an open side, round a mover) is guided back:
  // the path starts at the map's nearest point that far in, and the robot
  // drives straight there first.
  const Vec2 from = onto_grid(base, position, keep);
  const bool any_closed = std::any_of(closed_.begin(), closed_.end(), [](std::uint8_t c) { return c != 0; });
  const std::vector<detail::SweptDisc> sweeps = mover_sweeps(movers, params_);
  std::optional<OccupancyGrid> with_closed;
  if (any_closed || !sweeps.empty()) {
    std::vector<std::uint8_t> cells = base.cells();
    if (any_closed)
      for (std::size_t i = 0; i < cells.size(); ++i) cells[i] = cells[i] || closed_[i];
    for (const detail::SweptDisc& sweep : sweeps) detail::close_swept_cells(base, sweep, from, goal_, keep, cells);
    with_closed.emplace(base.rows(), base.cols(), base.resolution(), base.origin(), std::move(cells));
  }
  const OccupancyGrid& grid = with_closed ? *with_closed : base;
  std::vector<std::uint8_t> unknown;
  if (params_.unknown_cost > 0.0) unknown = world.unknown_cells();
  const auto ladder = [&](const OccupancyGrid& on) {
    for (double radius : radii_) {
      AStarParams astar;
      astar.inflation_radius = radius;
      astar.unknown_cost = params_.unknown_cost;
      GlobalPlan found;
      try {
        AStarPlanner planner(on, astar, terrain_);
        planner.set_unknown(unknown);
        found = planner.plan(from, goal_);
      } catch (const Error&) {
        continue;  // start or goal in a marked cell: no way from here on this map at this radius
      }
      if (found.status == GlobalStatus::Found) {
        if (from != position) found.path.insert(found.path.begin(), position);
        adopt(GlobalPath(std::move(found.path)));
        return true;
      }
    }
    return false;
  };
  if (ladder(grid)) return true;
  // What the scans found at the goal may be standing there for now (another
  // robot, a person): the way up to it is planned as if it were gone, and the
  // local planner stops short while it stays. A goal inside the given map's
  // obstacles stays refused.
  const OccupancyGrid* given = world.given_map();
  std::vector<std::uint8_t> cells = grid.cells();
  bool opened = false;
  const int reach = static_cast<int>(std::ceil(keep / base.resolution()));
  int goal_row, goal_col;
  if (!base.cell_of(goal_, goal_row, goal_col)) return false;
  for (int r = std::max(0, goal_row - reach); r <= std::min(base.rows() - 1, goal_row + reach); ++r)
    for (int c = std::max(0, goal_col - reach); c <= std::min(base.cols() - 1, goal_col + reach); ++c) {
      const std::size_t i = base.index(r, c);
      if (!cells[i] || (given && given->cells()[i]) || (base.cell_center(r, c) - goal_).norm() > keep) continue;
      cells[i] = 0;
      opened = true;
    }
  if (!opened) return false;
  return ladder(OccupancyGrid(base.rows(), base.cols(), base.resolution(), base.origin(), std::move(cells)));
}

bool RouteKeeper::ahead_blocked(const Vec2& position, WorldModel& world, const std::vector<Disc>& movers) {
  if (!path_) return true;
  if (detail::path_meets_sweeps(*path_, position, mover_sweeps(movers, params_), params_.mover_route_lookahead,
                                footprint_.inscribed_radius(), params_.keep_clear))
    return true;
  const std::shared_ptr<const DistanceField> field = world.field();
  if (!field) return false;
  // The same path on the same map, found clear from here or from farther back: still clear.
  const double from = path_->project(position).arc_length;
  if (clear_check_.map_version == world.version() && clear_check_.path_version == version_ && from >= clear_check_.from)
    return false;
  if (path_blocked(*path_, position, *field, footprint_.inscribed_radius())) return true;
  clear_check_ = ClearCheck{world.version(), version_, from};
  return false;
}

void RouteKeeper::give_up_ahead(const Vec2& position, const std::vector<Vec2>& sensed, const OccupancyGrid& map) {
  if (!path_) return;
  const double s0 = path_->project(position).arc_length;
  const double end = std::min(s0 + params_.give_up_length, path_->length());
  for (double s = s0; s <= end + 1e-9; s += 0.5 * map.resolution()) {
    const Vec2 p = path_->point_at(s);
    if ((p - position).norm() < params_.keep_clear || (p - goal_).norm() < params_.keep_clear) continue;
    int row, col;
    if (map.cell_of(p, row, col)) closed_[map.index(row, col)] = 1;
  }
  for (const Vec2& hit : sensed) {
    int row, col;
    if ((hit - position).norm() <= params_.sensed_close_radius && map.cell_of(hit, row, col))
      closed_[map.index(row, col)] = 1;
  }
}

}  // namespace fgdwa
