// checks redeclaration that uses the identifier's own previous value
#version 3.7;
#declare N = 1;
#declare N = N * 2;
#declare N = N * N + N;
#debug concat(str(N, 0, 6), "\n")
#declare V = <1, 1, 1>;
#declare V = V * 2 + V;
#debug concat(vstr(3, V, ",", 0, 6), "\n")
#declare S = "a";
#declare S = concat(S, S, S);
#debug concat(S, "\n")
