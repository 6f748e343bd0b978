// expect: 14:42: expected a value, found ','
// Found by fuzzing (slow: a Circle_Text of about 300 letters took 10.5 s of CPU
// under the sanitizers). shapes.inc's Circle_Text makes a text object per letter
// and measures every prefix of the string with Text_Width (so its cost grows with
// the square of the length); each of those texts searched the font folders (the
// system's fonts, for a POV-Ray font that is not installed) and read the font
// anew, and built its arrays one glyph at a time, copying them for every glyph.
// A parse now finds and loads each font once (text_parse.c, font_cache), and the
// arrays double as they fill (text.c, add_glyph): that input now takes 1.7 s
// under the sanitizers and 0.1 s built normally; this one, 120 letters, 0.6 s.
#version 3.7;
#include "shapes.inc"
#declare T = Circle_Text("timrom.ttf", "Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hel", 0.5, 0, 0.2, 10, 0, Align_Center, 90);
#declare B = Bevelled_Text("timrom.ttf", , z)
