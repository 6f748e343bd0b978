// text-escape-utf8.pov: \uNNNN escapes in text objects under charset utf8
// are the characters of those codes (POV-Ray's fonts timrom.ttf and
// cyrvetic.ttf). Extents rounded to 3 decimals: POV-Ray's text bounds are
// about 1e-5 larger than the glyphs. The expected output is what POV-Ray
// 3.7.0.10 prints.
#version 3.7;
global_settings { charset utf8 }
#macro Show(Font, Name, S)
  #local T = text { ttf Font S 1, 0 }
  #debug concat(Font, " ", Name, " ", str(max_extent(T).x, 0, 3), " ", str(max_extent(T).y, 0, 3), "\n")
#end
Show("timrom.ttf", "u0416", "A\u0416")
Show("timrom.ttf", "u00e9", "A\u00e9")
Show("cyrvetic.ttf", "u0416", "A\u0416")
Show("cyrvetic.ttf", "u00d6", "A\u00d6")
Show("cyrvetic.ttf", "u00f7", "A\u00f7")
Show("cyrvetic.ttf", "u00e9", "A\u00e9")
Show("cyrvetic.ttf", "u00c8", "A\u00c8")
Show("cyrvetic.ttf", "u0416 u00e9", "A\u0416\u00e9")
#declare T = text { ttf "cyrvetic.ttf" "A\u00d6" 1, 0 }
#debug concat("descender ", str(min_extent(T).y, 0, 3), "\n")
