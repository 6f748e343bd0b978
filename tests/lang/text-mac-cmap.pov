// text-mac-cmap.pov: under charset ascii (the default) POV-Ray looks codes
// of 0x80 and more up in the font's own Macintosh table (cmap platform 1),
// which for cyrvetic.ttf is not Mac Roman, and for timrom.ttf leaves
// "\u00f7", "\u00c8" and "\u00e9" without a glyph; a code past 0xFF reads on
// past the 256-entry table ("\u0116" in cyrvetic.ttf is its "A"). Extents
// rounded to 3 decimals (POV-Ray's bounds are 1e-5 wider: the lowest y
// of an "A" prints as -0.000 unrounded). The expected output is what
// POV-Ray 3.7.0.10 prints.
#version 3.7;
#macro Show(Font, Name, S)
  #local T = text { ttf Font S 1, 0 }
  #debug concat(Font, " ", Name, " ", str(max_extent(T).x, 0, 3), " ", str(floor(min_extent(T).y * 1000 + 0.5) / 1000, 0, 3), " ", str(max_extent(T).y, 0, 3), "\n")
#end
Show("cyrvetic.ttf", "A", "A")
Show("cyrvetic.ttf", "u00e9", "\u00e9")
Show("cyrvetic.ttf", "u00f7", "\u00f7")
Show("cyrvetic.ttf", "u00c8", "\u00c8")
Show("cyrvetic.ttf", "u0080", "A\u0080")
Show("cyrvetic.ttf", "u0116", "\u0116")
Show("cyrvetic.ttf", "u0416", "\u0416")
Show("timrom.ttf", "u00f7", "A\u00f7")
Show("timrom.ttf", "u00c8", "A\u00c8")
Show("timrom.ttf", "u00e9", "A\u00e9")
Show("timrom.ttf", "u0082", "A\u0082")
Show("timrom.ttf", "u0083", "A\u0083")
Show("timrom.ttf", "chr130", concat("A", chr(130)))
