// output_file.h: writes a whole file from memory for the binary writers (glTF, PNG, SVG): the
// file is written in one go and every write or close error is reported as "path: what".
#pragma once
#include <string>

namespace caio {

bool write_bytes(const std::string& path, const std::string& data, std::string& error);

}  // namespace caio
