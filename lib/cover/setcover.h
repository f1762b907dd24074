// setcover.h: choose the fewest balls that cover every (non-ignorable) sample: reduction to a
// fixpoint (forced balls, dominated balls, dominated samples), then an exact solve of the kernel
// (greedy, Lagrangian / LP bounds, row-weighting local search for the incumbent, CBC to prove it;
// time budget, honest bound/gap), or a heuristic (greedy, Coverage Axis++), each followed by
// redundancy removal.
// CBC is not thread-safe: every CBC call in the process goes through one mutex (the only
// process-wide state of the library); Clp's LPs need none and run at once.
#pragma once
#include "common.h"
#include "coverage.h"

namespace ca {

enum class Solver : int32_t { exact = 0, greedy = 1, capp = 2 };

// How hard the exact solver works for a proof (deterministic either way, unless the time limit
// cuts it short):
// - fast (default): greedy, the LP bound (raised by one ball when branching on one column of the
//   LP shows it; tried on components of at most kFastCbcMaxRows rows, and on larger ones whose
//   LP lies within kFastBranchShortfall of the next integer), local search; CBC only when a
//   single ball separates the incumbent from the bound and the kernel left after reduced-cost
//   fixing is small (kFastCbcMaxRows rows), with at most kFastCbcNodes branch-and-bound nodes
//   and without CBC's preprocessing and cuts (on such small kernels they cost more than they
//   save). Otherwise the local-search cover is returned with its LP bound and gap (usually
//   already the optimum: CBC's remaining work is the proof).
// - prove: greedy, the LP bound (with the branching step) and the local search as above, then a
//   short CBC search for a smaller cover among the columns of zero reduced cost at the LP duals
//   (at most 30 nodes, no strong branching: core_cover), then CBC until the cover is proven
//   optimal or the time limit ends it.
enum class Effort : int32_t { fast = 0, prove = 1 };
constexpr uint32_t kFastCbcMaxRows = 400;
// The fast effort's branching step also runs on larger components when their LP lies within
// this much of the next integer (see solve_component).
constexpr double kFastBranchShortfall = 0.2;
constexpr int kFastCbcNodes = 200;

struct CoverOptions {
    Solver solver = Solver::exact;
    // Wall-clock budget of the whole solve (reduction included); <= 0 means no limit. Anytime:
    // on expiry the best cover found so far (never worse than greedy) is returned with a valid
    // lower bound and gap. Overshoot: the reduction and the first greedy always run to the end,
    // and CBC checks its limit only between nodes, so its root LP and cut loop on a large
    // kernel can overrun the budget (by the time of one root LP on the densest kernels).
    double time_limit_s = 60.0;
    Effort effort = Effort::fast;  // see Effort
    int32_t threads = 1;          // CBC threads (1 = serial, deterministic)
    // Threads for the independent local-search runs (0 = all cores). Results do not depend on it.
    int32_t search_threads = 0;
    // Exact solver internal switch (tests, benchmarks): before CBC on a whole kernel component,
    // try row generation (exact ILPs on growing row subsets) with part of the budget. Off by
    // default: on the paper kernels it only delayed CBC (it still runs on components too large
    // for one CBC solve).
    bool row_generation = false;
    // 0 = off. n > 0: the caller only needs to know whether a cover of at most n balls exists
    // (the target size's bisection, selection.h): the exact solver stops a component once the
    // lower bounds show that every cover has more than n balls, and returns the best cover found
    // so far (more than n balls, not proven) with a valid lower bound above n. Any solve it does
    // not stop is the same as without it.
    uint32_t give_up_above = 0;
    // Optional per-sample / per-ball masks (empty = none). Non-zero = set.
    std::vector<uint8_t> ignorable_samples;   // need not be covered
    std::vector<uint8_t> forced_in;           // must be selected
    std::vector<uint8_t> forced_out;          // must not be selected
    // Needed by the Coverage Axis++ score only (ball centres and radii, undilated).
    const std::vector<Vec3>* centers = nullptr;
    const std::vector<double>* radii = nullptr;
};

struct CoverResult {
    std::vector<uint32_t> selected;        // ball indices, ascending
    int32_t proven_optimal = 0;            // 1 iff the exact solver proved optimality
    double objective = 0;                  // |selected|
    double lower_bound = 0;                // valid lower bound on the optimum
    double gap = 0;                        // (objective - lower_bound) / objective
    size_t rows_before = 0, cols_before = 0, rows_after = 0, cols_after = 0, forced = 0;
    double time_reduce_s = 0, time_solve_s = 0;
    size_t components = 0;                 // connected components of the kernel (exact solver)
    size_t cbc_components = 0;             // of which needed CBC (the rest: bound met the incumbent)
    size_t rowgen_rounds = 0;              // row-generation rounds (sub-problems solved), all components
    std::vector<uint32_t> uncovered;       // samples no allowed ball covers (only when allowed)
};

// A sample that no allowed ball covers and that is not ignorable makes the problem infeasible:
// returns Code::uncoverable listing how many and which, unless `skip_uncoverable` is set, in
// which case those samples are reported in result.uncovered and treated as ignorable.
Status solve_set_cover(const Coverage& cov, const CoverOptions& opt, bool skip_uncoverable,
                       const Monitor& monitor, CoverResult& result);

// Drops balls of `selected` (ascending on return) whose required samples are all covered by the
// other selected balls, smallest lists first (ties: lower index). Empty `required` = every
// sample required; balls with a non-zero `locked` entry (if given) are never dropped.
void remove_redundant_balls(const Coverage& cov, const std::vector<uint8_t>& required,
                            const std::vector<uint8_t>& locked, std::vector<uint32_t>& selected);

namespace detail {
// The reduction alone (exposed for tests): same checks as solve_set_cover; on success `forced`
// lists the balls the reduction selects (forced_in and forced by the reduction, ascending) and
// `kernel` is what remains (kernel.n_samples rows, kernel.n_balls columns, both directions
// filled), kernel_samples / kernel_balls giving their original indices. The optimum of the
// original problem equals forced.size() + the optimum of the kernel.
Status reduce_set_cover(const Coverage& cov, const CoverOptions& opt, bool skip_uncoverable, const Monitor& monitor,
                        std::vector<uint32_t>& forced, Coverage& kernel, std::vector<uint32_t>& kernel_balls,
                        std::vector<uint32_t>& kernel_samples);
}  // namespace detail

}  // namespace ca
