#pragma once
// The Program model: what a dialect front end produces and an interpreter consumes.
//
// Blocks and words are stored flat (one vector of words, blocks as ranges into it), so a
// million-block CAM program costs two allocations rather than a million.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "toolcomp/column.hpp"
#include "toolcomp/program/dialect.hpp"
#include "toolcomp/program/expr.hpp"
#include "toolcomp/program/short_text.hpp"
#include "toolcomp/geometry/vec.hpp"
#include "toolcomp/program/diagnostic.hpp"

namespace toolcomp {

// One address word: letter and value, with the column of its letter in the source line.
struct Word {
    char letter = 0;   // upper case
    double value = 0;  // as written (program units)
    int column = 0;    // 1-based column of the letter
    std::int32_t expr = -1;  // a computed value (X[#1+2], X#5): index of its expression
};

// A statement of an ISO block that computes or steers (LinuxCNC parameters and O-words,
// Fanuc Macro B). Expressions are indices into Program::expression; -1 = none.
enum class Stmt : std::uint8_t {
    assign,  // #n = value / #<name> = value (target: number expression, or name)
    // LinuxCNC O-words (label: "100" or "<name>")
    o_sub, o_endsub, o_call, o_return, o_if, o_elseif, o_else, o_endif,
    o_while, o_endwhile, o_do, o_repeat, o_endrepeat, o_break, o_continue,
    // LinuxCNC 2.9's Fanuc-style numbered subprograms: M98 as a line's first word (the call;
    // the line's other words are read, not run), M99 as a line's first word (the return in a
    // subprogram; in the main program the block runs as a stop)
    m98_call, m99_return,
    // Fanuc Macro B
    program_number,  // O1000 (label) at the start of a program; LinuxCNC: a bare O<n> line
    goto_n,          // GOTO n (target: expression of the sequence number)
    if_goto,         // IF [cond] GOTO n
    if_then,         // IF [cond] THEN: the assignments after it in the block are conditional
    while_do,        // WHILE [cond] DO m (loop: m)
    end_loop,        // END m
};
struct Statement {
    Stmt kind = Stmt::assign;
    int column = 0;
    std::string label;         // O-word label; assign to a named parameter: its name
    std::int32_t target = -1;  // assign: parameter number; goto: sequence number
    std::int32_t value = -1;   // assign value, condition, repeat count, return value
    std::int32_t loop = 0;     // Fanuc DO / END identifier
    std::vector<std::int32_t> args;  // o_call arguments
    std::string text;          // LinuxCNC O-word: the source line (its messages quote it)
};

// A token of a conversational block (Heidenhain Klartext): a keyword or address with an
// optional number ("X+10" -> key "X", value 10; "DR-" -> key "DR", sign -1, no value; "RL";
// "1"; a quoted name).
struct Token {
    ShortText key;           // upper case letters (empty for a plain number or a name)
    ShortText text;          // a quoted name, without the quotes; the text of a Q statement
    double value = 0;        // the number, or ±1 for a bare sign ("DR+")
    int param = 0;           // Heidenhain: a Q parameter in place of the number (X+Q5): its number + 1
                             // (0: none); Sinumerik: see its lexer
    int column = 0;
    std::int32_t expr = -1;  // a computed value: index of its expression (Program::expression)
    bool has_value = false;  // a number was written
    bool sign_only = false;  // "DR+" / "DR-"

    // key == k, lengths first, byte by byte: with `k` a literal the loop unrolls into a few
    // compares (std::string == "literal" calls strlen and memcmp; string_view == still calls
    // memcmp, a call a word for the one-letter keys of every block).
    bool is(std::string_view k) const noexcept {
        if (key.size() != k.size()) return false;
        const char* d = key.data();
        for (std::size_t i = 0; i < k.size(); ++i)
            if (d[i] != k[i]) return false;
        return true;
    }
};
static_assert(sizeof(Token) <= 40, "a million-block program holds millions of tokens");

struct Comment {
    std::string text;  // without the delimiters
    int column = 0;    // 1-based column of the opening delimiter
    bool semicolon = false;  // from ';' to the end of the line (else in parentheses)
};

struct Block {
    int line = 0;               // 1-based source line
    bool block_delete = false;  // the block starts with '/'
    bool computed = false;      // a word's value is an expression (Word::expr)
    std::uint32_t first_word = 0, word_count = 0;
    std::uint32_t first_comment = 0, comment_count = 0;
    std::uint32_t first_token = 0, token_count = 0;
    std::uint32_t first_statement = 0, statement_count = 0;
};

// The workpiece blank (Heidenhain BLK FORM 0.1 / 0.2), program units.
struct Blank {
    Vec3 min = Vec3::Zero(), max = Vec3::Zero();
    int axis = 2;  // tool axis 0 X, 1 Y, 2 Z
};

/// A parsed part program (blocks of words) in one dialect; create it with Program.read or
/// Program.parse.
class Program {
public:
    /// file name, or "<string>" (or the name given to parse)
    std::string name;
    /// dialect name: 'linuxcnc', 'fanuc', 'sinumerik', 'heidenhain' or 'rockwell'
    Dialect dialect = Dialect::linuxcnc;
    // How the text ended: '%' delimiters seen (opening / closing), and the last line with
    // content (for "program ended without M2/M30" errors).
    bool percent_open = false, percent_closed = false;
    int last_line = 0;
    // A program parsed leniently keeps the blocks before its first syntax error and the
    // error itself, which the interpreter raises when execution reaches that line (a
    // control reports a bad line only when it gets there: never after M2).
    /// the first syntax error of a leniently parsed program (a Diagnostic; raised when a
    /// run reaches its line), or None
    std::optional<Diagnostic> syntax_error;
    std::optional<Blank> blank;
    bool inch = false;  // conversational programs declare their unit (BEGIN PGM ... INCH)
    // A block begins with a statement that steers (Sinumerik: IF, WHILE, GOTOF, CASE, PROC
    // ...): the interpreter indexes the program's control structure before it runs it.
    bool control_statements = false;

    /// number of blocks
    std::size_t size() const { return blocks_.size(); }
    const Column<Block>& blocks() const { return blocks_; }
    std::span<const Word> words(const Block& b) const {
        return {words_.data() + b.first_word, b.word_count};
    }
    std::span<const Comment> comments(const Block& b) const {
        return {comments_.data() + b.first_comment, b.comment_count};
    }
    std::span<const Token> tokens(const Block& b) const { return {tokens_.data() + b.first_token, b.token_count}; }
    std::span<const Statement> statements(const Block& b) const {
        return {statements_.data() + b.first_statement, b.statement_count};
    }
    /// number of words in all blocks
    std::size_t word_count() const { return words_.size(); }
    const expr::Expr& expression(std::int32_t i) const { return exprs_[static_cast<std::size_t>(i)]; }

    // Building (front ends): open a block, add its words and comments, close it.
    void begin_block(int line, bool block_delete);
    void add_word(Word w) {
        words_.push_back(w);
        Block& b = blocks_.back();
        ++b.word_count;
        b.computed = b.computed || w.expr >= 0;
    }
    void add_token(Token&& t) {
        tokens_.push_back(std::move(t));
        ++blocks_.back().token_count;
    }
    // A new empty token of the open block, to be filled in place (a front end that fails
    // half-way drops the block with it).
    Token& new_token() {
        ++blocks_.back().token_count;
        return tokens_.emplace_back();
    }
    void add_comment(Comment c) {
        comments_.push_back(std::move(c));
        ++blocks_.back().comment_count;
    }
    void add_statement(Statement s) {
        statements_.push_back(std::move(s));
        ++blocks_.back().statement_count;
    }
    std::int32_t add_expression(expr::Expr e) {
        exprs_.push_back(std::move(e));
        return static_cast<std::int32_t>(exprs_.size() - 1);
    }
    void drop_last_expression() { exprs_.pop_back(); }
    std::size_t expression_count() const { return exprs_.size(); }
    // The expressions from the n-th on go (those of a line refused half-way).
    void drop_expressions_from(std::size_t n) { exprs_.erase(exprs_.begin() + static_cast<std::ptrdiff_t>(n), exprs_.end()); }
    // Removes the last block (a front end that failed half-way through it).
    void drop_last_block();
    // An empty program again, whose blocks, words, tokens and comments keep their memory: a file read
    // piece by piece parses each piece into the Program of the piece before last, into pages
    // already written (fresh pages cost the kernel's zeroing, and a grown column a copy).
    void clear();
    void reserve(std::size_t blocks, std::size_t words, std::size_t tokens = 0) {
        blocks_.reserve(blocks);
        words_.reserve(words);
        tokens_.reserve(tokens);
    }

private:
    Column<Block> blocks_;
    Column<Word> words_;
    std::vector<Comment> comments_;
    std::vector<Token, ColumnAllocator<Token>> tokens_;  // huge pages, kept for the next program
    std::vector<expr::Expr> exprs_;
    std::vector<Statement> statements_;
};

}  // namespace toolcomp
