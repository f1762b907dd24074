// read_child_command.cpp: `coverage-axis --internal-read PATH FORMAT SECONDS MIB`, the child
// process that reads one input through assimp for read_input (isolated_read.cpp). It lowers its
// own limits first (no core file, CPU time, and once the input's size is known its address
// space), reads the input with caio::read_mesh and writes one frame (read_frame.cpp) to its
// standard output; whatever the reader itself prints goes to standard error, which the parent
// keeps to quote in a crash's message. It ends with _exit: nothing of a reader that went wrong
// runs after the frame.
#include "isolated_read.h"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>

#include <sys/resource.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

namespace cli {
namespace {

// The address space a read through assimp gets by default: room for the process itself (the tool
// and its libraries) and a multiple of the input far above what assimp's importers build per input
// byte, so a legitimate file never meets it while a runaway allocation does within seconds
// (docs/cli.md has the figures).
constexpr double kBaseMemoryMiB = 512;
constexpr double kMemoryPerInputByte = 128;

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

}  // namespace

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
    // no destructors at exit: nothing of a reader that went wrong runs after the frame
    _exit(write_frame(frame_fd, ok, mesh, error, input_bytes) ? 0 : 1);
}

}  // namespace cli
