// context.cpp: versions, status names, the context (create, threads, progress, cancel, log,
// last error) and the exception firewall's recording half.
#include "context.h"
#include "struct_size.h"

#include <chrono>
#include <cstring>

namespace capi {

ca_status record(ca_context* ctx, const ca::Status& st) noexcept {
    if (!st.ok()) {
        try { ctx->last_error = st.message; } catch (...) {}
    }
    return static_cast<ca_status>(st.code);
}

ca_status record_exception(ca_context* ctx) noexcept {
    try {
        throw;
    } catch (const std::bad_alloc&) {
        try { ctx->last_error = "out of memory"; } catch (...) {}
        return CA_ERROR_OUT_OF_MEMORY;
    } catch (const std::length_error&) {  // a container asked for more than it can hold
        try { ctx->last_error = "out of memory: a size too large to allocate"; } catch (...) {}
        return CA_ERROR_OUT_OF_MEMORY;
    } catch (const std::exception& e) {
        try { ctx->last_error = std::string("internal error: ") + e.what(); } catch (...) {}
        return CA_ERROR_INTERNAL;
    } catch (...) {
        try { ctx->last_error = "internal error: unknown exception"; } catch (...) {}
        return CA_ERROR_INTERNAL;
    }
}

std::string struct_size_message(const char* name, uint32_t size, const PublishedSize* sizes, size_t count) {
    std::string m = std::string(name) + ".struct_size is " + std::to_string(size) + "; this library (ABI " +
                    std::to_string(CA_ABI_VERSION) + ") accepts ";
    for (size_t i = 0; i < count; ++i) {
        if (i) m += i + 1 == count ? " or " : ", ";
        m += std::to_string(sizes[i].size) + " (ABI " + std::to_string(sizes[i].abi) + ")";
    }
    return m + " (fill it with " + name + "_init, or set sizeof of a published layout)";
}

}  // namespace capi

ca::Monitor ca_context::monitor() const {
    ca::Monitor m;
    m.cancel_flag = &cancel;
    m.deadline = ca::Deadline::after(desc.time_limit_s);  // the budget of this call, from now
    if (desc.log) {
        ca_log_fn fn = desc.log;
        void* user = desc.log_user;
        m.log = [fn, user](int32_t level, const std::string& message) { fn(user, level, message.c_str()); };
    }
    if (desc.progress) {
        using Clock = std::chrono::steady_clock;
        ca_progress_fn fn = desc.progress;
        void* user = desc.progress_user;
        const double interval = desc.progress_interval_s;
        // Throttle state of this call: the last stage reported and when.
        m.progress = [fn, user, interval, last_stage = std::string(), last = Clock::time_point()](
                         const char* stage, double f) mutable {
            if (interval > 0) {
                const Clock::time_point now = Clock::now();
                const bool new_stage = last_stage != stage;
                if (!new_stage && f < 1 && std::chrono::duration<double>(now - last).count() < interval) return true;
                if (new_stage) last_stage = stage;
                last = now;
            }
            return fn(user, stage, f) == 0;
        };
    }
    return m;
}

extern "C" {

uint32_t ca_version(void) { return CA_VERSION_NUMBER; }
// The version's one decoding into text, from the same three numbers as CA_VERSION_NUMBER.
#define CA_TEXT_(x) #x
#define CA_NUMBER_TEXT_(x) CA_TEXT_(x)
const char* ca_version_string(void) {
    return CA_NUMBER_TEXT_(CA_VERSION_MAJOR) "." CA_NUMBER_TEXT_(CA_VERSION_MINOR) "." CA_NUMBER_TEXT_(CA_VERSION_PATCH);
}
uint32_t ca_abi_version(void) { return CA_ABI_VERSION; }

const char* ca_status_string(ca_status s) {
    switch (s) {
        case CA_OK: return "CA_OK: success";
        case CA_ERROR_INVALID_ARGUMENT: return "CA_ERROR_INVALID_ARGUMENT: an option is out of range";
        case CA_ERROR_NULL_POINTER: return "CA_ERROR_NULL_POINTER: a required pointer is NULL";
        case CA_ERROR_STRUCT_SIZE: return "CA_ERROR_STRUCT_SIZE: struct_size is not one this library knows";
        case CA_ERROR_INVALID_INPUT: return "CA_ERROR_INVALID_INPUT: NaN/Inf coordinate, out-of-range index or bad normal";
        case CA_ERROR_DEGENERATE_INPUT: return "CA_ERROR_DEGENERATE_INPUT: empty, flat or too few distinct points";
        case CA_ERROR_UNCOVERABLE: return "CA_ERROR_UNCOVERABLE: some samples are covered by no candidate ball";
        case CA_ERROR_GEOMETRY: return "CA_ERROR_GEOMETRY: the Delaunay or power diagram computation failed";
        case CA_ERROR_SOLVER: return "CA_ERROR_SOLVER: the set-cover solver failed";
        case CA_ERROR_CANCELLED: return "CA_ERROR_CANCELLED: cancelled by the caller";
        case CA_ERROR_OUT_OF_MEMORY: return "CA_ERROR_OUT_OF_MEMORY: out of memory";
        case CA_ERROR_BUFFER_TOO_SMALL: return "CA_ERROR_BUFFER_TOO_SMALL: the output buffer is too small";
        case CA_ERROR_INTERNAL: return "CA_ERROR_INTERNAL: internal error";
        case CA_ERROR_NO_CANDIDATES: return "CA_ERROR_NO_CANDIDATES: no inner candidate ball was found";
        case CA_ERROR_TIME_LIMIT: return "CA_ERROR_TIME_LIMIT: the context's time limit ran out";
        case CA_ERROR_TARGET_NOT_REACHED: return "CA_ERROR_TARGET_NOT_REACHED: the target error was not reached";
        default: return "unknown ca_status";
    }
}

// No context exists yet to hold a message: the status alone says what is wrong.
ca_status ca_context_create(const ca_context_desc* desc, ca_context** out) {
    if (!out) return CA_ERROR_NULL_POINTER;
    *out = nullptr;
    ca_context_desc d;
    if (capi::guarded_status([&] { return capi::read_input(desc, d); }) != CA_OK) return CA_ERROR_STRUCT_SIZE;
    if ((d.alloc == nullptr) != (d.free == nullptr)) return CA_ERROR_INVALID_ARGUMENT;
    if (d.threads < 0) return CA_ERROR_INVALID_ARGUMENT;
    if (!(d.progress_interval_s >= 0) || d.progress_interval_s > 1e9) return CA_ERROR_INVALID_ARGUMENT;
    if (!(d.time_limit_s >= 0)) return CA_ERROR_INVALID_ARGUMENT;  // NaN or negative; +Inf = unlimited
    ca_context* ctx = new (std::nothrow) ca_context();
    if (!ctx) return CA_ERROR_OUT_OF_MEMORY;
    ctx->desc = d;
    *out = ctx;
    return CA_OK;
}

void ca_context_destroy(ca_context* ctx) { delete ctx; }
void ca_context_request_cancel(ca_context* ctx) { if (ctx) ctx->cancel.store(1); }
void ca_context_clear_cancel(ca_context* ctx) { if (ctx) ctx->cancel.store(0); }
const char* ca_context_last_error(const ca_context* ctx) { return ctx ? ctx->last_error.c_str() : "ctx is NULL"; }

}  // extern "C"
