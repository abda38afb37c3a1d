#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <sstream>

#include "convert.hpp"
#include "fgdwa/tracking.hpp"

namespace py = pybind11;
using namespace fgdwa;
using namespace fgdwa::py_convert;

namespace {

py::tuple pair(const Vec2& v) { return py::make_tuple(v.x(), v.y()); }

}  // namespace

void init_tracking(py::module_& m) {
  const SegmentParams sd;
  py::class_<SegmentParams>(m, "SegmentParams",
                            "How segment_scan cuts a scan into clusters: breakpoint gap (m, growing by "
                            "range_gap_factor m per m of range), min_points, max_size (m), min_radius (m) of a "
                            "fitted disc, range_noise (m) the disc fit assumes.")
      .def(py::init([](FloatArg base_gap, FloatArg range_gap_factor, IntArg min_points, FloatArg max_size,
                       FloatArg min_radius, FloatArg range_noise) {
             SegmentParams p{to_float(base_gap, "base_gap"),
                             to_float(range_gap_factor, "range_gap_factor"),
                             to_int<int>(min_points, "segment min_points", 1, static_cast<int>(limits::kMaxBeams)),
                             to_float(max_size, "max_size"),
                             to_float(min_radius, "min_radius"),
                             to_float(range_noise, "range_noise")};
             p.validate();
             return p;
           }),
           py::arg("base_gap") = sd.base_gap, py::arg("range_gap_factor") = sd.range_gap_factor,
           py::arg("min_points") = sd.min_points, py::arg("max_size") = sd.max_size,
           py::arg("min_radius") = sd.min_radius, py::arg("range_noise") = sd.range_noise)
      .def_readonly("base_gap", &SegmentParams::base_gap)
      .def_readonly("range_gap_factor", &SegmentParams::range_gap_factor)
      .def_readonly("min_points", &SegmentParams::min_points)
      .def_readonly("max_size", &SegmentParams::max_size)
      .def_readonly("min_radius", &SegmentParams::min_radius)
      .def_readonly("range_noise", &SegmentParams::range_noise)
      .def("__repr__", [](const SegmentParams& p) {
        std::ostringstream s;
        s << "SegmentParams(base_gap=" << p.base_gap << ", range_gap_factor=" << p.range_gap_factor
          << ", min_points=" << p.min_points << ", max_size=" << p.max_size << ", min_radius=" << p.min_radius
          << ", range_noise=" << p.range_noise << ")";
        return s.str();
      });

  py::class_<OrientedBox>(m, "OrientedBox", "A box along the principal axes of a cluster's hits.")
      .def_property_readonly("center", [](const OrientedBox& b) { return pair(b.center); })
      .def_property_readonly("half_extents", [](const OrientedBox& b) { return pair(b.half_extents); },
                             "m, along the major then the minor axis.")
      .def_readonly("angle", &OrientedBox::angle, "rad, of the major axis.")
      .def("__repr__", [](const OrientedBox& b) {
        std::ostringstream s;
        s << "OrientedBox(center=(" << b.center.x() << ", " << b.center.y() << "), half_extents=("
          << b.half_extents.x() << ", " << b.half_extents.y() << "), angle=" << b.angle << ")";
        return s.str();
      });

  py::class_<Cluster>(m, "Cluster",
                      "Neighbouring hits of one scan and the disc fitted to them (its centre behind the near side "
                      "the lidar sees).")
      .def(py::init([](py::handle center, FloatArg radius, bool occluded) {
             Cluster c;
             c.center = to_vec2(center, "center");
             c.radius = to_float(radius, "radius");
             c.occluded = occluded;
             c.points = {c.center};
             c.validate();
             return c;
           }),
           py::arg("center"), py::arg("radius") = 0.3, py::arg("occluded") = false,
           "A cluster of one point at its centre, e.g. to feed a Tracker detections made elsewhere.")
      .def_property_readonly("points", [](const Cluster& c) { return points_array(c.points); }, "(n, 2) hits, m.")
      .def_readonly("first_beam", &Cluster::first_beam)
      .def_readonly("last_beam", &Cluster::last_beam)
      .def_property_readonly("center", [](const Cluster& c) { return pair(c.center); })
      .def_readonly("radius", &Cluster::radius)
      .def_readonly("box", &Cluster::box)
      .def_readonly("occluded", &Cluster::occluded,
                    "A beam beside an end hit something nearer, or an end is the field of view's.")
      .def("__repr__", [](const Cluster& c) {
        std::ostringstream s;
        s << "Cluster(" << c.points.size() << " points, center=(" << c.center.x() << ", " << c.center.y()
          << "), radius=" << c.radius << (c.occluded ? ", occluded" : "") << ")";
        return s.str();
      });

  m.def(
      "segment_scan",
      [](const Scan& scan, const SegmentParams& params, py::object mask) {
        if (mask.is_none()) return segment_scan(scan, params);
        const auto a = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(mask);
        if (!a || a.ndim() != 1) throw Error("mask: expected a one-dimensional array of flags");
        const std::vector<std::uint8_t> flags(a.data(), a.data() + a.size());
        return segment_scan(scan, params, &flags);
      },
      py::arg("scan"), py::arg("params") = sd, py::arg("mask") = py::none(),
      "Clusters of the scan's neighbouring hits, each with a fitted disc and box; beams whose mask entry is "
      "false are skipped (mask: one flag per beam, or None).");

  py::enum_<TrackStatus> track_status_enum(m, "TrackStatus", "Where a track is in its life.");
  track_status_enum
      .value("Tentative", TrackStatus::Tentative)
      .value("Confirmed", TrackStatus::Confirmed)
      .value("Lost", TrackStatus::Lost);
  refuse_unnamed_values(track_status_enum);

  const TrackerParams td;
  py::class_<TrackerParams>(m, "TrackerParams",
                            "Tracker settings: gates (m and std devs), accel_std (m/s^2), measurement_std (m), "
                            "confirm_hits, lost_time (s), moving test (moving_speed m/s, moving_sigmas, "
                            "moving_window s, free_margin m), prediction_window (s, velocity fit for prediction), max_speed (m/s), "
                            "uncertainty_sigmas, max_uncertainty (m).")
      .def(py::init([](FloatArg gate, FloatArg gate_sigmas, FloatArg accel_std, FloatArg measurement_std,
                       IntArg confirm_hits, FloatArg lost_time, FloatArg moving_speed, FloatArg moving_sigmas,
                       FloatArg moving_window, FloatArg free_margin, FloatArg max_speed, FloatArg uncertainty_sigmas,
                       FloatArg max_uncertainty, FloatArg prediction_window) {
             TrackerParams p{to_float(gate, "gate"),
                             to_float(gate_sigmas, "gate_sigmas"),
                             to_float(accel_std, "accel_std"),
                             to_float(measurement_std, "measurement_std"),
                             to_int<int>(confirm_hits, "tracker confirm_hits", 1, static_cast<int>(limits::kMaxEventCount)),
                             to_float(lost_time, "lost_time"),
                             to_float(moving_speed, "moving_speed"),
                             to_float(moving_sigmas, "moving_sigmas"),
                             to_float(moving_window, "moving_window"),
                             to_float(prediction_window, "prediction_window"),
                             to_float(free_margin, "free_margin"),
                             to_float(max_speed, "max_speed"),
                             to_float(uncertainty_sigmas, "uncertainty_sigmas"),
                             to_float(max_uncertainty, "max_uncertainty")};
             p.validate();
             return p;
           }),
           py::arg("gate") = td.gate, py::arg("gate_sigmas") = td.gate_sigmas, py::arg("accel_std") = td.accel_std,
           py::arg("measurement_std") = td.measurement_std, py::arg("confirm_hits") = td.confirm_hits,
           py::arg("lost_time") = td.lost_time, py::arg("moving_speed") = td.moving_speed,
           py::arg("moving_sigmas") = td.moving_sigmas, py::arg("moving_window") = td.moving_window,
           py::arg("free_margin") = td.free_margin, py::arg("max_speed") = td.max_speed, py::arg("uncertainty_sigmas") = td.uncertainty_sigmas,
           py::arg("max_uncertainty") = td.max_uncertainty, py::arg("prediction_window") = td.prediction_window)
      .def_readonly("gate", &TrackerParams::gate)
      .def_readonly("gate_sigmas", &TrackerParams::gate_sigmas)
      .def_readonly("accel_std", &TrackerParams::accel_std)
      .def_readonly("measurement_std", &TrackerParams::measurement_std)
      .def_readonly("confirm_hits", &TrackerParams::confirm_hits)
      .def_readonly("lost_time", &TrackerParams::lost_time)
      .def_readonly("moving_speed", &TrackerParams::moving_speed)
      .def_readonly("moving_sigmas", &TrackerParams::moving_sigmas)
      .def_readonly("moving_window", &TrackerParams::moving_window)
      .def_readonly("prediction_window", &TrackerParams::prediction_window)
      .def_readonly("free_margin", &TrackerParams::free_margin)
      .def_readonly("max_speed", &TrackerParams::max_speed)
      .def_readonly("uncertainty_sigmas", &TrackerParams::uncertainty_sigmas)
      .def_readonly("max_uncertainty", &TrackerParams::max_uncertainty)
      .def("__repr__", [](const TrackerParams& p) {
        std::ostringstream s;
        s << "TrackerParams(gate=" << p.gate << ", gate_sigmas=" << p.gate_sigmas << ", accel_std=" << p.accel_std
          << ", measurement_std=" << p.measurement_std << ", confirm_hits=" << p.confirm_hits
          << ", lost_time=" << p.lost_time << ", moving_speed=" << p.moving_speed
          << ", moving_sigmas=" << p.moving_sigmas << ", moving_window=" << p.moving_window
          << ", prediction_window=" << p.prediction_window
          << ", free_margin=" << p.free_margin
          << ", max_speed=" << p.max_speed << ", uncertainty_sigmas=" << p.uncertainty_sigmas << ")";
        return s.str();
      });

  py::class_<Track>(m, "Track", "One followed object: constant-velocity Kalman state and its moving label.")
      .def_readonly("id", &Track::id)
      .def_readonly("status", &Track::status)
      .def_property_readonly("position", [](const Track& t) { return pair(t.position); }, "m, at the last update.")
      .def_property_readonly("velocity", [](const Track& t) { return pair(t.velocity); }, "m/s, the filter's.")
      .def_property_readonly("window_velocity", [](const Track& t) { return pair(t.window_velocity); },
                             "m/s, slope of the centres over the last moving_window; the moving label uses it.")
      .def_property_readonly("predicted_velocity", [](const Track& t) { return pair(t.predicted_velocity); },
                             "m/s, slope of the centres over the last prediction_window; moving_discs use it.")
      .def_readonly("window_speed_std", &Track::window_speed_std)
      .def_property_readonly(
          "covariance",
          [](const Track& t) {
            py::array_t<double> out({4, 4});
            for (int r = 0; r < 4; ++r)
              for (int c = 0; c < 4; ++c) out.mutable_at(r, c) = t.covariance(r, c);
            return out;
          },
          "(4, 4) covariance of (x, y, vx, vy).")
      .def_readonly("radius", &Track::radius)
      .def_readonly("moving", &Track::moving)
      .def_readonly("hits", &Track::hits)
      .def_readonly("last_seen", &Track::last_seen)
      .def_readonly("age", &Track::age)
      .def_property_readonly("position_std", &Track::position_std)
      .def_property_readonly("speed_std", &Track::speed_std)
      .def("__repr__", [](const Track& t) {
        std::ostringstream s;
        s << "Track(id=" << t.id << ", " << to_string(t.status) << (t.moving ? ", moving" : "") << ", position=("
          << t.position.x() << ", " << t.position.y() << "), window_velocity=(" << t.window_velocity.x() << ", "
          << t.window_velocity.y() << "), radius=" << t.radius << ")";
        return s.str();
      });

  py::class_<Tracker>(m, "Tracker",
                      "Follows segment_scan's clusters from scan to scan and says which move. update() with each "
                      "scan's clusters and time; read tracks, moving_discs(), explains().")
      .def(py::init<const TrackerParams&>(), py::arg("params") = td)
      .def_property_readonly("params", &Tracker::params)
      .def(
          "update",
          [](Tracker& t, const std::vector<Cluster>& clusters, FloatArg time, const Scan* scan) {
            t.update(clusters, to_float(time, "time"), scan);
          },
          py::arg("clusters"), py::arg("time"), py::arg("scan") = nullptr,
          "Predicts the tracks to time (s, never going back), assigns the clusters, corrects, starts, loses and "
          "removes tracks. Pass the scan the clusters came from: without it only the window speed decides what "
          "moves, and static clutter seen from a moving robot can be called moving.")
      .def_property_readonly("tracks", &Tracker::tracks, "The tracks after the last update (a copy).")
      .def_property_readonly("cluster_tracks", &Tracker::cluster_tracks,
                             "For each cluster of the last update, the id of the track that took it.")
      .def_property_readonly("time", &Tracker::time, "s, of the last update (NaN before the first).")
      .def("moving_discs", &Tracker::moving_discs,
           "Moving tracks (confirmed or coasting) as Discs with their window velocity, radius grown by "
           "uncertainty_sigmas position std devs and growing by uncertainty_sigmas std devs of the filter's speed "
           "per second ahead.")
      .def(
          "explains",
          [](const Tracker& t, py::handle point, FloatArg margin) {
            return t.explains(to_vec2(point, "point"), to_float(margin, "margin"));
          },
          py::arg("point"), py::arg("margin") = 0.0,
          "Whether the point lies within margin (m) of a confirmed moving track's grown disc.")
      .def("reset", &Tracker::reset, "Forgets every track; ids keep counting.")
      .def("__repr__", [](const Tracker& t) {
        std::size_t moving = 0;
        for (const Track& track : t.tracks()) moving += track.moving;
        return "Tracker(" + std::to_string(t.tracks().size()) + " tracks, " + std::to_string(moving) + " moving)";
      });
}
