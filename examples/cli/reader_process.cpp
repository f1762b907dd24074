// reader_process.cpp: the reader child as the parent runs it: starts this executable
// (/proc/self/exe, by posix_spawn, which is safe while other batch threads run) as
// `coverage-axis --internal-read PATH FORMAT SECONDS MIB` with its standard output and error on
// pipes; feeds the output to the frame reader and keeps the start of the error; and waits for the
// child at most the read's time limit, stopping it (SIGKILL) past that.
#include "isolated_read.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <thread>

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace cli {
namespace {

// The child's standard error kept for a crash's message; the rest is read and dropped.
constexpr size_t kMaxStderr = 4096;

using Clock = std::chrono::steady_clock;
// A point in time counted in fractional ticks, as a time limit in seconds gives it.
using Deadline = decltype(Clock::now() + std::chrono::duration<double>(1));

// Milliseconds to `deadline` for poll, rounded up; 0 once it has passed.
int ms_left(Deadline deadline) {
    const double left = std::chrono::duration<double, std::milli>(deadline - Clock::now()).count();
    return left <= 0 ? 0 : int(std::min(left + 1, 1e6));
}

// A pipe whose ends are close-on-exec (other batch threads' children must not inherit them) and
// above the standard descriptors (so the child's dup2 onto 0-2 never overwrites one of them).
bool make_pipe(int fds[2]) {
    if (pipe2(fds, O_CLOEXEC) != 0) return false;
    for (int k = 0; k < 2; ++k)
        if (fds[k] < 3) {
            const int moved = fcntl(fds[k], F_DUPFD_CLOEXEC, 3);
            ::close(fds[k]);
            fds[k] = moved;
        }
    if (fds[0] >= 0 && fds[1] >= 0) return true;
    for (int k = 0; k < 2; ++k)
        if (fds[k] >= 0) ::close(fds[k]);
    return false;
}

// Starts the child with its standard output on `data` and its standard error on `err` (their
// write ends, which this closes); its standard input is /dev/null unless it reads "-". The child
// starts with no signal blocked and SIGPIPE at its default, whatever this thread has. -1 when it
// could not be started.
pid_t spawn_reader(const std::string& path, const std::string& format, double time_s, double memory_mib, int data_fd,
                   int err_fd) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, data_fd, 1);
    posix_spawn_file_actions_adddup2(&actions, err_fd, 2);
    if (path != "-") posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 34))
    posix_spawn_file_actions_addclosefrom_np(&actions, 3);
#endif
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    sigset_t none, pipe_default;
    sigemptyset(&none);
    sigemptyset(&pipe_default);
    sigaddset(&pipe_default, SIGPIPE);
    posix_spawnattr_setsigmask(&attr, &none);
    posix_spawnattr_setsigdefault(&attr, &pipe_default);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
    char seconds[32], mib[32];
    std::snprintf(seconds, sizeof seconds, "%.17g", time_s);
    std::snprintf(mib, sizeof mib, "%.17g", memory_mib);
    std::string arg0 = "coverage-axis", arg1 = "--internal-read", arg2 = path, arg3 = format;
    char* argv[] = {&arg0[0], &arg1[0], &arg2[0], &arg3[0], seconds, mib, nullptr};
    pid_t pid = -1;
    const int spawned = posix_spawn(&pid, "/proc/self/exe", &actions, &attr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
    ::close(data_fd);
    ::close(err_fd);
    return spawned == 0 ? pid : -1;
}

// Reads the child's standard output into `frame` and the start of its standard error into
// `stderr_text` until both end or `deadline` passes (true then); closes both.
bool collect_output(int data_fd, int err_fd, Deadline deadline, FrameReader& frame, std::string& stderr_text) {
    bool timed_out = false;
    pollfd fds[2] = {{data_fd, POLLIN, 0}, {err_fd, POLLIN, 0}};
    while (fds[0].fd >= 0 || fds[1].fd >= 0) {
        const int wait_ms = ms_left(deadline);
        if (wait_ms == 0) {
            timed_out = true;
            break;
        }
        const int ready = poll(fds, 2, wait_ms);
        if (ready < 0 && errno != EINTR) break;
        if (ready <= 0) continue;
        if (fds[0].fd >= 0 && fds[0].revents) {
            if (!frame.read_from(fds[0].fd)) {
                ::close(fds[0].fd);
                fds[0].fd = -1;
            }
        }
        if (fds[1].fd >= 0 && fds[1].revents) {
            char buf[1024];
            const ssize_t n = ::read(fds[1].fd, buf, sizeof buf);
            if (n > 0 && stderr_text.size() < kMaxStderr)
                stderr_text.append(buf, std::min(size_t(n), kMaxStderr - stderr_text.size()));
            if (n == 0 || (n < 0 && errno != EINTR && errno != EAGAIN)) {
                ::close(fds[1].fd);
                fds[1].fd = -1;
            }
        }
    }
    for (pollfd& p : fds)
        if (p.fd >= 0) ::close(p.fd);
    return timed_out;
}

// Waits for the child, which may not outlive the deadline either: past it (or when `timed_out`
// already) it is killed and reaped, and `timed_out` becomes true.
void wait_for_child(pid_t pid, Deadline deadline, bool& timed_out, int& status) {
    for (int pause_ms = 1;; pause_ms = std::min(2 * pause_ms, 20)) {
        if (timed_out || ms_left(deadline) == 0) {
            timed_out = true;
            kill(pid, SIGKILL);
            while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
            }
            break;
        }
        const pid_t w = waitpid(pid, &status, WNOHANG);
        if (w == pid || (w < 0 && errno != EINTR)) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(pause_ms));
    }
}

}  // namespace

bool run_reader_child(const std::string& path, const std::string& format, double time_s, double memory_mib,
                      FrameReader& frame, ChildEnd& end) {
    int data[2], err[2];
    if (!make_pipe(data)) return false;
    if (!make_pipe(err)) {
        ::close(data[0]);
        ::close(data[1]);
        return false;
    }
    const pid_t pid = spawn_reader(path, format, time_s, memory_mib, data[1], err[1]);
    if (pid < 0) {
        ::close(data[0]);
        ::close(err[0]);
        return false;
    }
    const Deadline deadline = Clock::now() + std::chrono::duration<double>(time_s);
    end.timed_out = collect_output(data[0], err[0], deadline, frame, end.stderr_text);
    // the pipes are closed (the child is exiting) or the deadline passed
    wait_for_child(pid, deadline, end.timed_out, end.status);
    return true;
}

}  // namespace cli
