// expect: 4:12: cannot use font file "obj-text-not-font.pov": it is not a TrueType font
// POV-Ray: "Error reading font file."
#version 3.7;
text { ttf "obj-text-not-font.pov" "x" 1, 0 }
