#pragma once
// What each fuzz target does with one input, shared by the libFuzzer executables (fuzz/*.cpp)
// and the regression test that replays saved inputs (tests/cpp/test_fuzz_regressions.cpp).
//
// Every function returns Outcome::ok when the input went through and Outcome::error when it
// was rejected with a toolcomp::Error, the documented way to refuse input. Anything else
// (another exception, a sanitizer report, a crash, a hang) is a bug.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "toolcomp/control/profile.hpp"
#include "toolcomp/dialects/heidenhain/lexer.hpp"
#include "toolcomp/dialects/iso/lexer.hpp"
#include "toolcomp/dialects/sinumerik/lexer.hpp"
#include "toolcomp/program/diagnostic.hpp"
#include "toolcomp/run.hpp"
#include "toolcomp/tools/sinumerik_edge.hpp"
#include "toolcomp/tools/tool_table.hpp"

#include "dialects/heidenhain/line_lexer.hpp"  // the lexers' two readings, compared (cpp/src)
#include "dialects/iso/line_lexer.hpp"
#include "dialects/sinumerik/line_lexer.hpp"

namespace toolcomp::fuzz {

enum class Outcome { ok, error };

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

template <class F>
Outcome ok_or_error(F&& f) {
    try {
        f();
        return Outcome::ok;
    } catch (const Error&) {
        return Outcome::error;
    }
}

// ---- front ends -------------------------------------------------------------------------

// Two readings of a block: the same line, counts and flags, and the same words (values bit
// for bit, columns, computed or not).
inline bool same_block(const Program& p, const Block& a, const Program& q, const Block& b) {
    if (a.line != b.line || a.word_count != b.word_count || a.comment_count != b.comment_count ||
        a.statement_count != b.statement_count || a.block_delete != b.block_delete)
        return false;
    const auto wa = p.words(a), wb = q.words(b);
    for (std::size_t k = 0; k < wa.size(); ++k)
        if (wa[k].letter != wb[k].letter || std::memcmp(&wa[k].value, &wb[k].value, sizeof(double)) != 0 ||
            wa[k].column != wb[k].column || (wa[k].expr < 0) != (wb[k].expr < 0))
            return false;
    return true;
}

// A text read in pieces of whole lines (at least `piece` bytes each, as a streamed run reads a
// file) must give the blocks and the syntax error of the text parsed whole (both leniently);
// a difference is a bug (std::logic_error).
inline void same_in_pieces(std::string_view text, Dialect d, std::size_t piece) {
    const Program whole = iso::parse(text, d, "<fuzz>", /*strict=*/false);
    iso::PieceParser parser(d, "<fuzz>", /*strict=*/false);
    std::size_t block = 0;
    Program last;
    for (std::size_t pos = 0; pos < text.size() && !parser.done();) {
        std::size_t end = text.find('\n', std::min(text.size(), pos + piece - 1));
        end = end == std::string_view::npos ? text.size() : end + 1;
        last = parser.parse(text.substr(pos, end - pos), std::move(last));  // over the piece before, as a run
        pos = end;
        for (std::size_t i = 0; i < last.size(); ++i, ++block) {
            if (block >= whole.size()) throw std::logic_error("pieces: more blocks than the whole text");
            if (!same_block(whole, whole.blocks()[block], last, last.blocks()[i]))
                throw std::logic_error("pieces: block " + std::to_string(block) + " differs");
        }
    }
    if (block != whole.size()) throw std::logic_error("pieces: fewer blocks than the whole text");
    const auto& ea = whole.syntax_error;
    const auto& eb = last.syntax_error;
    if (ea.has_value() != eb.has_value() || (ea && (ea->code != eb->code || ea->pos.line != eb->pos.line ||
                                                    ea->pos.column != eb->pos.column)))
        throw std::logic_error("pieces: the syntax error differs");
    if (!text.empty() && (whole.last_line != last.last_line || whole.percent_open != last.percent_open ||
                          whole.percent_closed != last.percent_closed))
        throw std::logic_error("pieces: the end of the text differs");
}

// The ISO lexer's fast path must read every line it takes as the general lexer reads it
// (words, values bit for bit, columns), and leave nothing behind on a line it refuses; a
// difference is a bug (std::logic_error).
inline void same_plain_reading(std::string_view text, Dialect d) {
    iso::LineBuffers buffers;
    for (std::size_t pos = 0; pos <= text.size();) {
        std::size_t nl = text.find('\n', pos);
        if (nl == std::string_view::npos) nl = text.size();
        const std::string_view line = text.substr(pos, nl - pos);
        pos = nl + 1;
        Program fast, slow;
        fast.dialect = slow.dialect = d;
        if (!iso::lex_line_fast(line, 1, fast)) {
            if (fast.size() != 0 || fast.word_count() != 0) throw std::logic_error("plain line: a refused line left words");
            continue;
        }
        try {
            iso::LineLexer(line, 1, slow, buffers).run();
        } catch (const Error&) {
            throw std::logic_error("plain line: taken, but the general lexer refuses it");
        }
        if (fast.size() != 1 || slow.size() != 1) throw std::logic_error("plain line: not one block");
        if (!same_block(fast, fast.blocks()[0], slow, slow.blocks()[0]))
            throw std::logic_error("plain line: the block differs");
    }
}

// ISO word-address front end. First byte: dialect (% 3: linuxcnc, fanuc, rockwell), strict
// (/ 3 even) or lenient parsing, and (/ 6) the size of the pieces the text is also read in;
// the rest is the program text.
inline Outcome iso_parse(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return Outcome::ok;
    static constexpr Dialect dialects[] = {Dialect::linuxcnc, Dialect::fanuc, Dialect::rockwell};
    const Dialect d = dialects[data[0] % 3];
    const bool strict = (data[0] / 3) % 2 == 0;
    const std::string_view text = as_text(data + 1, size - 1);
    const Outcome o = ok_or_error([&] { (void)iso::parse(text, d, "<fuzz>", strict); });
    same_in_pieces(text, d, 1 + data[0] / 6);
    same_plain_reading(text, d);
    return o;
}


// A Sinumerik text read in pieces of whole lines (at least `piece` bytes each) must give the
// blocks, tokens and syntax error of the text parsed whole (both leniently): the line numbers
// and DEFINE macros go on across pieces. A difference is a bug (std::logic_error).
// Token::param is an expression's index in assignments ("=", "FRAME=": the target's) and in
// value calls (1 + the target's, 0 when not assigned), and each piece numbers its expressions
// from 0: there only whether there is one is compared.
inline bool same_param(const Token& a, const Token& b) {
    if (a.key == "=" || a.key == "FRAME=") return true;
    if (sinumerik::is_value_call(a.key)) return (a.param > 0) == (b.param > 0);
    return a.param == b.param;
}
inline bool same_token(const Token& a, const Token& b) {
    return a.key == b.key && a.text == b.text && std::memcmp(&a.value, &b.value, sizeof(double)) == 0 &&
           a.has_value == b.has_value && a.sign_only == b.sign_only && same_param(a, b) && a.column == b.column &&
           (a.expr < 0) == (b.expr < 0);
}
// `text` cut into pieces of whole lines (each at least `piece` bytes, up to the next line
// end, the last maybe without one), as a file is read (program/file_pieces.hpp): f(piece)
// for each while it returns true.
template <typename F>
void for_each_piece(std::string_view text, std::size_t piece, F&& f) {
    for (std::size_t pos = 0; pos < text.size();) {
        std::size_t end = text.find('\n', std::min(text.size(), pos + piece - 1));
        end = end == std::string_view::npos ? text.size() : end + 1;
        if (!f(text.substr(pos, end - pos))) return;
        pos = end;
    }
}

// The blocks of the pieces, in turn, against those of the text parsed whole.
class SameBlocks {
public:
    SameBlocks(const Program& whole, const char* what) : whole_(whole), what_(what) {}
    template <typename SameToken>
    void piece(const Program& p, SameToken&& same_token) {
        for (std::size_t i = 0; i < p.size(); ++i, ++block_) {
            if (block_ >= whole_.size()) throw std::logic_error(std::string(what_) + ": more blocks than the whole text");
            const Block& a = whole_.blocks()[block_];
            const Block& b = p.blocks()[i];
            const auto ta = whole_.tokens(a), tb = p.tokens(b);
            bool same = a.line == b.line && a.block_delete == b.block_delete && ta.size() == tb.size();
            for (std::size_t k = 0; same && k < ta.size(); ++k) same = same_token(ta[k], tb[k]);
            if (!same) throw std::logic_error(std::string(what_) + ": block " + std::to_string(block_) + " differs");
        }
    }
    // The last piece: all blocks seen, the same syntax error.
    void last(const Program& p) const {
        if (block_ != whole_.size()) throw std::logic_error(std::string(what_) + ": fewer blocks than the whole text");
        const auto& ea = whole_.syntax_error;
        const auto& eb = p.syntax_error;
        if (ea.has_value() != eb.has_value() || (ea && (ea->code != eb->code || ea->pos.line != eb->pos.line ||
                                                        ea->pos.column != eb->pos.column)))
            throw std::logic_error(std::string(what_) + ": the syntax error differs");
    }

private:
    const Program& whole_;
    const char* what_;
    std::size_t block_ = 0;
};

// `text` read by `parser` in pieces against `whole`, the text parsed whole: the blocks and
// tokens of each piece (`same_token`), and the syntax error of the last. A parser with end()
// (Heidenhain: a held-back block, the frame's check) is given the file's end. Returns the
// last piece's Program.
template <typename Parser, typename SameToken>
Program read_in_pieces(const Program& whole, Parser& parser, std::string_view text, std::size_t piece,
                       const char* what, SameToken same_token) {
    SameBlocks same(whole, what);
    Program last;
    for_each_piece(text, piece, [&](std::string_view t) {
        last = parser.parse(t, std::move(last));
        same.piece(last, same_token);
        return !parser.done();
    });
    if constexpr (requires { parser.end(Program{}); }) {
        if (!parser.done()) {
            last = parser.end(std::move(last));
            same.piece(last, same_token);
        }
    }
    same.last(last);
    return last;
}

inline void same_sinumerik_in_pieces(std::string_view text, std::size_t piece) {
    sinumerik::PieceParser parser("<fuzz>", /*strict=*/false, piece);
    read_in_pieces(sinumerik::parse(text, "<fuzz>", /*strict=*/false), parser, text, piece, "sinumerik pieces", same_token);
}

// The same of a Klartext text: line numbers, the unit and the blank go on across pieces, a
// block continued with '~' past a piece's end is read with the next one, and the frame's
// errors (BEGIN PGM, END PGM missing) are found at END PGM or at the end.
inline bool same_heidenhain_token(const Token& a, const Token& b) {
    return a.key == b.key && a.text == b.text && std::memcmp(&a.value, &b.value, sizeof(double)) == 0 &&
           a.has_value == b.has_value && a.sign_only == b.sign_only && a.param == b.param && a.column == b.column &&
           a.expr == b.expr;
}
inline void same_heidenhain_in_pieces(std::string_view text, std::size_t piece) {
    const Program whole = heidenhain::parse(text, "<fuzz>", /*strict=*/false);
    heidenhain::PieceParser parser("<fuzz>", /*strict=*/false, piece);
    const Program last = read_in_pieces(whole, parser, text, piece, "heidenhain pieces", same_heidenhain_token);
    if (last.inch != whole.inch || last.last_line != whole.last_line || last.blank.has_value() != whole.blank.has_value() ||
        (last.blank && (last.blank->min != whole.blank->min || last.blank->max != whole.blank->max ||
                        last.blank->axis != whole.blank->axis)))
        throw std::logic_error("heidenhain pieces: the unit, the blank or the last line differs");
}

// A token-lexer's fast path (Sinumerik, Klartext) must read every line of `text` it takes as
// the general lexer reads it (tokens by `same_token`, values bit for bit, columns), and leave
// nothing behind on a line it refuses; lines with a byte of `cut_at` are not lines the
// parser gives it. A difference is a bug (std::logic_error).
template <typename Fast, typename General, typename SameToken>
void same_plain_token_reading(std::string_view text, const char* what, std::string_view cut_at, Fast fast_lexer,
                              General general_lexer, SameToken same_token) {
    for_each_piece(text, 1, [&](std::string_view line) {
        if (!line.empty() && line.back() == '\n') line.remove_suffix(1);
        if (line.find_first_of(cut_at) != std::string_view::npos) return true;
        Program fast, slow;
        if (!fast_lexer(line, 1, fast)) {
            if (fast.size() != 0) throw std::logic_error(std::string(what) + ": a refused line left a block");
            return true;
        }
        try {
            general_lexer(line, 1, slow);
        } catch (const Error&) {
            throw std::logic_error(std::string(what) + ": taken, but the general lexer refuses it");
        }
        if (slow.size() == 1 && slow.blocks()[0].comment_count != 0)
            throw std::logic_error(std::string(what) + ": taken, but the line has a comment");
        SameBlocks same(slow, what);
        same.piece(fast, same_token);
        same.last(fast);
        return true;
    });
}

inline void same_klartext_plain_reading(std::string_view text) {
    same_plain_token_reading(text, "klartext plain line", {}, heidenhain::lex_line_fast,
                             [](std::string_view l, int n, Program& p) { heidenhain::lex_line(l, n, p); },
                             same_heidenhain_token);
}

// Heidenhain conversational front end; the last byte's low bit parses leniently, the first
// byte sets the size of the pieces the text is also read in.
inline Outcome heidenhain_parse(const std::uint8_t* data, std::size_t size) {
    const std::string_view text = as_text(data, size);
    const bool strict = size == 0 || (data[size - 1] & 1) == 0;
    const Outcome o = ok_or_error([&] { (void)heidenhain::parse(text, "<fuzz>", strict); });
    same_heidenhain_in_pieces(text, 1 + (size ? data[0] % 64 : 0));
    same_klartext_plain_reading(text);
    return o;
}

// The Sinumerik parser cuts lines at CR too, and refuses a NUL before lexing.
inline void same_sinumerik_plain_reading(std::string_view text) {
    same_plain_token_reading(text, "sinumerik plain line", std::string_view("\r\0", 2), sinumerik::lex_line_fast,
                             sinumerik::lex_line, same_token);
}

// Sinumerik 840D front end; the last byte's low bit parses leniently, the first byte sets the
// size of the pieces the text is also read in.
inline Outcome sinumerik_parse(const std::uint8_t* data, std::size_t size) {
    const std::string_view text = as_text(data, size);
    const bool strict = size == 0 || (data[size - 1] & 1) == 0;
    const Outcome o = ok_or_error([&] { (void)sinumerik::parse(text, "<fuzz>", strict); });
    same_sinumerik_in_pieces(text, 1 + (size ? data[0] % 64 : 0));
    same_sinumerik_plain_reading(text);
    return o;
}

// ---- the whole pipeline -----------------------------------------------------------------

// Mill tools 1-8 (end mills, toroid, ball, zero radius, a radius that wear makes negative),
// lathe offsets 10-19 (every tip number, with wear) and a two-edge tool 20.
inline const ToolTable& pipeline_tools() {
    static const ToolTable t = [] {
        ToolTable tt;
        auto add = [&](int n, double x, double z, double r, double r2, int tip, double rw, double zw) {
            Tool tool;
            tool.number = n;
            tool.pocket = n;
            CuttingEdge& e = tool.edges.front();
            e.length = {x, 0, z};
            e.radius = r;
            e.corner_radius = r2;
            e.orientation = tip;
            e.radius_wear = rw;
            e.length_wear = {0.01, 0, zw};
            tt.set(tool);
        };
        add(1, 0, 50, 5, 0, 0, 0, 0);
        add(2, 0, 40, 3, 1, 0, -0.02, 0.05);
        add(3, 0, 75, 4, 4, 0, 0, 0);
        add(4, 0.5, 30, 0.5, 0, 0, 0, 0);
        add(5, 0, 100, 10, 2, 0, 0.1, -0.1);
        add(6, 0, 25, 1, 0, 0, 0, 0);
        add(7, 0, 20, 0, 0, 0, 0, 0);
        add(8, 0, 20, 0.1, 0, 0, -0.2, 0);
        for (int tip = 0; tip <= 9; ++tip) add(10 + tip, -2.5 + tip, 1.25 * tip, 0.8, 0, tip, 0.005, -0.01);
        Tool multi;
        multi.number = 20;
        multi.edges.front().radius = 2;
        CuttingEdge e2;
        e2.number = 2;
        e2.radius = 2.5;
        e2.length = {0, 0, 10};
        multi.set_edge(e2);
        tt.set(multi);
        return tt;
    }();
    return t;
}

// Parse + run with pipeline_tools(). First byte: % 8 picks dialect and profile
//   0 linuxcnc, 1 fanuc mill, 2 fanuc lathe, 3 rockwell, 4 heidenhain,
//   5 linuxcnc program under the sinumerik profile, 6 linuxcnc under the fanuc profile, 7 sinumerik;
// bit 3 runs lenient (strict = false), bit 4 skips '/' blocks.
inline Outcome pipeline(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return Outcome::ok;
    const unsigned sel = data[0];
    const std::string_view text = as_text(data + 1, size - 1);
    Dialect d = Dialect::linuxcnc;
    std::optional<ControlProfile> prof;
    switch (sel % 8) {
        case 1: d = Dialect::fanuc; break;
        case 2: d = Dialect::fanuc; prof = profile_for(Dialect::fanuc, MachineKind::lathe); break;
        case 3: d = Dialect::rockwell; break;
        case 4: d = Dialect::heidenhain; break;
        case 5: prof = profile_for(Dialect::sinumerik); break;
        case 6: prof = profile_for(Dialect::fanuc); break;
        case 7: d = Dialect::sinumerik; break;
        default: break;
    }
    if (!prof) prof = profile_for(d);
    // Loops and repeats stop with an error here instead of taking the fuzzer's time.
    prof->block_limit = 20000;
    RunOptions opt;
    opt.strict = (sel & 8) == 0;
    opt.block_delete = (sel & 16) != 0;
    opt.profile = *prof;
    return ok_or_error([&] {
        const Program p = parse_program(text, d, "<fuzz>", opt.strict);
        const Result r = run(p, &pipeline_tools(), opt);
        (void)r.ok();
    });
}

// ---- tool tables --------------------------------------------------------------------------

// Read; write back in the same format (the lossless path) and read that again; change one
// tool, remove one, add one and write (the partial-rewrite path); convert to every other
// format (the canonical writers). The last byte's low bit reads the lengths as inches.
inline Outcome table(TableFormat format, const std::uint8_t* data, std::size_t size) {
    const std::string_view text = as_text(data, size);
    const LengthUnit units = size > 0 && (data[size - 1] & 1) ? LengthUnit::inch : LengthUnit::mm;
    ToolTable t;
    if (ok_or_error([&] { t = read_tool_table(text, format, units); }) == Outcome::error) return Outcome::error;
    ok_or_error([&] { (void)read_tool_table(write_tool_table(t, format), format, units); });
    ok_or_error([&] {
        ToolTable edited = t;
        if (!edited.empty()) {
            Tool first = edited.tools().front();
            first.comment += " x";
            first.edges.front().radius += 0.125;
            first.edges.front().length.z() -= 1.5;
            edited.set(first);
            if (edited.size() > 1) edited.remove(edited.tools().back().number);
        }
        Tool added;
        added.number = 9999;
        added.edges.front().radius = 1.25;
        added.edges.front().length.z() = 42;
        edited.set(added);
        (void)read_tool_table(write_tool_table(edited, format), format, units);
    });
    for (TableFormat other : {TableFormat::linuxcnc, TableFormat::csv, TableFormat::json, TableFormat::heidenhain,
                              TableFormat::sinumerik})
        if (other != format) ok_or_error([&] { (void)write_tool_table(t, other); });
    return Outcome::ok;
}

// Sinumerik tool data ("$TC_DPn[t,d]=value" lines): parse, the totals of every edge, write,
// parse again.
inline Outcome tc_dp(const std::uint8_t* data, std::size_t size) {
    const std::string_view text = as_text(data, size);
    return ok_or_error([&] {
        const sinumerik::SinumerikEdgeMap edges = sinumerik::parse_tc_dp(text);
        for (const auto& [key, e] : edges) {
            (void)e.length(1);
            (void)e.radius(-1.0, 0.5);
            (void)sinumerik::tool_length_vector(e, Plane::zx);
        }
        (void)sinumerik::parse_tc_dp(sinumerik::write_tc_dp(edges));
    });
}

}  // namespace toolcomp::fuzz
