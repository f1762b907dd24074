// curve_tree.cpp: the curve skeleton of a medial skeleton as a tree over its balls (rig.h). The
// shortest paths from the root, where a step costs its length over the balls' mean radius, run
// along the fattest balls, so across a sheet they take its middle. The ends of those paths (the
// balls no neighbour is farther than) are tips; the farthest first, each tip's path is kept up to
// the tree built so far when the tip's ball reaches past every ball of that tree by more than
// min_branch times the ball's radius and the new path is longer than min_branch times the tip's
// radius (a limb does both; a sheet's rim, a bump or a fat ball in a crevice does not), while the
// joints stay within max_joints. The kept paths, cut at junctions, are the branches.
#include "rig.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <string>

namespace ca {
namespace {

using Graph = std::vector<std::vector<std::pair<uint32_t, double>>>;

// The skeleton's edges and face edges, then the shortest links joining its components to the
// root's (Prim's algorithm over the balls, a component at a time).
Graph graph_of(const Skeleton& s, uint32_t root) {
    const size_t n = s.balls.size();
    std::vector<std::vector<uint32_t>> adj(n);
    auto link = [&](uint32_t a, uint32_t b) {
        if (a == b) return;
        adj[a].push_back(b);
        adj[b].push_back(a);
    };
    for (const auto& e : s.edges) link(e[0], e[1]);
    for (const Tri& t : s.faces)
        for (int k = 0; k < 3; ++k) link(t[k], t[(k + 1) % 3]);
    for (auto& a : adj) {
        std::sort(a.begin(), a.end());
        a.erase(std::unique(a.begin(), a.end()), a.end());
    }
    // join the components: grow the root's, each time by the component of the ball nearest to it
    std::vector<char> inside(n, 0);
    std::vector<double> gap(n, std::numeric_limits<double>::infinity());
    std::vector<uint32_t> from(n, 0);
    auto absorb = [&](uint32_t start) {
        std::vector<uint32_t> stack{start};
        inside[start] = 1;
        std::vector<uint32_t> added;
        while (!stack.empty()) {
            const uint32_t v = stack.back();
            stack.pop_back();
            added.push_back(v);
            for (uint32_t w : adj[v])
                if (!inside[w]) {
                    inside[w] = 1;
                    stack.push_back(w);
                }
        }
        for (uint32_t v : added)
            for (size_t u = 0; u < n; ++u)
                if (!inside[u]) {
                    const double d = (s.balls[u].center - s.balls[v].center).norm();
                    if (d < gap[u] || (d == gap[u] && v < from[u])) {
                        gap[u] = d;
                        from[u] = v;
                    }
                }
    };
    absorb(root);
    for (;;) {
        size_t best = n;
        for (size_t u = 0; u < n; ++u)
            if (!inside[u] && (best == n || gap[u] < gap[best])) best = u;
        if (best == n) break;
        link(uint32_t(best), from[best]);
        absorb(uint32_t(best));
    }
    Graph g(n);
    for (size_t v = 0; v < n; ++v)
        for (uint32_t w : adj[v]) g[v].emplace_back(w, (s.balls[v].center - s.balls[w].center).norm());
    return g;
}

}  // namespace

Status curve_tree(const Skeleton& s, const RigOptions& opt, CurveTree& out) {
    out = CurveTree{};
    const size_t n = s.balls.size();
    if (opt.root < -1 || opt.root >= int64_t(n))
        return fail(Code::invalid_argument, "root " + std::to_string(opt.root) + " is not a ball of the " +
                                                std::to_string(n) + " (or -1: the largest)");
    if (opt.max_joints < 1) return fail(Code::invalid_argument, "max_joints must be at least 1");
    if (!(std::isfinite(opt.joint_spacing) && opt.joint_spacing > 0))
        return fail(Code::invalid_argument, "joint_spacing must be a finite number above 0");
    if (!(std::isfinite(opt.min_branch) && opt.min_branch >= 0))
        return fail(Code::invalid_argument, "min_branch must be a finite number >= 0");
    uint32_t root = 0;
    if (opt.root >= 0) root = uint32_t(opt.root);
    else
        for (uint32_t i = 1; i < n; ++i)
            if (s.balls[i].radius > s.balls[root].radius) root = i;
    out.root = root;
    out.graph = graph_of(s, root);
    const Graph& g = out.graph;

    // shortest paths from the root, a step costing its length over the mean radius of its balls
    double rmax = 0;
    for (const Ball& b : s.balls) rmax = std::max(rmax, b.radius);
    const double floor = rmax > 0 ? 0.05 * rmax : 1.0;
    std::vector<double> cost(n, std::numeric_limits<double>::infinity()), length(n, 0);
    std::vector<int64_t> up(n, -1);
    using Entry = std::pair<double, uint32_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    cost[root] = 0;
    queue.emplace(0.0, root);
    while (!queue.empty()) {
        const auto [c, v] = queue.top();
        queue.pop();
        if (c > cost[v]) continue;
        for (const auto& [w, len] : g[v]) {
            const double step = len / (0.5 * (s.balls[v].radius + s.balls[w].radius) + floor);
            if (c + step < cost[w]) {
                cost[w] = c + step;
                up[w] = v;
                length[w] = length[v] + len;
                queue.emplace(cost[w], w);
            }
        }
    }

    // tips: no neighbour costs more; the farthest along their paths first
    std::vector<uint32_t> tips;
    for (uint32_t v = 0; v < n; ++v) {
        if (v == root) continue;
        bool top = true;
        for (const auto& [w, len] : g[v]) top = top && (cost[w] < cost[v] || (cost[w] == cost[v] && w < v));
        if (top) tips.push_back(v);
    }
    std::sort(tips.begin(), tips.end(), [&](uint32_t a, uint32_t b) {
        return length[a] > length[b] || (length[a] == length[b] && a < b);
    });

    out.parent.assign(n, -1);
    out.in_tree.assign(n, 0);
    out.in_tree[root] = 1;
    std::vector<uint32_t> children(n, 0);
    size_t keys = 1;   // joints the kept branches need: the root, the junctions and the tips
    std::vector<uint32_t> tree_balls{root};
    for (uint32_t tip : tips) {
        uint32_t j = tip;
        while (!out.in_tree[j]) j = uint32_t(up[j]);
        // how far the tip's ball reaches past each tree ball, in that ball's radii: the least
        const Ball& t = s.balls[tip];
        double reach = std::numeric_limits<double>::infinity();
        for (uint32_t b : tree_balls) {
            const Ball& a = s.balls[b];
            if (a.radius > 0) reach = std::min(reach, ((t.center - a.center).norm() + t.radius - a.radius) / a.radius);
        }
        // and the branch is longer than that many of the tip's radii (a fat ball in a crevice is not)
        if (!(reach > opt.min_branch) || !(length[tip] - length[j] > opt.min_branch * t.radius)) continue;
        // a new tip, and a new junction where the path joins a ball with one child already
        const size_t more = 1 + (j != root && children[j] == 1 ? 1 : 0) - (j != root && children[j] == 0 ? 1 : 0);
        if (keys + more > opt.max_joints) continue;
        keys += more;
        for (uint32_t v = tip; !out.in_tree[v]; v = uint32_t(up[v])) {
            out.in_tree[v] = 1;
            tree_balls.push_back(v);
            out.parent[v] = up[v];
            ++children[uint32_t(up[v])];
        }
    }

    // branches: from each key ball, down each child to the next key ball, depth first from the root
    std::vector<std::vector<uint32_t>> kids(n);
    for (uint32_t v = 0; v < n; ++v)
        if (out.parent[v] >= 0) kids[size_t(out.parent[v])].push_back(v);
    std::vector<uint32_t> stack{root};
    while (!stack.empty()) {
        const uint32_t k = stack.back();
        stack.pop_back();
        for (uint32_t child : kids[k]) {
            std::vector<uint32_t> chain{child};
            while (kids[chain.back()].size() == 1) chain.push_back(kids[chain.back()][0]);
            out.branch_start.push_back(k);
            out.branches.push_back(chain);
            if (!kids[chain.back()].empty()) stack.push_back(chain.back());
        }
    }
    return Status::success();
}

}  // namespace ca
