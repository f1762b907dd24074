// isolated_read.h: the pieces of reading an input through assimp in a child process (read_input,
// isolated_read.cpp), shared by the files that hold them: the frame the child writes and the
// parent reads (read_frame.cpp), the child process started and watched by the parent
// (reader_process.cpp) and the child's own side (read_child_command.cpp).
#pragma once
#include "cli.h"

#include <cstdint>
#include <string>
#include <vector>

namespace cli {

// ---- the frame the child writes: a header, then the mesh's arrays or the error message ----

constexpr char kFrameMagic[8] = {'C', 'A', 'M', 'E', 'S', 'H', '0', '3'};

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

// The child's side: writes the frame of a read to `fd` (the mesh when `ok`, else `error`, cut to
// kMaxMessage; the dropped lines cut to kMaxDropped). False when a write fails.
bool write_frame(int fd, bool ok, const caio::MeshData& mesh, const std::string& error, uint64_t input_bytes);

// The parent's side: the frame as it arrives, the header, then the arrays it announces, read
// straight into `out`. Every count in the header is checked against the input's size before
// memory is taken for it.
class FrameReader {
public:
    FrameReader(caio::MeshData& out, uint64_t input_limit);
    // Reads what is ready on `fd`; false at its end (or when the frame turned out malformed).
    bool read_from(int fd);
    bool complete() const { return problem_.empty() && part_ == parts_.size(); }
    bool ok() const { return header_.ok == 1; }
    // The dropped parts' lines, once the frame is complete.
    std::vector<std::string> dropped() const;
    const std::string& message() const { return message_; }
    const std::string& problem() const { return problem_; }
    // The joint names cut from their bytes by their lengths, once the frame is complete; false
    // when the lengths do not add up to the bytes.
    bool take_joint_names();

private:
    struct Part {
        char* data;
        size_t size;
    };
    bool start_body();
    bool check_counts();
    bool size_arrays();
    void lay_out_parts();
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

// ---- the child process, as the parent sees it (reader_process.cpp) ----

// How a child's read ended.
struct ChildEnd {
    bool timed_out = false;    // the time limit passed: the child was stopped
    int status = 0;            // waitpid's status
    std::string stderr_text;   // the start of the child's standard error (for a crash's message)
};

// Starts `coverage-axis --internal-read PATH FORMAT SECONDS MIB` (this executable) with its
// standard output and error on pipes, feeds the output to `frame` and keeps the start of the error,
// and waits for the child at most `time_s` seconds from the start, stopping it past them. False
// when the child could not be started (then `frame` saw nothing).
bool run_reader_child(const std::string& path, const std::string& format, double time_s, double memory_mib,
                      FrameReader& frame, ChildEnd& end);

}  // namespace cli
