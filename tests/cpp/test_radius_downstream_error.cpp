// A stage after the radius stage refuses a move (an error downstream, as the segment limit
// raises): in a lenient run the path ends before that move, and the radius stage sends
// nothing more, in particular not the refused move a second time.
#include <catch2/catch.hpp>

#include <vector>

#include "pipeline.hpp"
#include "toolcomp/control/profile.hpp"
#include "toolcomp/dialects/iso/interpreter.hpp"
#include "toolcomp/run.hpp"

using namespace toolcomp;

namespace {
// Takes moves, and refuses the one numbered `refuse` (0-based) with a CompensationError.
struct Refusing : MotionSink {
    std::size_t refuse;
    std::vector<Motion> taken;
    std::size_t calls = 0;
    explicit Refusing(std::size_t n) : refuse(n) {}
    void push(const Motion& m) override {
        if (calls++ == refuse) throw CompensationError("refused", "refused downstream", {m.line, 0});
        taken.push_back(m);
    }
};
struct Nothing : MotionSink {
    void push(const Motion&) override {}
};
}  // namespace

TEST_CASE("radius stage: after an error downstream, no move is sent again") {
    // A square with G41 r = 1 (corner arcs at the outside corners), a lathe-free mill program.
    const Program prog = parse_program(
        "G21 G17 G90\nG0 X-5 Y-5\nG41.1 D2\nG1 X0 Y0 F100\nX10\nY10\nX0\nY0\nX10\nY10\nG40 G0 X20 Y20\nM2\n",
        Dialect::linuxcnc);
    const ControlProfile profile = profile_for(Dialect::linuxcnc);
    for (std::size_t refuse = 0; refuse < 8; ++refuse) {
        for (bool threads : {true, false}) {
            INFO("refused move " << refuse << (threads ? ", watch on its thread" : ", no thread"));
            RunOptions options;
            options.strict = false;
            options.threads = threads;
            Nothing nominal;
            Refusing comp(refuse);
            std::vector<Diagnostic> diagnostics;
            iso::InterpretOutput out;
            run_pipeline(prog, nullptr, options, profile, nominal, comp, diagnostics, out);
            CHECK(comp.calls == refuse + 1);  // the moves before, and the refused one once
            CHECK(comp.taken.size() == refuse);
            REQUIRE_FALSE(diagnostics.empty());
            CHECK(diagnostics.back().code == "refused");
        }
    }
}
