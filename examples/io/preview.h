// preview.h: a picture of a mesh and its medial skeleton, for a quick look and for documents:
// the mesh flat-shaded (z-buffered, one light from the viewer's upper left) in orthographic
// projection, and over it the skeleton: balls as translucent shaded spheres, faces as
// translucent triangles, edges as dark lines, ball centres as dots.
#pragma once
#include "mesh_io.h"

#include <string>

namespace caio {

struct PreviewOptions {
    int width = 800, height = 600;   // pixels (PNG) or the SVG's size
    bool automatic_view = true;      // true: the view of the largest projected bounding-box area
    double azimuth_deg = 0;          // about the up axis, 0 = looking from +z (y up) / -y (z up)
    double elevation_deg = 0;        // above the horizontal plane
    char up = 'y';                   // 'y' or 'z': the model's up axis
};

// The automatic view (azimuth, elevation in degrees) for a mesh: the direction that maximises
// the projected area of its bounding box, |dx| A_x + |dy| A_y + |dz| A_z, i.e. d ~ (A_x, A_y, A_z)
// with A the areas of the box's faces.
void automatic_view(const MeshData& mesh, char up, double& azimuth_deg, double& elevation_deg);

// Writes OUT.png (8-bit RGB, 2x2 supersampled, through stb_image_write) or OUT.svg (painter's
// order) by the path's extension. False with "path: what" on an unknown extension, a size
// outside 16..8192 or a write error.
bool write_preview(const std::string& path, const MeshData& mesh, const SkeletonData& skeleton,
                   const PreviewOptions& options, std::string& error);

}  // namespace caio
