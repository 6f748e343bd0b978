// checks #elseif chains without #else, where no branch is true
#version 3.7;
#declare Foo = 0;
#declare Bar = 1;
#if (Foo)
  #debug "Foo is true\n"
#elseif (Bar)
  #debug "Foo is false, but Bar is true\n"
#else
  #debug "Foo and Bar are both false\n"
#end
#if (0) #debug "a\n" #elseif (0) #debug "b\n" #end
#debug "done\n"
