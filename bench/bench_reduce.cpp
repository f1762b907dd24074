// bench_reduce.cpp: the two steps before the set-cover solve, timed on their own: building the
// coverage relation (build_coverage) and reducing it to its kernel (the reduction of the exact
// solver, detail::reduce_set_cover), per paper model at the defaults (|S| 1500, Voronoi
// candidates, delta 0.02). Each is repeated and its median printed, so that a change of a few
// milliseconds can be seen through the machine's noise.
#include "bench_common.h"
#include "bench_surface.h"
#include "candidates.h"
#include "coverage.h"
#include "setcover.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

constexpr int kRepeats = 9;

double median_ms(std::vector<double> t) {
    std::sort(t.begin(), t.end());
    return 1e3 * t[t.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    const std::string root = argc > 1 ? argv[1] : "../shared/data";
    const auto models = bench::list_files(root + "/meshes/paper", ".obj");
    std::printf("\n## Coverage and reduction (|S| 1500, Voronoi candidates, delta 0.02; median of %d runs, ms)\n\n",
                kRepeats);
    std::printf("| model | |S| x |P| | coverage entries | kernel | forced | coverage ms | reduction ms |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    double sum_cov = 0, sum_red = 0, max_red = 0;
    size_t n = 0, within_10ms = 0;
    for (const std::string& path : models) {
        const std::string name = bench::stem(path);
        ca::Surface s;
        if (!bench::load_surface(path, s)) { std::printf("| %s | read failed |\n", name.c_str()); continue; }
        ca::CandidateSet set;
        const ca::Status st = ca::generate_candidates(std::move(s), ca::CandidateOptions{}, ca::Monitor{}, set);
        if (!st.ok()) { std::printf("| %s | candidates failed: %s |\n", name.c_str(), st.message.c_str()); continue; }
        std::vector<ca::Vec3> centers;
        std::vector<double> dilated;
        for (const ca::Ball& b : set.balls) {
            centers.push_back(b.center);
            dilated.push_back(b.radius + 0.02);  // the surface is normalised: delta 0.02 of the longest side
        }
        ca::Coverage cov;
        std::vector<double> t_cov, t_red;
        bool ok = true;
        for (int k = 0; k < kRepeats && ok; ++k) {
            const auto t = std::chrono::steady_clock::now();
            ok = ca::build_coverage(set.cover_samples, centers, dilated, ca::Monitor{}, cov).ok();
            t_cov.push_back(bench::seconds_since(t));
        }
        std::vector<uint32_t> forced, kernel_balls, kernel_samples;
        ca::Coverage kernel;
        for (int k = 0; k < kRepeats && ok; ++k) {
            const auto t = std::chrono::steady_clock::now();
            ok = ca::detail::reduce_set_cover(cov, ca::CoverOptions{}, true, ca::Monitor{}, forced, kernel, kernel_balls,
                                              kernel_samples)
                     .ok();
            t_red.push_back(bench::seconds_since(t));
        }
        if (!ok) { std::printf("| %s | coverage or reduction failed |\n", name.c_str()); continue; }
        const double c = median_ms(t_cov), r = median_ms(t_red);
        std::printf("| %s | %zu x %zu | %zu | %zu x %zu | %zu | %.2f | %.2f |\n", name.c_str(), cov.n_samples,
                    cov.n_balls, cov.ball_samples.size(), kernel.n_samples, kernel.n_balls, forced.size(), c, r);
        sum_cov += c;
        sum_red += r;
        max_red = std::max(max_red, r);
        within_10ms += r <= 10.0;
        ++n;
    }
    std::printf("\n%zu models: coverage %.1f ms in all; reduction %.1f ms in all, max %.2f ms, %zu within 10 ms\n", n,
                sum_cov, sum_red, max_red, within_10ms);
    return 0;
}
