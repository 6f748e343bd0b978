// checks #ifdef / #ifndef followed by #elseif
#version 3.7;
#declare Bar = 1;
#ifdef (Foo)
  #debug "Foo\n"
#elseif (Bar)
  #debug "no Foo, Bar true\n"
#else
  #debug "neither\n"
#end
#ifndef (Bar)
  #debug "no Bar\n"
#elseif (Bar = 2)
  #debug "Bar is 2\n"
#else
  #debug "Bar is not 2\n"
#end
