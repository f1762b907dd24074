// failures.cpp: the shape of a failed run, alike for every command: a library status (exit 1,
// its CA_ERROR_* name and code, the step that failed and the context's message) or a file that
// could not be read or written (FILE_ERROR, exit 3), and its JSON for --json and batch lines.
#include "cli.h"

namespace cli {

Failure library_failure(ca_context* ctx, ca_status st, const std::string& step) {
    Failure f;
    const std::string name = ca_status_string(st);
    f.status = name.substr(0, name.find(':'));
    f.code = st;
    f.message = step + " failed: " + (ctx ? ca_context_last_error(ctx) : "");
    if (st == CA_ERROR_UNCOVERABLE) f.message += "; raise --delta, add candidates, pass --skip-uncoverable, or drop --volumetric-only";
    f.exit_code = 1;
    return f;
}

Failure file_failure(const std::string& message) {
    Failure f;
    f.status = "FILE_ERROR";
    f.message = message;
    f.exit_code = 3;
    return f;
}

Json error_json(const Failure& f) { return Json{{"status", f.status}, {"code", f.code}, {"message", f.message}}; }

}  // namespace cli
