// output_file.cpp: whole-file writes with errors reported (see output_file.h).
#include "output_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace caio {

bool write_bytes(const std::string& path, const std::string& data, std::string& error) {
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) {
        error = path + ": cannot open for writing: " + std::strerror(errno);
        return false;
    }
    const size_t n = std::fwrite(data.data(), 1, data.size(), f);
    int err = n != data.size() ? (errno ? errno : EIO) : 0;
    if (std::fclose(f) != 0 && err == 0) err = errno ? errno : EIO;
    if (err != 0) {
        error = path + ": write error: " + std::strerror(err);
        std::remove(path.c_str());
        return false;
    }
    return true;
}

}  // namespace caio
