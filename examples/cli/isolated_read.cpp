// isolated_read.cpp: reading an input through assimp in a child process, so that a crash, an
// assertion's abort, a hang or runaway memory inside a third-party importer ends that read with
// an error naming the file instead of ending the tool (or a whole batch). read_input starts the
// child (reader_process.cpp: this executable's `--internal-read`, read_child_command.cpp), which
// lowers its own limits, reads the input and writes one frame (read_frame.cpp): the mesh (the lines
// naming what the reader dropped, and the skin) or the error message. This file is the parent's
// judgement of how the child ended: past the time limit, a signal, a non-zero exit or a malformed
// frame becomes an error naming the file; a mesh that arrives is checked again (indices in range,
// joint names, caio::skin_problem like any reader's). Where the child cannot be started (no /proc,
// the executable gone) the read runs in this process.
#include "isolated_read.h"
#include "reader_common.h"

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <filesystem>

#include <sys/wait.h>

namespace cli {
namespace {

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

// Why the child's read failed, from how it ended and what it wrote ("" when it ended well and its
// frame is complete).
std::string ending_problem(const ChildEnd& end, const FrameReader& frame, double time_s) {
    if (end.timed_out)
        return "reading through assimp did not end within its time limit of " + seconds_text(time_s) +
               "; the reader was stopped (--read-time-limit, --time-limit)";
    if (!frame.problem().empty()) return "the assimp reader's output was malformed (" + frame.problem() + ")";
    const std::string said = last_line(end.stderr_text);
    const int status = end.status;
    if (WIFSIGNALED(status)) {
        const int sig = WTERMSIG(status);
        if (sig == SIGXCPU) return "the assimp reader used more than its " + seconds_text(time_s) + " of CPU time";
        return "the assimp reader crashed (" + signal_text(sig) + ")" + (said.empty() ? "" : ": " + said);
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return "the assimp reader exited with status " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) +
               (said.empty() ? "" : ": " + said);
    if (!frame.complete()) return "the assimp reader's output was malformed (cut short)";
    return "";
}

// What is wrong with the mesh that arrived ("" when nothing): its indices, its joint names (taken
// into `out` here) and its skin.
std::string mesh_problem(caio::MeshData& out, FrameReader& frame) {
    const size_t nv = out.positions.size() / 3;
    for (uint32_t i : out.triangles)
        if (i >= nv) return "the assimp reader's output was malformed (an index out of range)";
    if (!frame.take_joint_names()) return "the assimp reader's output was malformed (joint names)";
    const std::string skin = caio::skin_problem(out);
    if (!skin.empty()) return "the assimp reader's output was malformed (" + skin + ")";
    return "";
}

enum class Read { done, failed, not_started };

// Reads one input in the child. Read::not_started when the child could not be started (then
// neither `out` nor `error` was touched).
Read read_in_child(const std::string& path, const std::string& format, const ReadLimits& limits, caio::MeshData& out,
                   std::string& error) {
    const std::string name = path == "-" ? "<stdin>" : path;
    const double time_s = std::min(limits.time_s, 1e7);  // within what the clock and rlimits represent
    std::error_code ec;
    const auto file_bytes = path == "-" ? uintmax_t(-1) : std::filesystem::file_size(path, ec);
    FrameReader frame(out, ec ? UINT64_MAX : uint64_t(file_bytes));
    ChildEnd end;
    if (!run_reader_child(path, format, time_s, limits.memory_mib, frame, end)) return Read::not_started;

    auto failed = [&](const std::string& what) {
        out = caio::MeshData{};
        error = name + ": " + what;
        return Read::failed;
    };
    const std::string problem = ending_problem(end, frame, time_s);
    if (!problem.empty()) return failed(problem);
    if (!frame.ok()) {
        out = caio::MeshData{};
        error = frame.message();
        return Read::failed;
    }
    const std::string bad_mesh = mesh_problem(out, frame);
    if (!bad_mesh.empty()) return failed(bad_mesh);
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

}  // namespace cli
