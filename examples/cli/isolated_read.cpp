// isolated_read.cpp: reading an input through assimp in a child process, so that a crash, an
// assertion's abort, a hang or runaway memory inside a third-party importer ends that read with
// an error naming the file instead of ending the tool (or a whole batch). The tool starts its own
// executable (/proc/self/exe, by posix_spawn, which is safe while other batch threads run) with
// the internal command `--internal-read PATH FORMAT SECONDS MIB`. The child lowers its own limits
// first (no core file, CPU time, and once the input is loaded its address space), reads the input
// with caio::read_mesh and writes one frame to its standard output: a header, then the mesh (the
// lines naming what the reader dropped, and the skin) or the error message. Whatever the reader
// itself prints goes to the child's standard error, which the parent keeps to quote in a crash's
// message. Every count in the header is checked against the input's size before memory is taken
// for it, and the skin that arrives passes caio::skin_problem like any reader's. The parent waits at most the read's time limit
// and stops the child past it; a signal, a non-zero exit or a malformed frame becomes an error.
// Where the child cannot be started (no /proc, the executable gone) the read runs in this process.
#include "cli.h"
#include "reader_common.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

extern char** environ;

namespace cli {
namespace {

// ---- the frame the child writes: a header, then the mesh's arrays or the error message ----

constexpr char kMagic[8] = {'C', 'A', 'M', 'E', 'S', 'H', '0', '3'};

struct FrameHeader {
    char magic[8];
    uint64_t ok;             // 1: the mesh follows; 0: the error message follows
    uint64_t input_bytes;    // the input's size, which limits the counts below as it limits the readers
    uint64_t vertices, triangles, normals;  // normals: 0 or `vertices`
    uint64_t message_bytes;
    uint64_t dropped_bytes;  // after the mesh: MeshData::dropped, one line each, '\n'-separated
    // then the skin (SkinData): its joints (0: none), weights per vertex (0 without joints, else
    // 1..8), glTF node indices (0 or `joints`) and the bytes of the joint names, which follow
    // their lengths (one uint32 per joint)
    uint64_t joints, influences, gltf_nodes, name_bytes;
};

// A longer message from the child is taken for a malformed frame.
constexpr uint64_t kMaxMessage = 1 << 16;
// The same for the dropped parts' lines (at most 1001 lines of a few hundred characters).
constexpr uint64_t kMaxDropped = 1 << 20;
// The child's standard error kept for a crash's message; the rest is read and dropped.
constexpr size_t kMaxStderr = 4096;
// The address space a read through assimp gets by default: room for the process itself (the tool
// and its libraries) and a multiple of the input far above what assimp's importers build per input
// byte, so a legitimate file never meets it while a runaway allocation does within seconds
// (docs/cli.md has the figures).
constexpr double kBaseMemoryMiB = 512;
constexpr double kMemoryPerInputByte = 128;

bool write_all(int fd, const void* data, size_t n) {
    const char* p = static_cast<const char*>(data);
    while (n > 0) {
        const ssize_t w = ::write(fd, p, n);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) return false;
        p += w;
        n -= size_t(w);
    }
    return true;
}

// Lowers a limit of this process to `soft` (never above the hard limit in force); `hard_extra`
// seconds past it the hard limit (for RLIMIT_CPU: SIGXCPU at the soft limit, SIGKILL at the hard).
void lower_limit(int resource, rlim_t soft, rlim_t hard_extra = 0) {
    rlimit r{};
    if (getrlimit(resource, &r) != 0) return;
    const rlim_t hard = r.rlim_max;
    r.rlim_cur = hard == RLIM_INFINITY ? soft : std::min(soft, hard);
    if (hard == RLIM_INFINITY || r.rlim_cur + hard_extra <= hard) r.rlim_max = r.rlim_cur + hard_extra;
    setrlimit(resource, &r);
}

bool sanitizer_build() {
#if defined(__SANITIZE_ADDRESS__)
    return true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    return true;
#else
    return false;
#endif
#else
    return false;
#endif
}

// ---- the parent: start the child, read its frame and its standard error, wait for it ----

using Clock = std::chrono::steady_clock;

// The frame as it arrives: the header, then the arrays it announces, read straight into `out`.
class FrameReader {
public:
    FrameReader(caio::MeshData& out, uint64_t input_limit) : out_(out), input_limit_(input_limit) {
        parts_.push_back({reinterpret_cast<char*>(&header_), sizeof header_});
    }
    // Reads what is ready on `fd`; false at its end (or when the frame turned out malformed).
    bool read_from(int fd) {
        if (part_ == parts_.size()) {  // the frame is complete: nothing more may come
            char extra;
            const ssize_t n = ::read(fd, &extra, 1);
            if (n > 0) problem_ = "more bytes than its header announced";
            return n < 0 && (errno == EINTR || errno == EAGAIN);
        }
        Part& p = parts_[part_];
        const ssize_t n = ::read(fd, p.data + done_, p.size - done_);
        if (n < 0) return errno == EINTR || errno == EAGAIN;
        if (n == 0) return false;
        done_ += size_t(n);
        if (done_ == p.size) {
            done_ = 0;
            ++part_;
            if (part_ == 1 && !start_body()) return false;
        }
        return true;
    }
    bool complete() const { return problem_.empty() && part_ == parts_.size(); }
    bool ok() const { return header_.ok == 1; }
    // The dropped parts' lines, once the frame is complete.
    std::vector<std::string> dropped() const {
        std::vector<std::string> lines;
        for (size_t at = 0; at < dropped_.size();) {
            const size_t end = std::min(dropped_.find('\n', at), dropped_.size());
            lines.push_back(dropped_.substr(at, end - at));
            at = end + 1;
        }
        return lines;
    }
    const std::string& message() const { return message_; }
    const std::string& problem() const { return problem_; }
    // The joint names cut from their bytes by their lengths, once the frame is complete; false
    // when the lengths do not add up to the bytes.
    bool take_joint_names() {
        uint64_t total = 0;
        for (uint32_t n : name_lengths_) total += n;
        if (total != names_.size()) return false;
        size_t at = 0;
        for (uint32_t n : name_lengths_) {
            out_.skin.joint_names.push_back(names_.substr(at, n));
            at += n;
        }
        return true;
    }

private:
    struct Part {
        char* data;
        size_t size;
    };
    // Checks the header and lays out the parts it announces.
    bool start_body() {
        const FrameHeader& h = header_;
        if (std::memcmp(h.magic, kMagic, sizeof kMagic) != 0 || h.ok > 1) return problem_ = "no frame header", false;
        if (h.ok == 0) {
            if (h.message_bytes == 0 || h.message_bytes > kMaxMessage) return problem_ = "a bad message length", false;
            message_.resize(size_t(h.message_bytes));
            parts_.push_back({&message_[0], message_.size()});
            return true;
        }
        if (h.input_bytes > input_limit_ || h.vertices > h.input_bytes || h.triangles > h.input_bytes ||
            h.vertices > UINT32_MAX || (h.normals != 0 && h.normals != h.vertices) || h.dropped_bytes > kMaxDropped)
            return problem_ = "counts beyond the input's limits", false;
        // every joint and every byte of its name comes from the input
        if (h.joints > h.input_bytes || h.name_bytes > h.input_bytes || h.influences > caio::kMaxInfluences ||
            (h.joints == 0) != (h.influences == 0) || (h.gltf_nodes != 0 && h.gltf_nodes != h.joints))
            return problem_ = "skin counts beyond the input's limits", false;
        try {
            out_.positions.resize(size_t(3 * h.vertices));
            out_.triangles.resize(size_t(3 * h.triangles));
            out_.normals.resize(size_t(3 * h.normals));
            dropped_.resize(size_t(h.dropped_bytes));
            caio::SkinData& s = out_.skin;
            s.parents.resize(size_t(h.joints));
            s.inverse_bind.resize(size_t(16 * h.joints));
            s.joint_world.resize(size_t(16 * h.joints));
            s.gltf_nodes.resize(size_t(h.gltf_nodes));
            s.influences = uint32_t(h.influences);
            s.vertex_joints.resize(size_t(h.vertices * h.influences));
            s.vertex_weights.resize(size_t(h.vertices * h.influences));
            name_lengths_.resize(size_t(h.joints));
            names_.resize(size_t(h.name_bytes));
        } catch (const std::exception&) {  // bad_alloc, or length_error on a count past max_size
            return problem_ = "counts beyond this process's memory", false;
        }
        add(out_.positions);
        add(out_.triangles);
        add(out_.normals);
        if (!dropped_.empty()) parts_.push_back({&dropped_[0], dropped_.size()});
        caio::SkinData& s = out_.skin;
        add(s.parents);
        add(s.inverse_bind);
        add(s.joint_world);
        add(s.gltf_nodes);
        add(s.vertex_joints);
        add(s.vertex_weights);
        add(name_lengths_);
        if (!names_.empty()) parts_.push_back({&names_[0], names_.size()});
        return true;
    }
    template <class T>
    void add(std::vector<T>& v) {
        if (!v.empty()) parts_.push_back({reinterpret_cast<char*>(v.data()), v.size() * sizeof(T)});
    }

    caio::MeshData& out_;
    uint64_t input_limit_;
    FrameHeader header_{};
    std::vector<Part> parts_;
    size_t part_ = 0, done_ = 0;
    std::string message_, problem_, dropped_, names_;
    std::vector<uint32_t> name_lengths_;
};

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

// The child's last non-empty line of standard error, printable, at most 200 characters.
std::string last_line(const std::string& text) {
    size_t end = text.size();
    while (end > 0 && (text[end - 1] == '\n' || text[end - 1] == '\r' || text[end - 1] == ' ')) --end;
    const size_t newline = end == 0 ? std::string::npos : text.rfind('\n', end - 1);
    const size_t start = newline == std::string::npos ? 0 : newline + 1;
    return caio::detail::printable(text.substr(start, end - start), 200);
}

std::string seconds_text(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g s", s);
    return buf;
}

std::string signal_text(int sig) {
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 32))
    const char* abbrev = sigabbrev_np(sig);
    const char* descr = sigdescr_np(sig);
    if (abbrev && descr) return std::string("SIG") + abbrev + ", " + descr;
#endif
    return "signal " + std::to_string(sig);
}

enum class Read { done, failed, not_started };

// Reads one input in the child. Read::not_started when the child could not be started (then
// neither `out` nor `error` was touched).
Read read_in_child(const std::string& path, const std::string& format, const ReadLimits& limits, caio::MeshData& out,
                   std::string& error) {
    const std::string name = path == "-" ? "<stdin>" : path;
    const double time_s = std::min(limits.time_s, 1e7);  // within what the clock and rlimits represent
    int data[2], err[2];
    if (!make_pipe(data)) return Read::not_started;
    if (!make_pipe(err)) {
        ::close(data[0]);
        ::close(data[1]);
        return Read::not_started;
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, data[1], 1);
    posix_spawn_file_actions_adddup2(&actions, err[1], 2);
    if (path != "-") posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 34))
    posix_spawn_file_actions_addclosefrom_np(&actions, 3);
#endif
    // the child starts with no signal blocked and SIGPIPE at its default, whatever this thread has
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
    std::snprintf(mib, sizeof mib, "%.17g", limits.memory_mib);
    std::string arg0 = "coverage-axis", arg1 = "--internal-read", arg2 = path, arg3 = format;
    char* argv[] = {&arg0[0], &arg1[0], &arg2[0], &arg3[0], seconds, mib, nullptr};
    pid_t pid = -1;
    const int spawned = posix_spawn(&pid, "/proc/self/exe", &actions, &attr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
    ::close(data[1]);
    ::close(err[1]);
    if (spawned != 0) {
        ::close(data[0]);
        ::close(err[0]);
        return Read::not_started;
    }

    const auto deadline = Clock::now() + std::chrono::duration<double>(time_s);
    auto ms_left = [&]() {
        const double left = std::chrono::duration<double, std::milli>(deadline - Clock::now()).count();
        return left <= 0 ? 0 : int(std::min(left + 1, 1e6));
    };
    std::error_code ec;
    const auto file_bytes = path == "-" ? uintmax_t(-1) : std::filesystem::file_size(path, ec);
    FrameReader frame(out, ec ? UINT64_MAX : uint64_t(file_bytes));
    std::string stderr_text;
    bool timed_out = false;
    pollfd fds[2] = {{data[0], POLLIN, 0}, {err[0], POLLIN, 0}};
    while (fds[0].fd >= 0 || fds[1].fd >= 0) {
        const int wait_ms = ms_left();
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
    // the pipes are closed (the child is exiting) or the deadline passed: wait for the child, which
    // may not outlive the deadline either
    int status = 0;
    for (int pause_ms = 1;; pause_ms = std::min(2 * pause_ms, 20)) {
        if (timed_out || ms_left() == 0) {
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

    auto failed = [&](const std::string& what) {
        out = caio::MeshData{};
        error = name + ": " + what;
        return Read::failed;
    };
    if (timed_out)
        return failed("reading through assimp did not end within its time limit of " + seconds_text(time_s) +
                      "; the reader was stopped (--read-time-limit, --time-limit)");
    if (!frame.problem().empty()) return failed("the assimp reader's output was malformed (" + frame.problem() + ")");
    const std::string said = last_line(stderr_text);
    if (WIFSIGNALED(status)) {
        const int sig = WTERMSIG(status);
        if (sig == SIGXCPU) return failed("the assimp reader used more than its " + seconds_text(time_s) + " of CPU time");
        return failed("the assimp reader crashed (" + signal_text(sig) + ")" + (said.empty() ? "" : ": " + said));
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return failed("the assimp reader exited with status " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) +
                      (said.empty() ? "" : ": " + said));
    if (!frame.complete()) return failed("the assimp reader's output was malformed (cut short)");
    if (!frame.ok()) {
        out = caio::MeshData{};
        error = frame.message();
        return Read::failed;
    }
    const size_t nv = out.positions.size() / 3;
    for (uint32_t i : out.triangles)
        if (i >= nv) return failed("the assimp reader's output was malformed (an index out of range)");
    if (!frame.take_joint_names()) return failed("the assimp reader's output was malformed (joint names)");
    const std::string skin = caio::skin_problem(out);
    if (!skin.empty()) return failed("the assimp reader's output was malformed (" + skin + ")");
    out.dropped = frame.dropped();
    return Read::done;
}

}  // namespace

bool read_input(const std::string& path, const std::string& format, const ReadLimits& limits, caio::MeshData& out,
                std::string& error) {
    if (caio::is_assimp_input(path, format)) {
        const Read r = read_in_child(path, format, limits, out, error);
        if (r != Read::not_started) return r == Read::done;
    }
    return caio::read_mesh(path, format, out, error);
}

int read_child_command(int argc, char** argv) {
    if (argc != 6) {
        std::fprintf(stderr, "coverage-axis --internal-read PATH FORMAT SECONDS MIB: the tool's own reader process\n");
        return 2;
    }
#ifdef __linux__
    prctl(PR_SET_PDEATHSIG, SIGKILL);  // a parent that is gone no longer waits for this read
#endif
    const std::string path = argv[2], format = argv[3];
    const double seconds = std::strtod(argv[4], nullptr);
    double mib = std::strtod(argv[5], nullptr);
    lower_limit(RLIMIT_CORE, 0);
    // the parent stops this process at `seconds` of wall time; the CPU limit holds if it cannot
    lower_limit(RLIMIT_CPU, rlim_t(std::ceil(std::max(seconds, 0.0))) + 1, 1);
    // the frame goes to a copy of standard output; the reader's own prints go to standard error
    const int frame_fd = dup(1);
    dup2(2, 1);
    caio::MeshData mesh;
    std::string error;
    uint64_t input_bytes = 0;
    const bool ok = caio::read_mesh(path, format, mesh, error, [&](size_t bytes) {
        input_bytes = bytes;
        if (!(mib > 0)) mib = kBaseMemoryMiB + kMemoryPerInputByte * double(bytes) / (1 << 20);
        // an address-sanitizer build reserves terabytes of shadow memory up front: no limit there
        if (!sanitizer_build()) lower_limit(RLIMIT_AS, rlim_t(std::min(mib, 1e12) * (1 << 20)));
    });
    if (!ok && (error.find("bad_alloc") != std::string::npos || error.find("out of memory") != std::string::npos)) {
        char note[96];
        std::snprintf(note, sizeof note, " (the read's memory limit is %.0f MiB: --read-memory-limit)", mib);
        error += note;
    }
    if (!ok && error.size() > kMaxMessage) error.resize(kMaxMessage);
    FrameHeader h{};
    std::memcpy(h.magic, kMagic, sizeof kMagic);
    h.ok = ok ? 1 : 0;
    h.input_bytes = input_bytes;
    h.vertices = mesh.positions.size() / 3;
    h.triangles = mesh.triangles.size() / 3;
    h.normals = mesh.normals.size() / 3;
    h.message_bytes = ok ? 0 : error.size();
    std::string dropped;  // the reader's lines hold no newline (they are printable)
    for (const std::string& line : mesh.dropped) dropped += (dropped.empty() ? "" : "\n") + line;
    if (dropped.size() > kMaxDropped) dropped.resize(kMaxDropped);
    h.dropped_bytes = ok ? dropped.size() : 0;
    const caio::SkinData& s = mesh.skin;
    std::vector<uint32_t> name_lengths;
    std::string names;
    for (const std::string& n : s.joint_names) {
        name_lengths.push_back(uint32_t(n.size()));
        names += n;
    }
    if (ok) {
        h.joints = s.joint_names.size();
        h.influences = s.influences;
        h.gltf_nodes = s.gltf_nodes.size();
        h.name_bytes = names.size();
    }
    auto write_vector = [&](const auto& v) { return write_all(frame_fd, v.data(), v.size() * sizeof(v[0])); };
    const bool written =
        frame_fd >= 0 && write_all(frame_fd, &h, sizeof h) &&
        (ok ? write_all(frame_fd, mesh.positions.data(), mesh.positions.size() * sizeof(double)) &&
                  write_all(frame_fd, mesh.triangles.data(), mesh.triangles.size() * sizeof(uint32_t)) &&
                  write_all(frame_fd, mesh.normals.data(), mesh.normals.size() * sizeof(double)) &&
                  write_all(frame_fd, dropped.data(), dropped.size()) && write_vector(s.parents) &&
                  write_vector(s.inverse_bind) && write_vector(s.joint_world) && write_vector(s.gltf_nodes) &&
                  write_vector(s.vertex_joints) && write_vector(s.vertex_weights) && write_vector(name_lengths) &&
                  write_all(frame_fd, names.data(), names.size())
            : write_all(frame_fd, error.data(), error.size()));
    // no destructors at exit: nothing of a reader that went wrong runs after the frame
    _exit(written ? 0 : 1);
}

}  // namespace cli
