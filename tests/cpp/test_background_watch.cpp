// The overcut watch on its own thread against the watch called directly: the same random
// calls (contours of short lines and arcs that come back near themselves, tangent slack,
// unit changes, reports, reconfigurations), with other diagnostics pushed between them, give
// the same diagnostics in the same order, whether the run is short (no thread), long (many
// batches, the stage waiting for the thread) or settled midway and continued.
#include <catch2/catch.hpp>
#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "toolcomp/compensation/background_watch.hpp"

using namespace toolcomp;

namespace {

struct Both {
    explicit Both(bool thread = true) : background(thread) {}
    OvercutWatch direct;
    BackgroundWatch background;
    std::vector<Diagnostic> want, got;
};

// Drives both watches with `calls` random calls.
void drive(Both& w, std::mt19937& rng, int calls) {
    std::uniform_real_distribution<double> step(-1.5, 1.5), unit(0, 1);
    Vec2 at(0, 0);
    int line = 1;
    std::size_t settled = 0;
    auto element = [&] {
        const Vec2 to = at + Vec2(step(rng), step(rng));
        Element2 e = unit(rng) < 0.7 ? Element2::line(at, to)
                                     : Element2::arc(at, to, (at + to) / 2 + Vec2(step(rng), step(rng)) * 0.3,
                                                     unit(rng) < 0.5 ? 1 : -1);
        at = to;
        return e;
    };
    for (int i = 0; i < calls; ++i) {
        const double u = unit(rng);
        if (u < 0.002) {
            const int n = unit(rng) < 0.2 ? 0 : 1 + static_cast<int>(unit(rng) * 4);
            w.direct.configure(n, 0.001);
            w.background.configure(n, 0.001);
        } else if (u < 0.45) {
            const Element2 e = element();
            w.direct.programmed(e, line);
            w.background.programmed(e, line);
            ++line;
        } else if (u < 0.47) {
            w.direct.tangent_slack(0.01);
            w.background.tangent_slack(0.01);
        } else if (u < 0.85) {
            Element2 e = element();
            at -= Vec2(step(rng), step(rng)) * 0.5;  // the tool centre strays off the contour
            const int file = static_cast<int>(unit(rng) * 3);
            // settled up to three programmed elements before (a stage looking ahead)
            const std::size_t count = w.background.contour_count(), lag = static_cast<std::size_t>(unit(rng) * 4);
            settled = std::max(settled, count > lag ? count - lag : 0);
            w.direct.compensated(e, line - 1, file, 1.0, settled);
            w.background.compensated(e, line - 1, file, 1.0, settled);
        } else if (u < 0.95) {
            const bool all = unit(rng) < 0.05;
            w.direct.report(w.want, 1.0, all);
            w.background.report(w.got, 1.0, all);
            if (all) settled = 0;
        } else if (u < 0.951) {
            const double f = unit(rng) < 0.5 ? 25.4 : 1 / 25.4;
            w.direct.scale(f);
            w.background.scale(f);
        } else {  // another stage's diagnostic between the watch's
            const Diagnostic d{"other", Severity::warning, "line " + std::to_string(line), {line, 0, {}, 0}};
            w.want.push_back(d);
            w.got.push_back(d);
        }
    }
    w.direct.report(w.want, 1.0, true);
    w.background.report(w.got, 1.0, true);
}

void same(const std::vector<Diagnostic>& want, const std::vector<Diagnostic>& got) {
    REQUIRE(got.size() == want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
        INFO("diagnostic " << i);
        REQUIRE(got[i].code == want[i].code);
        REQUIRE(got[i].message == want[i].message);
        REQUIRE(got[i].pos.line == want[i].pos.line);
        REQUIRE(got[i].pos.file_index == want[i].pos.file_index);
    }
}

std::size_t overcuts(const std::vector<Diagnostic>& d) {
    std::size_t n = 0;
    for (const auto& x : d) n += x.code == "comp_overcut";
    return n;
}

}  // namespace

TEST_CASE("background watch: the same warnings in the same places as the watch called directly") {
    // thread = false: no thread, every call replayed as it is made (RunOptions::threads).
    for (const bool thread : {true, false}) {
        for (int calls : {10, 1000, 3 * static_cast<int>(BackgroundWatch::kBatch), 200000}) {
            INFO(calls << " calls, thread " << thread);
            std::mt19937 rng(calls);
            Both w(thread);
            w.direct.configure(3, 0.001);
            w.background.configure(3, 0.001);
            drive(w, rng, calls);
            w.background.settle(w.got);
            same(w.want, w.got);
            if (calls >= 1000) REQUIRE(overcuts(w.want) > 10);  // the contours do come back near themselves
        }
    }
}

TEST_CASE("background watch: settled midway, it goes on") {
    std::mt19937 rng(7);
    Both w;
    w.direct.configure(3, 0.001);
    w.background.configure(3, 0.001);
    drive(w, rng, 50000);
    w.background.settle(w.got);
    same(w.want, w.got);
    drive(w, rng, 50000);
    w.background.settle(w.got);
    w.background.settle(w.got);  // nothing new: nothing changes
    same(w.want, w.got);
}

TEST_CASE("background watch: abandoned unsettled (an error ends the run)") {
    std::mt19937 rng(3);
    Both w;
    w.background.configure(3, 0.001);
    drive(w, rng, 100000);
    // Destroyed without settle(): the thread stops, nothing is reported, nothing crashes.
}
