#pragma once
// Errors at the boundary of hrspace (scene files, CLI arguments, output
// files). The CLI turns an InputError into one line on stderr and exit status
// 2, an OutputError (a write that failed: full disk, I/O error) into one line
// and exit status 1.

#include <stdexcept>
#include <string>

namespace hrs {

//! Bad user input: the message names the file, the field and what is wrong.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

//! A write failed although its target was checked first (full disk, I/O
//! error): the message names the file and the system's reason.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace hrs
