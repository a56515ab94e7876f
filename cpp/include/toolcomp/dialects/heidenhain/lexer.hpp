#pragma once
// Front end for Heidenhain conversational (Klartext) programs, TNC 426 era.
//
// A block per line: an optional block number, then a function (L, C, CC, CR, CT, RND, CHF,
// LP, CP, TOOL DEF, TOOL CALL, APPR .., DEP .., BLK FORM, BEGIN/END PGM ...) and its words.
// Words are letters with an optional signed number (X+10, IX-5, DR-, RL, FMAX, F100, M3,
// LEN15, CCA180); a decimal comma is read as a point; ';' starts a comment; a '*' block is a
// structure block (kept as a comment). Lines after END PGM are not part of the program.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "toolcomp/program/program.hpp"

namespace toolcomp::heidenhain {

Program parse(std::string_view text, std::string name = "<string>", bool strict = true);

// A program file read a piece at a time (whole lines each: program/file_pieces.hpp): each
// piece's Program goes on with the line numbers, the unit (BEGIN PGM ... INCH) and the blank
// (BLK FORM) of the pieces before. A block continued with '~' past a piece's last line is
// held back and read with the next piece (a piece's Program holds whole blocks only). The
// frame is checked as parse() checks it: BEGIN PGM first and END PGM last, at END PGM or at
// end(). parse() above is a text read as one piece.
class PieceParser {
public:
    // `piece_bytes`: the size pieces grow to (room is reserved for that much), 0 for a text
    // parsed whole.
    PieceParser(std::string name, bool strict, std::size_t piece_bytes = 0);
    // `into`: a Program no longer needed, whose memory the piece reuses.
    Program parse(std::string_view piece, Program into = {});
    // The end of the text (no piece after the last one given): the block held back, if any,
    // and the frame's check (END PGM missing). Then done().
    Program end(Program into = {});
    // END PGM or a syntax error was met (lenient), or the end: later text is not part of the
    // program.
    bool done() const { return done_; }

private:
    void start_piece(Program& prog) const;
    void lex(std::string_view text, Program& prog);
    void finish_piece(Program& prog);
    void check_frame(Program& prog);

    std::string name_;
    bool strict_;
    std::size_t piece_bytes_;
    bool first_ = true, done_ = false;
    bool ended_ = false;   // END PGM seen
    bool failed_ = false;  // a syntax error (lenient)
    int line_ = 0;         // lines read so far
    int last_line_ = 0;    // the last line with a block
    bool inch_ = false;
    std::optional<Blank> blank_;
    std::string held_;  // the lines of a block continued past the last piece's end
    // The frame: the program's first block (its line), and its first block with tokens
    // (whether it is BEGIN PGM, its line and the first token's column).
    bool any_block_ = false, found_ = false, begins_ = false;
    int first_line_ = 0, found_line_ = 0, found_column_ = 0;
};

// Whether the blocks of `text` may depend on each other beyond the modal state, so that a
// run must read the whole program before it starts: a label or a jump to one (LBL, CALL LBL,
// LBL 0, FN 9 to FN 12 ... GOTO LBL), a contour given by labels (CYCL DEF 14, LABEL). A scan
// of the runs of letters outside ';' comments (so "CALL LBL1" and "lbl" have LBL): "yes" may
// be wrong, "no" is not. CALL PGM is none: the called file is read whole on its own.
// The unit and the blank are the whole program's before its first block runs: `start` says
// the text is the file's first piece (read before the run starts), where BEGIN PGM and BLK
// FORM may be, unless in a block continued with '~' (that one may end in the next piece);
// in any other piece they are control flow.
bool has_control_flow(std::string_view text, bool start = true);

}  // namespace toolcomp::heidenhain
