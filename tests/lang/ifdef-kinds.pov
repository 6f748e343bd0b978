// checks #ifdef on identifiers of every kind: float, vector, string, array, macro, object, function, spline
#version 3.7;
#declare F = 1;
#declare V = <1,2,3>;
#declare S = "s";
#declare A = array[2];
#macro M() #end
#declare O = sphere { 0, 1 }
#declare Fn = function { x }
#declare Sp = spline { 0, <0,0,0>, 1, <1,1,1> }
#declare P = pigment { rgb 1 }
#ifdef (F) #debug "F " #end
#ifdef (V) #debug "V " #end
#ifdef (S) #debug "S " #end
#ifdef (A) #debug "A " #end
#ifdef (M) #debug "M " #end
#ifdef (O) #debug "O " #end
#ifdef (Fn) #debug "Fn " #end
#ifdef (Sp) #debug "Sp " #end
#ifdef (P) #debug "P " #end
#ifdef (Nope) #debug "Nope " #end
#debug "\n"
