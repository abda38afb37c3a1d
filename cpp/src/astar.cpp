#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <queue>
#include <unordered_set>

#include "fgdwa/global_planner.hpp"
#include "validation.hpp"

namespace fgdwa {

const char* to_string(GlobalStatus status) {
  switch (status) {
    case GlobalStatus::Found: return "Found";
    case GlobalStatus::NoPath: return "NoPath";
    case GlobalStatus::Timeout: return "Timeout";
  }
  return "?";
}

std::vector<std::uint8_t> inflate(const OccupancyGrid& grid, double inflation_radius, const TerrainGrid* terrain) {
  detail::require_distance("inflation_radius", inflation_radius);
  if (terrain && !terrain->matches(grid)) throw Error("terrain: its cells must match the occupancy grid's");
  // Grade-4 cells keep the footprint off as obstacles do: the local planner
  // rejects a footprint over them, so a path hugging them could not be followed.
  std::optional<OccupancyGrid> with_impassable;
  if (terrain) {
    std::vector<std::uint8_t> cells = grid.cells();
    for (std::size_t i = 0; i < cells.size(); ++i)
      cells[i] = cells[i] || terrain->grades()[i] >= TerrainGrid::kMaxGrade;
    with_impassable.emplace(grid.rows(), grid.cols(), grid.resolution(), grid.origin(), std::move(cells));
  }
  const OccupancyGrid& obstacles = with_impassable ? *with_impassable : grid;
  // A cell is blocked when its centre lies within inflation_radius of an
  // obstacle cell's square. The squared distance to a square splits into a
  // row part and a column part, each (max(|d| - 1/2, 0) res)^2 for an offset of
  // d cells: so per column, only the nearest obstacle row counts, and only
  // columns within `reach` cells can be near enough. Four bytes per cell, no
  // distance field; the cost grows with cells x reach.
  const int rows = grid.rows(), cols = grid.cols();
  const double res = grid.resolution();
  const int reach = static_cast<int>(std::min<double>(std::ceil(inflation_radius / res + 0.5), std::max(rows, cols)));
  const std::int32_t far = reach + 1;
  // Per cell, rows to the nearest obstacle in its column, capped at `far`.
  std::vector<std::int32_t> column_gap(obstacles.cells().size(), far);
  for (int c = 0; c < cols; ++c) {
    int last = -1;  // the last obstacle row seen going up
    for (int r = 0; r < rows; ++r) {
      if (obstacles.occupied(r, c)) last = r;
      if (last >= 0) column_gap[grid.index(r, c)] = std::min(r - last, far);
    }
    last = -1;
    for (int r = rows - 1; r >= 0; --r) {
      if (obstacles.occupied(r, c)) last = r;
      std::int32_t& gap = column_gap[grid.index(r, c)];
      if (last >= 0) gap = std::min(gap, std::min(last - r, far));
    }
  }
  // Measured as DistanceField::distance measures (cell centres, then the
  // square's half size off each axis), so a centre exactly at the radius falls
  // on the same side as in the planner's field.
  const double half = 0.5 * res;
  // By offsets alone, a centre d columns and g rows from an obstacle cell
  // lies (max(d - 1/2, 0)^2 + max(g - 1/2, 0)^2)^(1/2) res from its square:
  // per column offset, the gaps certainly within the radius and those
  // certainly beyond it, allowing for how placing the centres rounds. Only a
  // gap between the two is measured as below.
  const double largest = std::max(std::abs(grid.origin().x()), std::abs(grid.origin().y())) + (rows + cols) * res;
  const double doubt = 1e-9 + 1e-12 * largest;
  std::vector<std::int32_t> surely_in(static_cast<std::size_t>(reach) + 1, -1), surely_out(static_cast<std::size_t>(reach) + 1, far);
  for (int d = 0; d <= reach; ++d) {
    const double dx = std::max(d * res - half, 0.0);
    for (std::int32_t g = far; g >= 0; --g) {
      const double dy = std::max(g * res - half, 0.0);
      const double nominal = std::sqrt(dx * dx + dy * dy);
      if (nominal < inflation_radius - doubt) {
        surely_in[static_cast<std::size_t>(d)] = g;
        break;
      }
      if (nominal > inflation_radius + doubt) surely_out[static_cast<std::size_t>(d)] = g;
    }
  }
  std::vector<std::uint8_t> blocked(grid.cells().size(), 0);
  // Per row, how many of the columns before each have an obstacle within
  // `reach` rows: a cell whose columns in reach have none is left free at
  // once, as the search below would leave it.
  std::vector<int> near_before(static_cast<std::size_t>(cols) + 1, 0);
  for (int r = 0; r < rows; ++r) {
    for (int q = 0; q < cols; ++q)
      near_before[static_cast<std::size_t>(q) + 1] =
          near_before[static_cast<std::size_t>(q)] + (column_gap[grid.index(r, q)] < far);
    for (int c = 0; c < cols; ++c) {
      if (obstacles.occupied(r, c)) {
        blocked[grid.index(r, c)] = 1;
        continue;
      }
      const int first = std::max(0, c - reach), last = std::min(cols - 1, c + reach);
      if (near_before[static_cast<std::size_t>(last) + 1] == near_before[static_cast<std::size_t>(first)]) continue;
      const Vec2 p = grid.cell_center(r, c);
      const auto within = [&](int row, int col) {
        if (row < 0 || row >= rows || !obstacles.occupied(row, col)) return false;
        const Vec2 o = grid.cell_center(row, col);
        const double dx = std::max(std::abs(p.x() - o.x()) - half, 0.0);
        const double dy = std::max(std::abs(p.y() - o.y()) - half, 0.0);
        return std::sqrt(dx * dx + dy * dy) < inflation_radius;
      };
      for (int q = first; q <= last; ++q) {
        const int gap = column_gap[grid.index(r, q)];
        const std::size_t d = static_cast<std::size_t>(std::abs(c - q));
        if (gap >= far || gap >= surely_out[d]) continue;
        if (gap <= surely_in[d] || within(r - gap, q) || within(r + gap, q)) {
          blocked[grid.index(r, c)] = 1;
          break;
        }
      }
    }
  }
  return blocked;
}

AStarPlanner::AStarPlanner(const OccupancyGrid& grid, const AStarParams& params, std::optional<TerrainGrid> terrain)
    : grid_(grid), params_(params), terrain_(std::move(terrain)) {
  params_.validate();
  blocked_ = inflate(grid_, params_.inflation_radius, terrain_ ? &*terrain_ : nullptr);
}

int AStarPlanner::grade(std::size_t cell) const { return terrain_ ? terrain_->grades()[cell] : 0; }

double AStarPlanner::multiplier(std::size_t cell) const {
  const double terrain = params_.terrain_cost.multiplier(std::min(grade(cell), TerrainGrid::kMaxGrade - 1));
  return !unknown_.empty() && unknown_[cell] ? terrain * (1.0 + params_.unknown_cost) : terrain;
}

void AStarPlanner::set_unknown(std::vector<std::uint8_t> unknown) {
  const std::size_t n = static_cast<std::size_t>(grid_.rows()) * grid_.cols();
  if (!unknown.empty() && unknown.size() != n)
    throw Error("unknown: " + std::to_string(unknown.size()) + " cells for a " + std::to_string(grid_.rows()) + " x " +
                std::to_string(grid_.cols()) + " grid");
  unknown_ = std::move(unknown);
}

bool AStarPlanner::shortcut_clear(const Vec2& a, const Vec2& b, double dearest) const {
  return segment_free(grid_, a, b, [&](int r, int c) {
    const std::size_t i = grid_.index(r, c);
    return !blocked_[i] && multiplier(i) <= dearest;
  });
}

bool segment_free(const OccupancyGrid& layout, const Vec2& a, const Vec2& b,
                  const std::function<bool(int, int)>& free) {
  // Amanatides and Woo's traversal of the cells the segment crosses. Every
  // cell it crosses must be on the grid: both ends first (which also keeps
  // the casts below within int).
  int row0, col0, row1, col1;
  if (!layout.cell_of(a, row0, col0) || !layout.cell_of(b, row1, col1)) return false;
  const double res = layout.resolution();
  const Vec2 p = (a - layout.origin()) / res, q = (b - layout.origin()) / res;
  int col = static_cast<int>(std::floor(p.x())), row = static_cast<int>(std::floor(p.y()));
  const int end_col = static_cast<int>(std::floor(q.x())), end_row = static_cast<int>(std::floor(q.y()));
  const auto ok = [&](int r, int c) { return layout.in_bounds(r, c) && free(r, c); };
  if (!ok(row, col)) return false;
  const Vec2 d = q - p;
  const int step_c = d.x() > 0 ? 1 : -1, step_r = d.y() > 0 ? 1 : -1;
  const double inf = std::numeric_limits<double>::infinity();
  const double delta_c = d.x() != 0.0 ? std::abs(1.0 / d.x()) : inf;
  const double delta_r = d.y() != 0.0 ? std::abs(1.0 / d.y()) : inf;
  double t_c = d.x() != 0.0 ? ((step_c > 0 ? col + 1 - p.x() : p.x() - col) * delta_c) : inf;
  double t_r = d.y() != 0.0 ? ((step_r > 0 ? row + 1 - p.y() : p.y() - row) * delta_r) : inf;
  while (col != end_col || row != end_row) {
    if (std::min(t_c, t_r) > 1.0) break;
    if (std::abs(t_c - t_r) < 1e-12) {
      if (!ok(row, col + step_c) || !ok(row + step_r, col)) return false;
      col += step_c;
      row += step_r;
      t_c += delta_c;
      t_r += delta_r;
    } else if (t_c < t_r) {
      col += step_c;
      t_c += delta_c;
    } else {
      row += step_r;
      t_r += delta_r;
    }
    if (!ok(row, col)) return false;
  }
  return true;
}

bool AStarPlanner::line_of_sight(const Vec2& a, const Vec2& b, int max_grade) const {
  return segment_free(grid_, a, b, [&](int r, int c) {
    const std::size_t i = grid_.index(r, c);
    return !blocked_[i] && grade(i) <= max_grade;
  });
}

GlobalPlan AStarPlanner::plan(const Vec2& start, const Vec2& goal) const {
  const auto tic = std::chrono::steady_clock::now();
  detail::require_point("start", start);
  detail::require_point("goal", goal);
  int sr, sc, gr, gc;
  if (!grid_.cell_of(start, sr, sc))
    throw Error("start (" + std::to_string(start.x()) + ", " + std::to_string(start.y()) + ") lies outside the map");
  if (!grid_.cell_of(goal, gr, gc))
    throw Error("goal (" + std::to_string(goal.x()) + ", " + std::to_string(goal.y()) + ") lies outside the map");
  if (grid_.occupied(sr, sc) || grade(grid_.index(sr, sc)) >= TerrainGrid::kMaxGrade)
    throw Error("start (" + std::to_string(start.x()) + ", " + std::to_string(start.y()) + ") lies inside an obstacle");
  if (grid_.occupied(gr, gc) || grade(grid_.index(gr, gc)) >= TerrainGrid::kMaxGrade)
    throw Error("goal (" + std::to_string(goal.x()) + ", " + std::to_string(goal.y()) + ") lies inside an obstacle");

  const int rows = grid_.rows(), cols = grid_.cols();
  const double res = grid_.resolution();
  const std::size_t n = static_cast<std::size_t>(rows) * cols;
  const std::size_t start_cell = grid_.index(sr, sc), goal_cell = grid_.index(gr, gc);
  double min_multiplier = params_.terrain_cost.multiplier(0);
  for (int g = 1; g < TerrainGrid::kMaxGrade; ++g) min_multiplier = std::min(min_multiplier, params_.terrain_cost.multiplier(g));
  const auto heuristic = [&](int r, int c) {
    const double dr = std::abs(r - gr), dc = std::abs(c - gc);
    return res * min_multiplier * (std::max(dr, dc) + (M_SQRT2 - 1.0) * std::min(dr, dc));
  };
  // A start in the inflated band (a robot close to an obstacle) may leave it:
  // the band's cells within the inflation radius of the start are open to it,
  // the obstacles themselves never.
  std::vector<std::uint8_t> escape;
  if (blocked_[start_cell]) {
    escape.assign(n, 0);
    const int reach = static_cast<int>(std::ceil(params_.inflation_radius / res));
    for (int r = std::max(0, sr - reach); r <= std::min(rows - 1, sr + reach); ++r)
      for (int c = std::max(0, sc - reach); c <= std::min(cols - 1, sc + reach); ++c)
        escape[grid_.index(r, c)] = !grid_.occupied(r, c) &&
                                    (grid_.cell_center(r, c) - start).norm() <= params_.inflation_radius &&
                                    grade(grid_.index(r, c)) < TerrainGrid::kMaxGrade;
  }
  const auto passable = [&](std::size_t i) {
    return !blocked_[i] || i == start_cell || i == goal_cell || (!escape.empty() && escape[i]);
  };

  static const int kDr[8] = {1, -1, 0, 0, 1, 1, -1, -1};
  static const int kDc[8] = {0, 0, 1, -1, 1, -1, 1, -1};
  // The cells one move from `cell` (visit(next, its row, its column, whether
  // diagonal)), as the search moves: a diagonal only between two passable
  // sides. The moves go both ways alike.
  const auto for_each_move = [&](std::size_t cell, auto&& visit) {
    const int r = static_cast<int>(cell / cols), c = static_cast<int>(cell % cols);
    for (int k = 0; k < 8; ++k) {
      const int nr = r + kDr[k], nc = c + kDc[k];
      if (!grid_.in_bounds(nr, nc)) continue;
      const std::size_t next = grid_.index(nr, nc);
      if (!passable(next)) continue;
      if (k >= 4 && (!passable(grid_.index(r, nc)) || !passable(grid_.index(nr, c)))) continue;
      visit(next, nr, nc, k >= 4);
    }
  };
  GlobalPlan plan;
  // A goal walled in at this radius (a mover's sweep or a fresh scan beside
  // it) would have the search sweep all it can reach from the start before
  // failing: the goal's own few cells, walked from the goal, settle that
  // first. The same answer: the moves are the search's, both ways.
  if (goal_cell != start_cell) {
    constexpr std::size_t kGoalPocket = 256;  // cells walked before leaving it to the search
    std::vector<std::size_t> pocket{goal_cell};
    std::unordered_set<std::size_t> seen{goal_cell};
    bool open_out = false;
    for (std::size_t i = 0; i < pocket.size() && !open_out; ++i)
      for_each_move(pocket[i], [&](std::size_t next, int, int, bool) {
        if (open_out || !seen.insert(next).second) return;
        if (next == start_cell || pocket.size() >= kGoalPocket) open_out = true;
        else pocket.push_back(next);
      });
    if (!open_out) {
      plan.planning_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - tic).count();
      return plan;
    }
  }

  struct Node {
    double f, h;
    std::size_t cell;
    bool operator>(const Node& o) const {
      if (f != o.f) return f > o.f;
      if (h != o.h) return h > o.h;
      return cell > o.cell;
    }
  };
  std::vector<double> g(n, std::numeric_limits<double>::infinity());
  std::vector<std::int64_t> parent(n, -1);
  std::vector<std::uint8_t> closed(n, 0);
  std::priority_queue<Node, std::vector<Node>, std::greater<Node>> open;
  g[start_cell] = 0.0;
  open.push({heuristic(sr, sc), heuristic(sr, sc), start_cell});
  bool found = false;
  while (!open.empty()) {
    const Node node = open.top();
    open.pop();
    if (closed[node.cell]) continue;
    closed[node.cell] = 1;
    if (node.cell == goal_cell) {
      found = true;
      break;
    }
    for_each_move(node.cell, [&](std::size_t next, int nr, int nc, bool diagonal) {
      if (closed[next]) return;
      const double length = diagonal ? res * M_SQRT2 : res;
      const double cost = g[node.cell] + length * multiplier(next);
      if (cost < g[next]) {
        g[next] = cost;
        parent[next] = static_cast<std::int64_t>(node.cell);
        const double h = heuristic(nr, nc);
        open.push({cost + h, h, next});
      }
    });
  }

  if (!found) {
    plan.status = GlobalStatus::NoPath;
  } else {
    std::vector<std::size_t> cells;
    for (std::int64_t i = static_cast<std::int64_t>(goal_cell); i >= 0; i = parent[static_cast<std::size_t>(i)])
      cells.push_back(static_cast<std::size_t>(i));
    std::reverse(cells.begin(), cells.end());
    std::vector<Vec2> points;
    std::vector<double> multipliers;
    for (std::size_t i : cells) {
      points.push_back(grid_.cell_center(static_cast<int>(i / cols), static_cast<int>(i % cols)));
      multipliers.push_back(multiplier(i));
    }
    points.front() = start;
    points.back() = goal;
    if (params_.simplify && points.size() > 2) {
      // Greedy shortcut: from each kept vertex, jump as far along the path as the
      // line of sight holds, over cells no dearer (steeper, or unknown where
      // that costs) than those of the stretch it replaces.
      std::vector<Vec2> kept{points.front()};
      std::size_t i = 0;
      while (i + 1 < points.size()) {
        std::size_t best = i + 1;
        double dearest = std::max(multipliers[i], multipliers[i + 1]);
        for (std::size_t j = i + 2; j < points.size(); ++j) {
          dearest = std::max(dearest, multipliers[j]);
          if (!shortcut_clear(points[i], points[j], dearest)) break;
          best = j;
        }
        kept.push_back(points[best]);
        i = best;
      }
      points = std::move(kept);
    }
    plan.status = GlobalStatus::Found;
    plan.path = std::move(points);
    plan.cost = g[goal_cell];
  }
  plan.planning_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - tic).count();
  return plan;
}

}  // namespace fgdwa
