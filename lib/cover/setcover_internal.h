// setcover_internal.h: what the set-cover files share; not part of the library's interface.
// The compact problem (rows = samples x columns = balls, stored both ways) with its heuristics
// and bounds (setcover_problem.cpp), the exact machinery (lagrangian.cpp: the Lagrangian bound;
// lp.cpp: the LP; cbc.cpp: CBC behind the process-wide mutex; row_generation.cpp), the local
// search (local_search.cpp),
// the reduction of the input and of compact problems (reduction.cpp), the input checks
// (setcover_checks.cpp) and the exact solve of one component (component_solve.cpp); the solve
// driver is setcover.cpp.
#pragma once
#include "setcover.h"
#include "timing.h"

#include <atomic>
#include <chrono>
#include <functional>
#include <limits>

namespace ca {
namespace sc {


// A compact set-cover problem: R rows (samples) x C columns (balls), every row coverable.
struct Problem {
    uint32_t R = 0, C = 0;
    std::vector<uint32_t> cptr, crow;  // column -> rows, ascending
    std::vector<uint32_t> rptr, rcol;  // row -> columns, ascending
    std::vector<uint32_t> col_id, row_id;  // original ball / sample index
};


// ---- setcover_problem.cpp ----
// Drop selected columns whose required rows are all covered by the others (see the definition).
void remove_redundant(const std::vector<uint32_t>& ptr, const std::vector<uint32_t>& idx, size_t R,
                      const std::vector<uint8_t>* required, const std::vector<uint8_t>* locked,
                      std::vector<uint32_t>& sel);
std::vector<uint32_t> greedy_complete(const Problem& P, const std::vector<uint32_t>& start);
std::vector<uint32_t> greedy_cover(const Problem& P);
std::vector<uint32_t> capp_cover(const Problem& P, const std::vector<Vec3>& centers,
                                 const std::vector<double>& radii, const std::vector<uint32_t>& preselected);
// 0, 1, ..., R-1: every row of P.
std::vector<uint32_t> all_rows(const Problem& P);
// The columns of reduced cost below max_cost, and the per_row cheapest columns of each of `rows`
// (ties to the lower index), as a mask over P's columns.
std::vector<uint8_t> core_columns(const Problem& P, const std::vector<double>& cost, double max_cost, size_t per_row,
                                  const std::vector<uint32_t>& rows);
uint32_t disjoint_bound(const Problem& P);
bool covers_problem(const Problem& P, const std::vector<uint32_t>& sel);
std::vector<Problem> split_components(const Problem& P);
Problem restrict_columns(const Problem& P, const std::vector<uint8_t>& keep);
// Fills the row -> column direction of Q from its column -> row direction.
void fill_rows(Problem& Q);
// Marks the rows of column c covered; for each row it newly covers, calls f(r, d) for every
// column d that meets row r (c included), so that greedy scores can drop what r gave them.
// Returns how many rows it newly covered.
template <class F>
uint32_t cover_column(const Problem& P, uint32_t c, std::vector<uint8_t>& covered, F&& f) {
    uint32_t newly = 0;
    for (uint32_t k = P.cptr[c]; k < P.cptr[c + 1]; ++k) {
        const uint32_t r = P.crow[k];
        if (covered[r]) continue;
        covered[r] = 1;
        ++newly;
        for (uint32_t q = P.rptr[r]; q < P.rptr[r + 1]; ++q) f(r, P.rcol[q]);
    }
    return newly;
}
Problem restrict_rows(const Problem& K, const std::vector<uint32_t>& rows);
void add_spread_rows(const Problem& K, std::vector<uint32_t> cand, size_t cap, std::vector<uint32_t>& rows);

// ---- lagrangian.cpp ----
// ---------------------------------------------------------------------------------------------
// Lagrangian relaxation of the covering rows (multipliers u >= 0):
//   L(u) = sum_i u_i + sum_j min(0, c_j(u)),  c_j(u) = 1 - sum_{i in j} u_i,
// a lower bound on the optimum for every u >= 0; L(u) + c_j(u) (c_j >= 0) bounds every cover
// that contains column j. Subgradient ascent (Held-Karp step, halving on stalls), with a
// primal heuristic on the reduced costs (Caprara-Fischetti-Toth score) every few steps.
struct Lagrange {
    double bound = 0;               // best L(u) found
    std::vector<double> u, cost;    // multipliers of the best bound and their reduced costs
    std::vector<uint32_t> best;     // best cover found (ascending), possibly improved on entry's
};
// `start`: initial multipliers (size R), or null for the usual 1/(max column size) start;
// `step`: the initial step factor (halved on stalls).
Lagrange lagrangian(const Problem& P, std::vector<uint32_t> incumbent, int max_iter, const Deadline& deadline,
                    const std::vector<double>* start = nullptr, double step = 2.0);

// The volume algorithm (Barahona & Anbil 2000) for the same bound: subgradient steps along the
// subgradient of a running average of the Lagrangian solutions. Its multipliers come much closer
// to the LP's than the subgradient method's, which stalls, and most of them are 0 (a sparse
// start for the LP by row generation). Stops after max_iter steps, at the deadline, or once
// ceil(bound) >= |best|; the reduced-cost greedy runs every 8 steps.
Lagrange volume_ascent(const Problem& P, std::vector<uint32_t> incumbent, int max_iter, const Deadline& deadline);

// ---- lp.cpp ----
// The LP relaxation min 1'x, Ax >= 1, 0 <= x <= 1, solved by Clp's dual simplex (no lock: any
// number of these run at once). Returns its row duals clamped to >= 0 (empty if Clp failed or ran out of time).
// The LP optimum equals the best Lagrangian bound; the bound itself is then recomputed from these
// multipliers by `lagrangian`, so it stays valid whatever the LP's tolerances.
std::vector<double> lp_duals(const Problem& P, double time_limit_s);
// The same LP by column generation from a core (columns of small reduced cost `cost` at the
// subgradient's multipliers, a few per row at least): the core LP is solved, every other
// column is priced at its duals and those with a negative reduced cost join it (primal simplex
// from the current basis) until none is left, so the duals are optimal for the whole of P.
// Faster than the whole LP, since most columns never enter. Empty on failure, like lp_duals.
std::vector<double> lp_duals_core(const Problem& P, const std::vector<double>& cost, double time_limit_s);

// The same LP by row and column generation, for near-optimal multipliers u0 with most rows at 0
// (volume_ascent's) and their reduced costs: the LP starts with the rows of positive u0 and a
// core of cheap columns; columns that its duals price below zero join (primal simplex), then
// rows that its solution leaves uncovered (dual simplex), until neither is left, so the duals
// are optimal for the whole of P. For large kernels, where most rows never bind and the whole
// LP (even by column generation) is too slow. Empty on failure, like lp_duals.
std::vector<double> lp_duals_rows(const Problem& P, const std::vector<double>& u0, const std::vector<double>& cost,
                                  double time_limit_s);

// Tries to prove that K has no cover of at most `size` columns: its LP relaxation, then for up to
// `max_branches` of the most fractional columns of the LP solution both branches (column out,
// column in); proven when the root's bound or both branches' bounds exceed `size`. Every bound is
// L(u) recomputed from Clp's duals on the branch's own problem, so a claim is valid whatever the
// LP's tolerances. Gives up (false) as soon as `stop()` is true, or once the branches have
// taken as many simplex iterations as the root LP (a deterministic limit). Cheaper than a
// node-limited CBC search for a one-ball gap on a small kernel.
bool no_cover_within(const Problem& K, size_t size, int max_branches, const std::function<bool()>& stop = {});

// ---- cbc.cpp ----
struct CbcOutcome {
    bool ok = false;            // CBC ran and returned without error
    bool has_solution = false;  // a cover better than the cutoff, verified
    bool proven = false;        // the search finished: `solution` optimal, or none below the cutoff
    double bound = -std::numeric_limits<double>::infinity();  // valid for solutions below the cutoff
    std::vector<uint32_t> solution;  // columns, ascending
};
// How CBC searches (run_cbc).
struct CbcSettings {
    double time_limit_s = 0;      // wall-clock limit; 0 = none
    int threads = 1;
    bool first_solution = false;  // stop at the first cover below the cutoff (not proven optimal)
    bool heuristics = true;       // CBC's own primal heuristics
    int max_nodes = 0;            // > 0: branch-and-bound node limit (deterministic, unlike the time limit)
    // No preprocessing and no cut generation, for short node-limited proofs on small kernels,
    // where they cost more than the branching they save.
    bool lean = false;
    // false: no strong branching and no pseudo-cost trust (CBC's "strong 0", "trust 0"), for a
    // quick search for covers rather than a proof.
    bool strong_branching = true;
    // A weighted cover (weighted_cover.cpp): per-column costs (null: 1 each, the cardinality
    // cover above), at most max_columns columns (0: no limit), and only solutions of cost below
    // `cutoff` (with costs; the unit cover's cutoff comes from its incumbent).
    const std::vector<double>* costs = nullptr;
    size_t max_columns = 0;
    double cutoff = 0;
};
// Looks for covers smaller than `incumbent` (cutoff incumbent - 1 + kCutoffSlack); with
// settings.costs, for covers of at most settings.max_columns columns that cost less than
// settings.cutoff (`incumbent` unused).
// Exceptions from CBC other than std::bad_alloc give ok = false.
constexpr double kCutoffSlack = 1e-3;
CbcOutcome run_cbc(const Problem& P, size_t incumbent, const CbcSettings& settings);

// A cover of P smaller than `incumbent` among the columns of P's LP optimal face: those whose
// reduced cost at the LP duals (`cost`) is below kCoreMaxCost, and each row's cheapest column.
// Reduced, then searched by CBC for at most kCoreCbcNodes nodes, without strong branching
// (time_limit_s > 0: also a time limit). Returns the cover (P-local, ascending), or empty if
// none was found (or CBC failed).
constexpr double kCoreMaxCost = 1e-4;
constexpr int kCoreCbcNodes = 30;
std::vector<uint32_t> core_cover(const Problem& P, const std::vector<double>& cost, size_t incumbent,
                                 double time_limit_s, int threads, const Monitor& monitor);

// ---- row_generation.cpp ----
// Row generation (lazy covering constraints) on a reduced component K, looking for covers
// smaller than `target` (the incumbent's size; `best` below, lowered as better covers appear).
// Loop: take the sub-problem on a row subset R (start: a maximal set of rows pairwise sharing
// no column); reduce it; look for a cover of R smaller than `best`, first with the Lagrangian
// heuristic, else with CBC stopped at its first solution below the cutoff best - 0.5. A
// solution that covers all of K becomes the incumbent; otherwise it is repaired into a cover
// of K (greedy + redundancy removal) and up to kRowsPerRound spread-out rows it leaves
// uncovered join R. Stops when R has no cover smaller than `best`.
// Why the bounds are valid: a cover of K, restricted to the columns meeting R, covers R, so
// every lower bound on the optimum over R (Lagrangian, CBC bound, a finished CBC search that
// finds nothing below the cutoff) is one on K. Each round adds rows or lowers `best`, so the
// loop ends, and when it ends with "nothing below `best` on R", `best` is optimal for K.
struct RowGenOutcome {
    std::vector<uint32_t> sel;  // K-local cover smaller than `target` (ascending), or empty
    double lb = 0;              // lower bound on the optimum of K (at most the best size)
    bool proven = false;        // the best cover (sel, or if empty the incumbent) is optimal
    size_t rounds = 0;          // sub-problems solved
};
// Share of the remaining budget given to row generation before CBC takes the whole component.
constexpr double kRowGenShare = 0.25;
RowGenOutcome row_generation(const Problem& K, size_t target, const Deadline& deadline,
                             int threads, const Monitor& monitor);

// ---- local_search.cpp ----
// Runs side by side share a race: when a run's best cover is known to be optimal (it reaches
// lower_bound or known_bound), the swap at which it was found is published in optimal_step
// (the smallest such swap); a run that has not found an optimal cover by then stops, since it
// can only end with a larger cover or a later one.
struct SearchRace {
    std::atomic<uint64_t> optimal_step{UINT64_MAX};
};

// What bounds one run of the local search.
struct SearchSettings {
    size_t lower_bound = 0;    // stop at a cover this small
    uint64_t max_steps = 0;    // at most this many swaps
    uint64_t seed = 1;
    Deadline deadline;         // a safety stop: results depend on it only when it cuts a run short
    // A lower bound another thread may raise during the search (the LP's); the search stops once
    // its best cover reaches it. That only saves time: below a bound the best cover cannot
    // change, so the result is the same whenever the bound arrives. May be null.
    const std::atomic<size_t>* known_bound = nullptr;
    SearchRace* race = nullptr;  // shared by runs side by side; may be null
};

struct SearchResult {
    std::vector<uint32_t> cover;  // ascending, redundancy-free, never larger than the start
    uint64_t steps = 0;           // swaps made
    uint64_t found_step = 0;      // the swap at which `cover` was first reached (0: the start)
};

// Row-weighting local search (RWLS) from the cover `start` of P: the smallest cover found.
// Stops after max_steps swaps, when it stalls (no improvement for max(2000, 5 (R + C)) swaps +
// as many as the last improvement took), at the deadline, or when a cover of lower_bound (or
// known_bound) columns is found. Deterministic for a seed unless the deadline cuts it short.
SearchResult local_search(const Problem& P, std::vector<uint32_t> start, const SearchSettings& settings);

// Independent runs of local_search from the same start with seeds seed, seed + 1, ...,
// seed + starts - 1 (the other settings shared; `race` is the pool's own), as a pool of work:
// every thread that calls work() takes the next run not yet started until none is left, so
// threads can join at any time (the LP's thread, once its LP is solved). best() (after every
// work() has returned) is the smallest cover, ties to the one found at the earliest swap, then
// to the lowest seed. A run stops early only when it can no longer be the one returned (see
// SearchRace), so best() is the same however many threads took part and whenever they joined.
class SearchRuns {
public:
    SearchRuns(const Problem& P, const std::vector<uint32_t>& start, const SearchSettings& settings, int starts);
    void work();
    std::vector<uint32_t> best() const;
    // A run has reached the lower bound or the known bound (a cover that small exists).
    bool reached_bound() const { return race_.optimal_step.load(std::memory_order_relaxed) != UINT64_MAX; }

private:
    const Problem& P_;
    const std::vector<uint32_t>& start_;
    SearchSettings settings_;
    SearchRace race_;
    std::atomic<size_t> next_{0};
    std::vector<std::vector<uint32_t>> found_;
    std::vector<uint64_t> found_at_;
};

// ---- reduction.cpp ----
// Reduction of the input to its kernel: rows = the `required` samples, columns = the `allowed`
// balls, the `locked` ones (forced in) selected first; `transpose_ok`: cov's sample -> ball
// lists are consistent with its ball -> sample lists (otherwise they are rebuilt). `forced` gets the balls the reduction
// selects (locked ones first, ascending, then the forced ones in the order found); the
// kernel's col_id / row_id are original indices. The optimum of the input is forced.size() +
// the kernel's.
Status reduce_coverage(const Coverage& cov, bool transpose_ok, const std::vector<uint8_t>& required,
                       const std::vector<uint8_t>& allowed, const std::vector<uint8_t>& locked, const Monitor& monitor,
                       std::vector<uint32_t>& forced, Problem& kernel);
// Reduction of a compact problem to its kernel (every row required, every column allowed):
// `forced` and the kernel's col_id / row_id are P-local.
Status reduce_problem(const Problem& P, const Monitor& monitor, std::vector<uint32_t>& forced, Problem& kernel);

// ---- setcover_checks.cpp ----
// Shared front part: checks, masks, uncoverable samples.
struct Prepared {
    std::vector<uint8_t> required, allowed, locked;
    bool transpose_ok = false;  // cov's sample -> ball lists can be used as they are
    std::vector<uint32_t> uncovered;
    size_t rows_before = 0, cols_before = 0;
};
Status prepare(const Coverage& cov, const CoverOptions& opt, bool skip_uncoverable, Prepared& pr);

// ---- component_solve.cpp ----
// Exact solve of one connected component: greedy -> Lagrangian bound and heuristic ->
// reduced-cost fixing (drop every column that no cover smaller than the incumbent can use) ->
// reduction of what is left -> CBC on that, with the incumbent as cutoff. `give_up_above` (off:
// kNoGiveUp): the caller only needs to know whether the component has a cover of at most that many
// columns; the solve ends as soon as its lower bound exceeds it (the best cover so far, not proven).
constexpr double kNoGiveUp = std::numeric_limits<double>::infinity();
struct ComponentResult {
    std::vector<uint32_t> sel;  // P-local columns, ascending
    double lb = 0;
    bool proven = false;
    bool used_cbc = false;
    size_t rowgen_rounds = 0;
};
ComponentResult solve_component(const Problem& P, const Deadline& deadline, int threads,
                                bool row_gen, Effort effort, int search_threads, const Monitor& monitor,
                                double give_up_above = kNoGiveUp);

}  // namespace sc
}  // namespace ca
