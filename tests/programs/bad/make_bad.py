#!/usr/bin/env python3
"""Writes the bad-input corpus of toolcomp (programs of every dialect and tool tables of every
format) into this directory. Deterministic: the same bytes on every run (no clock, a fixed
seed), every file well under 200 KB. The expected outcome of each file is in expected.json,
decided by hand; tests/python/test_bad_inputs.py checks it.

    python tests/programs/bad/make_bad.py          # rewrite the corpus
    python tests/programs/bad/make_bad.py --check  # fail if a file differs from what it writes
"""
import os
import random
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
BOM = b"\xef\xbb\xbf"
BIG = 100_000  # characters of the "very long line" cases
DEEP = 50_000  # nesting depth of the "deeply nested" cases (100,000 characters of brackets)

FILES = {}


def add(name, data):
    if isinstance(data, str):
        data = data.encode("utf-8")
    assert name not in FILES, name
    assert len(data) < 200_000, (name, len(data))
    FILES[name] = data


def garbage(seed, n, first=b""):
    """n pseudo-random bytes (fixed seed) after a fixed prefix, so the first bad byte is known."""
    rng = random.Random(seed)
    return first + bytes(rng.randrange(256) for _ in range(n))


def crlf(text):
    return text.replace("\n", "\r\n")


def cr_only(text):
    return text.replace("\n", "\r")


# ---------------------------------------------------------------------------------------------
# LinuxCNC (.ngc) and Fanuc (.nc / .tap): ISO G-code
# ---------------------------------------------------------------------------------------------
ISO_OK = "G21 G90 G17\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X10\nG1 Y10\nG0 Z5\nM2\n"
ISO_COMP = ("G21 G90 G17\nT1 M6\nG43\nG0 X-10 Y-10 Z5\nG1 Z-1 F100\nG41 D1 X0 Y0\nG1 X20\nG1 Y20\n"
            "G40 G0 X30 Y30\nM2\n")


def iso_cases(ext, prefix, m_end="M2", big=True):
    """big=False leaves out the 100,000-character variants that only repeat the LinuxCNC ones."""
    p = prefix
    ok = ISO_OK.replace("M2", m_end)
    comp = ISO_COMP.replace("M2", m_end)
    # valid despite looking odd
    add(f"{p}ok_bom.{ext}", BOM + ok.encode())
    add(f"{p}ok_crlf.{ext}", crlf(ok))
    add(f"{p}ok_crlf_bom.{ext}", BOM + crlf(comp).encode())
    add(f"{p}ok_nonascii_comment.{ext}", "(Fräser Ø6 – Tiefe ≤ 1 mm, 日本語)\n" + ok)
    add(f"{p}ok_semicolon_nonascii.{ext}", ok.replace("G1 X10\n", "G1 X10 ; Kontur außen ✓\n"))
    add(f"{p}ok_latin1_comment.{ext}", b"(Fr\xe4ser \xd86 mm)\n" + ok.encode())
    add(f"{p}ok_long_comment.{ext}", ok.replace("G1 X10\n", "G1 X10 (" + "c" * BIG + ")\n"))
    if big:
        add(f"{p}ok_long_leading_zeros.{ext}", ok.replace("G1 X10\n", "G1 X" + "0" * BIG + "10\n"))
    if big:
        add(f"{p}ok_long_decimals.{ext}", ok.replace("G1 X10\n", "G1 X10." + "3" * BIG + "\n"))
    add(f"{p}ok_tiny_number.{ext}", ok.replace("G1 X10\n", "G1 X10 Y0." + "0" * 319 + "1\n"))
    add(f"{p}ok_big_finite.{ext}", ok.replace("G1 X10\n", "G1 X1" + "0" * 300 + "\nG1 X10\n"))
    add(f"{p}ok_tool_negative_diameter.{ext}", comp.replace("T1 M6", "T4 M6").replace("D1", "D4"))
    add(f"{p}ok_full_circle.{ext}", ok.replace("G1 X10\n", "G2 X0 Y0 I5 J0\n"))
    # truncated and garbage
    add(f"{p}truncated_mid_word.{ext}", "G21 G90 G17\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X10 Y")
    add(f"{p}truncated_mid_comment.{ext}", "G21 G90 G17\nG0 X0 Y0 Z5\nG1 Z-1 F100 (start of the con")
    add(f"{p}truncated_no_end.{ext}", "G21 G90 G17\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X10\n")
    add(f"{p}empty.{ext}", b"")
    add(f"{p}binary_garbage.{ext}", garbage(1, 4096, b"\x00\x01"))
    add(f"{p}binary_after_code.{ext}", ("G21 G90\nG0 X0 Y0\n").encode() + garbage(2, 2048, b"\x7f"))
    add(f"{p}nul_byte.{ext}", "G21 G90\nG0 X0\x00 Y0\nM2\n")
    # numbers
    add(f"{p}huge_digits.{ext}", ok.replace("G1 X10\n", "G1 X1" + "0" * 400 + "\n"))
    add(f"{p}huge_exponent_1e308.{ext}", ok.replace("G1 X10\n", "G1 X1e308\n"))
    add(f"{p}tiny_exponent_1e-320.{ext}", ok.replace("G1 X10\n", "G1 X1e-320\n"))
    add(f"{p}nan_word.{ext}", ok.replace("G1 X10\n", "G1 XNAN\n"))
    add(f"{p}inf_word.{ext}", ok.replace("G1 X10\n", "G1 X-INF\n"))
    add(f"{p}infinity_word.{ext}", ok.replace("G1 X10\n", "G1 Xinfinity\n"))
    add(f"{p}two_points.{ext}", ok.replace("G1 X10\n", "G1 X1.2.3\n"))
    if big:
        add(f"{p}long_line_words.{ext}", ok.replace("G1 X10\n", "G1 " + "X1 " * (BIG // 3) + "\n"))
    add(f"{p}long_line_garbage.{ext}", ok.replace("G1 X10\n", "G1 X10 " + "?" * BIG + "\n"))
    # brackets, comments
    add(f"{p}deep_brackets.{ext}", ok.replace("G1 X10\n", "G1 X" + "[" * DEEP + "1" + "]" * DEEP + "\n"))
    if big:
        add(f"{p}deep_parens.{ext}", ok.replace("G1 X10\n", "G1 X10 " + "(" * DEEP + ")" * DEEP + "\n"))
    add(f"{p}unclosed_comment.{ext}", ok.replace("G1 X10\n", "G1 X10 (no end\n"))
    add(f"{p}stray_close_paren.{ext}", ok.replace("G1 X10\n", "G1 X10 ) Y2\n"))
    add(f"{p}nested_comment.{ext}", ok.replace("G1 X10\n", "G1 X10 (outer (inner) outer)\n"))
    add(f"{p}unbalanced_bracket.{ext}", ok.replace("G1 X10\n", "G1 X[1+2\n"))
    # words
    add(f"{p}unknown_word_dollar.{ext}", ok.replace("G1 X10\n", "G1 X10 $5\n"))
    add(f"{p}unknown_g_code.{ext}", ok.replace("G1 X10\n", "G1 X10\nG12.7 X5\n"))
    add(f"{p}unknown_m_code.{ext}", ok.replace("G1 X10\n", "G1 X10\nM250\n"))
    add(f"{p}ok_blank_inside_number.{ext}", ok.replace("G1 X10\n", "G1 X10 25\n"))
    add(f"{p}lowercase_words.{ext}", ok.lower())
    add(f"{p}nonascii_word.{ext}", ok.replace("G1 X10\n", "G1 X10 Ø5\n"))
    # duplicate modal codes
    add(f"{p}dup_motion.{ext}", ok.replace("G1 X10\n", "G0 G1 X10\n"))
    add(f"{p}dup_units.{ext}", ok.replace("G21 G90 G17\n", "G21 G20 G90 G17\n"))
    add(f"{p}dup_distance.{ext}", ok.replace("G21 G90 G17\n", "G21 G90 G91 G17\n"))
    add(f"{p}dup_plane.{ext}", ok.replace("G21 G90 G17\n", "G21 G90 G17 G18\n"))
    add(f"{p}dup_axis_word.{ext}", ok.replace("G1 X10\n", "G1 X10 X20\n"))
    add(f"{p}dup_spindle_m.{ext}", ok.replace("G1 X10\n", "M3 M4 S1000\nG1 X10\n"))
    # arcs
    add(f"{p}arc_inconsistent_radius.{ext}", ok.replace("G1 X10\n", "G2 X10 Y0 I3 J0\n"))
    add(f"{p}arc_r_too_small.{ext}", ok.replace("G1 X10\n", "G2 X10 Y0 R2\n"))
    add(f"{p}arc_zero_length_r.{ext}", ok.replace("G1 X10\n", "G2 X0 Y0 R5\n"))
    add(f"{p}arc_zero_radius.{ext}", ok.replace("G1 X10\n", "G2 X0 Y0 I0 J0\n"))
    add(f"{p}arc_huge_radius.{ext}", ok.replace("G1 X10\n", "G2 X10 Y0 R1" + "0" * 300 + "\n"))
    add(f"{p}arc_huge_center.{ext}", ok.replace("G1 X10\n", "G2 X0 Y0 I1" + "0" * 300 + " J0\n"))
    # tools
    add(f"{p}tool_missing_m6.{ext}", comp.replace("T1 M6", "T99 M6"))
    add(f"{p}tool_missing_g43h.{ext}", comp.replace("G43\n", "G43 H99\n"))
    add(f"{p}tool_missing_d.{ext}", comp.replace("D1 X0", "D99 X0"))
    add(f"{p}negative_d_word.{ext}", comp.replace("D1 X0", "D-1 X0"))
    add(f"{p}negative_t_word.{ext}", comp.replace("T1 M6", "T-1 M6"))


iso_cases("ngc", "lc_")
iso_cases("nc", "fa_", "M30", big=False)
# Fanuc-only: tape format, program numbers and the .tap suffix
add("fa_ok_tape_percent.tap", "%\n" + ISO_OK.replace("M2", "M30") + "%\n")
add("fa_o_word.tap", "%\nO1000 (PART)\n" + ISO_OK.replace("M2", "M30") + "%\n")
add("fa_macro_variable.nc", ISO_OK.replace("G1 X10\n", "#100=5\nG1 X#100\n").replace("M2", "M30"))
add("fa_ok_crlf_percent.tap", crlf("%\n" + ISO_OK.replace("M2", "M30") + "%\n"))
add("fa_ok_cr_only.tap", cr_only("G21 G90\nG0 X10 Y10\nM30\n"))  # CR is no end of block: one block
add("lc_cr_only.ngc", cr_only(ISO_OK))
add("lc_bad_letter_u.ngc", ISO_OK.replace("G1 X10\n", "G1 U10\n"))
add("fa_letter_u_mill.nc", ISO_OK.replace("G1 X10\n", "G1 U10\n").replace("M2", "M30"))

# ---------------------------------------------------------------------------------------------
# Allen-Bradley 9/Series lathe (dialect="rockwell")
# ---------------------------------------------------------------------------------------------
RW_OK = "G21 G18 G90\nT0101\nG0 X20 Z5\nG1 Z-10 F100\nG1 X30\nG0 X40 Z5\nM30\n"
add("rw_ok_bom.nc", BOM + RW_OK.encode())
add("rw_ok_crlf.nc", crlf(RW_OK))
add("rw_ok_semicolon_eob.nc", RW_OK.replace("\n", ";\n"))
add("rw_ok_nonascii_comment.nc", "(Drehmeißel 35°)\n" + RW_OK)
add("rw_truncated_mid_word.nc", RW_OK[: RW_OK.index("X30") + 1])
add("rw_binary_garbage.nc", garbage(3, 4096, b"\x02"))
add("rw_huge_digits.nc", RW_OK.replace("G1 X30\n", "G1 X9" + "9" * 400 + "\n"))
add("rw_nan_word.nc", RW_OK.replace("G1 X30\n", "G1 XNaN\n"))
add("rw_long_line_garbage.nc", RW_OK.replace("G1 X30\n", "G1 X30 " + "!" * BIG + "\n"))
add("rw_unclosed_comment.nc", RW_OK.replace("G1 X30\n", "G1 X30 (no end\n"))
add("rw_dup_motion.nc", RW_OK.replace("G1 X30\n", "G0 G1 X30\n"))
add("rw_arc_inconsistent_radius.nc", RW_OK.replace("G1 X30\n", "G2 X30 Z-10 I3 K0\n"))
add("rw_tool_missing.nc", RW_OK.replace("T0101", "T9999"))
add("rw_ok_u_w_words.nc", RW_OK.replace("G1 X30\n", "G1 U10 W-2\n"))

# ---------------------------------------------------------------------------------------------
# Heidenhain TNC conversational (.h)
# ---------------------------------------------------------------------------------------------
HH_LINES = ["BEGIN PGM BAD MM", "BLK FORM 0.1 Z X+0 Y+0 Z-20", "BLK FORM 0.2 X+100 Y+100 Z+0",
            "TOOL CALL 1 Z S3000", "L Z+50 R0 FMAX", "L X+0 Y+0 R0 FMAX", "L Z-2 R0 F100",
            "L X+10 Y+0 R0 F200", "L X+10 Y+10", "L Z+50 R0 FMAX", "M30", "END PGM BAD MM"]


def hh(lines):
    return "".join(f"{i} {l}\n" for i, l in enumerate(lines))


def hh_with(replace=None, insert=None):
    """The base program with block 8 (L X+10 Y+0 R0 F200) replaced or lines inserted after it."""
    lines = list(HH_LINES)
    if replace is not None:
        lines[7:8] = replace if isinstance(replace, list) else [replace]
    if insert is not None:
        lines[8:8] = insert if isinstance(insert, list) else [insert]
    return hh(lines)


HH_OK = hh(HH_LINES)
add("hh_ok_bom.h", BOM + HH_OK.encode())
add("hh_ok_crlf.h", crlf(HH_OK))
add("hh_ok_nonascii_comment.h", hh_with(insert="; Schlichten außen Ø10 – 日本語"))
add("hh_ok_nonascii_block_comment.h", hh_with(replace="L X+10 Y+0 R0 F200 ; Fräser läuft ✓"))
add("hh_ok_long_comment.h", hh_with(insert="; " + "k" * BIG))
add("hh_ok_q_nested_8.h", hh_with(insert=["Q1 = " + "(" * 8 + "10" + ")" * 8, "L X+Q1"]))
add("hh_ok_fn_huge_finite.h", hh_with(insert=["FN 0: Q1 = +1" + "0" * 300, "FN 0: Q1 = +10", "L X+Q1"]))
add("hh_ok_tiny_number.h", hh_with(insert="L X+10.5 Y+0." + "0" * 319 + "1"))
add("hh_ok_tool_def.h", hh(HH_LINES[:3] + ["TOOL DEF 7 L+0 R+3", "TOOL CALL 7 Z S3000"] + HH_LINES[4:]))
add("hh_ok_full_circle.h", hh_with(insert=["CC X+15 Y+0", "C X+10 Y+0 DR+"]))
add("hh_cr_only.h", cr_only(HH_OK))
add("hh_truncated_mid_block.h", HH_OK[: HH_OK.index("8 L X+10 Y+10") + 12])
add("hh_truncated_no_end_pgm.h", hh(HH_LINES[:10]))
add("hh_empty.h", b"")
add("hh_binary_garbage.h", garbage(4, 4096, b"\x03"))
add("hh_nul_byte.h", HH_OK.replace("L X+10 Y+10", "L X+10\x00 Y+10"))
add("hh_huge_digits.h", hh_with(insert="L X+1" + "0" * 400))
add("hh_huge_exponent.h", hh_with(insert="L X+1E308"))
add("hh_q_huge_digits.h", hh_with(insert=["Q1 = 1" + "0" * 400, "L X+Q1"]))
add("hh_q_overflow.h", hh_with(insert=["Q1 = 10 ^ 200", "Q2 = Q1 * Q1", "L X+Q2"]))
add("hh_q_pow_overflow.h", hh_with(insert=["Q1 = 10 ^ 400", "L X+Q1"]))
add("hh_q_fn_overflow.h", hh_with(insert=["FN 0: Q1 = +1" + "0" * 300, "FN 3: Q2 = +Q1 * +Q1", "L X+Q2"]))
add("hh_q_division_by_zero.h", hh_with(insert=["Q1 = 5 / 0", "L X+Q1"]))
add("hh_q_sqrt_negative.h", hh_with(insert=["Q1 = SQRT -4", "L X+Q1"]))
add("hh_q_nan_word.h", hh_with(insert=["Q1 = NAN", "L X+Q1"]))
add("hh_q_inf_word.h", hh_with(insert=["Q1 = INF", "L X+Q1"]))
add("hh_nan_coordinate.h", hh_with(insert="L X+NAN"))
add("hh_inf_coordinate.h", hh_with(insert="L X-inf"))
add("hh_q_deep_nesting.h", hh_with(insert=["Q1 = " + "(" * DEEP + "1" + ")" * DEEP, "L X+Q1"]))
add("hh_q_unbalanced_open.h", hh_with(insert=["Q1 = ((1 + 2) * 3", "L X+Q1"]))
add("hh_q_unbalanced_close.h", hh_with(insert=["Q1 = (1 + 2)) * 3", "L X+Q1"]))
add("hh_q_number_out_of_range.h", hh_with(insert="Q123456 = 5"))
add("hh_long_line_words.h", hh_with(insert="L " + "X+1 " * (BIG // 4)))
add("hh_long_line_garbage.h", hh_with(insert="L X+1 " + "#" * BIG))
add("hh_unclosed_quote.h", hh(HH_LINES[:3] + ['TOOL CALL "MILL Z S3000'] + HH_LINES[4:]))
add("hh_unknown_block.h", hh_with(insert="FOOBAR X+10"))
add("hh_unknown_word.h", hh_with(insert="L X+10 ZZ+5"))
add("hh_unsupported_axis_w.h", hh_with(insert="L X+10 W+5"))
add("hh_nonascii_word.h", hh_with(insert="L X+10 Ø5"))
add("hh_dup_comp.h", hh_with(replace="L X+10 Y+0 RL RR F200"))
add("hh_dup_axis.h", hh_with(replace="L X+10 X+20 Y+0 R0 F200"))
add("hh_arc_inconsistent_radius.h", hh_with(insert=["CC X+20 Y+10", "C X+20 Y+14 DR+"]))
add("hh_arc_cr_too_small.h", hh_with(insert="CR X+30 Y+10 R+2 DR-"))
add("hh_arc_cr_zero_length.h", hh_with(insert="CR X+10 Y+0 R+5 DR-"))
add("hh_arc_no_cc.h", hh(HH_LINES[:8] + ["C X+20 Y+0 DR+"] + HH_LINES[8:]))
add("hh_arc_zero_radius.h", hh_with(insert=["CC X+10 Y+0", "C X+10 Y+0 DR+"]))
add("hh_arc_missing_dr.h", hh_with(insert=["CC X+15 Y+0", "C X+20 Y+0"]))
add("hh_tool_missing.h", hh(HH_LINES[:3] + ["TOOL CALL 99 Z S3000"] + HH_LINES[4:]))
add("hh_tool_name_missing.h", hh(HH_LINES[:3] + ['TOOL CALL "NOSUCH" Z S3000'] + HH_LINES[4:]))
add("hh_tool_negative_radius_rl.h",
    hh(HH_LINES[:3] + ["TOOL DEF 7 L+0 R-3", "TOOL CALL 7 Z S3000"] + HH_LINES[4:7]
       + ["L X+10 Y+0 RL F200", "L X+30", "L Y+30", "L X+10 R0"] + HH_LINES[9:]))
add("hh_rnd_negative.h", hh_with(insert=["RND R-2", "L X+30"]))
add("hh_label_missing.h", hh_with(insert="CALL LBL 99"))

# ---------------------------------------------------------------------------------------------
# Sinumerik 840D (.mpf / .spf)
# ---------------------------------------------------------------------------------------------
SN_OK = ("G17 G90 G71\nT1 D1 M6\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X10\nG1 Y10\n"
         "G0 Z5\nM30\n")
SN_DEF = "DEF REAL A[3]\n"  # definitions come first in a Sinumerik program


def sn_with(old, new):
    assert old in SN_OK
    return SN_OK.replace(old, new, 1)


add("sn_ok_bom.mpf", BOM + SN_OK.encode())
add("sn_ok_crlf.mpf", crlf(SN_OK))
add("sn_ok_cr_only.mpf", cr_only(SN_OK))
add("sn_ok_header.mpf", "%_N_BAD_MPF\n;$PATH=/_N_MPF_DIR\n" + SN_OK)
add("sn_ok_nonascii_comment.mpf", sn_with("G1 X10\n", "G1 X10 ; Schruppen außen Ø10 – 日本語\n"))
add("sn_ok_latin1_comment.mpf", sn_with("G1 X10\n", "G1 X10 ;@@\n").encode().replace(b"@@", b"Fr\xe4ser \xd810"))
add("sn_ok_long_comment.mpf", sn_with("G1 X10\n", "G1 X10 ;" + "s" * BIG + "\n"))
add("sn_ok_nested_8.mpf", sn_with("G1 X10\n", "R1=" + "(" * 8 + "10" + ")" * 8 + "\nG1 X=R1\n"))
add("sn_ok_exponent_1ex308.mpf", sn_with("G1 X10\n", "R1=1EX308\nR2=R1/1EX307\nG1 X=R2\n"))
add("sn_ok_tiny_1ex-320.mpf", sn_with("G1 X10\n", "R1=1EX-320\nG1 X=10+R1\n"))
add("sn_ok_full_circle.mpf", sn_with("G1 X10\n", "G2 X0 Y0 I5 J0\n"))
add("sn_ok_negative_radius_edge.mpf",
    "$TC_DP1[1,1]=120\n$TC_DP3[1,1]=50\n$TC_DP6[1,1]=-3\n" + SN_OK.replace(
        "G1 X10\nG1 Y10\n", "G1 G41 X10 Y0\nG1 X20\nG1 Y10\nG40 G1 X30 Y30\n"))
add("sn_ok_spf_subprogram.spf", "PROC BADSUB\nG1 X5 F100\nM17\n")
add("sn_truncated_mid_word.mpf", SN_OK[: SN_OK.index("G1 Y10") + 4])
add("sn_truncated_no_end.mpf", SN_OK.replace("M30\n", ""))
add("sn_truncated_expression.mpf", sn_with("G1 X10\n", "R1=2*(3+\n"))
add("sn_empty.mpf", b"")
add("sn_binary_garbage.mpf", garbage(5, 4096, b"\x01"))
add("sn_nul_byte.mpf", sn_with("G1 X10\n", "G1 X10\x00\n"))
add("sn_huge_digits.mpf", sn_with("G1 X10\n", "G1 X1" + "0" * 400 + "\n"))
add("sn_huge_exponent_overflow.mpf", sn_with("G1 X10\n", "R1=1EX308\nR2=R1*10\nG1 X=R2\n"))
add("sn_exponent_out_of_range.mpf", sn_with("G1 X10\n", "R1=1EX400\nG1 X=R1\n"))
add("sn_e_notation.mpf", sn_with("G1 X10\n", "G1 X1e308\n"))
add("sn_nan_word.mpf", sn_with("G1 X10\n", "R1=NAN\nG1 X=R1\n"))
add("sn_inf_word.mpf", sn_with("G1 X10\n", "G1 X=INF\n"))
add("sn_sqrt_negative.mpf", sn_with("G1 X10\n", "R1=SQRT(-1)\nG1 X=R1\n"))
add("sn_division_by_zero.mpf", sn_with("G1 X10\n", "R1=5/0\nG1 X=R1\n"))
add("sn_acos_domain.mpf", sn_with("G1 X10\n", "R1=ACOS(2)\nG1 X=R1\n"))
add("sn_ln_zero.mpf", sn_with("G1 X10\n", "R1=LN(0)\nG1 X=R1\n"))
add("sn_pow_overflow.mpf", sn_with("G1 X10\n", "R1=EXP(1000)\nG1 X=R1\n"))
add("sn_deep_nesting.mpf", sn_with("G1 X10\n", "R1=" + "(" * DEEP + "1" + ")" * DEEP + "\nG1 X=R1\n"))
add("sn_deep_unary.mpf", sn_with("G1 X10\n", "R1=" + "-" * BIG + "1\nG1 X=R1\n"))
add("sn_deep_functions.mpf", sn_with("G1 X10\n", "R1=" + "ABS(" * 20000 + "1" + ")" * 20000 + "\nG1 X=R1\n"))
add("sn_long_sum.mpf", sn_with("G1 X10\n", "R1=" + "1+" * (BIG // 2) + "1\nG1 X=R1\n"))
add("sn_long_line_words.mpf", sn_with("G1 X10\n", "G1 " + "X1 " * (BIG // 3) + "\n"))
add("sn_unbalanced_open.mpf", sn_with("G1 X10\n", "R1=((1+2)*3\nG1 X=R1\n"))
add("sn_unbalanced_close.mpf", sn_with("G1 X10\n", "R1=(1+2))*3\nG1 X=R1\n"))
add("sn_unbalanced_ac.mpf", sn_with("G1 X10\n", "G1 X=AC(10\n"))
add("sn_unclosed_string.mpf", sn_with("T1 D1 M6\n", 'T="MILL D1 M6\n'))
add("sn_unknown_word.mpf", sn_with("G1 X10\n", "G1 X10\nFOOBAR\n"))
add("sn_unknown_function.mpf", sn_with("G1 X10\n", "R1=FOO(3)\nG1 X=R1\n"))
add("sn_undefined_variable.mpf", sn_with("G1 X10\n", "G1 X=_UNDEF\n"))
add("sn_unsupported_g_code.mpf", sn_with("G1 X10\n", "G1 X10\nG977 X5\n"))
add("sn_unknown_g_code.mpf", sn_with("G1 X10\n", "G1 X10\nG12345 X5\n"))
add("sn_dup_motion.mpf", sn_with("G1 X10\n", "G0 G1 X10\n"))
add("sn_dup_axis_word.mpf", sn_with("G1 X10\n", "G1 X10 X20\n"))
add("sn_dup_units.mpf", sn_with("G17 G90 G71\n", "G17 G90 G71 G70\n"))
add("sn_arc_inconsistent_radius.mpf", sn_with("G1 X10\n", "G2 X10 Y0 I3 J0\n"))
add("sn_arc_cr_too_small.mpf", sn_with("G1 X10\n", "G2 X10 Y0 CR=2\n"))
add("sn_arc_zero_length_cr.mpf", sn_with("G1 X10\n", "G2 X0 Y0 CR=5\n"))
add("sn_arc_zero_radius.mpf", sn_with("G1 X10\n", "G2 X0 Y0 I0 J0\n"))
add("sn_arc_huge_cr.mpf", sn_with("G1 X10\n", "G2 X10 Y0 CR=1EX300\n"))
add("sn_tool_missing.mpf", sn_with("T1 D1 M6\n", "T99 D1 M6\n"))
add("sn_edge_missing.mpf", sn_with("T1 D1 M6\n", "T1 D9 M6\n"))
add("sn_tool_name_missing.mpf", sn_with("T1 D1 M6\n", 'T="NOSUCH" D1 M6\n'))
add("sn_label_missing.mpf", sn_with("G1 X10\n", "GOTOF NOWHERE\nG1 X10\n"))
add("sn_endless_while.mpf", sn_with("G1 X10\n", "WHILE 1\nR1=R1+1\nENDWHILE\n"))
add("sn_array_too_big.mpf", "DEF REAL BIG[1000000]\n" + SN_OK)
add("sn_array_index_out_of_range.mpf", SN_DEF + sn_with("G1 X10\n", "A[5]=1\n"))
add("sn_nonascii_word.mpf", sn_with("G1 X10\n", "G1 X10 Ø5\n"))
add("sn_def_after_motion.mpf", sn_with("G1 X10\n", "G1 X10\nDEF REAL LATE\n"))

# ---------------------------------------------------------------------------------------------
# Tool tables
# ---------------------------------------------------------------------------------------------
TBL_OK = "T1 P1 Z+25 D10 ;end mill\nT2 P2 Z30 D6 ;drill\n"
add("tbl_ok_bom.tbl", BOM + TBL_OK.encode())
add("tbl_ok_crlf.tbl", crlf(TBL_OK))
add("tbl_ok_nonascii_comment.tbl", TBL_OK.replace(";end mill", ";Fräser Ø10 – 日本語"))
add("tbl_ok_negative_diameter.tbl", TBL_OK.replace("D10", "D-10"))
add("tbl_ok_long_comment.tbl", TBL_OK.replace(";end mill", ";" + "m" * BIG))
add("tbl_ok_empty.tbl", b"")
add("tbl_ok_big_finite.tbl", TBL_OK.replace("Z+25", "Z1e308"))
add("tbl_ok_tiny.tbl", TBL_OK.replace("Z+25", "Z1e-320"))
add("tbl_cr_only.tbl", cr_only(TBL_OK))
add("tbl_truncated_mid_word.tbl", "T1 P1 Z+25 D10 ;end mill\nT2 P2 Z")
add("tbl_binary_garbage.tbl", garbage(6, 4096, b"\x04"))
add("tbl_nul_byte.tbl", TBL_OK.replace("D6", "D6\x00"))
add("tbl_huge_exponent.tbl", TBL_OK.replace("D6", "D1e400"))
add("tbl_huge_digits.tbl", TBL_OK.replace("D6", "D1" + "0" * 400))
add("tbl_nan.tbl", TBL_OK.replace("D6", "Dnan"))
add("tbl_inf.tbl", TBL_OK.replace("D6", "D-inf"))
add("tbl_infinity.tbl", TBL_OK.replace("D6", "DInfinity"))
add("tbl_unknown_word.tbl", TBL_OK.replace("D6", "D6 K5"))
add("tbl_duplicate_word.tbl", TBL_OK.replace("D6", "D6 D7"))
add("tbl_duplicate_tool.tbl", TBL_OK + "T1 P3 D4\n")
add("tbl_missing_tool.tbl", TBL_OK + "P3 D4\n")
add("tbl_long_line_words.tbl", TBL_OK + "T3 P3 " + "D1 " * (BIG // 3) + "\n")
add("tbl_nonascii_word.tbl", TBL_OK + "T3 P3 Ø5\n")
add("tbl_bad_orientation.tbl", TBL_OK + "T3 P3 D0.8 Q12\n")

CSV_OK = "tool,pocket,z,diameter,comment\n1,1,25,10,end mill\n2,2,30,6,drill\n"
add("csv_ok_bom.csv", BOM + CSV_OK.encode())
add("csv_ok_crlf.csv", crlf(CSV_OK))
add("csv_ok_nonascii.csv", CSV_OK.replace("end mill", "\"Fräser Ø10, 日本語\""))
add("csv_ok_negative_radius.csv", CSV_OK.replace(",10,", ",-10,"))
add("csv_ok_long_comment.csv", CSV_OK.replace("end mill", "c" * BIG))
add("csv_cr_only.csv", cr_only(CSV_OK))
add("csv_truncated_row.csv", CSV_OK[:-8])
add("csv_truncated_quote.csv", CSV_OK + '3,3,20,4,"unterminated')
add("csv_binary_garbage.csv", garbage(7, 4096, b"\x05"))
add("csv_nan.csv", CSV_OK.replace(",6,", ",nan,"))
add("csv_inf.csv", CSV_OK.replace(",6,", ",inf,"))
add("csv_huge_exponent.csv", CSV_OK.replace(",6,", ",1e400,"))
add("csv_ok_big_finite.csv", CSV_OK.replace(",6,", ",1e308,"))
add("csv_extra_field.csv", CSV_OK.replace("2,2,30,6,drill", "2,2,30,6,drill,extra"))
add("csv_duplicate_column.csv", CSV_OK.replace("tool,pocket,z,diameter,comment", "tool,pocket,z,z,comment"))
add("csv_duplicate_tool.csv", CSV_OK + "1,3,20,4,again\n")
add("csv_missing_tool_column.csv", CSV_OK.replace("tool,", "tl,"))
add("csv_missing_tool.csv", CSV_OK + ",3,20,4,no number\n")
add("csv_bad_tool_number.csv", CSV_OK + "x3,3,20,4,bad\n")
add("csv_stray_quote.csv", CSV_OK.replace("drill", 'dr"ill'))
add("csv_bad_orientation.csv", "tool,diameter,orientation\n1,0.8,12\n")
add("csv_header_only_garbage.csv", "\x00\x00\x00\n1,2,3\n")

JSON_OK = '{"units": "mm", "tools": [{"tool": 1, "z": 25, "diameter": 10, "comment": "end mill"}, ' \
          '{"tool": 2, "z": 30, "diameter": 6}]}\n'
add("json_ok_bom.json", BOM + JSON_OK.encode())
add("json_ok_crlf_pretty.json", crlf('{\n  "units": "mm",\n  "tools": [\n    {"tool": 1, "diameter": 10}\n  ]\n}\n'))
add("json_ok_nonascii.json", JSON_OK.replace("end mill", "Fräser Ø10 – 日本語 \\u00e9"))
add("json_ok_negative_radius.json", JSON_OK.replace('"diameter": 10', '"diameter": -10'))
add("json_ok_long_comment.json", JSON_OK.replace("end mill", "j" * BIG))
add("json_ok_big_finite.json", JSON_OK.replace('"diameter": 6', '"diameter": 1e308'))
add("json_truncated.json", JSON_OK[:60])
add("json_empty.json", b"")
add("json_binary_garbage.json", garbage(8, 4096, b"\x06"))
add("json_nan.json", JSON_OK.replace('"diameter": 6', '"diameter": NaN'))
add("json_infinity.json", JSON_OK.replace('"diameter": 6', '"diameter": -Infinity'))
add("json_huge_exponent.json", JSON_OK.replace('"diameter": 6', '"diameter": 1e400'))
add("json_nan_string.json", JSON_OK.replace('"diameter": 6', '"diameter": "nan"'))
add("json_deep_arrays.json", '{"tools": ' + "[" * DEEP + "]" * DEEP + "}\n")
add("json_deep_objects.json", '{"tools": [], "x": ' + '{"a":' * 20000 + "1" + "}" * 20000 + "}\n")
add("json_unbalanced.json", JSON_OK.replace("]}", "}"))
add("json_trailing_comma.json", JSON_OK.replace("6}]}", "6},]}"))
add("json_duplicate_key.json", JSON_OK.replace('"z": 25', '"z": 25, "z": 26'))
add("json_duplicate_tool.json", JSON_OK.replace('"tool": 2', '"tool": 1'))
add("json_missing_tool.json", JSON_OK.replace('"tool": 2, ', ""))
add("json_tools_not_array.json", '{"tools": {"tool": 1}}\n')
add("json_single_quotes.json", JSON_OK.replace('"units": "mm"', "'units': 'mm'"))
add("json_bad_units.json", JSON_OK.replace('"mm"', '"furlong"'))
add("json_trailing_garbage.json", JSON_OK + "garbage\n")

T_HEAD = ("BEGIN TOOL .T MM\n"
          "T    NAME             L           R           R2          DL      DR      DR2     \n")
T_ROWS = ("1    MILL_10          +95.25      +5          +0          +0      -0.02   +0      \n"
          "2    DRILL_6          +80.5       +3          +0          +0      +0      +0      \n")
T_OK = T_HEAD + T_ROWS + "[END]\n"
add("t_ok_bom.t", BOM + T_OK.encode())
add("t_ok_crlf.t", crlf(T_OK))
add("t_ok_negative_radius.t", T_OK.replace("+5          +0", "-5          +0"))
add("t_ok_nonascii_name.t", T_OK.replace("MILL_10         ", "FRÄSER_10       "))
add("t_cr_only.t", cr_only(T_OK))
add("t_truncated_no_end.t", T_HEAD + T_ROWS)
add("t_truncated_mid_row.t", T_HEAD + T_ROWS[:100])
add("t_empty.t", b"")
add("t_binary_garbage.t", garbage(9, 4096, b"\x07"))
add("t_missing_header.t", "BEGIN TOOL .T MM\n" + T_ROWS + "[END]\n")
add("t_missing_begin.t", T_HEAD.split("\n", 1)[1] + T_ROWS + "[END]\n")
add("t_not_tool_table.t", "BEGIN PGM X MM\n" + T_ROWS + "[END]\n")
add("t_duplicate_tool.t", T_HEAD + T_ROWS + T_ROWS.split("\n")[0] + "\n[END]\n")
add("t_nan.t", T_OK.replace("+80.5       ", "nan         "))
add("t_inf.t", T_OK.replace("+80.5       ", "-inf        "))
add("t_bad_number.t", T_OK.replace("+80.5       ", "+8x0.5      "))
add("t_text_after_end.t", T_OK + "3    EXTRA            +1          +1          +0          +0      +0      +0      \n")
add("t_duplicate_column.t", T_OK.replace("DR2 ", "DR  "))
add("t_long_row.t", T_OK.replace("[END]", "3    LONG             +1          +1" + " " * BIG + "\n[END]"))

INI_OK = "$TC_DP1[1,1]=120\n$TC_DP3[1,1]=100\n$TC_DP6[1,1]=5\n$TC_DP1[2,1]=120\n$TC_DP3[2,1]=80\n$TC_DP6[2,1]=3\n"
add("ini_ok_bom.ini", BOM + INI_OK.encode())
add("ini_ok_crlf.ini", crlf(INI_OK))
add("ini_ok_comments.ini", "; Werkzeugdaten – Fräser Ø10\n" + INI_OK)
add("ini_ok_negative_radius.ini", INI_OK.replace("$TC_DP6[1,1]=5", "$TC_DP6[1,1]=-5"))
add("ini_ok_empty.ini", b"")
add("ini_ok_big_finite.ini", INI_OK.replace("=100", "=1E308"))
add("ini_cr_only.ini", cr_only(INI_OK))
add("ini_truncated.ini", INI_OK[:-9])
add("ini_binary_garbage.ini", garbage(10, 4096, b"\x08"))
add("ini_nan.ini", INI_OK.replace("=100", "=NAN"))
add("ini_inf.ini", INI_OK.replace("=100", "=-INF"))
add("ini_huge_exponent.ini", INI_OK.replace("=100", "=1E400"))
add("ini_huge_digits.ini", INI_OK.replace("=100", "=1" + "0" * 400))
add("ini_bad_parameter.ini", INI_OK + "$TC_DP99[1,1]=5\n")
add("ini_bad_edge.ini", INI_OK + "$TC_DP6[1,0]=5\n")
add("ini_bad_tool.ini", INI_OK + "$TC_DP6[-1,1]=5\n")
add("ini_bad_line.ini", INI_OK + "R1=5\n")
add("ini_unbalanced_bracket.ini", INI_OK + "$TC_DP6[3,1=5\n")
add("ini_expression.ini", INI_OK + "$TC_DP6[3,1]=((2+3)\n")
add("ini_long_line.ini", INI_OK + "$TC_DP6[3,1]=" + "1" * BIG + "\n")


def main():
    check = "--check" in sys.argv[1:]
    differ = []
    for name, data in sorted(FILES.items()):
        path = os.path.join(HERE, name)
        if check:
            try:
                with open(path, "rb") as f:
                    if f.read() != data:
                        differ.append(name)
            except FileNotFoundError:
                differ.append(name)
            continue
        with open(path, "wb") as f:
            f.write(data)
    if check:
        if differ:
            print("differ:", *differ)
            return 1
        print(f"{len(FILES)} files up to date")
        return 0
    print(f"wrote {len(FILES)} files")
    return 0


if __name__ == "__main__":
    sys.exit(main())
