// text-escape-ascii.pov: \uNNNN escapes above U+00FF in a text object under
// the default charset (ascii) are kept, not turned into spaces: POV-Ray
// shows the font's missing-glyph box for them (timrom.ttf). Extents
// rounded to 3 decimals. The expected output is what POV-Ray 3.7.0.10
// prints.
#version 3.7;
#macro Show(Font, Name, S)
  #local T = text { ttf Font S 1, 0 }
  #debug concat(Font, " ", Name, " ", str(max_extent(T).x, 0, 3), " ", str(max_extent(T).y, 0, 3), "\n")
#end
Show("timrom.ttf", "A", "A")
Show("timrom.ttf", "u0416", "A\u0416")
Show("timrom.ttf", "u0416 u0416", "A\u0416\u0416")
