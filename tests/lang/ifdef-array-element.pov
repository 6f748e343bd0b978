// checks #ifdef / #ifndef / defined() on array elements
#version 3.7;
#declare MyArray = array[10];
#declare MyArray[3] = 7;
#ifdef (MyArray[0]) #debug "first element is assigned\n" #else #debug "first element is not assigned\n" #end
#ifdef (MyArray[3]) #debug "element 3 is assigned\n" #else #debug "element 3 is not assigned\n" #end
#ifndef (MyArray[9]) #debug "element 9 is not assigned\n" #end
#for (I, 0, 9)
  #ifdef (MyArray[I]) #debug "1" #else #debug "0" #end
#end
#debug "\n"
