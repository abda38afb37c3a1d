#pragma once
// A map the robot builds as it goes (OctoMap's occupancy update, costmap_2d's
// marking and clearing): every cell holds the log-odds of being occupied. Each
// beam is ray-traced from the sensor to its hit: the cells it passes are
// evidence of free space, the hit's cell of an obstacle, and a beam with no
// return clears only. A spurious hit, or an object that moved away, fades
// after a few scans see through it; a real surface is hit scan after scan.
//
// Range noise is allowed for: a hit is placed two standard deviations beyond
// the reading (a reading short of a surface would otherwise mark the free cell
// in front of it) and a beam clears only up to three short of it.
//
// Lifecycle: construct with the layout of the map to build; integrate() every
// scan; field() when the planners need distances (rebuilt incrementally after
// cells change, whether they turned occupied or free).

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "fgdwa/geometry.hpp"
#include "fgdwa/grid.hpp"
#include "fgdwa/params.hpp"
#include "fgdwa/path.hpp"
#include "fgdwa/perception.hpp"
#include "fgdwa/scan_frame.hpp"

namespace fgdwa {

// The log-odds update of each cell (defaults: OctoMap's probabilities).
struct OccupancyParams {
  double hit = 0.85;        // p = 0.7
  double miss = -0.4;       // p = 0.4
  double clamp_min = -2.0;  // p = 0.12: a free cell turns after 3 hits
  double clamp_max = 3.5;   // p = 0.97: an occupied cell turns free after 10 misses
  double occupied = 0.5;
  double free = -0.5;
  double range_std = 0.0;
  double clear_range = std::numeric_limits<double>::infinity();
  // A surface's cell is where nearly every beam reaching it ends; the free
  // cell before it catches only the few readings that noise puts short,
  // however many beams cross it up close.
  double hit_share = 0.2;
  bool clear = true;
  double edge_margin = DistanceField::kDefaultEdgeMargin;
  double fade_time = std::numeric_limits<double>::infinity();

  static constexpr const char* kName = "occupancy";
  template <class V>
  static void fields(V& v) {
    using P = OccupancyParams;
    // Log-odds are kept as floats: every value stays far inside their range.
    const Bounds log_odds = Bounds::closed(-1e3, 1e3);
    v.real("hit", &P::hit, "", Bounds::positive(1e3), "log-odds added to the cell of a hit");
    v.real("miss", &P::miss, "", Bounds::below(-1e3, 0), "log-odds added to each cell a beam passes (< 0: a pass is evidence of free space)");
    v.real("clamp_min", &P::clamp_min, "", log_odds, "lowest log-odds a cell holds");
    v.real("clamp_max", &P::clamp_max, "", log_odds, "highest log-odds a cell holds");
    v.real("occupied", &P::occupied, "", log_odds, "a cell at or above this log-odds turns occupied");
    v.real("free", &P::free, "", log_odds, "at or below this an occupied cell turns free (between free and occupied it keeps its state)");
    v.real("range_std", &P::range_std, "m", Bounds::at_least(0), "the lidar's range noise: hits placed 2 std beyond, clearing stops 3 std short");
    v.real("clear_range", &P::clear_range, "m", Bounds::at_least(0).or_infinite(), "the farthest a beam clears (inf: no limit)");
    v.real("hit_share", &P::hit_share, "", Bounds::positive(1), "a cell some beams of a scan end in and others pass is hit when at least this share end in it");
    v.flag("clear", &P::clear, "beams clear the cells they pass (false: hits only, for static worlds)");
    v.real("edge_margin", &P::edge_margin, "m", Bounds::at_least(0), "the free margin the map's distance field keeps past the grid's edge");
    v.real("fade_time", &P::fade_time, "s", Bounds::positive(limits::kMaxHorizon).or_infinite(), "time constant with which an occupied cell no beam reaches fades toward unknown; it is unknown again once below occupied (inf: never fades; 20 s lets what drift smeared go)");
  }
  // clamp_min <= free < occupied <= clamp_max, hit >= occupied.
  void check_relations(const ParamPath& path) const;
  void validate() const { validate_params(*this); }
};

enum class CellState : std::uint8_t { Unknown, Free, Occupied };
const char* to_string(CellState state);

// Threads: one writer; nothing else may use the map while integrate(), mark()
// or field() run. A field it returned never changes while someone holds it
// (field() updates a copy then), so it may be shared with other threads.
class ScanMap {
 public:
  ScanMap(int rows, int cols, double resolution, Vec2 origin, const OccupancyParams& params = {});
  // An empty map with the layout of `like`.
  explicit ScanMap(const OccupancyGrid& like, const OccupancyParams& params = {});

  // One scan's evidence: each cell is updated at most once per scan, by the
  // vote of the beams ending and passing in it (hit_share). `keep_hit` (one entry per beam, or null for all)
  // says which beams' hits to mark: a beam whose hit belongs to a moving
  // obstacle still clears the cells before it. Hits outside the layout are
  // dropped, and beams are clipped to it. Returns how many cells turned
  // occupied or stopped being occupied.
  // `time` (s; NaN: none) lets the occupied cells no beam of this scan
  // reached fade since the last scan with a time (fade_time): what a wrong
  // pose once marked where the robot no longer looks does not stay for good.
  std::size_t integrate(const Scan& scan, const std::vector<std::uint8_t>* keep_hit = nullptr,
                        double time = std::numeric_limits<double>::quiet_NaN());
  // The same for a scan already taken apart once this cycle.
  std::size_t integrate(const ScanFrame& frame, const std::vector<std::uint8_t>* keep_hit = nullptr,
                        double time = std::numeric_limits<double>::quiet_NaN());
  // One hit on each cell holding these points; returns how many cells turned occupied.
  std::size_t mark(const std::vector<Vec2>& points);

  // The map so far: occupied cells are obstacles, unknown and free cells are not.
  const OccupancyGrid& grid() const { return grid_; }
  // Its distance field, brought up to date on the first call after changes
  // (incrementally: equal to a fresh build of grid()). A field returned
  // earlier never changes: while anyone still holds it, the update goes to a
  // copy; otherwise it is made in place.
  std::shared_ptr<const DistanceField> field();
  // The cells (grid indices) that turned occupied or stopped being occupied
  // in the last integrate() or mark().
  const std::vector<std::size_t>& changed_cells() const { return changed_; }
  std::size_t occupied_count() const { return occupied_; }
  // Cells observed at least once.
  std::size_t known_count() const { return known_; }
  const OccupancyParams& params() const { return params_; }
  CellState state(int row, int col) const { return static_cast<CellState>(states_[grid_.index(row, col)]); }
  float log_odds(int row, int col) const { return log_odds_[grid_.index(row, col)]; }
  // Row-major, one CellState per cell.
  const std::vector<std::uint8_t>& states() const { return states_; }
  const std::vector<float>& log_odds() const { return log_odds_; }

 private:
  // Adds `delta` to the cell's log-odds; returns whether it turned occupied (+1), stopped being occupied (-1) or neither.
  int update(std::size_t cell, double delta);
  // Calls visit(cell) for the cells the segment a-b crosses, in order, clipped to the layout.
  template <class Visit>
  void traverse(const Vec2& a, const Vec2& b, Visit&& visit) const;
  bool cell_index(const Vec2& p, std::size_t& cell) const;
  // Starts a new update round: each cell is updated at most once in it.
  void next_scan();
  // Fades the occupied cells this scan did not reach by exp(-elapsed / fade_time);
  // returns how many turned unknown.
  std::size_t fade(double time);
  // Publishes the changed cells in grid(); returns `changed`.
  std::size_t commit(std::size_t changed);

  OccupancyParams params_;
  OccupancyGrid grid_;
  std::vector<std::uint8_t> states_;
  std::vector<float> log_odds_;
  // Per cell, the last scan that reached it and that scan's beams ending and
  // passing in it: one update per cell and scan, decided by their vote.
  struct Tally {
    std::uint32_t scan = 0, hits = 0, passes = 0;
  };
  Tally& tally(std::size_t cell);
  std::vector<Tally> tallies_;
  std::uint32_t scan_id_ = 0;
  std::vector<std::size_t> touched_;
  std::size_t occupied_ = 0, known_ = 0;
  std::vector<std::size_t> changed_;  // cells that flipped in the last integrate() or mark()
  std::vector<std::size_t> fading_;   // the cells that may be occupied (each listed once, per listed_)
  std::vector<std::uint8_t> listed_;
  double faded_at_ = std::numeric_limits<double>::quiet_NaN();  // s, the last scan's time
  std::vector<std::size_t> pending_;  // cells that flipped since field() last ran
  bool pending_all_ = false;          // too many to list: compare every cell
  std::shared_ptr<DistanceField> field_;
};

// Whether the path ahead of `position` passes closer than `clearance` to an
// obstacle of `field`: the path from its point nearest `position` onward,
// checked every half cell. The part behind the robot does not count.
bool path_blocked(const GlobalPath& path, const Vec2& position, const DistanceField& field, double clearance);

}  // namespace fgdwa
