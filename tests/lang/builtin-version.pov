// checks the version identifier after #version 3.7
#version 3.7;
#debug concat("version=", str(version, 0, 6), "\n")
#if (version >= 3.7) #debug "at least 3.7\n" #end
#if (version < 3.5) #debug "old\n" #else #debug "new\n" #end
