// cbc.cpp: CBC (the C interface, silenced, with a cutoff and a time limit, behind the library's
// only process-wide mutex) and the search for a cover on the LP optimal face (core_cover).
#include "setcover_internal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <new>
#include <numeric>
#include <string>

#include <coin/Cbc_C_Interface.h>

namespace ca {
namespace sc {

namespace {
// CBC 2.10's Cbc_newModel and Cbc_solve run CbcMain0 / CbcMain1, which parse the options through
// process-wide globals (CbcOrClpRead_mode, the signal handler's current model): two at once can
// misread each other's options. Every CBC model's life (create, solve, read, delete) in the
// process therefore goes through this one mutex, the library's only process-wide state. Clp
// needs none: a ClpSimplex keeps all of its state (factorization, pricing, random numbers) in
// the object, Clp 1.17's function-level statics are all in debugging code compiled out of the
// library, and CBC's own parallel search runs one ClpSimplex per thread the same way.
std::mutex& cbc_mutex() {
    static std::mutex m;
    return m;
}
}  // namespace

// Solves the kernel with CBC, looking only for covers smaller than `incumbent` (the best known
// cover): the cutoff incumbent - 1 + kCutoffSlack prunes at least as much as a MIP start would.
// A MIP start (Cbc_setMIPStartI) is deliberately not used: in CBC 2.10 its processing ("Reduced
// search") ignores the time limit and can take far longer than the cutoff alone.
// With `first_solution`, CBC stops at the first cover below the cutoff (not proven optimal).
namespace {
CbcOutcome run_cbc_unguarded(const Problem& P, size_t incumbent, const CbcSettings& settings) {
    const double time_limit_s = settings.time_limit_s;
    const int threads = settings.threads, max_nodes = settings.max_nodes;
    const bool first_solution = settings.first_solution, heuristics = settings.heuristics, lean = settings.lean,
               strong_branching = settings.strong_branching;
    CbcOutcome out;
    std::vector<CoinBigIndex> colstart(P.C + 1);
    std::vector<int> rowidx(P.crow.begin(), P.crow.end());
    for (uint32_t c = 0; c <= P.C; ++c) colstart[c] = CoinBigIndex(P.cptr[c]);
    std::vector<double> val(P.crow.size(), 1.0), lb(P.C, 0.0), ub(P.C, 1.0), obj(P.C, 1.0), rlb(P.R, 1.0);
    const bool weighted = settings.costs != nullptr;
    if (weighted) obj = *settings.costs;
    char buf[64];

    std::lock_guard<std::mutex> lock(cbc_mutex());
    struct Deleter { void operator()(Cbc_Model* m) const { Cbc_deleteModel(m); } };
    std::unique_ptr<Cbc_Model, Deleter> model(Cbc_newModel());
    if (!model) return out;
    Cbc_Model* m = model.get();
    Cbc_loadProblem(m, int(P.C), int(P.R), colstart.data(), rowidx.data(), val.data(), lb.data(), ub.data(),
                    obj.data(), rlb.data(), nullptr);
    for (uint32_t c = 0; c < P.C; ++c) Cbc_setInteger(m, int(c));
    if (settings.max_columns > 0) {  // sum x <= max_columns
        std::vector<int> all(P.C);
        std::iota(all.begin(), all.end(), 0);
        Cbc_addRow(m, "columns", int(P.C), all.data(), ub.data(), 'L', double(settings.max_columns));
    }
    Cbc_setParameter(m, "log", "0");  // otherwise CBC prints to stdout
    Cbc_setParameter(m, "slog", "0");
    Cbc_setParameter(m, "timeMode", "elapsed");
    if (time_limit_s > 0 && std::isfinite(time_limit_s)) {
        std::snprintf(buf, sizeof buf, "%.6f", time_limit_s);
        Cbc_setParameter(m, "sec", buf);
    }
    std::snprintf(buf, sizeof buf, "%d", std::max(1, threads));
    Cbc_setParameter(m, "threads", buf);
    // Objective values are integral: a cover smaller than the incumbent has value <= incumbent - 1,
    // so every node whose LP bound exceeds that is pruned (a looser cutoff such as
    // incumbent - 0.5 would keep exploring nodes with bounds in (incumbent - 1, incumbent - 0.5)).
    if (weighted) std::snprintf(buf, sizeof buf, "%.17g", settings.cutoff);
    else std::snprintf(buf, sizeof buf, "%.4f", double(incumbent) - 1.0 + kCutoffSlack);
    Cbc_setParameter(m, "cutoff", buf);
    // CBC's root heuristics (feasibility pump, mini branch and bound) are costly on large
    // kernels and rarely beat a local-search incumbent.
    if (!heuristics) Cbc_setParameter(m, "heuristicsOnOff", "off");
    if (first_solution) Cbc_setParameter(m, "maxSolutions", "1");
    // On small kernels with a one-ball gap, preprocessing and cuts cost more than they save and
    // do not change the outcome.
    if (lean) {
        Cbc_setParameter(m, "preprocess", "off");
        Cbc_setParameter(m, "cuts", "off");
    }
    if (!strong_branching) {
        Cbc_setParameter(m, "strong", "0");
        Cbc_setParameter(m, "trust", "0");
    }
    if (max_nodes > 0) {
        std::snprintf(buf, sizeof buf, "%d", max_nodes);
        Cbc_setParameter(m, "maxNodes", buf);
    }
    const Clock::time_point t0 = Clock::now();
    Cbc_solve(m);
    const double elapsed = seconds_since(t0);
    out.ok = true;
    const bool finished = Cbc_status(m) == 0;
    const double bp = Cbc_getBestPossibleObjValue(m);
    const double* x = Cbc_bestSolution(m) ? Cbc_getColSolution(m) : nullptr;
    if (x) {
        for (uint32_t c = 0; c < P.C; ++c)
            if (x[c] > 0.5) out.solution.push_back(c);
        if (weighted) {
            double value = 0;
            for (uint32_t c : out.solution) value += obj[c];
            out.has_solution = covers_problem(P, out.solution) && value < settings.cutoff &&
                               (settings.max_columns == 0 || out.solution.size() <= settings.max_columns);
        } else {
            out.has_solution = covers_problem(P, out.solution) && out.solution.size() < incumbent;
        }
        if (!out.has_solution) out.solution.clear();
    }
    // CBC 2.10 reports "finished, linear relaxation infeasible or worse than the cutoff"
    // (status 0, secondary status 1) also when its time limit interrupts the root LP, with the
    // interrupted LP value (below the cutoff) as bound, which would falsely "prove" the
    // incumbent optimal on a sub-problem with little time left. When CBC
    // used half its time limit or more, such a claim is trusted only with a bound at or above
    // the cutoff (a genuine one can come from preprocessing with a lower LP bound), and its
    // bound is not used.
    const double cutoff = weighted            ? settings.cutoff
                          : out.has_solution ? double(out.solution.size()) - 1.0 + kCutoffSlack
                                             : double(incumbent) - 1.0 + kCutoffSlack;
    const bool near_limit = time_limit_s > 0 && std::isfinite(time_limit_s) && elapsed >= 0.5 * time_limit_s;
    const bool trusted = Cbc_secondaryStatus(m) != 1 || bp >= cutoff - 1e-9 || !near_limit;
    if (trusted && std::isfinite(bp) && bp < 1e40) out.bound = bp;
    // Optimal below the cutoff, or proven that nothing beats the incumbent.
    if (out.has_solution)
        out.proven = finished && trusted && Cbc_isProvenOptimal(m) != 0;
    else
        out.proven = finished && trusted && Cbc_isProvenInfeasible(m) != 0;
    return out;
}
}  // namespace

// Any exception from CBC other than bad_alloc is a failed solve (ok = false): the callers keep
// their incumbent.
CbcOutcome run_cbc(const Problem& P, size_t incumbent, const CbcSettings& settings) {
    try {
        return run_cbc_unguarded(P, incumbent, settings);
    } catch (const std::bad_alloc&) {
        throw;
    } catch (...) {
        return CbcOutcome{};
    }
}


// Why: the local search's covers can contain a few columns of positive reduced cost at the LP
// duals while an optimum uses only columns of reduced cost 0 (the LP optimal face). Restricted
// to those, CBC without strong branching finds such a cover within a few nodes, where the whole
// kernel or strong branching would take far longer; a small node limit keeps the attempt cheap
// when there is none.
std::vector<uint32_t> core_cover(const Problem& P, const std::vector<double>& cost, size_t incumbent,
                                 double time_limit_s, int threads, const Monitor& monitor) {
    // every row keeps a column: its cheapest
    const Problem Q = restrict_columns(P, core_columns(P, cost, kCoreMaxCost, 1, all_rows(P)));
    std::vector<uint32_t> forced;  // Q-local
    Problem K;                     // col_id Q-local
    if (!reduce_problem(Q, monitor, forced, K).ok()) return {};
    std::vector<uint32_t> sel;
    for (uint32_t c : forced) sel.push_back(Q.col_id[c]);
    if (K.R > 0) {
        if (forced.size() + 1 >= incumbent) return {};  // K needs a column too
        CbcSettings cs;
        cs.time_limit_s = time_limit_s;
        cs.threads = threads;
        cs.heuristics = false;
        cs.max_nodes = kCoreCbcNodes;
        cs.lean = true;
        cs.strong_branching = false;
        const CbcOutcome cbc = run_cbc(K, incumbent - forced.size(), cs);
        if (!cbc.ok || !cbc.has_solution) return {};
        for (uint32_t c : cbc.solution) sel.push_back(Q.col_id[K.col_id[c]]);
    }
    std::sort(sel.begin(), sel.end());
    if (sel.size() >= incumbent || !covers_problem(P, sel)) return {};
    return sel;
}

}  // namespace sc
}  // namespace ca
