// selection_step.cpp: a run's selection: the user-control index files (--ignore-samples,
// --force-in, --force-out) become per-sample and per-ball masks of the select options, then
// ca_select covers the samples. A --target-error that is not reached lets the run go on with the
// best selection found; the Failure it leaves carries exit code 4 for the end of the run.
#include "run_steps.h"

namespace cli {
namespace {

// One index file and the mask of the select options it fills.
struct MaskFile {
    const std::string& path;
    size_t size;                 // the samples or the candidates: every index must be below it
    std::vector<uint8_t>& mask;
    const uint8_t** field;
    size_t* count;
    const char* what;            // "sample" or "candidate", for the message
};

// Reads the index file (if one is named) into its mask; an index out of range is a file error.
bool read_mask(MaskFile m, Failure& failure) {
    if (m.path.empty()) return true;
    std::vector<uint32_t> idx;
    std::string err;
    if (!caio::read_indices(m.path, idx, err)) return failure = file_failure(err), false;
    m.mask.assign(m.size, 0);
    for (uint32_t i : idx) {
        if (i >= m.size)
            return failure = file_failure(m.path + ": " + m.what + " index " + std::to_string(i) + " out of range (" +
                                          std::to_string(m.size) + " " + m.what + "s)"),
                   false;
        m.mask[i] = 1;
    }
    *m.field = m.mask.data();
    *m.count = m.mask.size();
    return true;
}

}  // namespace

bool make_selection(Run& run, const RunOptions& o, Failure& failure) {
    ca_select_options so = o.select;
    const size_t n_samples = ca_candidate_set_sample_count(run.set), n_candidates = ca_candidate_set_count(run.set);
    std::vector<uint8_t> ignorable, forced_in, forced_out;
    for (MaskFile m :
         {MaskFile{o.ignore_samples_file, n_samples, ignorable, &so.ignorable_samples, &so.ignorable_samples_count, "sample"},
          MaskFile{o.force_in_file, n_candidates, forced_in, &so.forced_in, &so.forced_in_count, "candidate"},
          MaskFile{o.force_out_file, n_candidates, forced_out, &so.forced_out, &so.forced_out_count, "candidate"}})
        if (!read_mask(m, failure)) return false;
    const ca_status st = ca_select(run.ctx, run.set, &so, &run.sel);
    if (st == CA_ERROR_TARGET_NOT_REACHED) {  // the run goes on with the best selection; exit 4 at the end
        failure = library_failure(run.ctx, st, "selection");
        failure.message = std::string(ca_context_last_error(run.ctx)) +
                          "; the outputs hold that skeleton (raise --samples or add --fit to search further)";
        failure.exit_code = 4;
        return true;
    }
    if (st != CA_OK) return failure = library_failure(run.ctx, st, "selection"), false;
    return true;
}

}  // namespace cli
