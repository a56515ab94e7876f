#pragma once
// The words a Klartext path block may carry (private to the Heidenhain front end).
#include <span>

#include "toolcomp/program/program.hpp"

namespace toolcomp::heidenhain {

// Checks the words of one block of a path function (L, C, CC, CR, CT, CTP, LP, CP, RND, CHF,
// LN, APPR, DEP) against what that function takes. Throws ParseError:
//  * bad_word: a word the function does not take (ZZ+5), or an axis (X, IX ...), a polar
//    coordinate (PR, PA), the feed or the direction given twice;
//  * unsupported_word: a TNC word toolcomp does not model (parallel axes U V W, incremental
//    rotary axes, FZ / FU feeds).
// Other blocks (BEGIN PGM, BLK FORM, TOOL CALL, Q statements ...) are not checked here.
void check_path_words(std::span<const Token> tokens, int line);

}  // namespace toolcomp::heidenhain
