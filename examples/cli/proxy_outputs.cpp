// proxy_outputs.cpp: --proxies and --proxies-json: the engine proxies of the skeleton
// (ca_proxies: spheres, capsules or boxes), their primitives and placements as the writers take
// them (glTF, --colliders, --rig), their stats for the report, and the --proxies-json file.
#include "output_file.h"
#include "run_steps.h"

namespace cli {
namespace {

// The proxies' primitives, and how an engine places each, as the writers take them.
std::vector<caio::ProxyData> proxy_data(const ca_proxy_set* p) {
    std::vector<caio::ProxyData> out(ca_proxy_set_count(p));
    const int32_t* kinds = ca_proxy_set_kinds(p);
    const double *centers = ca_proxy_set_centers(p), *radii = ca_proxy_set_radii(p);
    for (size_t i = 0; i < out.size(); ++i) {
        caio::ProxyData& d = out[i];
        d.kind = kinds[i];
        for (int k = 0; k < 3; ++k) {
            d.a[k] = centers[6 * i + size_t(k)];
            d.b[k] = centers[6 * i + 3 + size_t(k)];
        }
        d.radius_a = radii[2 * i];
        d.radius_b = radii[2 * i + 1];
        ca_proxy_placement pl;
        pl.struct_size = sizeof pl;
        ca_proxy_set_placement(p, i, &pl);   // i < count: cannot fail
        caio::ColliderShape& c = d.placed;
        c.kind = pl.kind;
        for (int k = 0; k < 3; ++k) {
            c.translation[k] = pl.center[k];
            c.size[k] = 2 * pl.half_extents[k];
        }
        for (int k = 0; k < 4; ++k) c.rotation[k] = pl.rotation[k];
        c.radius_top = pl.radius_top;
        c.radius_bottom = pl.radius_bottom;
        c.height = pl.height;
    }
    return out;
}

// The proxies' stats (--json's "proxies" and the --proxies-json file's fields).
Json proxy_stats_json(const ca_proxy_stats& s, const RunOptions& o, size_t count) {
    return Json{{"shapes", o.proxies},
                {"mode", o.proxy_mode},
                {"count", count},
                {"count_limit", o.proxy.count},
                {"hd_surface_to_proxies", s.hd_surface_to_proxies},
                {"hd_proxies_to_surface", s.hd_proxies_to_surface},
                {"hd_two_sided", s.hd_two_sided},
                {"mean_surface_to_proxies", s.mean_surface_to_proxies},
                {"mean_proxies_to_surface", s.mean_proxies_to_surface},
                {"outside_bound", s.outside_bound},
                {"skeleton_outside", s.skeleton_outside},
                {"union_volume", s.union_volume},
                {"outside_volume", s.outside_volume},
                {"radius_change", s.radius_change},
                {"diagonal", s.diagonal},
                {"candidates", s.candidates},
                {"surface_cells", s.surface_cells},
                {"time_s", s.time_s}};
}

}  // namespace

// --proxies: the engine proxies of the skeleton, their data for the writers and their stats.
bool run_proxies(Run& run, const RunOptions& o, std::vector<caio::ProxyData>& proxies, Json& proxy_stats,
                 Failure& failure) {
    const ca_skeleton_view view = skeleton_view(run.sk);
    const ca_status st = ca_proxies(run.ctx, run.set, &view, &o.proxy, &run.proxies);
    if (st != CA_OK) return failure = library_failure(run.ctx, st, "proxies"), false;
    ca_proxy_stats ps;
    ps.struct_size = sizeof ps;
    ca_proxy_set_stats(run.proxies, &ps);
    proxies = proxy_data(run.proxies);
    proxy_stats = proxy_stats_json(ps, o, proxies.size());
    return true;
}

// --proxies-json: {"proxies": [one object per primitive], then the stats}.
bool write_proxies_json(const std::string& path, const std::vector<caio::ProxyData>& proxies, const Json& stats,
                        Failure& failure) {
    Json list = Json::array();
    for (const caio::ProxyData& p : proxies) {
        const Json a = {p.a[0], p.a[1], p.a[2]}, b = {p.b[0], p.b[1], p.b[2]};
        const caio::ColliderShape& c = p.placed;
        if (p.kind == CA_PROXY_CAPSULE)
            list.push_back({{"kind", "capsule"}, {"a", a}, {"radius_a", p.radius_a}, {"b", b}, {"radius_b", p.radius_b}});
        else if (p.kind == CA_PROXY_BOX)
            list.push_back({{"kind", "box"}, {"center", a}, {"rotation", {c.rotation[0], c.rotation[1], c.rotation[2], c.rotation[3]}},
                            {"half_extents", {c.size[0] / 2, c.size[1] / 2, c.size[2] / 2}}});
        else list.push_back({{"kind", "sphere"}, {"center", a}, {"radius", p.radius_a}});
    }
    Json doc = {{"proxies", list}};
    for (const auto& [key, value] : stats.items()) doc[key] = value;
    std::string err;
    if (!caio::write_bytes(path, doc.dump(1) + "\n", err)) return failure = file_failure(err), false;
    return true;
}

}  // namespace cli
