// context.h: the C boundary's shared machinery: the context (options, cancel flag, last error,
// log, progress), the exception firewall every entry point runs through, and the memory of the
// opaque results (the caller's allocator travels with each result).
#pragma once

#include "coverage_axis.h"

#include "common.h"

#include <atomic>
#include <cstdlib>
#include <new>
#include <stdexcept>
#include <string>

struct ca_context {
    ca_context_desc desc{};
    std::atomic<int> cancel{0};
    std::string last_error;

    // Cancel flag, the caller's progress callback (throttled to desc.progress_interval_s) and log,
    // and the budget of one call (desc.time_limit_s from now).
    ca::Monitor monitor() const;
};

namespace capi {

// Result arrays live in memory from the context's allocator; the allocator travels with the
// result so destroy works after the context is gone.
struct Allocator {
    ca_alloc_fn alloc = nullptr;
    ca_free_fn free = nullptr;
    void* user = nullptr;
    void* get(size_t bytes) const {
        if (bytes == 0) bytes = 1;
        void* p = alloc ? alloc(user, bytes) : std::malloc(bytes);
        if (!p) throw std::bad_alloc();
        return p;
    }
    void put(void* p) const {
        if (!p) return;
        if (free) free(user, p);
        else std::free(p);
    }
};

template <class T>
struct Array {
    T* data = nullptr;
    size_t size = 0;
    void assign(const Allocator& a, size_t n) {
        data = static_cast<T*>(a.get(n * sizeof(T)));
        size = n;
    }
    void release(const Allocator& a) { a.put(data); data = nullptr; size = 0; }
};

inline Allocator allocator_of(const ca_context* ctx) { return {ctx->desc.alloc, ctx->desc.free, ctx->desc.alloc_user}; }

// Allocates a result object with the context's allocator and constructs it in place.
template <class T>
T* make_result(const ca_context* ctx) {
    Allocator a = allocator_of(ctx);
    void* mem = a.get(sizeof(T));
    T* obj = new (mem) T();
    obj->allocator = a;
    return obj;
}
template <class T>
void destroy_result(T* obj) {
    if (!obj) return;
    Allocator a = obj->allocator;
    obj->release_arrays();
    obj->~T();
    a.put(obj);
}

// Owns a freshly made result until it is handed to the caller.
template <class T>
struct Pending {
    T* obj;
    explicit Pending(T* o) : obj(o) {}
    ~Pending() { destroy_result(obj); }
    Pending(const Pending&) = delete;
    Pending& operator=(const Pending&) = delete;
    T* release() { T* o = obj; obj = nullptr; return o; }
};

// The exception firewall, the only place exceptions are caught: runs f (returning ca::Status)
// on a context, records the message, and turns any exception into a status.
ca_status record(ca_context* ctx, const ca::Status& st) noexcept;
ca_status record_exception(ca_context* ctx) noexcept;  // inside a catch block

template <class F>
ca_status guarded(ca_context* ctx, F&& f) noexcept {
    if (!ctx) return CA_ERROR_NULL_POINTER;
    try {
        ctx->last_error.clear();
        return record(ctx, f());
    } catch (...) {
        return record_exception(ctx);
    }
}

// The same firewall for calls without a context (getters that fill structs, ca_*_defaults):
// the status only.
template <class F>
ca_status guarded_status(F&& f) noexcept {
    try {
        return static_cast<ca_status>(f().code);
    } catch (const std::bad_alloc&) {
        return CA_ERROR_OUT_OF_MEMORY;
    } catch (const std::length_error&) {
        return CA_ERROR_OUT_OF_MEMORY;
    } catch (...) {
        return CA_ERROR_INTERNAL;
    }
}

}  // namespace capi
