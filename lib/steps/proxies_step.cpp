// proxies_step.cpp: engine proxies as one request: the caller's skeleton brought to the candidate
// set's internal units, the proxies made on the set's surface with its inside and distance
// queries (proxies.h), and the result in the caller's units.
#include "steps.h"

namespace ca {

Status proxies_step(const CandidateSet& set, const Skeleton& skeleton, const ProxyOptions& opt,
                    const Monitor& monitor, ProxyResult& out) {
    out = ProxyResult{};
    if (Status st = check_mesh_set(set, "engine proxies"); !st.ok()) return st;
    const Normalization& n = set.surface.norm;
    Skeleton sk = skeleton;
    for (Ball& b : sk.balls) {
        b.center = n.to_internal(b.center);
        b.radius /= n.scale;
    }
    Status st = make_proxies(set.surface.mesh, set.queries, sk, opt, monitor, out);
    if (!st.ok()) return st;
    for (Proxy& p : out.proxies) {
        for (Ball* b : {&p.a, &p.b}) {
            b->center = n.to_user(b->center);
            b->radius *= n.scale;
        }
        p.half *= n.scale;  // boxes; the axes are directions
    }
    out.stats.diagonal *= n.scale;
    out.stats.union_volume *= n.scale * n.scale * n.scale;
    out.stats.outside_volume *= n.scale * n.scale * n.scale;
    out.stats.outside_objective *= n.scale * n.scale * n.scale;
    out.stats.outside_lower_bound *= n.scale * n.scale * n.scale;
    return Status::success();
}

}  // namespace ca
