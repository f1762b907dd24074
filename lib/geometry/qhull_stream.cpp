// qhull_stream.cpp: Qhull's message stream with a stop test (see qhull_stream.h).
#include "qhull_stream.h"

extern "C" {
#include <libqhull_r/libqhull_r.h>
}

namespace ca {

namespace {

constexpr size_t kMaxLine = 1000;   // longer message lines are cut (they only name an error)

#if defined(__linux__) || defined(__GLIBC__)
#define CA_QHULL_STREAM_CALLBACKS 1
ssize_t write_chunk(void* cookie, const char* text, size_t size) {
    static_cast<QhullStream*>(cookie)->write(text, size);
    return ssize_t(size);
}
FILE* open_stream(QhullStream* self) {
    cookie_io_functions_t io{};
    io.write = write_chunk;
    return fopencookie(self, "w", io);
}
#elif defined(__APPLE__) || defined(__FreeBSD__) || defined(__NetBSD__) || defined(__OpenBSD__)
#define CA_QHULL_STREAM_CALLBACKS 1
int write_chunk(void* cookie, const char* text, int size) {
    static_cast<QhullStream*>(cookie)->write(text, size_t(size));
    return size;
}
FILE* open_stream(QhullStream* self) { return funopen(self, nullptr, write_chunk, nullptr, nullptr); }
#else
#define CA_QHULL_STREAM_CALLBACKS 0
FILE* open_stream(QhullStream*) { return std::tmpfile(); }   // read back by first_line()
#endif

}  // namespace

QhullStream::QhullStream(qhT* qh, const Monitor& monitor) : qh_(qh), monitor_(monitor) {
    file_ = open_stream(this);
    // Unbuffered, so each message reaches write() (and the stop test) when Qhull writes it.
    if (file_ && CA_QHULL_STREAM_CALLBACKS) std::setvbuf(file_, nullptr, _IONBF, 0);
    can_stop_ = file_ && CA_QHULL_STREAM_CALLBACKS && (monitor.cancel_flag || monitor.deadline.limited());
}

QhullStream::~QhullStream() {
    if (file_) std::fclose(file_);
}

void QhullStream::write(const char* text, size_t size) {
    if (can_stop_ && !stopped_ && monitor_.stopped()) {
        stopped_ = true;
        qh_->STOPadd = 1;   // "stop after adding 0 more vertices": qh_buildhull returns at its next point
    }
    if (!first_error_.empty()) return;
    for (size_t i = 0; i < size; ++i) {
        if (text[i] == '\n') end_line();
        else if (line_.size() < kMaxLine) line_ += text[i];
    }
}

void QhullStream::end_line() {
    // Qhull prefixes errors and warnings with their code ("QH6154 qhull precision error: ...");
    // build reports and follow-up lines have none.
    if (first_error_.empty() && line_.compare(0, 2, "QH") == 0) first_error_ = line_;
    if (first_text_.empty() && !line_.empty()) first_text_ = line_;
    line_.clear();
}

std::string QhullStream::first_line() {
    if (!CA_QHULL_STREAM_CALLBACKS && file_) {
        std::fflush(file_);
        std::rewind(file_);
        char chunk[512];
        size_t got;
        while (first_error_.empty() && (got = std::fread(chunk, 1, sizeof chunk, file_)) > 0) write(chunk, got);
    }
    if (!line_.empty()) end_line();
    return first_error_.empty() ? first_text_ : first_error_;
}

}  // namespace ca
