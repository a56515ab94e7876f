#pragma once
// Working data of the Sinumerik interpreter. Private to the front end; the entry point is
// toolcomp::sinumerik::interpret().
//
// Positions are millimetres (G70/G700 inch words are converted as they are read) in the
// output system (see interpreter.hpp): `pos_` is where the tool is there; the programmable
// frame maps program (workpiece) coordinates p to it: out = frame.a * p + frame.t.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <array>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "../idle_watch.hpp"
#include "toolcomp/program/source_files.hpp"
#include "toolcomp/dialects/sinumerik/interpreter.hpp"
#include "codes.hpp"
#include "control_statements.hpp"
#include "corner_sink.hpp"
#include "frame_value.hpp"

namespace toolcomp::sinumerik {

// A program's control structures and jump targets, found once per program.
// A formal parameter of PROC name(REAL A, VAR INT B, ...).
struct Formal {
    std::string name;
    bool by_reference = false;  // VAR
    bool integer = false;       // INT or BOOL
    bool boolean = false;
    std::size_t text = 0;  // STRING[n]: n
    bool array = false;    // VAR REAL A[n] / A[n, m] / A[, m]: the caller's whole array
    bool axis = false;     // AXIS
};

struct ProgramInfo {
    std::vector<Formal> formals;       // PROC name(...)'s parameters
    std::vector<std::size_t> partner;  // IF->ELSE/ENDIF, ELSE->ENDIF, WHILE<->ENDWHILE, ...
    std::vector<std::uint8_t> kind;    // the block's control statement (Ctl)
};

struct Variable {
    std::vector<double> v;
    bool integer = false;
    // STRING[n]: the values are texts of at most `length` characters
    bool text = false;
    bool axis = false;  // AXIS: the text is an axis name (X, Y, Z, A, B, C)
    std::size_t length = 0;
    std::vector<std::string> s;
    // A VAR parameter: the caller's variable (its element `ref_at`) or R parameter `r_index`.
    Variable* ref = nullptr;
    std::size_t ref_at = 0;
    bool whole = false;  // VAR REAL A[n]: `ref` is the caller's whole array
    int r_index = -1;
    std::size_t cols = 0;  // two-dimensional [rows, cols]; 0 for scalars and one dimension
    // Row-major position of the indices, or nullopt when they do not fit the declaration.
    std::optional<std::size_t> at(std::span<const double> idx) const;
};

// A value word of a block, evaluated.
struct Value {
    double v = 0;
    int column = 0;
    std::int16_t mod = 0;  // 1 AC, 2 IC, 3 DC, 4 ACP, 5 ACN
    bool set = false;
};
static_assert(sizeof(Value) == 16, "a block holds 40 of them, made anew each block");

// A block's G or M functions (code, column) in their order: a few are kept in place, without
// an allocation for each block; a block with more moves them to the heap.
class CodeList {
public:
    using Item = std::pair<int, int>;
    void emplace_back(int code, int column) {
        if (n_ < kInline) {
            inline_[n_++] = {code, column};
            return;
        }
        if (n_ == kInline) heap_.assign(inline_.begin(), inline_.end());
        heap_.emplace_back(code, column);
        ++n_;
    }
    const Item* begin() const { return n_ <= kInline ? inline_.data() : heap_.data(); }
    const Item* end() const { return begin() + n_; }

private:
    static constexpr std::size_t kInline = 6;
    std::array<Item, kInline> inline_{};
    std::vector<Item> heap_;
    std::size_t n_ = 0;
};

// What one block asks for, after its expressions are evaluated.
struct BlockData {
    std::array<Value, 26> letter;  // A..Z (R is never an address)
    Value cr, ar, turn, disc, offn, rpl, i1, j1, k1, tcarr, lims, rnd, chf, chr;
    CodeList g;  // code, column
    CodeList m;
    std::vector<std::pair<std::string, int>> keywords;  // NORM, CDON, TRANS ..., column
    std::string tool_name;  // T="name"
    int tool_name_column = 0;
    const Value& operator[](char c) const { return letter[static_cast<std::size_t>(c - 'A')]; }
    Value& operator[](char c) { return letter[static_cast<std::size_t>(c - 'A')]; }
    bool has(char c) const { return (*this)[c].set; }
    bool keyword(std::string_view k) const {
        for (const auto& [w, c] : keywords)
            if (w == k) return true;
        return false;
    }
};

// What a block calls besides its addresses (interp_block.cpp).
struct BlockCalls {
    std::string name, args;  // a subprogram: by name (with its arguments), L<n>, CALL "path"
    int column = 0;
    bool mcall = false;  // MCALL in this block: the cycle after it is called modally
    std::optional<std::pair<std::string, std::vector<double>>> drill;  // CYCLE8x called here
    std::optional<std::pair<std::string, std::string>> pattern;        // HOLES1/2, CYCLE801 called here
};

// A block's G functions by group (-1: none in the block), its M functions and keywords
// (interp_execute.cpp).
struct BlockCodes {
    int motion = -1, plane = -1, comp = -1, corner = -1, dist = -1, units = -1, nonmodal = -1, workoffset = -1,
        feedmode = -1;
    bool cip = false, ct = false;  // CIP, CT
    bool machine = false;          // G53, G153, SUPA
    std::string frame_word;        // TRANS, ATRANS, ROT, AROT, SCALE, ASCALE, MIRROR, AMIRROR
    int frame_column = 0;
    bool m6 = false, stop = false, end = false, sub_end = false;  // M6; M0/M1; M2/M30; M17
};

struct Modal {
    int motion = G0;  // G0, G1, G2, G3, CIP, CT
    int feed_mode = G94;  // G94 mm/min, G95 mm/rev, G96 mm/rev at a constant cutting speed
    Plane plane = Plane::xy;
    bool incremental = false;
    bool inch = false;       // G70 / G700: geometry in inches
    bool inch_feed = false;  // G700: feed too
    bool diameter = false;   // DIAMON
    int side = 0;            // G41 +1, G42 -1
    std::optional<EntryStyle> entry;      // NORM / KONT; none: the profile's
    std::optional<OutsideCorner> outside;  // G450 / G451
    std::optional<GougeReaction> gouge;    // CDON / CDOF
    double disc = -1;        // DISC
    double offn = 0;         // OFFN, mm
    int settable = 0;        // the settable frame: 0 G500 (at power-on), 1-4 G54-G57, 5-99 G505-G599
};

class Interp : public expr::Env {
public:
    Interp(const Program& prog, const ToolTable* tools, const ControlProfile& profile, const InterpretOptions& opts,
           MotionSink& sink, std::vector<Diagnostic>& diags);
    void run();
    const std::vector<std::string>& files() const { return files_.names(); }
    double dwell_seconds() const { return dwell_seconds_; }

    // expr::Env
    double get(const std::string& name, std::span<const double> idx) override;
    std::optional<std::string> text(const std::string& name, std::span<const double> idx) override;

private:
    struct Context {
        const Program* prog;
        const ProgramInfo* info;
        std::size_t pc = 0;
        std::map<std::string, Variable> locals;
        bool executable_seen = false;  // DEF only before the first executable block
        int passes_left = 0;           // L.. P n: further passes
        int call_line = 0;
        int file = 0;  // Path::files index of prog
        std::vector<bool> subpar;  // $P_SUBPAR[n]: the call gave parameter n (1-based here at n - 1)
        // PROC ... SAVE: the caller's modal G functions and frame, restored at the return.
        struct Saved {
            Modal modal;
            Frame frame;
            std::optional<FrameValue> components;
        };
        std::optional<Saved> saved;
        // Program sections being repeated (REPEAT / REPEATB): blocks [start, end], `left` more
        // times, then on at `back`.
        struct Section {
            std::size_t start, end, back;
            long left;
        };
        std::vector<Section> sections;
    };

    // ---- execution (interp.cpp) ----------------------------------------------------------
    const ProgramInfo& info_of(const Program& p);
    bool step();  // executes one block; false when the main program ended
    bool next_main_piece();
    int file_index(const std::string& name);
    bool pieces_ended_ = false;  // the main program's last piece is the one in stack_.front()
    void block(std::span<const Token> t);
    bool statement_or_call(const Token& x, BlockCalls& calls, bool& words);
    bool control(std::span<const Token> t, std::uint8_t kind);  // true when the block was a control statement
    void jump(const Token& t);
    void section_repeat(std::span<const Token> t);  // REPEAT label [label] P=n, REPEATB label P=n
    void call(const std::string& name, int passes, int column, const std::string& args = {});
    // PROC parameters (interp_proc.cpp): the callee's locals from the call's arguments, read
    // in the caller's context: values, or references (VAR) to the caller's variables.
    std::map<std::string, Variable> bind_arguments(const std::string& name, const ProgramInfo& callee,
                                                   const std::string& args, int column);
    Variable reference_to(const std::string& actual, const Formal& f, const std::string& name, int column);
    static std::vector<Formal> parse_formals(const std::string& text, int line, int column);
    Token axis_address(const Token& t);  // AX[X]=10 as X10
    void no_path_call(const Token& x);  // CYCLE832, WORKPIECE, CYCLE800 without a swivel
    // Drilling cycles (interp_drilling.cpp): CYCLE81-CYCLE89, CYCLE840, directly or with MCALL.
    static bool drilling_cycle_name(const std::string& name);
    // A call's arguments evaluated where it is called (an empty one 0); more than `most`: 12340.
    std::vector<double> evaluate_arguments(const std::string& name, const std::string& text, std::size_t most, int column);
    std::vector<double> cycle_arguments(const std::string& name, const std::string& text, int column);
    void drilling_cycle(const std::string& name, const std::vector<double>& args, int column);
    void hole_pattern(const std::string& name, const std::string& args, int column);  // HOLES1, HOLES2, CYCLE801
    std::vector<Vec2> grid_holes(const std::vector<double>& args, int num1, int num2, int column);
    struct ModalCall {
        std::string name;
        std::vector<double> args;
    };
    std::optional<ModalCall> modal_call_;  // MCALL CYCLE8x(...)
    bool blending_noted_ = false;
    static bool shopturn_step(const std::string& name);  // F_HEAD, E_DRILL, ...
    static bool standard_cycle(const std::string& name);  // CYCLE95, POCKET3, ...
    [[noreturn]] void refuse_shopturn(const std::string& name, int column) const;
    bool ret();  // end of the current program level; false at the end of the main program
    [[noreturn]] void fail(const std::string& code, const std::string& msg, int column = 0) const;
    void info(const char* code, const std::string& msg, int column = 0);
    double eval(std::int32_t e, int column);
    double value_of(const Token& t);
    // X10, X=AC(R1) into `v`: its value, AC/IC... (the lexer's param 1-5), column. Written in
    // place: a Value returned and copied costs a stalled load a word.
    void set_address(Value& v, const Token& t);
    std::pair<Variable*, std::size_t> element(Variable& v, std::span<const double> idx, const std::string& name, int column);
    std::optional<std::string> axis_named(const std::string& name);  // X, $P_AXN3, an AXIS variable
    std::string axis_value(const expr::Expr& e, int column);  // AXIS: X, an AXIS variable, $P_AXN1
    void set_text(Variable& var, std::span<const double> idx, const std::string& name, std::string value, int column);
    std::string eval_text_string(const std::string& text, int column);
    std::string eval_string(const expr::Expr& e, int column);  // a STRING value
    double eval_text(const std::string& text, int column);  // an argument of a call

    // ---- variables (interp_vars.cpp) ------------------------------------------------------
    void define(std::span<const Token> t);
    void assign(const Token& t);
    Variable* find_variable(const std::string& name);
    static bool machine_data_name(const std::string& name);  // $MN_, $MC_, $MA_, $SN_, $SC_, $SA_
    std::string machine_data_key(const std::string& name, std::span<const double> idx);
    std::optional<double> machine_datum(const std::string& name, std::span<const double> idx);
    std::map<std::string, double> setting_data_;  // $S.._ written by the program
    void set_variable(const std::string& name, std::span<const double> idx, double v, int column);
    void value_call(const Token& t);  // GETTCOR / SETTCOR / LENTOAX
    // The arguments of a call: split at the commas outside brackets and quotes, each trimmed.
    static std::vector<std::string> split_args(const std::string& text);

    // ---- tools (interp_tools.cpp) -----------------------------------------------------------
    void select_tool(const BlockData& b);
    void change_tool();
    void to_tool_change_position();  // the machine's tool change position, before a change
    void select_edge(int d, int column);
    const SinumerikEdge* edge() const;  // the active edge, or nullptr (T0 / D0)
    // Edge d of tool t of the ToolTable as $TC_DP data (a tool data file's own data when
    // unchanged, else through edge_from_common).
    std::optional<SinumerikEdge> table_edge(int t, int d) const;
    void update_tool_offset();
    double radius_now() const;  // the active edge's radius + OFFN, mm

    // ---- one block, step by step in the control's order (interp_execute.cpp) ------------------
    void execute(BlockData& b, int first_column);
    BlockCodes g_functions(const BlockData& b);
    void blending_note(int g, int column);
    void keyword_functions(const BlockData& b, BlockCodes& c, int first_column) const;
    void m_functions(const BlockData& b, BlockCodes& c) const;
    void set_feed_and_speed(const BlockData& b, const BlockCodes& c);
    void tool_change(const BlockData& b, const BlockCodes& c, int first_column);
    void set_plane_and_dimensions(const BlockData& b, const BlockCodes& c, int first_column);
    void set_radius_comp(const BlockData& b, const BlockCodes& c, int first_column);
    void frame_functions(const BlockData& b, const BlockCodes& c, int first_column);
    bool motion(const BlockData& b, const BlockCodes& c, int first_column);  // true: the block moved
    std::array<double, 3> rotary_targets(const BlockData& b) const;
    void dwell(const BlockData& b, const BlockCodes& c, int first_column);
    void check_unused_words(const BlockData& b, bool moved) const;
    void stop_and_end(const BlockData& b, const BlockCodes& c);

    // ---- geometry (interp_motion.cpp) -------------------------------------------------------
    double unit() const { return st_.inch ? kMmPerInch : 1.0; }
    Vec3 program_pos() const { return actual_.invert(pos_ - zero_shift_); }
    Vec3 end_point(const BlockData& b, bool machine) const;
    void frame_statement(const BlockData& b, const std::string& which, int column);
    // Frames (interp_frames.cpp): the chain basic : settable : programmable, frame variables.
    void set_programmable(const Frame& f, std::optional<FrameValue> components);
    void select_settable(int n);
    void refresh_frames();
    std::string assignment_target(const Token& t, std::vector<double>& idx);  // name, indices
    void frame_assign(const Token& t);
    FrameValue frame_expression(const std::string& text, int column);
    FrameValue frame_function(const std::string& name, const std::string& args, int column);
    FrameValue& frame_variable(const std::string& name, std::span<const double> idx, std::size_t whole, bool write, int column);
    std::optional<double> frame_component(const std::string& name, std::span<const double> idx);
    bool set_frame_component(const std::string& name, std::span<const double> idx, double v, int column);
    void programmable_offset(const BlockData& b, int g, int column);  // G58, G59
    void move(MotionKind kind, const Vec3& end, const BlockData& b);
    void arc(const BlockData& b, const Vec3& end_prog);
    void corner_request(const BlockData& b, int column);  // RND=, CHF=, CHR= at the end of the block's move
    double modulo_target(double from, const Value& v) const;  // DC, ACP, ACN
    Motion motion_(MotionKind kind, const Vec3& end) const;
    double feed_rate(const Vec3& end) const;  // mm/min of a feed move ending at `end`
    double css_speed(double x) const;         // G96: rev/min at X (radius, mm); inf at the axis
    RadiusRequest radius_request() const;
    bool mirrored() const;  // the frame mirrors the working plane
    int file() const { return stack_.empty() ? 0 : stack_.back().file; }  // of the block being run

    const Program& main_;
    const ToolTable* tools_;
    const ControlProfile& profile_;
    InterpretOptions opts_;
    CornerSink corners_;  // RND=, CHF=, CHR= between a block's move and the next
    MotionSink& sink_;    // corners_, which hands the moves on
    std::vector<Diagnostic>& diags_;

    std::vector<Context> stack_;
    std::map<const Program*, std::unique_ptr<ProgramInfo>> infos_;
    SourceFiles files_;
    std::deque<Program> loaded_;  // subprograms read from the search path
    std::map<std::string, const Program*> loaded_by_name_;
    std::size_t executed_ = 0;
    IdleWatch idle_;  // blocks in a row without a move
    int line_ = 0;

    Modal st_;
    Vec3 pos_ = Vec3::Zero();
    std::array<double, 3> abc_{0, 0, 0};
    Frame frame_;                          // the programmable frame
    std::optional<FrameValue> pframe_ = FrameValue{};  // its components (none: a chain that shears)
    std::map<int, FrameValue> uifr_;       // $P_UIFR[n]: the settable frames' data
    FrameValue iframe_, bframe_;           // the active settable frame, the basic frame
    FrameValue actframe_scratch_;          // $P_ACTFRAME as read
    bool settable_neutral_ = true;         // iframe_ and bframe_ both neutral
    Frame actual_;                         // basic : settable : programmable, what maps the moves
    Vec3 zero_shift_ = Vec3::Zero();  // type P toolholder: table rotation
    // The machine's work origin (Machine::work_origin) in output coordinates (mm, a lathe's X
    // a radius): output = machine coordinates of the tool tip less it. Zero without a machine.
    Vec3 work_origin_ = Vec3::Zero();
    double lims_ = 0;                 // LIMS: the speed limit under G96, rev/min (0: none)
    double feed_ = 0;                 // F: mm/min (G94) or mm/rev (G95, G96)
    double speed_ = 0;                // S: spindle speed, rev/min
    double dwell_seconds_ = 0;        // G4 F / S, seconds
    double cutting_speed_ = 0;        // S under G96: m/min
    std::optional<Vec2> last_tangent_;  // direction at the end of the last plane move (CT)

    std::array<double, 1000> r_{};  // R0..R999
    std::map<std::string, Variable> globals_;
    SinumerikEdgeMap edges_;
    std::map<int, Toolholder> holders_;
    int selected_ = 0, tool_ = 0, d_ = 0, tcarr_ = 0;
    bool diam90_ = false;  // DIAM90: absolute X in diameter, incremental in radius
    Vec3 tool_offset_ = Vec3::Zero();
    Vec3 tool_axis_ = Vec3(0, 0, 1);
    std::optional<SinumerikEdge> active_;  // the active edge as selected (later $TC_DP writes
                                           // take effect at the next T/D selection)
    bool ended_ = false;
    bool warned_blending_ = false;
    std::size_t moves_ = 0;  // moves given to the sink (a block that adds none moves nothing)
};

}  // namespace toolcomp::sinumerik
