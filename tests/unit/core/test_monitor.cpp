// test_monitor.cpp: the call's time budget and cancellation as the steps see them: a Deadline's
// earliest-of-two, the Monitor's stop checks, and the status a stopped step returns (time limit
// naming the stage, or cancelled).
#include <doctest/doctest.h>

#include "common.h"

#include <atomic>
#include <string>

using namespace ca;

TEST_CASE("monitor: the earlier of two deadlines, unlimited when both are") {
    const Deadline none, spent = Deadline::after(1e-12), far = Deadline::after(1e6);
    CHECK(!none.earliest(none).limited());
    CHECK(spent.earliest(none).expired());
    CHECK(none.earliest(spent).expired());
    CHECK(far.earliest(spent).expired());
    CHECK(spent.earliest(far).expired());
    CHECK(!far.earliest(none).expired());
    CHECK(far.earliest(none).limited());
}

TEST_CASE("monitor: a spent budget stops the work and names the stage, a cancel wins over it") {
    Monitor m;
    int calls = 0;
    m.progress = [&](const char*, double) { ++calls; return true; };
    CHECK(m.report("sampling", 0));
    CHECK(!m.stopped());
    CHECK(!m.stopped_at(0));
    m.deadline = Deadline::after(1e-12);
    CHECK(m.stopped());
    CHECK(!m.report("sampling", 0.5));
    CHECK(calls == 1);  // a stopped step does not call the caller back
    CHECK(m.stopped_at(0));
    CHECK(m.stopped_at(Monitor::kCheckEvery));
    CHECK(!m.stopped_at(1));  // only every kCheckEvery items
    Status st = m.stop_status("coverage");
    CHECK(st.code == Code::time_limit);
    CHECK(st.message == "time limit reached in coverage");
    std::atomic<int> flag{1};
    m.cancel_flag = &flag;
    st = m.stop_status("coverage");
    CHECK(st.code == Code::cancelled);
    CHECK(st.message.find("coverage") != std::string::npos);
    // the callback's own cancel (no flag, no deadline) is a cancel
    Monitor c;
    c.progress = [](const char*, double) { return false; };
    CHECK(!c.report("inside", 0));
    CHECK(c.stop_status("inside").code == Code::cancelled);
}
