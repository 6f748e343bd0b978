// checks that relational operators bind tighter than & and |, and & and | share one level left to right
#version 3.7;
#debug concat("(1<2 & 3>4)=", str((1<2 & 3>4), 0, 6), "\n")
#debug concat("(1<2 | 3>4)=", str((1<2 | 3>4), 0, 6), "\n")
#debug concat("(1 | 0 & 0)=", str((1 | 0 & 0), 0, 6), "\n")
#debug concat("(0 & 0 | 1)=", str((0 & 0 | 1), 0, 6), "\n")
#debug concat("(0 & 1 | 1)=", str((0 & 1 | 1), 0, 6), "\n")
#debug concat("(1 | 1 & 0)=", str((1 | 1 & 0), 0, 6), "\n")
#debug concat("(1 | (1 & 0))=", str((1 | (1 & 0)), 0, 6), "\n")
#debug concat("(!0 & !0)=", str((!0 & !0), 0, 6), "\n")
