// read_frame.cpp: the frame in which the reader child hands its result to the tool (CAMESH03): a
// fixed header (isolated_read.h), then either the mesh (positions, triangles, normals, the lines
// naming what the reader dropped, then the skin: parents, bind matrices, glTF nodes, weights and
// the joint names after their lengths) or the error message. The child writes it (write_frame);
// the parent reads it as it arrives (FrameReader), checking every count in the header against the
// input's size and fixed bounds before it takes memory for it, so a broken or hostile child cannot
// make the tool allocate what the input could not hold.
#include "isolated_read.h"

#include <algorithm>
#include <cerrno>
#include <cstring>

#include <unistd.h>

namespace cli {
namespace {

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

}  // namespace

bool write_frame(int fd, bool ok, const caio::MeshData& mesh, const std::string& error, uint64_t input_bytes) {
    const std::string message = error.substr(0, size_t(kMaxMessage));
    FrameHeader h{};
    std::memcpy(h.magic, kFrameMagic, sizeof kFrameMagic);
    h.ok = ok ? 1 : 0;
    h.input_bytes = input_bytes;
    h.vertices = mesh.positions.size() / 3;
    h.triangles = mesh.triangles.size() / 3;
    h.normals = mesh.normals.size() / 3;
    h.message_bytes = ok ? 0 : message.size();
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
    auto write_vector = [&](const auto& v) { return write_all(fd, v.data(), v.size() * sizeof(v[0])); };
    return fd >= 0 && write_all(fd, &h, sizeof h) &&
           (ok ? write_vector(mesh.positions) && write_vector(mesh.triangles) && write_vector(mesh.normals) &&
                     write_all(fd, dropped.data(), dropped.size()) && write_vector(s.parents) &&
                     write_vector(s.inverse_bind) && write_vector(s.joint_world) && write_vector(s.gltf_nodes) &&
                     write_vector(s.vertex_joints) && write_vector(s.vertex_weights) && write_vector(name_lengths) &&
                     write_all(fd, names.data(), names.size())
               : write_all(fd, message.data(), message.size()));
}

FrameReader::FrameReader(caio::MeshData& out, uint64_t input_limit) : out_(out), input_limit_(input_limit) {
    parts_.push_back({reinterpret_cast<char*>(&header_), sizeof header_});
}

bool FrameReader::read_from(int fd) {
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

std::vector<std::string> FrameReader::dropped() const {
    std::vector<std::string> lines;
    for (size_t at = 0; at < dropped_.size();) {
        const size_t end = std::min(dropped_.find('\n', at), dropped_.size());
        lines.push_back(dropped_.substr(at, end - at));
        at = end + 1;
    }
    return lines;
}

bool FrameReader::take_joint_names() {
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

// Checks the header, then lays out the parts it announces: the message, or the mesh's arrays.
bool FrameReader::start_body() {
    const FrameHeader& h = header_;
    if (std::memcmp(h.magic, kFrameMagic, sizeof kFrameMagic) != 0 || h.ok > 1) return problem_ = "no frame header", false;
    if (h.ok == 0) {
        if (h.message_bytes == 0 || h.message_bytes > kMaxMessage) return problem_ = "a bad message length", false;
        message_.resize(size_t(h.message_bytes));
        parts_.push_back({&message_[0], message_.size()});
        return true;
    }
    if (!check_counts() || !size_arrays()) return false;
    lay_out_parts();
    return true;
}

// The mesh's and the skin's counts within what the input could hold.
bool FrameReader::check_counts() {
    const FrameHeader& h = header_;
    if (h.input_bytes > input_limit_ || h.vertices > h.input_bytes || h.triangles > h.input_bytes ||
        h.vertices > UINT32_MAX || (h.normals != 0 && h.normals != h.vertices) || h.dropped_bytes > kMaxDropped)
        return problem_ = "counts beyond the input's limits", false;
    // every joint and every byte of its name comes from the input
    if (h.joints > h.input_bytes || h.name_bytes > h.input_bytes || h.influences > caio::kMaxInfluences ||
        (h.joints == 0) != (h.influences == 0) || (h.gltf_nodes != 0 && h.gltf_nodes != h.joints))
        return problem_ = "skin counts beyond the input's limits", false;
    return true;
}

// The arrays sized as the header says; false when this process cannot hold them.
bool FrameReader::size_arrays() {
    const FrameHeader& h = header_;
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
    return true;
}

// The parts after the header, in the order the child writes them (write_frame).
void FrameReader::lay_out_parts() {
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
}

}  // namespace cli
