// cli.h: pieces the command-line tool's commands share.
#pragma once
#include "coverage_axis.h"
#include "mesh_io.h"

#include <string>

namespace cli {

// A borrowed view of a mesh or point cloud read from a file.
ca_surface_view surface_view(const caio::MeshData& mesh);

// Evaluates a skeleton against the input surface; prints a one-line error and returns false on failure.
bool evaluate(ca_context* ctx, const caio::MeshData& mesh, const ca_skeleton_view& skeleton,
              const ca_evaluate_options& options, ca_evaluation& out);

// The JSON members of an evaluation (without braces), e.g. "hd_two_sided":1.23,...
std::string evaluation_json(const ca_evaluation& e);

// `coverage-axis evaluate INPUT SKELETON.ma [options]`
int evaluate_command(int argc, char** argv);

}  // namespace cli
