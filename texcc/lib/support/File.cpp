#include "texcc/Support/File.h"

#include <cctype>
#include <cerrno>
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
  int Fd = openRegular(Path, Why);
  if (Fd < 0)
    return false;
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
  }
  ::close(Fd);
  Text = std::move(Out);
  return true;
}

} // namespace texcc
