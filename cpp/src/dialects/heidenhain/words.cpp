// Word checks of Klartext path blocks. The interpreter looks words up by name, so a word it
// does not know (a typo, a word of another function) would otherwise be ignored silently,
// and of an axis given twice the last value would win.
#include "words.hpp"
#include "toolcomp/program/codes.hpp"

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace toolcomp::heidenhain {

namespace {

// Bits of the word groups a function takes.
enum : unsigned {
    kAxes = 1u << 0,     // X Y Z, IX IY IZ
    kRotary = 1u << 1,   // A B C
    kComp = 1u << 2,     // R0 RL RR (and R+ / R- in L blocks)
    kFeed = 1u << 3,     // F, FMAX
    kM = 1u << 4,        // M functions, LA (M120 LA n)
    kPolar = 1u << 5,    // PR IPR PA IPA
    kDir = 1u << 6,      // DR+ / DR-
    kRadius = 1u << 7,   // R (CR, RND, APPR/DEP)
    kLenCca = 1u << 8,   // LEN, CCA (APPR / DEP)
    kNormal = 1u << 9,   // NX NY NZ TX TY TZ (LN)
    kNumber = 1u << 10,  // a plain number (CHF 2)
};

struct Function {
    std::string_view name;
    std::size_t first;  // tokens before this one name the function
    unsigned groups;
};

constexpr std::array<Function, 13> kFunctions{{
    {"L", 1, kAxes | kRotary | kComp | kFeed | kM},
    {"C", 1, kAxes | kDir | kComp | kFeed | kM},
    {"CC", 1, kAxes},
    {"CR", 1, kAxes | kRadius | kDir | kComp | kFeed | kM},
    {"CT", 1, kAxes | kComp | kFeed | kM},
    {"CTP", 1, kAxes | kPolar | kComp | kFeed | kM},
    {"LP", 1, kAxes | kPolar | kComp | kFeed | kM},
    {"CP", 1, kAxes | kPolar | kDir | kComp | kFeed | kM},
    {"RND", 1, kRadius | kFeed | kM},
    {"CHF", 1, kNumber | kFeed | kM},
    {"LN", 1, kAxes | kNormal | kComp | kFeed | kM},
    {"APPR", 2, kAxes | kPolar | kRadius | kLenCca | kComp | kFeed | kM},
    {"DEP", 2, kAxes | kPolar | kRadius | kLenCca | kComp | kFeed | kM},
}};

// The group of a word and, for words that may stand once only, the slot that two of them
// would share (X and IX both set the X axis); -1: may repeat (M functions, RL/RR/R0, whose
// conflicts the interpreter reports).
struct Kind {
    unsigned group = 0;
    int slot = -1;
};

std::optional<Kind> kind_of(const Token& t) {
    const std::string_view k = t.key;  // compared with literals: the length first
    if (k.empty()) return Kind{kNumber, 0};
    static constexpr std::array<std::string_view, 3> axes{"X", "Y", "Z"};
    for (int i = 0; i < 3; ++i)
        if (k == axes[i] || (k.size() == 2 && k[0] == 'I' && k.substr(1) == axes[i])) return Kind{kAxes, 1 + i};
    if (k == "A" || k == "B" || k == "C") return Kind{kRotary, 4 + (k[0] - 'A')};
    if (k == "RL" || k == "RR") return Kind{kComp, -1};
    if (k == "R") {
        if ((t.has_value && t.value == 0 && t.param == 0) || t.sign_only) return Kind{kComp | kRadius, -1};
        return Kind{kRadius, 7};
    }
    if (k == "F" || k == "FMAX") return Kind{kFeed, 8};
    if (k == "M" || k == "LA") return Kind{kM, -1};
    if (k == "MB") return Kind{kM, 20};  // M140 MB
    if (k == "PR" || k == "IPR") return Kind{kPolar, 9};
    if (k == "PA" || k == "IPA") return Kind{kPolar, 10};
    if (k == "DR") return Kind{kDir, 11};
    if (k == "LEN") return Kind{kLenCca, 12};
    if (k == "CCA") return Kind{kLenCca, 13};
    static constexpr std::array<std::string_view, 6> normal{"NX", "NY", "NZ", "TX", "TY", "TZ"};
    for (int i = 0; i < 6; ++i)
        if (k == normal[i]) return Kind{kNormal, 14 + i};
    return std::nullopt;
}

// Words of the TNC that toolcomp does not model: refused by name rather than as unknown.
const char* unsupported(std::string_view k) {
    if (k == "U" || k == "V" || k == "W" || k == "IU" || k == "IV" || k == "IW")
        return "parallel axes (U, V, W) are not supported by toolcomp";
    if (k == "IA" || k == "IB" || k == "IC") return "incremental rotary axes (IA, IB, IC) are not supported by toolcomp";
    if (k == "FZ" || k == "FU") return "feed per tooth / per revolution (FZ, FU) is not supported by toolcomp";
    if (k == "FAUTO") return "FAUTO is not supported by toolcomp";
    return nullptr;
}

std::string spelled(const Token& t) {
    if (t.key.empty()) return "a number";
    std::string s = t.key;
    if (t.sign_only) s += t.value < 0 ? "-" : "+";
    return "'" + s + "'";
}

}  // namespace

void check_path_words(std::span<const Token> t, int line) {
    if (t.empty()) return;
    const Function* f = nullptr;
    const std::string_view head = t[0].key;
    for (const Function& g : kFunctions)
        if (head == g.name) {
            f = &g;
            break;
        }
    if (!f) return;
    auto fn = [&] { return f->first == 2 && t.size() > 1 ? t[0].key + " " + t[1].key : t[0].key.str(); };  // for messages
    std::array<int, 21> seen{};
    for (std::size_t i = f->first; i < t.size(); ++i) {
        const Token& k = t[i];
        if (const char* why = unsupported(k.key))
            throw ParseError(code::unsupported_word, k.key + ": " + why, {line, k.column});
        const auto kind = kind_of(k);
        if (!kind || !(kind->group & f->groups))
            throw ParseError(code::bad_word, "Word " + spelled(k) + " is not allowed in a " + fn() + " block", {line, k.column});
        if (kind->slot < 0) continue;
        if (seen[static_cast<std::size_t>(kind->slot)]++)
            throw ParseError(code::bad_word, "Word " + spelled(k) + " given twice in one " + fn() + " block (or with its " +
                                             "absolute / incremental twin)",
                             {line, k.column});
    }
}

}  // namespace toolcomp::heidenhain
