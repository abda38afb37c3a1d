#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <sstream>

#include "bind_params.hpp"
#include "convert.hpp"
#include "fgdwa/scan_matcher.hpp"

namespace py = pybind11;
using namespace fgdwa;
using namespace fgdwa::py_convert;

void init_scan_matcher(py::module_& m) {
  bind_params<ScanMatchParams>(m, "ScanMatchParams",
                               "The scan-to-map matcher: search window and steps, scoring, when a match is refused.");

  py::enum_<MatchStatus> status(m, "MatchStatus", "Why a scan's match was or was not used.");
  status.value("Accepted", MatchStatus::Accepted)
      .value("Off", MatchStatus::Off)
      .value("NoMap", MatchStatus::NoMap)
      .value("TooFewPoints", MatchStatus::TooFewPoints)
      .value("PoorFit", MatchStatus::PoorFit)
      .value("NotBetter", MatchStatus::NotBetter)
      .value("Ambiguous", MatchStatus::Ambiguous);
  refuse_unnamed_values(status);

  py::class_<ScanMatch>(m, "ScanMatch", "One scan matched to a map.")
      .def_readonly("status", &ScanMatch::status)
      .def_readonly("pose", &ScanMatch::pose, "The scan's best pose found (the one given when none was searched).")
      .def_readonly("score", &ScanMatch::score, "Its mean score, in [0, 1].")
      .def_readonly("given_score", &ScanMatch::given_score, "The mean score at the pose given.")
      .def_readonly("runner_up", &ScanMatch::runner_up, "The best score farther than ambiguity_radius from the best.")
      .def_readonly("points", &ScanMatch::points, "Hits scored.")
      .def_property_readonly("accepted", &ScanMatch::accepted)
      .def("__repr__", [](const ScanMatch& r) {
        std::ostringstream s;
        s << "ScanMatch(status=" << to_string(r.status) << ", pose=(" << r.pose.x << ", " << r.pose.y << ", "
          << r.pose.theta << "), score=" << r.score << ", given_score=" << r.given_score << ")";
        return s.str();
      });

  py::class_<ScanMatcher>(m, "ScanMatcher",
                          "Correlative scan-to-map matching in a bounded window around the scan's pose.")
      .def(py::init<const ScanMatchParams&>(), py::arg("params") = ScanMatchParams())
      .def(
          "match",
          [](const ScanMatcher& matcher, const Scan& scan, const DistanceField& field, FloatArg depth) {
            return matcher.match(ScanFrame(scan), field, to_float(depth, "depth"));
          },
          py::arg("scan"), py::arg("field"), py::arg("depth") = 0.0,
          "The pose near scan.pose at which the scan's hits (each pushed `depth` m along its beam) fit the "
          "field's obstacles best, and whether it is clearly better than scan.pose (ScanMatch).")
      .def_property_readonly("params", &ScanMatcher::params, py::return_value_policy::copy);
}
