#pragma once
// The one exception type of the library: thrown on misuse (bad parameters, bad
// input shapes, a start inside an obstacle). Expected outcomes of a control cycle
// are reported as a status in the result instead.
#include <stdexcept>
#include <string>

namespace fgdwa {

class Error : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

}  // namespace fgdwa
