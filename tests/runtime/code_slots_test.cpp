// The tiering mechanism both tiered back ends share (runtime/tiering.h): a
// key's code is made once, on the compile thread or by a caller that waits;
// the first made is the one kept; nothing waits for a queued compile.
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <future>
#include <string>
#include <thread>

#include "runtime/compile_queue.h"
#include "runtime/tiering.h"

using namespace glslrun;

namespace {

struct Code {
    int made_by;
};
using Slots = rt::CodeSlots<std::string, Code>;

// A compile that counts its calls and makes code tagged `tag`.
Slots::Compile counting(std::atomic<int>& calls, int tag, double seconds = 0.001) {
    return [&calls, tag, seconds](const std::atomic<bool>*) {
        ++calls;
        Slots::Made made;
        made.code = std::make_unique<Code>(Code{tag});
        made.seconds = seconds;
        return made;
    };
}

void wait_for_queue() {
    for (int i = 0; i < 20000 && rt::compiles_pending() > 0; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    REQUIRE(rt::compiles_pending() == 0);
}

}  // namespace

TEST_CASE("code slots: a waiting caller makes a key's code once", "[runtime][tiering]") {
    auto slots = Slots::make();
    std::atomic<int> calls{0};
    CHECK(slots->ready("a") == nullptr);
    CHECK(!slots->requested("a"));
    const Code* a = slots->get("a", counting(calls, 1));
    REQUIRE(a);
    CHECK(a->made_by == 1);
    CHECK(slots->get("a", counting(calls, 2)) == a);  // made: not again
    CHECK(calls == 1);
    bool made = false;
    CHECK(slots->ready("a", &made) == a);
    CHECK(made);
    CHECK(slots->get("b", counting(calls, 3))->made_by == 3);
    CHECK(slots->compiles().compiled == 2);
    CHECK(slots->seconds() == Approx(0.002));
}

TEST_CASE("code slots: a queued compile serves later, and the first code made is kept", "[runtime][tiering]") {
    std::promise<void> release;
    std::shared_future<void> released = release.get_future().share();
    REQUIRE(rt::submit_compile([released] { released.wait(); }));  // holds the compile thread
    auto slots = Slots::make();
    std::atomic<int> calls{0};
    slots->queue("k", counting(calls, 1));
    slots->queue("k", counting(calls, 2));  // asked before: not queued again
    CHECK(slots->requested("k"));
    CHECK(slots->ready("k") == nullptr);  // queued behind the held job
    CHECK(rt::compiles_pending() == 2);
    // A caller that cannot wait makes it here; the queued job's code comes second.
    const Code* here = slots->get("k", counting(calls, 3));
    CHECK(here->made_by == 3);
    release.set_value();
    wait_for_queue();
    CHECK(calls == 2);
    CHECK(slots->ready("k") == here);
    CHECK(slots->compiles().compiled == 2);  // both counted
}

TEST_CASE("code slots: a queued compile finds its slots gone", "[runtime][tiering]") {
    std::promise<void> release;
    std::shared_future<void> released = release.get_future().share();
    REQUIRE(rt::submit_compile([released] { released.wait(); }));
    std::atomic<int> calls{0};
    auto slots = Slots::make();
    slots->queue("k", counting(calls, 1));
    slots.reset();  // would never return if it waited for the queued compile
    release.set_value();
    wait_for_queue();
    CHECK(calls == 0);
}

TEST_CASE("code slots: code stored from elsewhere is kept where the key had none", "[runtime][tiering]") {
    auto slots = Slots::make();
    std::atomic<int> calls{0};
    Slots::Made loaded;
    loaded.code = std::make_unique<Code>(Code{7});
    loaded.loaded = true;
    CHECK(slots->put("k", std::move(loaded)));
    CHECK(slots->compiles().loaded == 1);
    CHECK(slots->get("k", counting(calls, 1))->made_by == 7);
    CHECK(calls == 0);
    Slots::Made again;
    again.code = std::make_unique<Code>(Code{8});
    CHECK(!slots->put("k", std::move(again)));
    CHECK(slots->ready("k")->made_by == 7);
}
