// checks substr() positions (1-based) and lengths
#version 3.7;
#debug concat(substr("ABCDEFGHI", 4, 2), "\n")
#debug concat(substr("ABCDEFGHI", 1, 9), "\n")
#debug concat(substr("ABCDEFGHI", 9, 1), "\n")
#debug concat(substr("ABCDEFGHI", 1, 1), "\n")
#debug concat("[", substr("ABCDEFGHI", 3, 0), "]\n")
#declare S = "The quick brown fox";
#debug concat(substr(S, 5, 5), "|", substr(S, strlen(S)-2, 3), "\n")
