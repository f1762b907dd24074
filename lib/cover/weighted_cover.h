// weighted_cover.h: a weighted set cover with a limit on the number of columns,
//   min sum c_j x_j  subject to  every row covered,  sum x_j <= K,  x binary,
// for the engine proxies that hug the shape (lib/proxies/hug_proxies.cpp: rows are surface
// points, columns are primitives, costs their volume outside the shape). Solved by the set-cover
// engine's parts: a greedy cover whose price per column is raised until it uses at most K
// columns, a local search of add-and-drop and re-cover moves, the Lagrangian bound of the
// covering rows (the K most negative reduced costs), the same greedy on the reduced costs at the
// bound's multipliers (then the local search again), and CBC (run_cbc, behind the library's CBC
// mutex) on a core of columns of small reduced cost with a node limit. Deterministic: fixed
// iteration and node counts, the time limit only cuts a solve short.
#pragma once
#include "common.h"

namespace ca {

struct WeightedCoverProblem {
    uint32_t rows = 0;
    std::vector<uint32_t> ptr{0}, idx;  // column j covers rows idx[ptr[j] .. ptr[j + 1]), ascending
    std::vector<double> cost;           // per column, >= 0 and finite
    size_t max_columns = 1;             // K >= 1
};

struct WeightedCoverOptions {
    double time_limit_s = 2.0;          // safety: <= 0 none; cuts the Lagrangian, local search and CBC short
    int lagrange_iterations = 100;      // subgradient steps for the lower bound
    int cbc_nodes = 50;                 // CBC's node limit on the core (0: no CBC)
    size_t cbc_max_incidences = 60000;  // CBC runs only on a core this small (column-row incidences)
    double cbc_time_limit_s = 0.5;      // and at most this long (checked between its nodes)
};

struct WeightedCoverResult {
    std::vector<uint32_t> selected;     // ascending
    double objective = 0;               // sum of the selected costs
    double lower_bound = 0;             // valid for every feasible solution of the problem
    bool cbc_improved = false;          // CBC found the returned solution
    bool proven_optimal = false;        // the bound meets the objective
};

// invalid_argument: sizes inconsistent, a cost negative or not finite, K = 0; uncoverable: a row
// no column covers; infeasible (uncoverable too) when no K columns cover all rows is not checked
// ahead: the greedy's answer with the most column-saving price is returned as an error then.
Status solve_weighted_cover(const WeightedCoverProblem& problem, const WeightedCoverOptions& opt,
                            const Monitor& monitor, WeightedCoverResult& out);

}  // namespace ca
