// expect: 4:12: text may not read "/etc/passwd"
// The file rule: fonts come from the scene folder, +L, the stdlib, system fonts.
#version 3.7;
text { ttf "/etc/passwd" "x" 1, 0 }
