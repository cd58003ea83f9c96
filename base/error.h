// The one exception type of the pipeline: a user error whose message names the values involved
// (as pbrt's LookAt does), so the command line and the UI can show it as it is.
#pragma once

#include <stdexcept>
#include <string>

namespace vplab {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace vplab
