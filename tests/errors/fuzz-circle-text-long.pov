// expect: 14:42: expected a value, found ','
// Found by fuzzing (10 s under the sanitizers): shapes.inc's Circle_Text makes a
// text object per letter, and each one searched the font folders (the system's
// fonts, for a POV-Ray font that is not installed) and read the font anew:
// 43,000 stat calls and 3,300 files opened for 300 letters. A parse now finds and
// loads each font once (text_parse.c, font_cache). Its Text_Width of every prefix
// of the string also built each text's arrays one glyph at a time, copying them
// for every glyph (under the sanitizers, realloc always copies): they double now
// (text.c, add_glyph). 7.4 s -> 1.4 s under the sanitizers, 0.1 s built normally.
#version 3.7;
#include "shapes.inc"
#declare T = Circle_Text("timrom.ttf", "Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello,", 0.5, 0, 0.2, 3, 0, Align_Center, 90);
#declare U = Circle_Text("timrom.ttf", "Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello, world Hello,", 0.5, 0, 0.2, 3, 1, Align_Left, 0);
#declare B = Bevelled_Text("timrom.ttf", , z)
