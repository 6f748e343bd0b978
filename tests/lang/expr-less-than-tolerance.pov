// checks < <= > >= with values that differ by less than 1e-10
#version 3.7;
#declare A = 1;
#declare B = 1 + 1e-12;
#debug concat(str((A < B), 0, 0), str((A <= B), 0, 0), str((A > B), 0, 0), str((A >= B), 0, 0), str((B > A), 0, 0), "\n")
#declare C = 1 + 1e-8;
#debug concat(str((A < C), 0, 0), str((A <= C), 0, 0), str((A > C), 0, 0), str((A >= C), 0, 0), str((C > A), 0, 0), "\n")
