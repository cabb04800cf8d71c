#include "texcc/Support/File.h"

#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace texcc {

namespace {

std::string reasonOf(int Errno) {
  switch (Errno) {
  case ENOENT:
    return "no such file";
  case ELOOP:
    return "too many levels of symbolic links";
  case EISDIR:
    return "it is a folder";
  default: {
    std::string S = std::strerror(Errno);
    if (!S.empty())
      S[0] = char(std::tolower(static_cast<unsigned char>(S[0])));
    return S;
  }
  }
}

/// The reason a file of this mode is not a regular file ("" for a regular file).
std::string kindProblem(mode_t Mode) {
  if (S_ISREG(Mode))
    return "";
  if (S_ISDIR(Mode))
    return "it is a folder";
  if (S_ISFIFO(Mode))
    return "it is a FIFO, not a regular file";
  if (S_ISCHR(Mode) || S_ISBLK(Mode))
    return "it is a device, not a regular file";
  if (S_ISSOCK(Mode))
    return "it is a socket, not a regular file";
  return "it is not a regular file";
}

/// Opens Path for reading, never blocking; returns the descriptor of a regular file or -1.
int openRegular(const std::string &Path, std::string &Why) {
  int Fd;
  do
    Fd = ::open(Path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  while (Fd < 0 && errno == EINTR);
  if (Fd < 0) {
    Why = reasonOf(errno);
    return -1;
  }
  struct stat St;
  if (::fstat(Fd, &St) != 0) {
    Why = reasonOf(errno);
    ::close(Fd);
    return -1;
  }
  Why = kindProblem(St.st_mode);
  if (!Why.empty()) {
    ::close(Fd);
    return -1;
  }
  return Fd;
}

} // namespace

bool checkRegularFile(const std::string &Path, std::string &Why) {
  int Fd = openRegular(Path, Why);
  if (Fd < 0)
    return false;
  ::close(Fd);
  return true;
}

bool readRegularFile(const std::string &Path, std::string &Text, std::string &Why) {
  return readRegularFile(Path, Text, Why, SIZE_MAX);
}

std::string tooLarge(unsigned long long Size, size_t MaxBytes) {
  auto mib = [](unsigned long long B) {
    char Buf[32];
    std::snprintf(Buf, sizeof Buf, "%.1f MiB", double(B) / (1 << 20));
    return std::string(Buf);
  };
  return "it is " + std::to_string(Size) + " bytes (" + mib(Size) + "), more than the " +
         mib(MaxBytes) + " limit";
}

bool readRegularFile(const std::string &Path, std::string &Text, std::string &Why,
                     size_t MaxBytes) {
  int Fd = openRegular(Path, Why);
  if (Fd < 0)
    return false;
  struct stat St;
  if (MaxBytes != SIZE_MAX && ::fstat(Fd, &St) == 0 &&
      static_cast<unsigned long long>(St.st_size) > MaxBytes) {
    Why = tooLarge(static_cast<unsigned long long>(St.st_size), MaxBytes);
    ::close(Fd);
    return false;
  }
  std::string Out;
  char Buf[1 << 16];
  for (;;) {
    ssize_t N = ::read(Fd, Buf, sizeof Buf);
    if (N == 0)
      break;
    if (N < 0) {
      if (errno == EINTR)
        continue;
      Why = reasonOf(errno);
      ::close(Fd);
      return false;
    }
    Out.append(Buf, size_t(N));
    if (Out.size() > MaxBytes) { // it grew while being read
      Why = tooLarge(Out.size(), MaxBytes);
      ::close(Fd);
      return false;
    }
  }
  ::close(Fd);
  Text = std::move(Out);
  return true;
}

} // namespace texcc
