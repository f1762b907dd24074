// selection.cpp: dilation, coverage and the set-cover solve, glued together (see selection.h):
// the plain solve, divide and conquer over spatial parts of the samples, and the bisection on
// the dilation for a target size.
#include "selection.h"
#include "timing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <new>

namespace ca {

namespace {

double dilate_with(double radius, Dilation d, double value) { return d == Dilation::offset ? radius + value : radius * value; }

// The coverage for smaller radii, filtered from one built for larger (or equal) radii.
Coverage shrink_coverage(const Coverage& big, const std::vector<Vec3>& samples, const std::vector<Vec3>& centers,
                         const std::vector<double>& radii) {
    Coverage c;
    c.n_samples = big.n_samples;
    c.n_balls = big.n_balls;
    c.ball_ptr.assign(c.n_balls + 1, 0);
    c.ball_samples.reserve(big.ball_samples.size());
    for (size_t i = 0; i < c.n_balls; ++i) {
        for (uint32_t k = big.ball_ptr[i]; k < big.ball_ptr[i + 1]; ++k)
            if (covers(centers[i], radii[i], samples[big.ball_samples[k]])) c.ball_samples.push_back(big.ball_samples[k]);
        c.ball_ptr[i + 1] = uint32_t(c.ball_samples.size());
    }
    c.build_transpose();
    return c;
}

// Median cuts along the longest side of the parts' boxes until every part is small enough.
void split_parts(const std::vector<Vec3>& pts, std::vector<uint32_t> ids, size_t max_part,
                 std::vector<std::vector<uint32_t>>& parts) {
    if (ids.size() <= max_part) {
        std::sort(ids.begin(), ids.end());
        parts.push_back(std::move(ids));
        return;
    }
    Vec3 lo = pts[ids[0]], hi = lo;
    for (uint32_t i : ids) { lo = lo.cwiseMin(pts[i]); hi = hi.cwiseMax(pts[i]); }
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    const size_t mid = ids.size() / 2;
    std::nth_element(ids.begin(), ids.begin() + long(mid), ids.end(), [&](uint32_t a, uint32_t b) {
        return pts[a][axis] != pts[b][axis] ? pts[a][axis] < pts[b][axis] : a < b;
    });
    std::vector<uint32_t> left(ids.begin(), ids.begin() + long(mid)), right(ids.begin() + long(mid), ids.end());
    split_parts(pts, std::move(left), max_part, parts);
    split_parts(pts, std::move(right), max_part, parts);
}

// The whole problem's masks (which samples must be covered, which balls may or must be chosen),
// checked first, so that errors name global sample indices. Samples no allowed ball covers go to
// res.uncovered and are dropped from the required ones when opt.skip_uncoverable is set.
struct GlobalMasks {
    std::vector<uint8_t> required, allowed, locked;
};

Status global_masks(const Coverage& cov, const SelectOptions& opt, const CoverOptions& cover, CoverResult& res,
                    GlobalMasks& g) {
    const size_t m = cov.n_samples, n = cov.n_balls;
    g.required.assign(m, 1);
    g.allowed.assign(n, 1);
    g.locked.assign(n, 0);
    for (size_t j = 0; j < cover.ignorable_samples.size() && j < m; ++j) g.required[j] = !cover.ignorable_samples[j];
    for (size_t a = 0; a < cover.forced_out.size() && a < n; ++a) g.allowed[a] = !cover.forced_out[a];
    for (size_t a = 0; a < cover.forced_in.size() && a < n; ++a) g.locked[a] = cover.forced_in[a] != 0;
    if ((!cover.ignorable_samples.empty() && cover.ignorable_samples.size() != m) ||
        (!cover.forced_in.empty() && cover.forced_in.size() != n) || (!cover.forced_out.empty() && cover.forced_out.size() != n))
        return fail(Code::invalid_argument, "set cover: mask sizes do not match the problem");
    for (size_t a = 0; a < n; ++a)
        if (g.locked[a] && !g.allowed[a]) return fail(Code::invalid_argument, "set cover: a ball is both forced in and forced out");
    for (uint32_t j = 0; j < m; ++j) {
        if (!g.required[j]) continue;
        bool ok = false;
        for (uint32_t k = cov.sample_ptr[j]; k < cov.sample_ptr[j + 1] && !ok; ++k) ok = g.allowed[cov.sample_balls[k]] != 0;
        if (!ok) res.uncovered.push_back(j);
    }
    if (!res.uncovered.empty()) {
        if (!opt.skip_uncoverable)
            return fail(Code::uncoverable, std::to_string(res.uncovered.size()) + " of " + std::to_string(m) +
                                               " samples are covered by no candidate ball (first: " +
                                               std::to_string(res.uncovered[0]) + ")");
        for (uint32_t j : res.uncovered) g.required[j] = 0;
    }
    for (uint8_t v : g.required) res.rows_before += v;
    for (uint8_t v : g.allowed) res.cols_before += v;
    return Status::success();
}

// One part's sub-problem: its samples (local indices in part order), every ball covering one of
// them (`balls`, ascending global indices), and the global masks carried over into pc. local_of
// and ball_local are all UINT32_MAX on entry and are left so on return.
void part_problem(const Coverage& cov, const std::vector<uint32_t>& part, const GlobalMasks& g,
                  std::vector<uint32_t>& local_of, std::vector<uint32_t>& ball_local, Coverage& sub,
                  std::vector<uint32_t>& balls, CoverOptions& pc) {
    sub = Coverage{};
    sub.n_samples = part.size();
    balls.clear();
    for (uint32_t l = 0; l < part.size(); ++l) {
        local_of[part[l]] = l;
        for (uint32_t k = cov.sample_ptr[part[l]]; k < cov.sample_ptr[part[l] + 1]; ++k) {
            const uint32_t a = cov.sample_balls[k];
            if (ball_local[a] == UINT32_MAX) { ball_local[a] = 0; balls.push_back(a); }
        }
    }
    std::sort(balls.begin(), balls.end());
    sub.n_balls = balls.size();
    sub.ball_ptr.assign(balls.size() + 1, 0);
    for (uint32_t b = 0; b < balls.size(); ++b) {
        const uint32_t a = balls[b];
        ball_local[a] = b;
        for (uint32_t k = cov.ball_ptr[a]; k < cov.ball_ptr[a + 1]; ++k)
            if (local_of[cov.ball_samples[k]] != UINT32_MAX) sub.ball_samples.push_back(local_of[cov.ball_samples[k]]);
        sub.ball_ptr[b + 1] = uint32_t(sub.ball_samples.size());
    }
    sub.build_transpose();
    pc.ignorable_samples.assign(part.size(), 0);
    for (uint32_t l = 0; l < part.size(); ++l) pc.ignorable_samples[l] = !g.required[part[l]];
    pc.forced_in.assign(balls.size(), 0);
    pc.forced_out.assign(balls.size(), 0);
    for (uint32_t b = 0; b < balls.size(); ++b) {
        pc.forced_in[b] = g.locked[balls[b]];
        pc.forced_out[b] = !g.allowed[balls[b]];
    }
    for (uint32_t j : part) local_of[j] = UINT32_MAX;
    for (uint32_t a : balls) ball_local[a] = UINT32_MAX;
}

// Adds a part's solve to the whole's counters; any part's lower bound also bounds the whole.
void add_part(const CoverResult& pr, CoverResult& res) {
    res.lower_bound = std::max(res.lower_bound, pr.lower_bound);
    res.time_reduce_s += pr.time_reduce_s;
    res.rows_after += pr.rows_after;
    res.cols_after += pr.cols_after;
    res.forced += pr.forced;
    res.components += pr.components;
    res.cbc_components += pr.cbc_components;
}

// The merged parts' selection, made irredundant, against the global greedy cover: the smaller one
// is kept, and the greedy's global bound (forced balls of the whole reduction + disjoint kernel
// rows) joins the parts' bound.
Status finish_parts(const Coverage& cov, const SelectOptions& opt, const CoverOptions& cover, const GlobalMasks& g,
                    const Monitor& monitor, std::vector<uint32_t> selected, CoverResult& res) {
    for (uint32_t a = 0; a < cov.n_balls; ++a)
        if (g.locked[a]) selected.push_back(a);
    remove_redundant_balls(cov, g.required, g.locked, selected);
    CoverOptions gc = cover;
    gc.solver = Solver::greedy;
    CoverResult greedy;
    if (monitor.cancelled()) return fail(Code::cancelled, "set cover: cancelled");
    if (solve_set_cover(cov, gc, opt.skip_uncoverable, monitor, greedy).ok()) {
        res.lower_bound = std::max(res.lower_bound, greedy.lower_bound);
        if (greedy.selected.size() < selected.size()) selected = greedy.selected;
    }
    res.selected = selected;
    res.objective = double(selected.size());
    res.lower_bound = std::min(res.lower_bound, res.objective);
    res.proven_optimal = cover.solver == Solver::exact && res.lower_bound >= res.objective ? 1 : 0;
    res.gap = res.objective > 0 ? (res.objective - res.lower_bound) / res.objective : 0.0;
    return Status::success();
}

// Divide and conquer (see SelectOptions::dc_threshold): the samples cut into spatial parts, each
// part solved alone, the union finished by finish_parts.
Status solve_parts(const Coverage& cov, const std::vector<Vec3>& samples, const SelectOptions& opt,
                   const CoverOptions& cover, const Monitor& monitor, CoverResult& res, uint32_t& n_parts) {
    const size_t m = cov.n_samples, n = cov.n_balls;
    const auto t0 = Clock::now();
    res = CoverResult{};
    GlobalMasks g;
    Status masks = global_masks(cov, opt, cover, res, g);
    if (!masks.ok()) return masks;

    std::vector<uint32_t> all(m);
    for (uint32_t j = 0; j < m; ++j) all[j] = j;
    std::vector<std::vector<uint32_t>> parts;
    split_parts(samples, std::move(all), std::max<size_t>(1, opt.dc_part_samples), parts);
    n_parts = uint32_t(parts.size());

    CoverOptions pc = cover;
    pc.centers = nullptr;
    pc.radii = nullptr;
    if (pc.time_limit_s > 0 && std::isfinite(pc.time_limit_s)) pc.time_limit_s = cover.time_limit_s / double(parts.size());
    std::vector<uint32_t> selected, balls, local_of(m, UINT32_MAX), ball_local(n, UINT32_MAX);
    std::vector<Vec3> sub_centers;
    std::vector<double> sub_radii;
    Coverage sub;
    for (const auto& part : parts) {
        if (monitor.cancelled()) return fail(Code::cancelled, "set cover: cancelled");
        part_problem(cov, part, g, local_of, ball_local, sub, balls, pc);
        if (cover.solver == Solver::capp && cover.centers && cover.radii) {
            sub_centers.clear();
            sub_radii.clear();
            for (uint32_t a : balls) { sub_centers.push_back((*cover.centers)[a]); sub_radii.push_back((*cover.radii)[a]); }
            pc.centers = &sub_centers;
            pc.radii = &sub_radii;
        }
        CoverResult pr;
        Status st = solve_set_cover(sub, pc, false, monitor, pr);
        if (!st.ok()) return st;
        for (uint32_t b : pr.selected) selected.push_back(balls[b]);
        add_part(pr, res);
    }
    Status finished = finish_parts(cov, opt, cover, g, monitor, std::move(selected), res);
    if (!finished.ok()) return finished;
    res.time_solve_s = seconds_since(t0) - res.time_reduce_s;
    return Status::success();
}

// One selection at a fixed coverage.
Status solve_coverage(const Coverage& cov, const CandidateSet& set, const SelectOptions& opt, const CoverOptions& cover,
                      const Monitor& monitor, CoverResult& res, uint32_t& parts) {
    parts = 0;
    Status st = opt.dc_threshold > 0 && cov.n_samples > opt.dc_threshold
                    ? solve_parts(cov, set.cover_samples, opt, cover, monitor, res, parts)
                    : solve_set_cover(cov, cover, opt.skip_uncoverable, monitor, res);
    // say why a sample has no ball and what to do: candidates are inside the shape, so a sample
    // with nothing inside behind it (an open scan's rim, a sheet, a hole) gets none within delta
    if (st.code == Code::uncoverable)
        st.message += ": no candidate ball inside the shape reaches them within the dilation (no inside behind "
                      "them: an open surface, a sheet or a part thinner than the sampling); skip_uncoverable "
                      "(--skip-uncoverable) gives the skeleton of the rest";
    return st;
}

// The options in range and a set to select from.
Status check_select(const CandidateSet& set, const SelectOptions& opt) {
    if (opt.dilation == Dilation::offset && !(std::isfinite(opt.delta) && opt.delta >= 0))
        return fail(Code::invalid_argument, "delta must be a finite number >= 0");
    if (opt.dilation == Dilation::scale && !(std::isfinite(opt.scale) && opt.scale >= 1))
        return fail(Code::invalid_argument, "scale must be a finite number >= 1");
    if (opt.target_count > 0 && !(std::isfinite(opt.target_tolerance) && opt.target_tolerance > 0))
        return fail(Code::invalid_argument, "target_tolerance must be a finite number > 0");
    if (set.balls.empty()) return fail(Code::no_candidates, "the candidate set has no balls");
    if (set.cover_samples.empty()) return fail(Code::degenerate_input, "the candidate set has no surface samples");
    return Status::success();
}

// What the two strategies share: the candidate balls, their radii dilated at the current
// value, the cover options pointing at them, and the clock of the whole selection.
struct Selecting {
    Selecting(const CandidateSet& set, const SelectOptions& opt, const Monitor& monitor)
        : set(set), opt(opt), monitor(monitor), n(set.balls.size()), centers(n), radii(n), dilated(n) {
        for (size_t i = 0; i < n; ++i) {
            centers[i] = set.balls[i].center;
            radii[i] = set.balls[i].radius;
        }
        cover = opt.cover;
        if (cover.search_threads == 0) cover.search_threads = opt.threads;
        cover.centers = &centers;
        cover.radii = &radii;
    }
    Selecting(const Selecting&) = delete;   // cover points at its own arrays

    void make_radii(double value) {
        for (size_t i = 0; i < n; ++i) dilated[i] = dilate_with(radii[i], opt.dilation, value);
    }
    // The selection of out.cover at dilation `value` with these dilated radii.
    void finish(double value, const std::vector<double>& dil_radii, Selection& out) const {
        out.indices = out.cover.selected;
        out.dilated_radii.clear();
        for (uint32_t i : out.indices) out.dilated_radii.push_back(dil_radii[i]);
        out.delta = opt.dilation == Dilation::offset ? value : 0;
        out.scale = opt.dilation == Dilation::scale ? value : 0;
        out.time_total_s = seconds_since(t0);
    }
    // Once a cover is solved, a budget that ran out meanwhile leaves it the result (the
    // solver stopped early with its best cover); only a cancel discards it.
    bool solved_report() const {
        return monitor.deadline.expired() ? !monitor.cancelled() : monitor.report("selection", 1);
    }

    const CandidateSet& set;
    const SelectOptions& opt;
    const Monitor& monitor;
    const Clock::time_point t0 = Clock::now();
    const size_t n;
    std::vector<Vec3> centers;
    std::vector<double> radii, dilated;
    CoverOptions cover;
};

// One cover at the options' dilation.
Status select_plain(Selecting& s, Selection& out) {
    const SelectOptions& opt = s.opt;
    const double value = opt.dilation == Dilation::offset ? opt.delta : opt.scale;
    s.make_radii(value);
    Coverage cov;
    Status st = build_coverage(s.set.cover_samples, s.centers, s.dilated, s.monitor, cov, opt.threads);
    if (!st.ok()) return st;
    out.time_coverage_s = seconds_since(s.t0);
    if (s.monitor.cancelled()) return s.monitor.stop_status("selection");
    st = solve_coverage(cov, s.set, opt, s.cover, s.monitor, out.cover, out.parts);
    if (!st.ok()) return st;
    out.probes = 1;
    if (!s.solved_report()) return s.monitor.stop_status("selection");
    s.finish(value, s.dilated, out);
    return Status::success();
}

// Target size: bracket, then bisect. `big` is the coverage at the upper end of the
// bracket; every probe below it is filtered from it (coverage grows with the dilation).
Status select_target_count(Selecting& s, Selection& out) {
    const SelectOptions& opt = s.opt;
    const Monitor& monitor = s.monitor;
    const Dilation dil = opt.dilation;
    const uint32_t K = opt.target_count;
    const double lowest = dil == Dilation::offset ? 0.0 : 1.0;
    const double highest = dil == Dilation::offset ? 4.0 : 1e6;  // offset 4 > the unit cube's diagonal
    Coverage big;
    double t_cov = 0;
    // Solves at `value`: fits = cover found with <= K balls; an uncoverable sample counts as
    // "too many balls".
    CoverResult best;
    uint32_t best_parts = 0;
    double best_value = -1;
    std::vector<double> best_radii;
    // each probe only decides whether K balls suffice: a solve whose bounds show that they do not
    // stops there (the decision, and every solve that is not stopped, as without it)
    CoverOptions decide = s.cover;
    decide.give_up_above = K;
    auto probe = [&](double value, bool rebuild, bool& fits) -> Status {
        if (monitor.stopped()) return monitor.stop_status("selection");
        s.make_radii(value);
        const auto tc = Clock::now();
        Coverage cov;
        if (rebuild) {
            Status st = build_coverage(s.set.cover_samples, s.centers, s.dilated, monitor, big, opt.threads);
            if (!st.ok()) return st;
        } else {
            cov = shrink_coverage(big, s.set.cover_samples, s.centers, s.dilated);
        }
        t_cov += seconds_since(tc);
        CoverResult res;
        uint32_t parts = 0;
        ++out.probes;
        Status st = solve_coverage(rebuild ? big : cov, s.set, opt, decide, monitor, res, parts);
        if (st.code == Code::uncoverable) { fits = false; return Status::success(); }
        if (!st.ok()) return st;
        fits = res.objective <= double(K);
        if (fits) {
            best = std::move(res);
            best_parts = parts;
            best_value = value;
            best_radii = s.dilated;
        }
        return Status::success();
    };
    double lo = lowest, hi = dil == Dilation::offset ? opt.delta : opt.scale;
    bool fits = false;
    Status st = probe(hi, true, fits);
    if (!st.ok()) return st;
    if (fits) {
        bool fits_lo = false;
        if (hi > lowest) {
            // the lower end may already fit
            st = probe(lowest, false, fits_lo);
            if (!st.ok()) return st;
        }
        if (fits_lo || hi <= lowest) hi = lo = lowest;
    } else {
        for (;;) {
            lo = hi;
            hi = dil == Dilation::offset ? std::max(2 * hi, 0.01) : std::max(2 * hi, 1.1);
            if (hi > highest) return fail(Code::invalid_argument, "no dilation gives a cover with target_count balls");
            st = probe(hi, true, fits);
            if (!st.ok()) return st;
            if (fits) break;
        }
    }
    while (hi - lo > opt.target_tolerance) {
        const double mid = 0.5 * (lo + hi);
        st = probe(mid, false, fits);
        if (!st.ok()) return st;
        if (fits) hi = mid; else lo = mid;
    }
    if (best_value < 0) return fail(Code::internal, "target size: no probe fitted");
    out.cover = std::move(best);
    out.parts = best_parts;
    out.time_coverage_s = t_cov;
    if (!s.solved_report()) return monitor.stop_status("selection");
    s.finish(best_value, best_radii, out);
    return Status::success();
}

}  // namespace

double dilate(double radius, const SelectOptions& opt) {
    return dilate_with(radius, opt.dilation, opt.dilation == Dilation::offset ? opt.delta : opt.scale);
}

Status select_balls(const CandidateSet& set, const SelectOptions& opt, const Monitor& monitor, Selection& out) {
    out = Selection{};
    const Status st = check_select(set, opt);
    if (!st.ok()) return st;
    Selecting s(set, opt, monitor);   // starts the clock of out.time_total_s
    if (!monitor.report("selection", 0)) return monitor.stop_status("selection");
    return opt.target_count == 0 ? select_plain(s, out) : select_target_count(s, out);
}

}  // namespace ca
