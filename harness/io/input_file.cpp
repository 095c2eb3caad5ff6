#include "harness/io/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <istream>
#include <sstream>

namespace cyclecert {

std::string byteSizeText(unsigned long long bytes) {
  static const char* const units[] = {"bytes", "KiB", "MiB", "GiB", "TiB"};
  double size = static_cast<double>(bytes);
  std::size_t unit = 0;
  while (size >= 1024 && unit + 1 < std::size(units)) {
    size /= 1024;
    ++unit;
  }
  std::ostringstream s;
  s.precision(unit == 0 ? 0 : 3);
  s << std::fixed << size;
  std::string text = s.str();
  if (unit > 0) {  // 64.000 → 64, 1.500 → 1.5
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') text.pop_back();
  }
  return text + " " + units[unit];
}

namespace {

// What a file that is not a regular file is, for the message.
std::string fileKind(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

// `size`: "70 MiB", or "" when only known to be over the cap.
std::string overCap(const std::string& name, const std::string& size, std::size_t maxBytes) {
  return "cannot read " + name + ": it is " + (size.empty() ? "" : size + ", ") + "larger than the " +
         byteSizeText(maxBytes) + " cyclecert reads from one input file";
}

class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

}  // namespace

std::string readInputFile(const std::string& path, std::size_t maxBytes) {
  // O_NONBLOCK: opening a FIFO without a writer would wait for one. Regular files ignore it.
  const Descriptor fd(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC));
  if (fd.get() < 0) {
    const int error = errno;
    if (error == ENOENT) throw InputFileError("cannot read '" + path + "': no such file");
    throw InputFileError("cannot read '" + path + "': " + std::strerror(error));
  }
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0) throw InputFileError("cannot read '" + path + "': " + std::strerror(errno));
  if (!S_ISREG(st.st_mode)) {
    throw InputFileError("cannot read '" + path + "': it is " + fileKind(st.st_mode) + "; give a regular file" +
                         (S_ISDIR(st.st_mode) ? std::string()
                                              : std::string(" (a FIFO or a device could block or never end)")));
  }
  if (const auto size = static_cast<unsigned long long>(st.st_size); size > maxBytes) {
    // In bytes when rounding would make it look no larger than the cap.
    const std::string sizeText =
        byteSizeText(size) == byteSizeText(maxBytes) ? std::to_string(size) + " bytes" : byteSizeText(size);
    throw InputFileError(overCap("'" + path + "'", sizeText, maxBytes));
  }
  std::string text;
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::read(fd.get(), buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputFileError("cannot read '" + path + "': " + std::strerror(errno));
    if (n == 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
    if (text.size() > maxBytes) throw InputFileError(overCap("'" + path + "'", "", maxBytes));  // it grew
  }
  return text;
}

std::string readInputStream(std::istream& in, const std::string& name, std::size_t maxBytes) {
  std::string text;
  char buffer[65536];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > maxBytes) throw InputFileError(overCap(name, "", maxBytes));
  }
  if (in.bad()) throw InputFileError("cannot read " + name);
  return text;
}

BoundedLine readBoundedLine(std::istream& in, std::string& line, std::size_t maxBytes) {
  line.clear();
  // In chunks through istream::getline (libstdc++ scans its buffer for the newline at once): a
  // character at a time made reading a results file 7 % slower than std::getline.
  constexpr std::streamsize kChunk = 1 << 16;
  char chunk[kChunk];
  bool tooLong = false, any = false;
  for (;;) {
    in.getline(chunk, kChunk);
    const std::streamsize extracted = in.gcount();
    const bool atEnd = in.eof();
    const bool chunkFull = in.fail() && !atEnd;  // kChunk − 1 characters stored, no newline yet
    const bool newline = !in.fail() && !atEnd;   // the line ended with a newline (extracted, not stored)
    const auto stored = static_cast<std::size_t>(extracted - (newline ? 1 : 0));
    any = any || extracted > 0;
    if (!tooLong && line.size() + stored > maxBytes) {
      tooLong = true;
      std::string().swap(line);
    }
    if (!tooLong) line.append(chunk, stored);
    if (chunkFull) {
      in.clear();
      continue;
    }
    if (!any) {
      in.setstate(std::ios::failbit);
      return BoundedLine::End;
    }
    if (atEnd) in.clear(std::ios::eofbit);  // the last line, without a newline: read, not failed
    return tooLong ? BoundedLine::TooLong : BoundedLine::Line;
  }
}

}  // namespace cyclecert
