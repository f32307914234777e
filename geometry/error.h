#pragma once
// Errors at the boundary of hrspace (scene files, CLI arguments). The CLI turns
// an InputError into one line on stderr and exit status 2.

#include <stdexcept>
#include <string>

namespace hrs {

//! Bad user input: the message names the file, the field and what is wrong.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace hrs
