#pragma once
// Reading one input document whole — a program, a spec case, a toolpath JSON, run.json — with the
// checks that keep a mistaken path from hanging or exhausting the run: a directory, a FIFO, a
// device or a socket is refused (it would read as nothing, or forever), and so is a file over
// kMaxInputBytes. Results files are read line by line instead (results_file.h), each line at most
// kMaxInputBytes (readBoundedLine).
#include <cstddef>
#include <iosfwd>
#include <stdexcept>
#include <string>

namespace cyclecert {

inline constexpr std::size_t kMaxInputBytes = std::size_t{64} << 20;  // 64 MiB

// An input that is not there, not a regular file, too large or unreadable; the message names the
// path, what it is and what would be accepted.
struct InputFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The whole of a regular file of at most `maxBytes`.
std::string readInputFile(const std::string& path, std::size_t maxBytes = kMaxInputBytes);

// The whole of a stream (standard input) of at most `maxBytes`; `name` names it in the error.
std::string readInputStream(std::istream& in, const std::string& name, std::size_t maxBytes = kMaxInputBytes);

// The next line of `in` (without its newline) into `line`, as std::getline, but a line longer than
// `maxBytes` is skipped to its end and not kept: Line, TooLong (`line` then holds nothing) or End.
// A results file torn by a killed run, or a stray binary file, cannot take all memory this way.
enum class BoundedLine { Line, TooLong, End };
BoundedLine readBoundedLine(std::istream& in, std::string& line, std::size_t maxBytes = kMaxInputBytes);

// "64 MiB", "1.5 KiB", "12 bytes": a size for a message.
std::string byteSizeText(unsigned long long bytes);

}  // namespace cyclecert
