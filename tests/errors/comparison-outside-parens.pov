// expect: 4:16: '<' outside parentheses: POV-Ray compares and tests only inside them, as in (A < B)
// Comparisons bind only inside parentheses, as in POV-Ray: the
// declaration would end at the "<".
#declare A = 1 < 2;
