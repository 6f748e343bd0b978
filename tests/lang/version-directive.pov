// checks that #version changes the version identifier, and can be changed back
#version 3.7;
#debug concat(str(version, 0, 2), "\n")
#version 3.5;
#debug concat(str(version, 0, 2), "\n")
#version 3.6;
#debug concat(str(version, 0, 2), "\n")
#version 3.7;
#debug concat(str(version, 0, 2), "\n")
