#include "fgdwa/mapping.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "fgdwa/error.hpp"
#include "validation.hpp"

namespace fgdwa {

void OccupancyParams::check_relations(const ParamPath& path) const {
  using detail::format_number;
  if (!(clamp_min <= free && free < occupied && occupied <= clamp_max))
    throw Error(path.str() + ": need clamp_min <= free < occupied <= clamp_max, got " + format_number(clamp_min) + " <= " +
                format_number(free) + " < " + format_number(occupied) + " <= " + format_number(clamp_max));
  if (hit < occupied)
    fail_param(path.field("hit"), format_number(hit),
               "must reach the occupied threshold (" + format_number(occupied) + ") so that a first hit marks an unknown cell");
}

const char* to_string(CellState state) {
  switch (state) {
    case CellState::Unknown: return "unknown";
    case CellState::Free: return "free";
    case CellState::Occupied: return "occupied";
  }
  return "?";
}

namespace {
// The free cells of a grid, its size checked before they are made.
std::vector<std::uint8_t> empty_cells(int rows, int cols) {
  detail::require_grid_size(rows, cols);
  return std::vector<std::uint8_t>(static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols), 0);
}
}  // namespace

ScanMap::ScanMap(int rows, int cols, double resolution, Vec2 origin, const OccupancyParams& params)
    : params_(params),
      grid_(rows, cols, resolution, origin, empty_cells(rows, cols)),
      states_(grid_.cells().size(), static_cast<std::uint8_t>(CellState::Unknown)),
      log_odds_(grid_.cells().size(), 0.0f),
      tallies_(grid_.cells().size()),
      listed_(grid_.cells().size(), 0) {
  params_.validate();
}

ScanMap::ScanMap(const OccupancyGrid& like, const OccupancyParams& params)
    : ScanMap(like.rows(), like.cols(), like.resolution(), like.origin(), params) {}

bool ScanMap::cell_index(const Vec2& p, std::size_t& cell) const {
  int row = 0, col = 0;
  if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !grid_.cell_of(p, row, col)) return false;
  cell = grid_.index(row, col);
  return true;
}

int ScanMap::update(std::size_t cell, double delta) {
  float& l = log_odds_[cell];
  l = static_cast<float>(std::clamp(static_cast<double>(l) + delta, params_.clamp_min, params_.clamp_max));
  std::uint8_t& state = states_[cell];
  const auto before = static_cast<CellState>(state);
  CellState after = before;
  if (l >= params_.occupied) after = CellState::Occupied;
  else if (l <= params_.free || before == CellState::Unknown) after = CellState::Free;
  if (before == CellState::Unknown) ++known_;
  state = static_cast<std::uint8_t>(after);
  if (after == before) return 0;
  if (after == CellState::Occupied) {
    grid_.set(cell, true);
    changed_.push_back(cell);
    ++occupied_;
    if (!listed_[cell]) {
      listed_[cell] = 1;
      fading_.push_back(cell);
    }
    return 1;
  }
  if (before == CellState::Occupied) {
    grid_.set(cell, false);
    changed_.push_back(cell);
    --occupied_;
    return -1;
  }
  return 0;
}

// Amanatides and Woo's traversal in cell units, after clipping the segment to
// the layout's box (Liang and Barsky).
template <class Visit>
void ScanMap::traverse(const Vec2& a, const Vec2& b, Visit&& visit) const {
  const double inv = 1.0 / grid_.resolution();
  double x0 = (a.x() - grid_.origin().x()) * inv, y0 = (a.y() - grid_.origin().y()) * inv;
  const double dx = (b.x() - a.x()) * inv, dy = (b.y() - a.y()) * inv;
  const double cols = grid_.cols(), rows = grid_.rows();
  double t0 = 0.0, t1 = 1.0;
  const auto clip = [&](double p, double q) {  // keeps the part where p t <= q
    if (p == 0.0) return q >= 0.0;
    const double r = q / p;
    if (p < 0.0) t0 = std::max(t0, r);
    else t1 = std::min(t1, r);
    return t0 <= t1;
  };
  if (!(clip(-dx, x0) && clip(dx, cols - x0) && clip(-dy, y0) && clip(dy, rows - y0))) return;
  const double sx = x0 + t0 * dx, sy = y0 + t0 * dy;
  int col = std::min(static_cast<int>(std::floor(sx)), grid_.cols() - 1);
  int row = std::min(static_cast<int>(std::floor(sy)), grid_.rows() - 1);
  col = std::max(col, 0);
  row = std::max(row, 0);
  const int step_col = dx > 0 ? 1 : (dx < 0 ? -1 : 0), step_row = dy > 0 ? 1 : (dy < 0 ? -1 : 0);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // Parameter t (along a-b) of the next column and row boundary, and the t between boundaries.
  double next_col = step_col > 0 ? (col + 1 - x0) / dx : (step_col < 0 ? (col - x0) / dx : kInf);
  double next_row = step_row > 0 ? (row + 1 - y0) / dy : (step_row < 0 ? (row - y0) / dy : kInf);
  const double delta_col = step_col ? std::abs(1.0 / dx) : kInf, delta_row = step_row ? std::abs(1.0 / dy) : kInf;
  for (;;) {
    visit(grid_.index(row, col));
    if (std::min(next_col, next_row) >= t1) return;
    if (next_col < next_row) {
      col += step_col;
      next_col += delta_col;
    } else {
      row += step_row;
      next_row += delta_row;
    }
    if (!grid_.in_bounds(row, col)) return;
  }
}

void ScanMap::next_scan() {
  if (++scan_id_ == 0) {  // the stamps wrapped around: start them over
    std::fill(tallies_.begin(), tallies_.end(), Tally{});
    scan_id_ = 1;
  }
  touched_.clear();
  changed_.clear();
}

ScanMap::Tally& ScanMap::tally(std::size_t cell) {
  Tally& t = tallies_[cell];
  if (t.scan != scan_id_) {
    t = Tally{scan_id_, 0, 0};
    touched_.push_back(cell);
  }
  return t;
}

std::size_t ScanMap::integrate(const Scan& scan, const std::vector<std::uint8_t>* keep_hit, double time) {
  return integrate(ScanFrame(scan), keep_hit, time);
}

std::size_t ScanMap::integrate(const ScanFrame& frame, const std::vector<std::uint8_t>* keep_hit, double time) {
  const Scan& scan = frame.scan();
  if (keep_hit && keep_hit->size() != scan.ranges.size())
    throw Error("ScanMap::integrate: keep_hit has " + std::to_string(keep_hit->size()) + " entries for a scan of " +
                std::to_string(scan.ranges.size()) + " beams");
  next_scan();
  // A hit lies on an obstacle's surface, where rounding may put it in the free
  // cell beside; a micrometre further along the beam it is inside. Range
  // noise pushes it further: two standard deviations.
  const double depth = 2.0 * params_.range_std + 1e-6 * grid_.resolution();
  const double short_of_hit = 3.0 * params_.range_std;
  const Vec2 origin(scan.pose.x, scan.pose.y);
  constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  const std::vector<Vec2>& directions = frame.directions();
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    const double r = scan.ranges[i];
    if (std::isnan(r)) continue;
    const Vec2& direction = directions[i];
    std::size_t hit = kNone;
    if (std::isfinite(r) && (!keep_hit || (*keep_hit)[i]) && cell_index(origin + (r + depth) * direction, hit))
      ++tally(hit).hits;
    if (!params_.clear) continue;
    const double reach = std::min(std::isfinite(r) ? r - short_of_hit : scan.max_range, params_.clear_range);
    if (!(reach > 0.0)) continue;
    traverse(origin, origin + reach * direction, [&](std::size_t cell) {
      if (cell != hit) ++tally(cell).passes;
    });
  }
  std::size_t changed = 0;
  for (const std::size_t cell : touched_) {
    const Tally& t = tallies_[cell];
    const bool hit = t.hits > 0 && t.hits >= params_.hit_share * (t.hits + t.passes);
    changed += update(cell, hit ? params_.hit : params_.miss) != 0;
  }
  changed += fade(time);
  return commit(changed);
}

std::size_t ScanMap::fade(double time) {
  if (std::isnan(time) || std::isinf(params_.fade_time)) return 0;
  const double elapsed = std::isnan(faded_at_) ? 0.0 : time - faded_at_;
  faded_at_ = time;
  if (!(elapsed > 0.0)) return 0;
  const float keep = static_cast<float>(std::exp(-elapsed / params_.fade_time));
  std::size_t faded = 0, n = 0;
  for (const std::size_t cell : fading_) {
    if (states_[cell] != static_cast<std::uint8_t>(CellState::Occupied)) {
      listed_[cell] = 0;
      continue;
    }
    fading_[n++] = cell;
    if (tallies_[cell].scan == scan_id_) continue;  // this scan saw it: its evidence is fresh
    float& l = log_odds_[cell];
    l *= keep;
    if (l >= params_.occupied) continue;
    // Below the occupied threshold by fading alone: nothing says what is there any more.
    l = 0.0f;
    states_[cell] = static_cast<std::uint8_t>(CellState::Unknown);
    grid_.set(cell, false);
    changed_.push_back(cell);
    --occupied_;
    --known_;
    listed_[cell] = 0;
    --n;
    ++faded;
  }
  fading_.resize(n);
  return faded;
}

std::size_t ScanMap::mark(const std::vector<Vec2>& points) {
  if (points.size() > static_cast<std::size_t>(limits::kMaxPoints))
    throw Error(detail::describe("points", points.size(), "at most " + std::to_string(limits::kMaxPoints)));
  detail::require_points("points", points.data(), points.size(), limits::kMaxQueryCoordinate);
  next_scan();
  for (const Vec2& p : points) {
    std::size_t cell = 0;
    if (cell_index(p, cell)) ++tally(cell).hits;
  }
  std::size_t added = 0;
  for (const std::size_t cell : touched_) added += update(cell, params_.hit) > 0;
  return commit(added);
}

std::size_t ScanMap::commit(std::size_t changed) {
  // Kept only for a field to update, and no longer than the map: past that a
  // whole comparison costs no more.
  if (field_ && !pending_all_) {
    pending_.insert(pending_.end(), changed_.begin(), changed_.end());
    if (pending_.size() > grid_.cells().size()) {
      pending_.clear();
      pending_all_ = true;
    }
  }
  return changed;
}

std::shared_ptr<const DistanceField> ScanMap::field() {
  if (!field_) {
    field_ = std::make_shared<DistanceField>(grid_, params_.edge_margin);
  } else if (!pending_.empty() || pending_all_) {
    // A field that someone else still holds stays as they saw it: the update goes to a copy.
    if (field_.use_count() > 1) field_ = std::make_shared<DistanceField>(*field_);
    if (pending_all_) field_->update(grid_);
    else field_->update(grid_, pending_);
  }
  pending_.clear();
  pending_all_ = false;
  return field_;
}

bool path_blocked(const GlobalPath& path, const Vec2& position, const DistanceField& field, double clearance) {
  detail::require_query_point("position", position);
  detail::require_magnitude("clearance", clearance, limits::kMaxLength);
  if (!field.has_obstacles()) return false;
  const double spacing = 0.5 * field.grid().resolution();
  const double end = path.length();
  // The field is 1-Lipschitz and the path no shorter than the straight line,
  // so from a point at distance d nothing nearer than `clearance` lies within
  // d - clearance along it: far from obstacles the walk takes long strides.
  // Path lengths are bounded (limits::kMaxPathLength), so s + spacing > s.
  for (double s = path.project(position).arc_length;;) {
    const double d = field.distance(path.point_at(std::min(s, end)));
    if (d < clearance) return true;
    if (s >= end) return false;
    s += std::max(spacing, d - clearance);
  }
}

}  // namespace fgdwa
