#pragma once
// Diagnostics and the single exception family of toolcomp.
//
// Every message the engine produces carries a stable machine-readable code (snake_case,
// e.g. "arc_end_off_circle"), a human message (where a real control has a message of its
// own, that exact text), and the source position (1-based line and column; 0 when unknown).
#include <stdexcept>
#include <string>
#include <vector>

namespace toolcomp {

enum class Severity { info = 0, warning = 1, error = 2 };

struct SourcePos {
    int line = 0;    // 1-based; 0 = not tied to a source line
    int column = 0;  // 1-based; 0 = whole line
    std::string file;  // the called program or subprogram file the line is in; "" = the main program
    // Set by stages that know only the file's index (Motion::file) and not its name: the run
    // puts the name of files[file_index] in `file` (-1: not known).
    int file_index = -1;
};

/// A message from the engine: stable code, severity, text and source position.
struct Diagnostic {
    /// stable machine-readable code, snake_case (e.g. 'arc_end_off_circle')
    std::string code;
    /// 'info', 'warning' or 'error'
    Severity severity = Severity::error;
    /// human-readable message (the control's own text where it has one)
    std::string message;
    SourcePos pos;
};

// Which stage raised an error; maps to the Python classes ParseError, ProgramError,
// CompensationError, ToolTableError (all deriving from toolcomp.Error).
enum class ErrorKind { generic, parse, program, compensation, tool_table };

// `message` with each NUL byte written as "\x00": what() is a C string, which a NUL (quoted
// from a program or a file name) would cut short.
std::string without_nul(const std::string& message);

class Error : public std::runtime_error {
public:
    Error(ErrorKind kind, std::string code, const std::string& message, SourcePos pos = {})
        : std::runtime_error(message.find('\0') == std::string::npos ? message : without_nul(message)),
          kind_(kind), code_(std::move(code)), pos_(pos) {}
    ErrorKind kind() const noexcept { return kind_; }
    const std::string& code() const noexcept { return code_; }
    SourcePos pos() const noexcept { return pos_; }
    int line() const noexcept { return pos_.line; }
    int column() const noexcept { return pos_.column; }
    const std::string& file() const noexcept { return pos_.file; }
    Diagnostic diagnostic() const { return {code_, Severity::error, what(), pos_}; }

private:
    ErrorKind kind_;
    std::string code_;
    SourcePos pos_;
};

struct ParseError : Error {
    ParseError(std::string code, const std::string& msg, SourcePos pos = {})
        : Error(ErrorKind::parse, std::move(code), msg, pos) {}
};
struct ProgramError : Error {
    ProgramError(std::string code, const std::string& msg, SourcePos pos = {})
        : Error(ErrorKind::program, std::move(code), msg, pos) {}
};
struct CompensationError : Error {
    CompensationError(std::string code, const std::string& msg, SourcePos pos = {})
        : Error(ErrorKind::compensation, std::move(code), msg, pos) {}
};
struct ToolTableError : Error {
    ToolTableError(std::string code, const std::string& msg, SourcePos pos = {})
        : Error(ErrorKind::tool_table, std::move(code), msg, pos) {}
};

// Throws an error of e's kind, code and message at `pos`.
[[noreturn]] void throw_at(const Error& e, const SourcePos& pos);

}  // namespace toolcomp
