// checks #version with an expression and the version identifier in comparisons
#version 3.7;
#declare Saved = version;
#version 3.0 + 0.5;
#debug concat(str(version, 0, 2), " ", str((version < 3.6), 0, 0), "\n")
#version Saved;
#debug concat(str(version, 0, 2), " ", str((version >= 3.7), 0, 0), "\n")
