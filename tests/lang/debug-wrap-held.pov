// Wrapped #debug lines are written at a newline and at every 160th
// column; what is held when the parse ends is never written (POV-Ray 3.7).
#version 3.7;
#debug "first\n"
#debug "abcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuv"
#debug "abcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwx\n"
#debug "abcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrst"
#debug "abcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuv"
#debug "tail without newline"
