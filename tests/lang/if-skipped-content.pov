// checks that a skipped branch may contain text that would not parse, as long as directives nest
#version 3.7;
#if (0)
  this is { not valid ) scene ] text
  #declare X = ;
  #undef
#else
  #debug "the false branch was skipped\n"
#end
#if (1)
  #debug "true branch\n"
#else
  more garbage < < <
#end
