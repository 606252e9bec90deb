// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

namespace lsys::testing {

/// The 3D Hilbert curve of seed 000 and ABOP fig. 1.19, as printed.
constexpr const char* kHilbert =
    "n=2, \u03B4=90\u00B0\nA\n"
    "A \u2192 B-F+CFC+F-D&F^D-F+&&CFC+F+B//\n"
    "B \u2192 A&F^CFB^F^D^^-F-D^|F^B|FC^F^A//\n"
    "C \u2192 |D^|F^B-F+C^F^A&&FA&F^C+F+B^F^D//\n"
    "D \u2192 |CFB-F+B|FA&F^A&&FB-F+B|FC//\n";

/// Honda's monopodial tree, ABOP Table 2.1 a, as seed 000 prints it.
constexpr const char* kHonda =
    "#define r1 0.9 /* contraction ratio for the trunk */\n"
    "#define r2 0.6 /* contraction ratio for branches */\n"
    "#define a0 45 /* branching angle from the trunk */\n"
    "#define a2 45 /* branching angle for lateral axes */\n"
    "#define d 137.5 /* divergence angle */\n"
    "#define wr 0.707 /* width decrease rate */\n"
    "n = 10\n"
    "\u03C9 : A(1, 10)\n"
    "p1 : A(l, w) : * \u2192 !(w)F(l) [ &(a0)B(l*r2, w*wr) ] /(d)A(l*r1, "
    "w*wr)\n"
    "p2 : B(l, w) : * \u2192 !(w)F(l) [ -(a2)$C(l*r2, w*wr) ] C(l*r1, w*wr)\n"
    "p3 : C(l, w) : * \u2192 !(w)F(l) [ +(a2)$B(l*r2, w*wr) ] B(l*r1, w*wr)\n";

}  // namespace lsys::testing
