// The table of dialects (table.hpp), and the names and suffixes of program/dialect.hpp read
// from it.
#include "table.hpp"
#include "toolcomp/program/codes.hpp"

#include <algorithm>
#include <string>

#include "toolcomp/dialects/heidenhain/interpreter.hpp"
#include "toolcomp/dialects/heidenhain/lexer.hpp"
#include "toolcomp/dialects/iso/interpreter.hpp"
#include "toolcomp/dialects/iso/lexer.hpp"
#include "toolcomp/dialects/sinumerik/interpreter.hpp"
#include "toolcomp/dialects/sinumerik/lexer.hpp"
#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/program/text.hpp"

namespace toolcomp {

namespace {
SearchPath search_of(const RunOptions& o) { return {o.search_path, o.follow_links, o.limits}; }

// ---- front ends ------------------------------------------------------------------------
template <Dialect D>
Program parse_iso(std::string_view text, std::string name, bool strict) {
    return iso::parse(text, D, std::move(name), strict);
}
Program parse_sinumerik(std::string_view text, std::string name, bool strict) {
    return sinumerik::parse(text, std::move(name), strict);
}
Program parse_heidenhain(std::string_view text, std::string name, bool strict) {
    return heidenhain::parse(text, std::move(name), strict);
}

// ---- interpreters: the run's options as each takes them ---------------------------------
void interpret_iso(const DialectRun& r) {
    const RunOptions& o = r.options;
    iso::InterpretOptions iopts;
    iopts.block_delete = o.block_delete;
    iopts.progress = o.progress;
    iopts.progress_every = o.progress_every ? o.progress_every : 1;
    iopts.search = search_of(o);
    iopts.machine = o.machine.get();
    iopts.start = o.start;
    iopts.parameters = o.parameters;
    iopts.probes = o.probes;
    iopts.next_piece = r.hooks.next_piece;
    iopts.file_opened = r.hooks.file_opened;
    iso::interpret(r.program, r.tools, r.profile, iopts, r.sink, r.diagnostics, &r.out);
}

void interpret_sinumerik(const DialectRun& r) {
    const RunOptions& o = r.options;
    const ControlProfile& p = r.profile;
    sinumerik::InterpretOptions s;
    s.lengths.tool_length_const = p.tool_length_const;
    s.lengths.tool_length_type = p.tool_length_type;
    s.lengths.wear_sign_inverted = p.wear_sign < 0;
    s.tool_parameter_def_mask = p.tool_parameter_def_mask;
    s.block_delete = o.block_delete;
    s.progress = o.progress;
    s.progress_every = o.progress_every ? o.progress_every : 1;
    s.search = search_of(o);
    s.machine = o.machine.get();
    s.start = o.start;
    s.next_piece = r.hooks.next_piece;
    s.file_opened = r.hooks.file_opened;
    sinumerik::interpret(r.program, r.tools, p, s, r.sink, r.diagnostics, &r.out);
}

void interpret_heidenhain(const DialectRun& r) {
    const RunOptions& o = r.options;
    heidenhain::interpret(r.program, r.tools, r.profile, r.sink, r.diagnostics, o.progress,
                          o.progress_every ? o.progress_every : 1, search_of(o), &r.out, o.machine.get(),
                          o.block_delete, o.start, {r.hooks.next_piece, r.hooks.file_opened});
}

// ---- reading a file a piece at a time ------------------------------------------------------
template <typename Parser>
class Pieces : public PieceReader {
public:
    explicit Pieces(Parser p) : p_(std::move(p)) {}
    Program parse(std::string_view piece, Program into) override { return p_.parse(piece, std::move(into)); }
    bool done() const override { return p_.done(); }
    std::optional<Program> end(Program into) override {
        if constexpr (requires { p_.end(std::move(into)); })
            return p_.end(std::move(into));
        else
            return std::nullopt;
    }

private:
    Parser p_;
};
std::unique_ptr<PieceReader> iso_pieces(Dialect d, std::string name, bool strict, std::size_t piece_bytes) {
    return std::make_unique<Pieces<iso::PieceParser>>(iso::PieceParser(d, std::move(name), strict, piece_bytes));
}
std::unique_ptr<PieceReader> heidenhain_pieces(Dialect, std::string name, bool strict, std::size_t piece_bytes) {
    return std::make_unique<Pieces<heidenhain::PieceParser>>(heidenhain::PieceParser(std::move(name), strict, piece_bytes));
}
std::unique_ptr<PieceReader> sinumerik_pieces(Dialect, std::string name, bool strict, std::size_t piece_bytes) {
    return std::make_unique<Pieces<sinumerik::PieceParser>>(sinumerik::PieceParser(std::move(name), strict, piece_bytes));
}

// Scans of each piece alike, wherever it is in the file.
template <bool (*Scan)(std::string_view)>
bool any_piece(std::string_view text, bool) {
    return Scan(text);
}

constexpr DialectRow kDialects[] = {
    {.dialect = Dialect::linuxcnc, .name = "linuxcnc", .suffixes = {"ngc", ""}, .cr_ends_line = false,
     .interpreter_checks_travel = true, .parse = parse_iso<Dialect::linuxcnc>, .interpret = interpret_iso,
     .has_control_flow = any_piece<iso::has_control_flow>, .pieces = iso_pieces},
    {.dialect = Dialect::fanuc, .name = "fanuc", .suffixes = {"nc", "tap"}, .cr_ends_line = true,
     .interpreter_checks_travel = true, .parse = parse_iso<Dialect::fanuc>, .interpret = interpret_iso,
     .has_control_flow = any_piece<iso::has_control_flow>, .pieces = iso_pieces},
    {.dialect = Dialect::sinumerik, .name = "sinumerik", .suffixes = {"mpf", "spf"}, .cr_ends_line = true,
     .interpreter_checks_travel = false, .parse = parse_sinumerik, .interpret = interpret_sinumerik,
     .has_control_flow = any_piece<sinumerik::has_control_flow>, .pieces = sinumerik_pieces},
    {.dialect = Dialect::heidenhain, .name = "heidenhain", .suffixes = {"h", ""}, .cr_ends_line = true,
     .interpreter_checks_travel = false, .parse = parse_heidenhain, .interpret = interpret_heidenhain,
     .has_control_flow = heidenhain::has_control_flow, .pieces = heidenhain_pieces},
    {.dialect = Dialect::rockwell, .name = "rockwell", .suffixes = {"", ""}, .cr_ends_line = true,
     .interpreter_checks_travel = true, .parse = parse_iso<Dialect::rockwell>, .interpret = interpret_iso,
     .has_control_flow = any_piece<iso::has_control_flow>, .pieces = iso_pieces},
};

std::string lower(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(), [](char c) { return ascii_lower(c); });
    return out;
}
}  // namespace

std::span<const DialectRow> dialect_table() { return kDialects; }

std::vector<DialectNames> dialect_names() {
    std::vector<DialectNames> out;
    for (const DialectRow& r : kDialects) out.push_back({r.dialect, r.name, r.suffixes});
    return out;
}

const DialectRow& dialect_row(Dialect d) {
    for (const DialectRow& r : kDialects)
        if (r.dialect == d) return r;
    throw ParseError(code::dialect_not_supported, "The dialect is not supported by toolcomp");
}

std::string_view dialect_name(Dialect d) {
    for (const DialectRow& r : kDialects)
        if (r.dialect == d) return r.name;
    return "unknown";
}

bool cr_ends_line(Dialect d) { return dialect_row(d).cr_ends_line; }

Dialect dialect_from_name(std::string_view name) {
    const std::string l = lower(name);
    std::string all;
    for (const DialectRow& r : kDialects) {
        if (r.name == l) return r.dialect;
        all += (all.empty() ? "" : ", ") + std::string(r.name);
    }
    throw ParseError(code::unknown_dialect, "Unknown dialect '" + std::string(name) + "' (expected " + all + ")");
}

std::optional<Dialect> dialect_from_suffix(std::string_view path) {
    const auto dot = path.rfind('.');
    if (dot == std::string_view::npos) return std::nullopt;
    const std::string ext = lower(path.substr(dot + 1));
    for (const DialectRow& r : kDialects)
        for (std::string_view s : r.suffixes)
            if (!s.empty() && s == ext) return r.dialect;
    return std::nullopt;
}

Dialect dialect_of_file(std::string_view path, std::optional<Dialect> given) {
    if (given) return *given;
    if (auto s = dialect_from_suffix(path)) return *s;
    throw ParseError(code::unknown_dialect,
                     "Cannot tell the dialect of '" + std::string(path) + "' from its suffix; pass dialect=");
}

}  // namespace toolcomp
