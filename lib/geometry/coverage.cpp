// coverage.cpp: the sparse sample/ball coverage relation (see coverage.h). One nanoflann
// radius query per ball over a k-d tree of the samples; both directions stored as sorted
// compressed lists (put in order by two transposes, not by sorting). Never dense.
#include "coverage.h"
#include "kdtree.h"
#include "parallel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <new>

namespace ca {

void Coverage::build_transpose() {
    sample_ptr.assign(n_samples + 1, 0);
    for (uint32_t j : ball_samples) sample_ptr[size_t(j) + 1]++;
    for (size_t j = 0; j < n_samples; ++j) sample_ptr[j + 1] += sample_ptr[j];
    sample_balls.assign(ball_samples.size(), 0);
    std::vector<uint32_t> next(sample_ptr.begin(), sample_ptr.end() - 1);
    // Balls are visited in ascending order, so every sample's list comes out sorted.
    for (size_t i = 0; i < n_balls; ++i)
        for (uint32_t k = ball_ptr[i]; k < ball_ptr[i + 1]; ++k)
            sample_balls[next[ball_samples[k]]++] = uint32_t(i);
}

Status build_coverage(const std::vector<Vec3>& samples, const std::vector<Vec3>& centers,
                      const std::vector<double>& dilated_radii, const Monitor& monitor, Coverage& out, int threads) {
    if (centers.size() != dilated_radii.size())
        return fail(Code::invalid_argument, "build_coverage: centers and radii differ in size");
    if (samples.size() >= size_t(std::numeric_limits<uint32_t>::max()) ||
        centers.size() >= size_t(std::numeric_limits<uint32_t>::max()))
        return fail(Code::invalid_argument, "build_coverage: too many samples or balls");
    for (const Vec3& p : samples)
        if (!p.allFinite()) return fail(Code::invalid_input, "build_coverage: non-finite sample");
    for (size_t i = 0; i < centers.size(); ++i) {
        if (!centers[i].allFinite()) return fail(Code::invalid_input, "build_coverage: non-finite ball centre");
        if (!std::isfinite(dilated_radii[i]) || dilated_radii[i] < 0)
            return fail(Code::invalid_input, "build_coverage: radius must be finite and >= 0");
    }
    Coverage cov;
    cov.n_samples = samples.size();
    cov.n_balls = centers.size();
    cov.ball_ptr.assign(cov.n_balls + 1, 0);
    if (!samples.empty() && !centers.empty()) {
        const PointTree tree(samples);
        // Balls are independent: in batches of kBatch balls, each thread queries a contiguous
        // range into its own list, and the lists are appended in ball order after the batch
        // (the same arrays for any thread count; at most one batch held twice in memory).
        constexpr size_t kBatch = 4096;
        const int threads_used = resolve_threads(threads);
        struct Range { size_t begin = 0, end = 0; std::vector<uint32_t> samples; std::vector<uint32_t> sizes; };
        for (size_t start = 0; start < cov.n_balls; start += kBatch) {
            const size_t stop = std::min(cov.n_balls, start + kBatch);
            const size_t workers = std::min<size_t>(size_t(std::max(1, threads_used)), stop - start);
            const size_t chunk = (stop - start + workers - 1) / workers;
            std::vector<Range> ranges(workers);
            auto query = [&](size_t w) {
                Range& rg = ranges[w];
                rg.begin = std::min(stop, start + w * chunk);
                rg.end = std::min(stop, rg.begin + chunk);
                for (size_t i = rg.begin; i < rg.end; ++i) {
                    // the covers rule (coverage.h); unsorted hits: the lists are put in
                    // ascending order once, at the end
                    const size_t hits = tree.for_each_within_squared(
                        centers[i], covered_radius2(dilated_radii[i]), [&](size_t j) { rg.samples.push_back(uint32_t(j)); });
                    rg.sizes.push_back(uint32_t(hits));
                }
            };
            // a worker thread that cannot be started does its range here: the same arrays; a
            // worker's exception (out of memory) reaches the caller after all have ended
            run_workers(workers, query);
            for (const Range& rg : ranges) {
                if (cov.ball_samples.size() + rg.samples.size() >= size_t(std::numeric_limits<uint32_t>::max()))
                    return fail(Code::out_of_memory, "build_coverage: coverage relation exceeds 2^32 entries");
                cov.ball_samples.insert(cov.ball_samples.end(), rg.samples.begin(), rg.samples.end());
                uint32_t at = cov.ball_ptr[rg.begin];
                for (size_t i = rg.begin; i < rg.end; ++i) cov.ball_ptr[i + 1] = (at += rg.sizes[i - rg.begin]);
            }
            if (!monitor.report("coverage", double(stop) / double(cov.n_balls)))
                return monitor.stop_status("coverage");
        }
    }
    // The ball lists are in k-d tree order: the sample lists built from them come out
    // ascending (balls visited in order), and the ball lists rebuilt from those too: two
    // linear passes, so no list needs a sort of its own.
    cov.build_transpose();
    {
        std::vector<uint32_t> next(cov.ball_ptr.begin(), cov.ball_ptr.end() - 1);
        for (size_t j = 0; j < cov.n_samples; ++j)
            for (uint32_t k = cov.sample_ptr[j]; k < cov.sample_ptr[j + 1]; ++k)
                cov.ball_samples[next[cov.sample_balls[k]]++] = uint32_t(j);
    }
    if (!monitor.report("coverage", 1.0)) return monitor.stop_status("coverage");
    out = std::move(cov);
    return Status::success();
}

}  // namespace ca
