#include "fgdwa/world_model.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace fgdwa {

const char* to_string(MapMode mode) {
  switch (mode) {
    case MapMode::Known: return "known";
    case MapMode::Scan: return "scan";
  }
  return "?";
}

namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}
}  // namespace

WorldModel::WorldModel(const OccupancyGrid& map, MapMode mode, const NavigatorParams& params,
                       const LidarParams& lidar, const Footprint& footprint, double edge_margin)
    : params_(params),
      noise_std_(lidar.noise_std),
      range_std_(std::max(params.occupancy.range_std, lidar.noise_std)),
      footprint_(footprint),
      mode_(mode),
      tracker_(params.tracker) {
  OccupancyParams occupancy = params_.occupancy;
  occupancy.range_std = range_std_;
  occupancy.edge_margin = edge_margin;
  if (mode_ == MapMode::Known) {
    known_map_ = std::make_unique<OccupancyGrid>(map);
    planning_map_ = std::make_unique<OccupancyGrid>(map);
    known_field_ = std::make_shared<DistanceField>(map, occupancy.edge_margin);
    has_field_ = true;
    if (params_.learn_obstacles) scan_map_ = std::make_unique<ScanMap>(map, occupancy);
  } else {
    scan_map_ = std::make_unique<ScanMap>(map, occupancy);
  }
}

const OccupancyGrid& WorldModel::map() const { return planning_map_ ? *planning_map_ : scan_map_->grid(); }

double WorldModel::hit_tolerance() const { return 0.5 * map().resolution() + 3.0 * noise_std_; }

const WorldUpdate& WorldModel::update(const ScanFrame* frame, double time, const std::vector<Disc>& discs) {
  Clock::time_point tic = Clock::now();
  update_.movers = discs;
  update_.tracked.clear();
  update_.new_cells = 0;
  if (frame) set_aside_known(*frame);
  if (frame && params_.track_moving) {
    track(*frame, time);
    update_.movers.insert(update_.movers.end(), update_.tracked.begin(), update_.tracked.end());
  }
  update_.tracking_time = seconds_since(tic);

  tic = Clock::now();
  if (scan_map_ && frame) {
    if (field_stale_) field();  // the cells the last scan changed, before this one's
    update_.new_cells = scan_map_->integrate(*frame, &keep_hit_, time);
    if (update_.new_cells) {
      if (known_map_)
        // The known map with what the scans found that it lacks.
        for (const std::size_t i : scan_map_->changed_cells())
          planning_map_->set(i, known_map_->cells()[i] != 0 || scan_map_->grid().cells()[i] != 0);
      has_field_ = true;
      field_stale_ = true;
      ++version_;
    }
  }
  update_.map_time = seconds_since(tic);
  return update_;
}

std::shared_ptr<const DistanceField> WorldModel::field() {
  if (!has_field_) return nullptr;
  if (!known_map_) return scan_map_->field();
  if (field_stale_) {
    // A field someone else still holds stays as they saw it: the update goes to a copy.
    if (!planning_field_ || planning_field_.use_count() > 1)
      planning_field_ = std::make_shared<DistanceField>(planning_field_ ? *planning_field_ : *known_field_);
    planning_field_->update(*planning_map_, scan_map_->changed_cells());
    field_stale_ = false;
  }
  if (planning_field_) return planning_field_;
  return known_field_;
}

std::vector<std::uint8_t> WorldModel::unknown_cells() const {
  std::vector<std::uint8_t> unknown;
  if (!scan_map_ || known_map_) return unknown;
  unknown.resize(scan_map_->states().size());
  for (std::size_t i = 0; i < unknown.size(); ++i)
    unknown[i] = scan_map_->states()[i] == static_cast<std::uint8_t>(CellState::Unknown);
  return unknown;
}

void WorldModel::set_aside_known(const ScanFrame& frame) {
  const std::size_t n = frame.size();
  const double tolerance = hit_tolerance();
  // Only the tracker and the learnt map ask whether a hit is on the known map.
  const bool prior = known_field_ && known_field_->has_obstacles() && (scan_map_ || params_.track_moving);
  // A hit on the known map's obstacles is neither segmented (they are static)
  // nor marked in the scan map (it teaches nothing new, and hits that noise
  // carries past a thin obstacle would thicken it).
  segment_mask_.assign(n, 1);
  if (prior)
    for (std::size_t i = 0; i < n; ++i)
      if (frame.has_hit(i) && known_field_->distance(frame.beam_hits()[i]) <= tolerance) segment_mask_[i] = 0;
  keep_hit_ = segment_mask_;
}

void WorldModel::track(const ScanFrame& frame, double time) {
  // Every hit off the known map's obstacles is segmented, the scan map's
  // settled cells included: a slow mover that is not yet labelled marks its
  // cells scan after scan, and masking them would cut it up and hide it from
  // the tracker. An object cut by the field of view's edge is tracked too; its
  // cluster is occluded, so its centre weighs less in the moving test.
  const double tolerance = hit_tolerance();
  std::vector<Cluster> clusters = segment_scan(frame, params_.segment, &segment_mask_);
  tracker_.update(clusters, time, &frame.scan());
  std::vector<Disc>& tracked = update_.tracked;
  tracked = tracker_.moving_discs();
  // Nothing stands inside the robot: a track there is made of its own surroundings.
  tracked.erase(std::remove_if(tracked.begin(), tracked.end(),
                               [&](const Disc& d) { return footprint_.signed_distance(frame.scan().pose, d.center) <= 0.0; }),
                tracked.end());
  if (tracked.empty()) return;
  for (Disc& d : tracked) d.radius += params_.mover_margin;
  for (std::size_t i = 0; i < frame.size(); ++i) {
    if (!frame.has_hit(i)) continue;
    for (const Disc& d : tracked)
      if ((frame.beam_hits()[i] - d.center).norm() <= d.radius + tolerance) keep_hit_[i] = 0;
  }
}

}  // namespace fgdwa
