#include "toolcomp/run.hpp"

#include <fstream>
#include <sstream>

#include "toolcomp/compensation/stages.hpp"
#include "toolcomp/dialects/heidenhain/interpreter.hpp"
#include "toolcomp/dialects/heidenhain/lexer.hpp"
#include "toolcomp/dialects/iso/interpreter.hpp"
#include "toolcomp/dialects/iso/lexer.hpp"
#include "toolcomp/dialects/sinumerik/interpreter.hpp"
#include "toolcomp/dialects/sinumerik/lexer.hpp"

namespace toolcomp {

namespace {
bool is_iso(Dialect d) { return d == Dialect::linuxcnc || d == Dialect::fanuc || d == Dialect::rockwell; }

[[noreturn]] void dialect_not_supported(Dialect d) {
    throw ParseError("dialect_not_supported",
                     "The " + std::string(dialect_name(d)) + " dialect is not supported by toolcomp yet");
}

// Sends every move to two consumers.
class Tee : public MotionSink {
public:
    Tee(MotionSink& a, MotionSink& b) : a_(a), b_(b) {}
    void push(const Motion& m) override {
        a_.push(m);
        b_.push(m);
    }
    void control(const ControlEvent& e) override {
        a_.control(e);
        b_.control(e);
    }
    void finish() override {
        a_.finish();
        b_.finish();
    }

private:
    MotionSink& a_;
    MotionSink& b_;
};

sinumerik::InterpretOptions sinumerik_options(const RunOptions& o, const ControlProfile& p) {
    sinumerik::InterpretOptions s;
    s.lengths.tool_length_const = p.tool_length_const;
    s.lengths.tool_length_type = p.tool_length_type;
    s.lengths.wear_sign_inverted = p.wear_sign < 0;
    s.tool_parameter_def_mask = p.tool_parameter_def_mask;
    s.block_delete = o.block_delete;
    s.progress = o.progress;
    s.progress_every = o.progress_every ? o.progress_every : 1;
    s.search_path = o.search_path;
    return s;
}
}  // namespace

Program parse_program(std::string_view text, Dialect dialect, std::string name, bool strict) {
    if (dialect == Dialect::heidenhain) return heidenhain::parse(text, std::move(name), strict);
    if (dialect == Dialect::sinumerik) return sinumerik::parse(text, std::move(name), strict);
    if (!is_iso(dialect)) dialect_not_supported(dialect);
    return iso::parse(text, dialect, std::move(name), strict);
}

Program read_program(const std::string& path, std::optional<Dialect> dialect, bool strict) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw ParseError("file_not_found", "Cannot open program file '" + path + "'");
    std::ostringstream ss;
    ss << f.rdbuf();
    Dialect d;
    if (dialect) {
        d = *dialect;
    } else if (auto s = dialect_from_suffix(path)) {
        d = *s;
    } else {
        throw ParseError("unknown_dialect",
                         "Cannot tell the dialect of '" + path + "' from its suffix; pass dialect=");
    }
    return parse_program(ss.str(), d, path, strict);
}

bool Result::ok() const {
    for (const auto& d : diagnostics)
        if (d.severity == Severity::error) return false;
    return true;
}

Result run(const Program& program, const ToolTable* tools, const RunOptions& options) {
    Result res;
    res.blocks = program.size();
    if (program.blank) {
        const double unit = program.inch ? kMmPerInch : 1.0;
        res.blank = Blank{program.blank->min * unit, program.blank->max * unit, program.blank->axis};
    }
    // One segment per block is the common case (CAM output): reserving it up front avoids the
    // copies and the doubled capacity of growing columns (peak memory).
    res.nominal.reserve(program.size());
    res.path.reserve(program.size());
    ControlProfile profile = options.profile ? *options.profile : profile_for(program.dialect);
    CompensationChain chain(profile, res.path, res.diagnostics);
    Tee tee(res.nominal, chain);
    iso::InterpretOptions iopts;
    iopts.block_delete = options.block_delete;
    iopts.progress = options.progress;
    iopts.progress_every = options.progress_every ? options.progress_every : 1;
    iopts.search_path = options.search_path;
    iopts.parameters = options.parameters;
    iso::InterpretOutput out;
    out.files.push_back(program.name);
    try {
        if (program.dialect == Dialect::heidenhain)
            heidenhain::interpret(program, tools, profile, tee, res.diagnostics, iopts.progress, iopts.progress_every,
                                  options.search_path, &out.files);
        else if (program.dialect == Dialect::sinumerik)
            sinumerik::interpret(program, tools, profile, sinumerik_options(options, profile), tee, res.diagnostics,
                                 &out.files);
        else if (is_iso(program.dialect))
            iso::interpret(program, tools, profile, iopts, tee, res.diagnostics, &out);
        else
            dialect_not_supported(program.dialect);
    } catch (const Error& e) {
        if (options.strict) throw;
        tee.finish();
        res.diagnostics.push_back(e.diagnostic());
    }
    res.nominal.files = out.files;
    res.path.files = std::move(out.files);
    res.parameters = std::move(out.parameters);
    return res;
}

}  // namespace toolcomp
