// preview.cpp: the mesh-and-skeleton picture (see preview.h). One camera projects both; the PNG
// is rasterised in software (z-buffered mesh, skeleton blended over it in painter's order) and
// encoded by stb_image_write; the SVG draws the same primitives as sorted polygons and circles.
#include "preview.h"

#include "output_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <numeric>
#include <vector>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace caio {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Vec {
    double x = 0, y = 0, z = 0;
};
Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec operator*(double s, Vec a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec cross(Vec a, Vec b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
Vec normalized(Vec a) {
    const double n = std::sqrt(dot(a, a));
    return n > 0 ? (1 / n) * a : a;
}

// Model coordinates in a y-up frame: z-up models turn (x, y, z) -> (x, z, -y).
Vec y_up(const double* p, char up) { return up == 'z' ? Vec{p[0], p[2], -p[1]} : Vec{p[0], p[1], p[2]}; }

struct Color {
    double r, g, b;
};
Color operator*(double s, Color c) { return {s * c.r, s * c.g, s * c.b}; }
const Color kMesh{0.80, 0.81, 0.84}, kBall{0.25, 0.45, 0.90}, kFace{0.95, 0.45, 0.20}, kEdge{0.10, 0.10, 0.15};

// Screen position (pixels, y down) and depth (larger = nearer the viewer).
struct Point {
    double x, y, depth;
};

struct Camera {
    Vec right, up, dir, light;
    double scale = 1, cu = 0, cv = 0, width = 0, height = 0;
    Point project(Vec p) const {
        return {width / 2 + (dot(p, right) - cu) * scale, height / 2 - (dot(p, up) - cv) * scale, dot(p, dir)};
    }
    // Lambert term of a surface normal, two-sided (meshes may face either way).
    double shade(Vec n) const { return 0.3 + 0.7 * std::fabs(dot(normalized(n), light)); }
};

Camera make_camera(const MeshData& mesh, const SkeletonData& s, const PreviewOptions& o, double width, double height) {
    double az = o.azimuth_deg, el = o.elevation_deg;
    if (o.automatic_view) automatic_view(mesh, o.up, az, el);
    az *= kPi / 180;
    el *= kPi / 180;
    Camera c;
    c.dir = {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
    c.right = normalized(cross(Vec{0, 1, 0}, c.dir));
    if (dot(c.right, c.right) < 0.5) c.right = {1, 0, 0};  // looking straight up or down
    c.up = cross(c.dir, c.right);
    c.light = normalized(c.dir + 0.6 * c.up - 0.4 * c.right);
    double lo_u = INFINITY, hi_u = -INFINITY, lo_v = INFINITY, hi_v = -INFINITY;
    auto extend = [&](Vec p, double r) {
        lo_u = std::min(lo_u, dot(p, c.right) - r);
        hi_u = std::max(hi_u, dot(p, c.right) + r);
        lo_v = std::min(lo_v, dot(p, c.up) - r);
        hi_v = std::max(hi_v, dot(p, c.up) + r);
    };
    for (size_t i = 0; i + 2 < mesh.positions.size(); i += 3) extend(y_up(&mesh.positions[i], o.up), 0);
    for (size_t i = 0; i < s.radii.size(); ++i) extend(y_up(&s.centers[3 * i], o.up), s.radii[i]);
    c.width = width;
    c.height = height;
    if (lo_u <= hi_u) {
        const double span = std::max({hi_u - lo_u, (hi_v - lo_v) * width / height, 1e-300});
        c.scale = 0.92 * width / span;
        c.cu = (lo_u + hi_u) / 2;
        c.cv = (lo_v + hi_v) / 2;
    }
    return c;
}

// The skeleton's balls, faces and edges, each sorted back to front.
struct Scene {
    std::vector<Point> centers;
    std::vector<double> radii_px;
    std::vector<Vec> world;
    std::vector<size_t> balls, faces, edges;
};

Scene make_scene(const SkeletonData& s, const Camera& cam, char up) {
    Scene sc;
    const size_t nv = s.radii.size();
    for (size_t i = 0; i < nv; ++i) {
        sc.world.push_back(y_up(&s.centers[3 * i], up));
        sc.centers.push_back(cam.project(sc.world.back()));
        sc.radii_px.push_back(s.radii[i] * cam.scale);
    }
    auto depth = [&](const std::vector<uint32_t>& idx, size_t k, size_t n) {
        double d = 0;
        for (size_t j = 0; j < n; ++j) d += sc.centers[idx[k * n + j]].depth;
        return d / double(n);
    };
    auto sorted = [](size_t count, auto key) {
        std::vector<size_t> order(count);
        std::iota(order.begin(), order.end(), size_t(0));
        std::vector<double> keys(count);
        for (size_t i = 0; i < count; ++i) keys[i] = key(i);
        std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return keys[a] < keys[b]; });
        return order;
    };
    sc.balls = sorted(nv, [&](size_t i) { return sc.centers[i].depth; });
    sc.faces = sorted(s.faces.size() / 3, [&](size_t f) { return depth(s.faces, f, 3); });
    sc.edges = sorted(s.edges.size() / 2, [&](size_t e) { return depth(s.edges, e, 2); });
    return sc;
}

// ---- PNG: a float RGB canvas with a depth buffer -------------------------------------------

struct Canvas {
    int w, h;
    std::vector<float> rgb;
    std::vector<double> depth;
    Canvas(int w_, int h_) : w(w_), h(h_), rgb(size_t(w_) * h_ * 3, 1.0f), depth(size_t(w_) * h_, -INFINITY) {}
    void blend(int x, int y, Color c, double a) {
        float* p = &rgb[(size_t(y) * w + x) * 3];
        p[0] = float(p[0] * (1 - a) + c.r * a);
        p[1] = float(p[1] * (1 - a) + c.g * a);
        p[2] = float(p[2] * (1 - a) + c.b * a);
    }
    // Pixel range of [lo, hi] clipped to the canvas.
    void range(double lo, double hi, int n, int& a, int& b) const {
        a = std::max(0, int(std::floor(lo)));
        b = std::min(n - 1, int(std::ceil(hi)));
    }

    // Fills a triangle; with `zbuffer` only where it is nearer than what is drawn (and records it).
    void triangle(Point a, Point b, Point c, Color col, double alpha, bool zbuffer) {
        const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        if (std::fabs(area) < 1e-12) return;
        int x0, x1, y0, y1;
        range(std::min({a.x, b.x, c.x}), std::max({a.x, b.x, c.x}), w, x0, x1);
        range(std::min({a.y, b.y, c.y}), std::max({a.y, b.y, c.y}), h, y0, y1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const double px = x + 0.5, py = y + 0.5;
                const double w0 = ((b.x - px) * (c.y - py) - (b.y - py) * (c.x - px)) / area;
                const double w1 = ((c.x - px) * (a.y - py) - (c.y - py) * (a.x - px)) / area;
                const double w2 = 1 - w0 - w1;
                if (w0 < 0 || w1 < 0 || w2 < 0) continue;
                if (zbuffer) {
                    const double z = w0 * a.depth + w1 * b.depth + w2 * c.depth;
                    double& d = depth[size_t(y) * w + x];
                    if (z <= d) continue;
                    d = z;
                }
                blend(x, y, col, alpha);
            }
    }
    // A shaded sphere of radius r (pixels) with a rim line.
    void sphere(Point c, double r, const Camera& cam, Color col, double alpha, double rim) {
        int x0, x1, y0, y1;
        range(c.x - r, c.x + r, w, x0, x1);
        range(c.y - r, c.y + r, h, y0, y1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const double dx = (x + 0.5 - c.x) / r, dy = (c.y - y - 0.5) / r, rr = dx * dx + dy * dy;
                if (rr > 1) continue;
                const Vec n = dx * cam.right + dy * cam.up + std::sqrt(1 - rr) * cam.dir;
                const double lit = 0.35 + 0.65 * std::max(0.0, dot(n, cam.light));
                if (std::sqrt(rr) * r > r - rim) blend(x, y, 0.6 * col, 0.7);
                else blend(x, y, lit * col, alpha);
            }
    }
    // A line of the given width, anti-aliased at its border.
    void line(Point a, Point b, double width, Color col) {
        const double half = width / 2;
        int x0, x1, y0, y1;
        range(std::min(a.x, b.x) - width, std::max(a.x, b.x) + width, w, x0, x1);
        range(std::min(a.y, b.y) - width, std::max(a.y, b.y) + width, h, y0, y1);
        const double ex = b.x - a.x, ey = b.y - a.y, len2 = ex * ex + ey * ey;
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const double px = x + 0.5 - a.x, py = y + 0.5 - a.y;
                const double t = len2 > 0 ? std::clamp((px * ex + py * ey) / len2, 0.0, 1.0) : 0;
                const double dist = std::hypot(px - t * ex, py - t * ey);
                const double cover = std::clamp(half + 0.5 - dist, 0.0, 1.0);
                if (cover > 0) blend(x, y, col, cover);
            }
    }
};

// 8-bit RGB, each output pixel the mean of ss x ss canvas pixels.
std::vector<unsigned char> downsample(const Canvas& c, int ss) {
    const int w = c.w / ss, h = c.h / ss;
    std::vector<unsigned char> out(size_t(w) * h * 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int k = 0; k < 3; ++k) {
                double sum = 0;
                for (int j = 0; j < ss; ++j)
                    for (int i = 0; i < ss; ++i) sum += c.rgb[(size_t(y * ss + j) * c.w + (x * ss + i)) * 3 + k];
                out[(size_t(y) * w + x) * 3 + k] = (unsigned char)std::lround(std::clamp(sum / (ss * ss), 0.0, 1.0) * 255);
            }
    return out;
}

Vec triangle_normal(const MeshData& m, size_t t, char up) {
    const Vec a = y_up(&m.positions[3 * m.triangles[t]], up), b = y_up(&m.positions[3 * m.triangles[t + 1]], up),
              c = y_up(&m.positions[3 * m.triangles[t + 2]], up);
    return cross(b - a, c - a);
}

std::string render_png(const MeshData& mesh, const SkeletonData& s, const PreviewOptions& o) {
    const int ss = 2;
    Canvas cv(o.width * ss, o.height * ss);
    const Camera cam = make_camera(mesh, s, o, cv.w, cv.h);
    std::vector<Point> p;
    for (size_t i = 0; i + 2 < mesh.positions.size(); i += 3) p.push_back(cam.project(y_up(&mesh.positions[i], o.up)));
    for (size_t t = 0; t + 2 < mesh.triangles.size(); t += 3)
        cv.triangle(p[mesh.triangles[t]], p[mesh.triangles[t + 1]], p[mesh.triangles[t + 2]],
                    cam.shade(triangle_normal(mesh, t, o.up)) * kMesh, 1.0, true);
    if (mesh.triangles.empty())  // a point cloud: its points as small grey squares
        for (const Point& q : p) cv.line(q, q, 2.0 * ss, 0.6 * kMesh);
    const Scene sc = make_scene(s, cam, o.up);
    for (size_t i : sc.balls) cv.sphere(sc.centers[i], sc.radii_px[i], cam, kBall, 0.22, 1.0 * ss);
    for (size_t f : sc.faces) {
        const uint32_t* t = &s.faces[3 * f];
        cv.triangle(sc.centers[t[0]], sc.centers[t[1]], sc.centers[t[2]],
                    cam.shade(cross(sc.world[t[1]] - sc.world[t[0]], sc.world[t[2]] - sc.world[t[0]])) * kFace, 0.55, false);
    }
    for (size_t e : sc.edges) cv.line(sc.centers[s.edges[2 * e]], sc.centers[s.edges[2 * e + 1]], 1.6 * ss, kEdge);
    for (const Point& c : sc.centers) cv.line(c, c, 4.0 * ss, kEdge);
    const std::vector<unsigned char> pixels = downsample(cv, ss);
    std::string png;
    stbi_write_png_to_func(
        [](void* user, void* data, int size) { static_cast<std::string*>(user)->append(static_cast<char*>(data), size_t(size)); },
        &png, o.width, o.height, 3, pixels.data(), o.width * 3);
    return png;
}

// ---- SVG ------------------------------------------------------------------------------------

std::string rgb(Color c) {
    char b[40];
    std::snprintf(b, sizeof b, "rgb(%d,%d,%d)", int(std::lround(std::clamp(c.r, 0.0, 1.0) * 255)),
                  int(std::lround(std::clamp(c.g, 0.0, 1.0) * 255)), int(std::lround(std::clamp(c.b, 0.0, 1.0) * 255)));
    return b;
}
std::string points(std::initializer_list<Point> ps) {
    std::string s;
    char b[48];
    for (const Point& p : ps) {
        std::snprintf(b, sizeof b, "%s%.1f,%.1f", s.empty() ? "" : " ", p.x, p.y);
        s += b;
    }
    return s;
}

std::string render_svg(const MeshData& mesh, const SkeletonData& s, const PreviewOptions& o) {
    const Camera cam = make_camera(mesh, s, o, o.width, o.height);
    char b[256];
    std::string out;
    std::snprintf(b, sizeof b, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"0 0 %d %d\">\n",
                  o.width, o.height, o.width, o.height);
    out += b;
    out += "<defs><radialGradient id=\"ball\" cx=\"35%\" cy=\"35%\" r=\"65%\"><stop offset=\"0\" stop-color=\"" +
           rgb(1.0 * Color{0.8, 0.87, 1.0}) + "\"/><stop offset=\"1\" stop-color=\"" + rgb(0.6 * kBall) +
           "\"/></radialGradient></defs>\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    std::vector<Point> p;
    for (size_t i = 0; i + 2 < mesh.positions.size(); i += 3) p.push_back(cam.project(y_up(&mesh.positions[i], o.up)));
    const size_t nt = mesh.triangles.size() / 3;
    std::vector<size_t> order(nt);
    std::iota(order.begin(), order.end(), size_t(0));
    std::vector<double> depth(nt);
    for (size_t t = 0; t < nt; ++t)
        depth[t] = p[mesh.triangles[3 * t]].depth + p[mesh.triangles[3 * t + 1]].depth + p[mesh.triangles[3 * t + 2]].depth;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t c) { return depth[a] < depth[c]; });
    for (size_t t : order) {
        const std::string fill = rgb(cam.shade(triangle_normal(mesh, 3 * t, o.up)) * kMesh);
        out += "<polygon points=\"" + points({p[mesh.triangles[3 * t]], p[mesh.triangles[3 * t + 1]], p[mesh.triangles[3 * t + 2]]}) +
               "\" fill=\"" + fill + "\" stroke=\"" + fill + "\" stroke-width=\"0.5\"/>\n";
    }
    if (nt == 0)
        for (const Point& q : p) {
            std::snprintf(b, sizeof b, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"1\" fill=\"%s\"/>\n", q.x, q.y, rgb(0.6 * kMesh).c_str());
            out += b;
        }
    const Scene sc = make_scene(s, cam, o.up);
    for (size_t i : sc.balls) {
        std::snprintf(b, sizeof b, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" fill=\"url(#ball)\" fill-opacity=\"0.3\" stroke=\"%s\" stroke-opacity=\"0.7\" stroke-width=\"0.8\"/>\n",
                      sc.centers[i].x, sc.centers[i].y, sc.radii_px[i], rgb(0.6 * kBall).c_str());
        out += b;
    }
    for (size_t f : sc.faces) {
        const uint32_t* t = &s.faces[3 * f];
        const Color c = cam.shade(cross(sc.world[t[1]] - sc.world[t[0]], sc.world[t[2]] - sc.world[t[0]])) * kFace;
        out += "<polygon points=\"" + points({sc.centers[t[0]], sc.centers[t[1]], sc.centers[t[2]]}) + "\" fill=\"" + rgb(c) +
               "\" fill-opacity=\"0.55\"/>\n";
    }
    for (size_t e : sc.edges) {
        const Point a = sc.centers[s.edges[2 * e]], c = sc.centers[s.edges[2 * e + 1]];
        std::snprintf(b, sizeof b, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"1.6\"/>\n", a.x,
                      a.y, c.x, c.y, rgb(kEdge).c_str());
        out += b;
    }
    for (const Point& c : sc.centers) {
        std::snprintf(b, sizeof b, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"2\" fill=\"%s\"/>\n", c.x, c.y, rgb(kEdge).c_str());
        out += b;
    }
    return out + "</svg>\n";
}

std::string extension(const std::string& path) {
    const size_t dot = path.find_last_of('.'), slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    std::string e = path.substr(dot + 1);
    for (char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
    return e;
}

}  // namespace

void automatic_view(const MeshData& mesh, char up, double& azimuth_deg, double& elevation_deg) {
    Vec lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i + 2 < mesh.positions.size(); i += 3) {
        const Vec p = y_up(&mesh.positions[i], up);
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    const Vec e = lo.x <= hi.x ? hi - lo : Vec{1, 1, 1};
    Vec d{e.y * e.z, e.x * e.z, e.x * e.y};  // the box's face areas
    if (dot(d, d) <= 0) d = {1, 1, 1};
    azimuth_deg = std::atan2(d.x, d.z) * 180 / kPi;
    elevation_deg = std::atan2(d.y, std::hypot(d.x, d.z)) * 180 / kPi;
}

bool write_preview(const std::string& path, const MeshData& mesh, const SkeletonData& skeleton,
                   const PreviewOptions& options, std::string& error) {
    try {
        if (options.width < 16 || options.height < 16 || options.width > 8192 || options.height > 8192) {
            error = path + ": the picture size must be 16..8192 pixels per side";
            return false;
        }
        if (mesh.positions.size() % 3 || mesh.triangles.size() % 3 || skeleton.centers.size() != 3 * skeleton.radii.size()) {
            error = path + ": inconsistent mesh or skeleton arrays";
            return false;
        }
        const size_t nv = mesh.positions.size() / 3, ns = skeleton.radii.size();
        for (uint32_t i : mesh.triangles)
            if (i >= nv) { error = path + ": mesh index out of range"; return false; }
        for (const auto* idx : {&skeleton.edges, &skeleton.faces})
            for (uint32_t i : *idx)
                if (i >= ns) { error = path + ": skeleton index out of range"; return false; }
        const std::string ext = extension(path);
        if (ext == "png") return write_bytes(path, render_png(mesh, skeleton, options), error);
        if (ext == "svg") return write_bytes(path, render_svg(mesh, skeleton, options), error);
        error = path + ": a preview file ends in .png or .svg";
        return false;
    } catch (const std::exception& e) {
        error = path + ": " + e.what();
        return false;
    }
}

}  // namespace caio
