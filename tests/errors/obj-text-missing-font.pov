// expect: 4:12: cannot find font file "nosuchfont.ttf"
// POV-Ray: "Cannot open font file."
#version 3.7;
text { ttf "nosuchfont.ttf" "x" 1, 0 }
