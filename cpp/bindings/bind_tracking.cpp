#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <sstream>

#include "bind_params.hpp"
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
  bind_params<SegmentParams>(m, "SegmentParams", "How a scan's hits are split into clusters (objects to track).");

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
  bind_params<TrackerParams>(m, "TrackerParams", "Tracks of moving obstacles: association, Kalman filter, moving label.");

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
      .def_property_readonly("current_velocity", [](const Track& t) { return pair(t.current_velocity); },
                             "m/s, a parabola's through the window's centres, at the last one (fitted while hypothesis_time > 0).")
      .def_property_readonly("acceleration", [](const Track& t) { return pair(t.acceleration); },
                             "m/s^2, the same parabola's; the second prediction keeps it where significant.")
      .def_readonly("acceleration_std", &Track::acceleration_std, "m/s^2, its std per coordinate (inf until four centres).")
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
      .def_readonly("last_fast", &Track::last_fast, "s, the last association at which a moving track's window speed held its label (moving_hold counts from it)")
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
