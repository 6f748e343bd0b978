// debug-wrap-blanks.pov: POV-Ray 3.7's #debug stream breaks long lines
// at a tab, vertical tab or form feed as at a space, and ends a line at a
// carriage return as at a newline. The expected output is what
// POV-Ray 3.7.0.10 prints.
#version 3.7;
#macro Str(C, N)
  #local S = "";
  #for (I, 1, N) #local S = concat(S, C); #end
  S
#end
#debug concat(Str("a", 65), "\t", Str("b", 30), "\n")
#debug concat(Str("a", 65), "\v", Str("b", 30), "\n")
#debug concat(Str("a", 65), "\f", Str("b", 30), "\n")
#debug concat(Str("a", 65), "\r", Str("b", 30), "\n")
#debug concat(Str("a", 65), "-", Str("b", 30), "\n")
#debug concat(Str("a\tb", 30), "\n")
#debug "a\rb\n"
#debug "c\r\n"
#debug "d\r"
#debug "e\n"
// Random messages that lucent used to break elsewhere.
#debug "        w     nop klm     g          i     nop k          cd no     vwx          uvw  klm  i    \t     m \t\t       ijk               \t              qr  \t         \t          \n"
#debug "|\n"
#debug "                            lmnopqr uvwxyzabc                                                 \f                              no\rtuvwxyzabcd             "
#debug "      \n"
#debug "|\n"
#debug "vwx qrs ijk fghi\tcd \t   \t  \t\t   \t\t\t     \t \t  \t\t  \v \t   \t\t\t tuvwxy \t  \t      \t\t      \t                      \t     \t\t  \t    \t "
#debug "\t   \t\t\t\t  \f\t\t\t     \t\to\v    \t   \t    \v \t     \t\t  \n"
#debug "|\n"
