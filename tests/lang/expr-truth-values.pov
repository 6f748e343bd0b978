// checks what counts as true in #if: zero, tiny values, negatives
#version 3.7;
#macro T(V) #if (V) #debug "T" #else #debug "F" #end #end
T(0) T(1) T(-1) T(0.5) T(1e-5) T(1e-9) T(1e-11) T(-1e-11) T(1e-300)
#debug "\n"
