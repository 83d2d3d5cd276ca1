// Typed errors thrown at the I/O edge only; engine loops never throw (docs/architecture.md).
#pragma once
#include <stdexcept>
#include <string>

namespace s4d {

// Any user-facing failure: bad argument, unknown generator, unreadable file.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A malformed input file. what() reads "file:line: message" so users can find the spot.
class ParseError : public Error {
 public:
  ParseError(std::string file, int line, const std::string& message)
      : Error(file + ":" + (line > 0 ? std::to_string(line) + ":" : std::string()) + " " + message),
        file_(std::move(file)),
        line_(line) {}
  const std::string& file() const { return file_; }
  int line() const { return line_; }  // 1-based; 0 when the error is not tied to a line

 private:
  std::string file_;
  int line_;
};

}  // namespace s4d
