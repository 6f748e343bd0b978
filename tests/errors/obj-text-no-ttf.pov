// expect: 4:8: expected ttf or internal
// POV-Ray: "ttf expected"
#version 3.7;
text { "timrom.ttf" "x" 1, 0 }
