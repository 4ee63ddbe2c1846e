// reaped_command.cpp — see reaped_command.h.
#include "reaped_command.h"

#include <errno.h>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>

#include "reaped_process.h"

namespace vgc {

int run_reaped_shell(const std::string& command, std::string* output, std::size_t output_limit) {
  const int null_fd = open("/dev/null", O_RDONLY | O_CLOEXEC);
  if (null_fd < 0) return -1;
  int out[2] = {-1, -1};
  if (output && pipe2(out, O_CLOEXEC) != 0) {
    close(null_fd);
    return -1;
  }
  std::string sh = "/bin/sh", dash_c = "-c", text = command;
  char* argv[] = {sh.data(), dash_c.data(), text.data(), nullptr};
  ReapedProcess proc;
  std::string error;
  const bool started = spawn_reaped("/bin/sh", argv, null_fd, output ? out[1] : 1, 2, &proc, &error);
  close(null_fd);
  if (output) close(out[1]);
  if (!started) {
    if (output) close(out[0]);
    return -1;
  }
  if (output) {
    output->clear();
    char buf[4096];
    for (;;) {
      const ssize_t n = read(out[0], buf, sizeof buf);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      const std::size_t keep = std::min(static_cast<std::size_t>(n), output_limit - std::min(output_limit, output->size()));
      output->append(buf, keep);
    }
    close(out[0]);
  }
  // The reaper ends when the command does (and with the command's status).
  int status = 0;
  while (waitpid(proc.pid, &status, 0) < 0 && errno == EINTR) {
  }
  close(proc.control_fd);
  return status;
}

}  // namespace vgc
