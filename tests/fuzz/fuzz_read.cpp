// fuzz_read.cpp: libFuzzer harness for one file reader of examples/io; built once per format as
// fuzz_read_<format> with CA_FUZZ_FORMAT set to the format name (make fuzz). The input bytes are
// the file. A crash, sanitizer report, or a result breaking the reader's contract (an index out
// of range, normals not one per vertex, output beyond one vertex and one triangle per input byte,
// a skin that fails caio::skin_problem, a failure without a message or with output left) is a bug.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "mesh_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    caio::MeshData m;
    std::string error;
    const bool ok = caio::read_mesh_buffer(bytes, CA_FUZZ_FORMAT, m, error);
    if (!ok) {
        if (error.empty() || !m.positions.empty() || !m.triangles.empty() || !m.normals.empty() || !m.skin.empty())
            std::abort();
        return 0;
    }
    const size_t nv = m.positions.size() / 3;
    if (m.positions.size() % 3 != 0 || m.triangles.size() % 3 != 0 || nv == 0) std::abort();
    if (!m.normals.empty() && m.normals.size() != m.positions.size()) std::abort();
    if (nv > size || m.triangles.size() / 3 > size) std::abort();
    for (uint32_t i : m.triangles)
        if (i >= nv) std::abort();
    if (!caio::skin_problem(m).empty() || m.skin.joint_names.size() > size) std::abort();
    return 0;
}
