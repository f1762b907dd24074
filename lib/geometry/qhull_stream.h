// qhull_stream.h: the stream Qhull writes its messages to during one run. It keeps the first
// error or warning line for the Status (nothing reaches the caller's stderr) and is the only
// place inside a Qhull run where the library's code runs: where the C library lets a FILE* call
// back (fopencookie, funopen), every message Qhull writes -- with the periodic build report
// (option()'s 'TF2000': one per 2000 new facets) -- tests the monitor, and a stop sets Qhull's own
// "stop adding points" limit (qhT.STOPadd, option 'TA'), which ends the build at the next point
// with a valid partial hull that the caller then drops. The report changes no result (it only
// prints; its clock reading uses localtime(), whose shared buffer only feeds this stream's
// dropped text).
#pragma once
#include "common.h"

#include <cstdio>
#include <string>

struct qhT;

namespace ca {

class QhullStream {
public:
    // `qh` is the run's Qhull state (stopped through it), `monitor` the stop test.
    QhullStream(qhT* qh, const Monitor& monitor);
    ~QhullStream();
    QhullStream(const QhullStream&) = delete;
    QhullStream& operator=(const QhullStream&) = delete;

    FILE* file() { return file_; }
    // Whether the run can be stopped through this stream (the platform has stream callbacks and
    // the monitor can ever say stop); if so the run's options get the report frequency option().
    bool can_stop() const { return can_stop_; }
    static const char* option() { return " TF2000"; }
    // Whether a stop was seen (and the build told to stop).
    bool stopped() const { return stopped_; }
    // Qhull's first error or warning line ("QH6xxx ..."), else its first non-empty line.
    std::string first_line();

    // Called with each chunk Qhull writes (public for the C callbacks only).
    void write(const char* text, size_t size);

private:
    void end_line();

    qhT* qh_;
    const Monitor& monitor_;
    FILE* file_ = nullptr;
    bool can_stop_ = false;
    bool stopped_ = false;
    std::string line_, first_error_, first_text_;
};

}  // namespace ca
